"""The student edition holds what a student needs and nothing hidden: no reference solutions, no
source notebooks, no generators or seeds, no hidden test data; its local judge runs the samples
only, and it still knows every group's points. (tests/nbgrader/test_docs.py follows its README in
a fresh venv and runs lessons 10 and 12 there.)

Run: .venv/bin/python -m pytest tests/nbgrader/test_student_edition.py -x -q
"""

from __future__ import annotations

import json
import os
import random
import re
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
import yaml

from grader.course.course_notebooks import notebook_path
from grader.contest.kattis import expected_verdicts
from grader.problems import REPO, list_problems, load_problem
from grader.course.student_edition import LESSON_SOLUTIONS, lesson_solutions, write_edition

pytestmark = pytest.mark.xdist_group("student-edition")  # one worker writes the edition once


@pytest.fixture(scope="module")
def edition(tmp_path_factory):
    return write_edition(tmp_path_factory.mktemp("ed") / "student")


def test_layout(edition):
    for p in list_problems():
        assert (edition / "assignments" / p.id / "statement" / "problem.en.md").is_file()
        assert list((edition / "assignments" / p.id / "data" / "sample").glob("*.in"))
        assert (edition / "exercises" / p.id / f"{p.id}.ipynb").is_file()
    for d in ("reference_impl", "grader", "notebooks"):
        assert (edition / d).is_dir()


def test_nothing_hidden(edition):
    files = [f for f in edition.rglob("*") if f.is_file()]
    names = {part for f in files for part in f.relative_to(edition).parts}
    assert not names & {"generators", "source", ".cache", "tests", "gradebook.db", "nbgrader_config.py"}
    shipped = {str(f.relative_to(edition / "solutions")) for f in files if f.is_relative_to(edition / "solutions")}
    assert shipped == {"README.md", *(f"{p}/{n}" for p, names in LESSON_SOLUTIONS.items() for n in names)}
    for rel in shipped - {"README.md"}:
        assert expected_verdicts(rel.split("/")[0])[rel.split("/")[1]] != "AC"
    texts = {f: f.read_text(errors="replace") for f in files}
    # the accepted solutions: the wrong ones reproduce the original tutorial's code, which the
    # lessons show on purpose
    solutions = [REPO / "solutions" / p.id / name for p in list_problems()
                 for name, verdict in expected_verdicts(p.id).items() if verdict == "AC"]
    # long lines of the reference solutions that the library (which students get) does not share
    library = "".join(f.read_text() for d in ("reference_impl", "grader") for f in (REPO / d).rglob("*.py"))
    # validators and checkers are shipped on purpose (students check their output with them)
    library += "".join(f.read_text() for pattern in ("*/input_validators/**/*.py", "*/output_validator/*.py")
                       for f in (REPO / "assignments").glob(pattern))
    # and the wrong solutions a lesson judges (their input/output boilerplate is every solution's)
    library += "".join((REPO / "solutions" / p / n).read_text() for p, names in LESSON_SOLUTIONS.items() for n in names)
    sol_lines = {ln.strip() for s in solutions for ln in s.read_text().splitlines()
                 if len(ln.strip()) > 50 and ln.strip() not in library}
    assert len(sol_lines) > 20
    hidden = set()
    for p in list_problems():
        course = yaml.safe_load((edition / "assignments" / p.id / "course.yaml").read_text())
        assert "seed" not in course and "generator" not in course
        for g in course["groups"]:  # scored groups: name, points, withheld, and per case kind/scale only
            assert g.get("withheld") or g["points"] == 0 and "cases" not in g, g
            assert all(set(c) <= {"kind", "scale"} for c in g.get("cases", [])), g["name"]
        for t in p.tests():
            if t.group != "sample":
                hidden.update(tok for tok in re.findall(r"[-+0-9.eE]+", t.input_text) if len(tok) >= 10)
    assert len(hidden) > 100
    lengths = {len(tok) for tok in hidden}
    public = hidden & numeric_substrings(library, lengths)  # the library is public
    for f, text in texts.items():
        assert "### BEGIN SOLUTION" not in text, f
        assert not [ln for ln in sol_lines if ln in text], f"{f} holds reference solution code"
        leaked = sorted((hidden & numeric_substrings(text, lengths)) - public)  # hidden tokens in text
        assert not leaked, f"{f} holds hidden test numbers {leaked[:3]}"


