"""Every problem under assignments/ exports to a Kattis package that problemtools' verifyproblem
accepts (0 errors) as a scoring problem with its groups, and its accepted reference solutions
(Python and C++) score per group in problemtools exactly as our judge scores them.

What is exported (kept short because verifyproblem runs every validator and every submission on
every test): the samples, all tests of the first scored group, and the first test of the last
scored group (the large one, where a too-slow solution times out), i.e. ``--groups
<first>,<last>:1``. Problems are discovered, so new ones are covered when they arrive; one test
per problem, so pytest-xdist spreads them over its workers.

Every problem's package goes through verifyproblem's ``config``, ``data`` and ``submissions``
checks: problem.yaml, the test data and its testdata.yaml files, the input validators on every
exported test, and the accepted submissions, which must be AC with full points in every exported
group (``accepted.cpp`` compiled with problemtools' own flags beside the Python one), the output
validator judging them. Its ``validators`` check (the validators' compile, then about a hundred runs
of the output validator on problemtools' junk outputs, and the input validators on junk inputs,
which can only warn) runs on :data:`FULL_MATRIX`; for every problem the same junk outputs go
through the exported output validator in this process
(``test_exported_output_validator_survives_problemtools_junk``), seconds instead of 20 CPU-s each.
Placing the other reference solutions is one piece of code for every problem, so the full matrix
runs on one problem, :data:`FULL_MATRIX`: every reference solution is judged by our judge to place
it (``accepted``, ``partially_accepted``, ``wrong_answer``), and verifyproblem must give each the
verdict of its directory. For the other
problems verifyproblem runs only ``accepted/`` (``-s accepted/``); their wrong solutions' verdicts
under our judge are tested in ``tests/grader/test_solutions.py``, and there the accepted ones
score 100 of 100, so their expected points per exported group are each group's points.

The C++ reference solutions (``expected_cpp.yaml``) are exported beside the Python ones, so
verifyproblem compiles them with its own flags and runs them: ``accepted.cpp`` must score every
exported group, as our expected verdict says. Where each other C++ file goes is tested without
problemtools below.

Measured 2026-12-06 with the 12 problems: all submissions of every problem in one test with a
pool of 2 took 602 s of CPU (552 user + 51 system), 908 s in CI. As now (``/usr/bin/time`` around
pytest, load average 8 on 2 cores): the full matrix on proximity-network 102 s of CPU (345 s of
wall time), each other problem 20-25 s of CPU (55-130 s of wall time), about 330 s of CPU in all.
Without the ``validators`` check on the other problems (2026-12-06, load 5): delaunay 38.9 -> 21.5
CPU-s (benchmarks/README.md, "The test suite's CI time: cuts per test").

Run: .venv/bin/python -m pytest tests/grader/test_kattis.py -q
"""
from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from grader.contest.judge import Judge
from grader.contest.kattis import (LANGUAGES_YAML, cpp_placements, expected_cpp, expected_verdicts, export, group_dirname,
                                   scored_groups, selection, shortname)
from grader.problems import REPO, list_problems, load_problem

VERIFY = Path(sys.executable).with_name("verifyproblem")
PROBLEMS = [p.id for p in list_problems(REPO / "assignments")]
#: the problem whose every reference solution is placed by judging it and run by verifyproblem
#: (its package has accepted, partially_accepted and wrong_answer submissions, and a C++ file placed by
#: judging it: quadratic.cpp; delaunay, with twice the solutions, took 630 s alone on a loaded machine)
FULL_MATRIX = "proximity-network"


def export_groups(problem_id: str) -> list[str]:
    """``[first scored group, last scored group:1]`` (one entry when they are the same)."""
    p = next(q for q in list_problems(REPO / "assignments") if q.id == problem_id)
    scored = [g.name for g in p.groups if g.name != "sample" and g.points > 0]
    return [scored[0]] if len(scored) == 1 else [scored[0], f"{scored[-1]}:1"]


def results_table(out: str) -> dict[str, dict[str, str]]:
    """verifyproblem's "Submission results" table: submission file -> column -> cell."""
    lines = out.splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.strip() == "Submission results:")
    head = lines[start + 1].split()
    rows = {}
    for ln in lines[start + 2:]:
        cells = ln.split()
        if len(cells) != len(head) or not cells[0].endswith((".py", ".cpp")):
            break
        rows[cells[0]] = dict(zip(head, cells))
    return rows


