"""Problem packages load, validate (the checker protocol in full), generate deterministic tests,
and reject bad input clearly. Every problem under assignments/ is discovered, not listed here.

Run: .venv/bin/python -m pytest tests/grader/test_problems.py -q
"""
from __future__ import annotations

import shutil

import pytest

from grader.judging import checker_runtime
from grader.judging.checker_protocol import foreign_imports, validate_checker
from grader.contest.kattis import embed_checker
from grader.problems import Problem, list_problems, load_problem

PROBLEMS = [p.id for p in list_problems()]


def test_the_first_two_problems_are_listed():
    assert {"delaunay", "bowyer-watson-timed"} <= set(PROBLEMS)


@pytest.mark.parametrize("pid", PROBLEMS)
def test_package_is_sound(pid):
    p = load_problem(pid)
    assert p.validate() == []
    assert "reference_impl" in p.forbidden and "grader" in p.forbidden
    assert sum(g.points for g in p.groups) == 100
    assert p.groups[0].name == "sample" and p.groups[0].points == 0
    statement = (p.path / "statement" / "problem.en.md").read_text()
    assert "SPEC" not in statement and f"{p.entry}(" in statement


@pytest.mark.parametrize("pid", PROBLEMS)
def test_checker_keeps_the_protocol_on_every_test(pid):
    """Round trips, the reference answer accepted (also as JSON data), draw runs."""
    assert validate_checker(load_problem(pid)) == []


@pytest.mark.parametrize("pid", PROBLEMS)
def test_input_validator_accepts_every_test(pid):
    assert load_problem(pid).validate_inputs() == []


def test_delaunay_forbids_the_triangulation_libraries():
    for pid in ("delaunay", "bowyer-watson-timed"):
        assert "scipy.spatial" in load_problem(pid).forbidden


def test_generator_is_seeded_and_covers_the_tutorial():
    gen = load_problem("delaunay").generator
    assert gen.generate({"kind": "uniform", "n": 5}, 3) == gen.generate({"kind": "uniform", "n": 5}, 3)
    assert gen.generate({"kind": "tutorial", "shuffle": False}, 0) == [[1.0, 1.0], [3.0, 2.0], [5.0, 1.0], [4.0, 4.0]]
    with pytest.raises(ValueError, match="unknown case kind"):
        gen.generate({"kind": "spiral"}, 0)


def test_hidden_groups_hold_the_degenerate_cases():
    p = load_problem("delaunay")
    kinds = {c["kind"] for g in p.groups for c in g.cases}
    assert {"tutorial", "grid", "cocircular", "collinear", "duplicates", "scaled"} <= kinds
    scales = {c.get("scale") for g in p.groups for c in g.cases}
    assert 1e-300 in scales and 1e300 in scales


def test_unknown_problem_is_a_clear_error():
    with pytest.raises(ValueError, match="unknown problem 'nope'.*delaunay"):
        load_problem("nope")


def test_checker_types_results_strictly():
    chk = load_problem("delaunay").checker
    assert chk.from_result([[0, 1, 2]], None) == [[0, 1, 2]]
    for bad in ([[0.0, 1, 2]], [[0, 1]], "012", [[True, 1, 2]], None):
        with pytest.raises(chk.PresentationError):
            chk.from_result(bad, None)
    with pytest.raises(chk.PresentationError):
        chk.read_output("2\n0 1 2\n", None)


# -- the protocol validator catches each kind of broken checker -------------------------------
def _broken_copy(tmp_path, edit) -> Problem:
    src = load_problem("delaunay").path
    dest = tmp_path / "broken"
    shutil.copytree(src, dest, ignore=shutil.ignore_patterns("__pycache__"))
    (dest / "course.yaml").write_text((dest / "course.yaml").read_text().replace(
        "  - name: large", "  - name: large-unused").split("  - name: tiny")[0]
        + "  - name: tiny\n    points: 100\n    cases:\n      - {kind: tutorial, shuffle: false}\n")
    chk = dest / "output_validator" / "checker.py"
    chk.write_text(edit(chk.read_text()))
    return Problem.load(dest)