NUMERIC = re.compile(r"[-+0-9.eE]+")


def numeric_substrings(text: str, lengths: set[int]) -> set[str]:
    """Every substring of ``text`` whose length is in ``lengths`` and whose characters all occur in
    numbers (``[-+0-9.eE]``). A token made of those characters occurs in ``text`` (``tok in text``)
    exactly when it is in this set, so one set intersection checks every hidden number against a
    file at once (about 900k numbers against 300 files: ``tok in text`` one by one took 500 s).

    >>> sorted(numeric_substrings("x = 1.25e-3, y", {4}))
    ['.25e', '1.25', '25e-', '5e-3']
    """
    out: set[str] = set()
    for run in NUMERIC.findall(text):
        for n in lengths:
            out.update(run[i:i + n] for i in range(len(run) - n + 1))
    return out


def test_numeric_substrings_finds_what_substring_search_finds():
    rng = random.Random(7)
    alphabet = "0123456789.eE-+ x,\n"
    for _ in range(300):
        text = "".join(rng.choice(alphabet) for _ in range(rng.randrange(0, 80)))
        tokens = {"".join(rng.choice("0123456789.eE-+") for _ in range(rng.randrange(3, 8))) for _ in range(40)}
        tokens |= {text[i:i + n] for i in range(0, len(text), 7) for n in (3, 5) if len(text) >= i + n}
        tokens = {t for t in tokens if NUMERIC.fullmatch(t)}
        lengths = {len(t) for t in tokens} or {3}
        assert tokens & numeric_substrings(text, lengths) == {t for t in tokens if t in text}, text


def test_released_notebooks_have_stubs(edition):
    for p in list_problems():
        nb = nbformat.read(edition / "exercises" / p.id / f"{p.id}.ipynb", 4)
        first = next(c for c in nb.cells if c.metadata.get("nbgrader", {}).get("solution"))
        assert "raise NotImplementedError()" in first.source
        assert len(nb.cells) == len(nbformat.read(notebook_path(p.id), 4).cells)


def test_local_judge_runs_the_samples_only(edition):
    p = list_problems()[0]
    r = subprocess.run([sys.executable, "-m", "grader", "judge", p.id, f"exercises/{p.id}/{p.id}.ipynb", "--json"],
                       cwd=edition, capture_output=True, text=True, timeout=600)
    assert r.returncode == 1, r.stderr  # the judge exits 1 for any verdict but AC
    out = json.loads(r.stdout)
    assert {t["group"] for t in out["tests"]} == {"sample"}
    assert out["verdict"] == "CE"  # the released stub defines no entry function yet
    assert Path(edition / "grader").resolve() != (REPO / "grader").resolve()


def test_points_and_withheld_groups(edition):
    r = subprocess.run([sys.executable, "-m", "grader", "list", "--json"], cwd=edition, capture_output=True,
                       text=True, timeout=300, env={**os.environ, "PYTHONPATH": str(edition)})
    assert r.returncode == 0, r.stderr
    listed = {row["id"]: row["points"] for row in json.loads(r.stdout)}
    assert listed == {p.id: "100" for p in list_problems()}
    for p in list_problems():
        public = load_problem(p.id, edition / "assignments")
        assert [(g.name, g.points) for g in public.groups] == [(g.name, g.points) for g in p.groups]
        assert [len(g.cases) for g in public.groups if g.withheld] == [len(g.cases) for g in p.groups if g.cases]
        assert {t.group for t in public.tests()} == {"sample"} and public.validate() == []
        assert sum(public.group_points.values()) == 0 and public.points == 100


def test_an_accepted_solution_is_never_shipped(tmp_path, monkeypatch):
    fake = tmp_path / "solutions" / "delaunay"
    fake.mkdir(parents=True)
    (fake / "wrong_tutorial.py").write_text("def delaunay(points):\n    return []\n")
    (fake / "expected.yaml").write_text("wrong_tutorial.py: AC\n")
    with pytest.raises(ValueError, match="wrong_tutorial.py is AC"):
        lesson_solutions(tmp_path / "out", tmp_path / "solutions")
    (fake / "expected.yaml").write_text("wrong_tutorial.py: WA exhaustive\n")
    assert [p.name for p in lesson_solutions(tmp_path / "out", tmp_path / "solutions")] == ["wrong_tutorial.py"]