def verify_one(problem_id: str, tmp_path: Path, full: bool) -> dict:
    """Export, run verifyproblem, and say what our judge gives the accepted solutions on the same
    tests. ``full``: every reference solution placed by judging it and run by verifyproblem;
    otherwise the others are placed by their expected verdicts and only ``accepted/`` is run."""
    (tmp_path / "config" / "problemtools").mkdir(parents=True)
    (tmp_path / "config" / "problemtools" / "languages.yaml").write_text(LANGUAGES_YAML)
    groups = export_groups(problem_id)
    dest = export(problem_id, tmp_path / "kattis", groups=groups, judge=full)
    env = {**os.environ, "XDG_CONFIG_HOME": str(tmp_path / "config"),
           "PATH": f"{Path(sys.executable).parent}:{os.environ.get('PATH', '')}"}
    only = [] if full else ["-s", "accepted/"]
    parts = ["config", "data", "validators", "submissions"] if full else ["config", "data", "submissions"]
    proc = subprocess.run([str(VERIFY), str(dest), *only, "-p", *parts],
                          cwd=tmp_path, env=env, capture_output=True, text=True, timeout=1800)
    problem = load_problem(problem_id)
    exported = selection(problem, scored_groups(problem, groups))
    full_points = {group_dirname(problem, g.name): g.points for g in exported.groups}
    ours = {}
    for name, verdict in expected_verdicts(problem_id).items():
        if verdict == "AC" and full:
            # some problems share a solution through a symbolic link, which the judge (rightly)
            # refuses to follow in a submission: judge the file it points to
            src = (REPO / "solutions" / problem_id / name).resolve()
            r = Judge(exported, hide=[str(src.parent)]).judge_path(src)
            ours[name] = {group_dirname(problem, g): (p if r.group_passed(g) else 0) for g, p in r.group_points.items()}
        elif verdict == "AC":  # 100 of 100 under our judge on every test (tests/grader/test_solutions.py)
            ours[name] = full_points
    for name, (verdict, _failing) in expected_cpp(problem_id).items():
        if verdict == "AC":  # every exported group, full points (tests/grader/test_solutions.py)
            ours[name] = full_points
    subs = {d.name: sorted(f.name for f in d.iterdir()) for d in (dest / "submissions").iterdir()}
    return {"out": proc.stdout + proc.stderr, "ours": ours, "dest": dest, "subs": subs}


def test_the_full_matrix_problem_has_every_kind_of_placement():
    """:data:`FULL_MATRIX` is a problem, and its expected verdicts include wrong and slow solutions."""
    assert FULL_MATRIX in PROBLEMS, PROBLEMS
    assert {"AC", "WA", "TLE"} <= set(expected_verdicts(FULL_MATRIX).values())


@pytest.mark.slow
@pytest.mark.skipif(not VERIFY.exists(), reason="problemtools is not installed")
@pytest.mark.parametrize("pid", sorted(PROBLEMS, key=lambda pid: pid != FULL_MATRIX))  # the longest first
def test_verifyproblem_accepts_the_problem_with_its_groups(pid, tmp_path):
    full = pid == FULL_MATRIX
    res = verify_one(pid, tmp_path, full)
    out, dest = res["out"], res["dest"]
    assert dest.name == shortname(pid) and re.fullmatch(r"[a-z0-9]+", dest.name)
    summary = [ln for ln in out.splitlines() if " tested: " in ln]
    # A wrong answer that is also slow (the original tutorial's code on random points) may
    # hit the time limit first under problemtools on a loaded machine: still a rejection, the
    # only disagreement tolerated; any other error fails.
    errors = re.search(r"tested: (\d+) errors?", summary[-1]) if summary else None
    slow_wrong = re.findall(r"ERROR wrong_answer/\S+ .* got TLE", out)
    assert errors and int(errors.group(1)) == len(slow_wrong), (pid, out[-4000:])
    assert "accepted" in res["subs"], (pid, res["subs"])
    cpp_ac = {n for n, (v, _) in expected_cpp(pid).items() if v == "AC"}
    assert cpp_ac <= set(res["subs"]["accepted"]), (pid, res["subs"])  # C++ is in the package
    table = results_table(out)
    assert set(res["ours"]) <= set(table), (pid, sorted(table))
    for name, per_group in res["ours"].items():
        row = table[name]
        for col, points in per_group.items():  # problemtools prints AC(<points>):<time> per group
            assert re.fullmatch(rf"AC\({points}\):\S+", row[col]), (pid, name, col, row)
        assert row["Pts"] == str(sum(per_group.values())), (pid, name, row)
    if full:
        assert {"accepted", "partially_accepted", "wrong_answer"} <= set(res["subs"]), res["subs"]
        for kind in res["subs"]:
            assert re.search(rf"{kind}/\S+ .*(OK|got TLE)", out), (pid, kind, out[-3000:])
    else:
        assert re.search(r"accepted/\S+ .*OK", out), (pid, out[-3000:])
        assert set(table) <= set(res["subs"]["accepted"]), (pid, sorted(table))  # only accepted/ ran


