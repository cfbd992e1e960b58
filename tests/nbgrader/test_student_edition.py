"""The student edition holds what a student needs and nothing hidden: no solutions, no source
notebooks, no generators or seeds, no hidden test data; its local judge runs the samples only.

Run: .venv/bin/python -m pytest tests/nbgrader/test_student_edition.py -x -q
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
import yaml

from grader.course_notebooks import notebook_path
from grader.kattis import expected_verdicts
from grader.problems import REPO, list_problems
from grader.student_edition import write_edition

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
    assert not names & {"solutions", "generators", "source", ".cache", "tests", "gradebook.db", "nbgrader_config.py"}
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
    sol_lines = {ln.strip() for s in solutions for ln in s.read_text().splitlines()
                 if len(ln.strip()) > 50 and ln.strip() not in library}
    assert len(sol_lines) > 20
    hidden = set()
    for p in list_problems():
        course = yaml.safe_load((edition / "assignments" / p.id / "course.yaml").read_text())
        assert "seed" not in course and "generator" not in course
        assert all("cases" not in g for g in course["groups"])
        for t in p.tests():
            if t.group != "sample":
                hidden.update(tok for tok in re.findall(r"[-+0-9.eE]+", t.input_text) if len(tok) >= 10)
    assert len(hidden) > 100
    for f, text in texts.items():
        assert "### BEGIN SOLUTION" not in text, f
        assert not [ln for ln in sol_lines if ln in text], f"{f} holds reference solution code"
        leaked = [tok for tok in hidden if tok in text and tok not in library]  # the library is public
        assert not leaked, f"{f} holds hidden test numbers {leaked[:3]}"


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