@pytest.mark.parametrize("edit,finding", [
    (lambda s: s.replace("def write_input(args: list)", "def write_input_(args: list)"), "lacks write_input"),
    (lambda s: s.replace("def check(args: list, triangles", "def check(args: list, *, triangles"), "check must be callable"),
    (lambda s: s.replace("LIBRARY = (", "import numpy\nLIBRARY = ("), "imports numpy"),
    (lambda s: s.replace('LIBRARY = ("judge_io", "verify", "bulk")', 'LIBRARY = ("judge_io", "delaunay")'), "must be stdlib-only"),
    (lambda s: s.replace('LIBRARY = ("judge_io", "verify", "bulk")', 'LIBRARY = ("no_such_module",)'), "does not exist"),
    (lambda s: s + '\nif __name__ == "__main__":\n    pass\n', "own __main__"),
    (lambda s: s.replace("return judge_io.write_points(args[0])", "return judge_io.write_points([p[::-1] for p in args[0]])"),
     "read_input(write_input(args)) != args"),
    (lambda s: s.replace("return judge_io.write_index_rows(triangles)", "return judge_io.write_index_rows(triangles[1:])"),
     "read_output(write_output(answer))"),
    # check() accepts early (``return True, "ok"``) and ends with ``return ok, message``: both edited
    (lambda s: s.replace("    return ok, message\n", "    return False, 'no'\n").replace('return True, "ok"', "return False, 'no'"),
     "reference answer is rejected"),
    (lambda s: s.replace("    return ok, message\n", "    return int(ok), message\n").replace('return True, "ok"', 'return 1, "ok"'),
     "check must return (bool, message)"),
    (lambda s: s.replace("        ax.set_aspect(", "        1 / 0\n        ax.set_aspect("), "draw failed"),
    # issue 23's crash: isdigit() is true for '²', int('²') raises; 5000 digits exceed int()'s limit
    (lambda s: s.replace("    if announced is not None:\n", "    if first.isdigit():\n        announced = int(first)\n"
                         "    if announced is not None:\n"), "hostile answer: read_output raised ValueError"),
])
def test_protocol_violations_are_reported(tmp_path, edit, finding):
    errors = validate_checker(_broken_copy(tmp_path, edit))
    assert any(finding in e for e in errors), errors


def test_sound_copy_passes(tmp_path):
    assert validate_checker(_broken_copy(tmp_path, lambda s: s)) == []


def test_foreign_imports_skip_draw_only():
    src = "import json\ndef draw(ax):\n    import matplotlib\ndef check():\n    from numpy import array\n"
    assert foreign_imports(src, "c.py") == ["numpy"]
    assert foreign_imports("from . import verify\n", "c.py") == ["."]


@pytest.mark.parametrize("pid", PROBLEMS)
def test_exported_checker_is_self_contained(pid, tmp_path):
    """The Kattis copy imports no file of this checkout: run it from an empty directory."""
    import subprocess
    import sys

    p = load_problem(pid)
    exported = tmp_path / "checker.py"
    exported.write_text(embed_checker(p))
    assert checker_runtime.library_names(exported.read_text()) == checker_runtime.library_names(p.checker_path.read_text())
    test = p.tests()[0]
    (tmp_path / "in").write_text(test.input_text)
    (tmp_path / "ans").write_text(test.answer_text)
    (tmp_path / "fb").mkdir()
    for team, code in ((test.answer_text, 42), ("garbage\n", 43)):
        r = subprocess.run([sys.executable, "-I", str(exported), "in", "ans", "fb"], input=team, text=True,
                           cwd=tmp_path, capture_output=True, env={"PATH": "/usr/bin:/bin"})
        assert r.returncode == code, (team, r.stderr[-2000:])
        assert (tmp_path / "fb" / "judgemessage.txt").read_text().strip()