def _exported_validator(problem_id: str) -> dict:
    """The namespace of the problem's exported output validator (the file ``export`` writes)."""
    from grader.contest.kattis import embed_checker

    ns = {"__name__": f"kattis_junk_{problem_id.replace('-', '_')}"}
    exec(compile(embed_checker(load_problem(problem_id)), "checker.py", "exec"), ns)
    return ns


def _validate(ns: dict, folder: Path, input_text: str, answer_text: str, team: bytes) -> tuple[int, str]:
    """Run the exported validator's Kattis entry in this process: its exit code and judge message."""
    import io

    (folder / "in").write_text(input_text)
    (folder / "ans").write_text(answer_text)
    old, sys.stdin = sys.stdin, io.TextIOWrapper(io.BytesIO(team))
    try:
        code = ns["_checker_runtime"]["kattis_main"](ns, ["checker.py", str(folder / "in"), str(folder / "ans"), str(folder)])
    finally:
        sys.stdin = old
    return code, (folder / "judgemessage.txt").read_text()


@pytest.mark.skipif(not VERIFY.exists(), reason="problemtools is not installed")
@pytest.mark.parametrize("pid", sorted(PROBLEMS))
def test_exported_output_validator_survives_problemtools_junk(pid, tmp_path):
    """verifyproblem's ``validators`` part, the output validator's half, for every problem in this
    process (verifyproblem runs that part on :data:`FULL_MATRIX` only: per problem it is about a
    hundred validator processes, 20 CPU-s). problemtools' own junk outputs go through the exported
    validator on the tests it would export (the samples and the first scored group): the four junk
    files are rejected on some test (problemtools warns otherwise), and none of the junk, nor the
    twenty "crash" files on the first three tests, makes it crash (a judge error: verifyproblem's
    only error in that part); every run exits 42 or 43 with a message. The input validators' half
    only warns, and ``data`` still runs them on every exported test."""
    from problemtools.checks import validators as pt

    problem = load_problem(pid)
    cases = [(f.read_text(), f.with_suffix(".ans").read_text()) for f in sorted((problem.path / "data" / "sample").glob("*.in"))]
    first, _count = scored_groups(problem, export_groups(pid))[0]
    cases += [(t.input_text, t.answer_text) for t in problem.tests() if t.group == first.name]
    assert len(cases) >= 3, (pid, len(cases))
    ns = _exported_validator(pid)
    for junk_cases, where in ((pt._JUNK_CASES, cases), (pt._JUNK_CASES_CRASH, cases[:3])):
        for desc, junk in junk_cases:
            codes = []
            for input_text, answer_text in where:
                code, message = _validate(ns, tmp_path, input_text, answer_text, junk)
                assert code in (42, 43) and message.strip(), (pid, desc, code, message)
                codes.append(code)
            if junk_cases is pt._JUNK_CASES:
                assert 43 in codes, (pid, desc, "accepted on every test")


def test_export_writes_scored_groups(tmp_path):
    """The package's layout and testdata.yaml files (no problemtools needed)."""
    import yaml

    dest = export("delaunay", tmp_path, groups=["tiny", "large:1"], judge=False)
    secret = dest / "data" / "secret"
    assert sorted(d.name for d in secret.iterdir() if d.is_dir()) == ["01-tiny", "05-large"]
    tiny_cases = len(next(g for g in load_problem("delaunay").groups if g.name == "tiny").cases)
    assert len(list((secret / "01-tiny").glob("*.in"))) == tiny_cases and len(list((secret / "05-large").glob("*.in"))) == 1
    tiny = yaml.safe_load((secret / "01-tiny" / "testdata.yaml").read_text())
    assert tiny == {"on_reject": "break", "grader_flags": "min", "accept_score": 15, "range": "0 15"}
    top = yaml.safe_load((secret / "testdata.yaml").read_text())
    assert "accept_if_any_accepted" in top["grader_flags"] and top["range"] == "0 45"
    # no group accepted: the first failing group's verdict decides (as our judge does), so a later
    # test near the time limit cannot turn a fast WA into a TLE
    assert "first_error" in top["grader_flags"].split()
    assert yaml.safe_load((dest / "problem.yaml").read_text())["type"] == "scoring"
    with pytest.raises(ValueError, match="positive integer"):
        export("delaunay", tmp_path, groups=["large:0"])


def test_cpp_submissions_go_where_their_expected_verdict_holds(tmp_path, capsys):
    """Without problemtools: C++ files are placed from ``expected_cpp.yaml`` for the exported groups
    (the judge does not take ``.cpp`` yet, and a WA does not depend on the time limit); a TLE is
    never placed unjudged; a compile error never goes in; the package's README says what is left out."""
    assert expected_cpp("delaunay")["wrong_double.cpp"] == ("WA", ["degenerate"])
    dest = export("delaunay", tmp_path, judge=False)  # every group
    subs = {f.name: f.parent.name for f in (dest / "submissions").rglob("*.cpp")}
    assert subs == {"accepted.cpp": "accepted", "wrong_double.cpp": "partially_accepted"}
    readme = (dest / "README.md").read_text()
    assert "`quadratic.cpp`: its TLE" in readme and "`compile_error.cpp`: a compile error" in readme
    assert "6 s per test" in readme and "quadratic.cpp left out" in capsys.readouterr().err

    problem = load_problem("delaunay")
    for groups, expected in ((["degenerate"], "wrong_answer"), (["tiny", "degenerate"], "partially_accepted"),
                             (["tiny", "large:1"], None)):
        placed, left = cpp_placements(selection(problem, scored_groups(problem, groups)), judge=False, partial=True)
        assert placed.get("wrong_double.cpp") == expected, (groups, placed, left)
        assert placed["accepted.cpp"] == "accepted" and "quadratic.cpp" in left and "compile_error.cpp" in left
    # a first failure outside the export: its verdict there is unknown, so it is left out
    placed, left = cpp_placements(selection(load_problem("edge-flip"), scored_groups(load_problem("edge-flip"), ["medium"])),
                                  judge=False, partial=True)
    assert "wrong_double.cpp" not in placed and "not exported" in left["wrong_double.cpp"]


def test_cpp_expected_verdicts_are_known(monkeypatch):
    """A verdict that names no Kattis directory is a clear error naming the problem and the file."""
    import grader.contest.kattis as kattis

    monkeypatch.setattr(kattis, "expected_cpp", lambda pid: {"accepted.cpp": ("OK", [])})
    with pytest.raises(ValueError, match="delaunay: expected_cpp.yaml: accepted.cpp: unknown verdict 'OK'"):
        kattis.cpp_placements(load_problem("delaunay"), judge=False)


def test_cpp_files_are_judged_under_twice_the_package_limit_once_the_judge_takes_them(monkeypatch):
    """Once ``.cpp`` is among the judge's languages every non-AC C++ file is judged on the exported
    tests, under twice the package's (Python) limit, problemtools' safety margin: what passes there
    is left out, a partial score is ``partially_accepted``, none is its first failure's directory.
    (The judge is replaced here by one that reports given scores: the placement is what is tested.)"""
    import grader.contest.judge as judge_module
    import grader.judging.languages as languages
    from grader.judging.verdicts import JudgeResult, TestResult

    monkeypatch.setattr(languages, "language_of", lambda path: languages.CPP)
    problem = load_problem("delaunay")
    exported = selection(problem, scored_groups(problem, ["tiny", "large:1"]))
    outcome = {"wrong_double.cpp": ("WA", ["tiny"]), "quadratic.cpp": ("TLE", ["large"]), "compile_error.cpp": None}
    limits = []

    class FakeJudge:
        def __init__(self, p, hide=()):
            limits.append(p.time_limit_for("cpp"))

        def judge_path(self, src):
            verdict, failing = outcome[Path(src).name]
            tests = [TestResult(f"{g}/01", g, verdict if g in failing else "AC", 0.1) for g in ("tiny", "large")]
            return JudgeResult("delaunay", str(src), tests, {"tiny": 15, "large": 30})

    monkeypatch.setattr(judge_module, "Judge", FakeJudge)
    placed, left = cpp_placements(exported, judge=True, partial=True)
    assert placed == {"accepted.cpp": "accepted", "wrong_double.cpp": "partially_accepted",
                      "quadratic.cpp": "partially_accepted"}, (placed, left)
    assert limits == [2 * problem.time_limit] * 2 and "compile_error.cpp" in left
    outcome["quadratic.cpp"] = ("TLE", [])  # passes every exported group under 12 s: left out
    outcome["wrong_double.cpp"] = ("WA", ["tiny", "large"])
    placed, left = cpp_placements(exported, judge=True, partial=True)
    assert placed["wrong_double.cpp"] == "wrong_answer" and "2 times the package's time limit" in left["quadratic.cpp"]
