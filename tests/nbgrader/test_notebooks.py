"""The generated nbgrader source notebooks: current, points = group points, entry in the first
solution cell, only magics in the check cell, nothing hidden inside, and `nbgrader validate` passes.

Run: .venv/bin/python -m pytest tests/nbgrader/test_notebooks.py -x -q
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

from grader.course.course_notebooks import (CHECK_ID, build_notebook, group_cell_id, notebook_path, render, scored_groups,
                                    write_all)
from grader.course.nbgrader_autograde import nbgrader_env
from grader.problems import list_problems, load_problem
from grader.judging.submissions import Submission

PROBLEMS = list_problems()
IDS = [p.id for p in PROBLEMS]


def test_committed_notebooks_are_current():
    assert write_all(check=True) == [], "run: python -m grader.course_notebooks"


def test_generation_is_deterministic():
    p = PROBLEMS[0]
    assert render(p) == render(p)


@pytest.mark.parametrize("problem", PROBLEMS, ids=IDS)
def test_notebook_matches_its_problem(problem):
    nb = nbformat.read(notebook_path(problem.id), 4)
    nbformat.validate(nb)
    meta = [c.metadata["nbgrader"] for c in nb.cells]
    graded = {m["grade_id"]: m["points"] for m in meta if m.get("grade")}
    assert graded == {group_cell_id(g.name): g.points for g in scored_groups(problem)}
    assert sum(graded.values()) == sum(g.points for g in problem.groups)
    assert all(not c.outputs for c in nb.cells if c.cell_type == "code"), "committed with outputs"
    first = next(c for c in nb.cells if c.metadata["nbgrader"].get("solution"))
    assert "### BEGIN SOLUTION" in first.source and "### END SOLUTION" in first.source
    code = re.sub(r"^\s*### (BEGIN|END) SOLUTION\s*$", "", first.source, flags=re.M)
    assert Submission.from_source(code).mode(problem.entry) == "function"
    # what the judge sees of the whole notebook: the solution and comments, never the check cell
    check = next(c for c in nb.cells if c.metadata["nbgrader"]["grade_id"] == CHECK_ID)
    assert all(line.startswith("%") for line in check.source.splitlines())
    judged = Submission.from_path(notebook_path(problem.id))
    assert "check_samples" not in judged.source and judged.mode(problem.entry) == "function"
    # hidden data never sits in the notebook: no hidden test input line appears in it
    text = notebook_path(problem.id).read_text()
    for t in problem.tests():
        if t.group != "sample" and len(t.input_text) > 40:
            # lines distinctive enough to be data ("count" or "1.0 1.0" also occur in statements)
            first = t.input_text.splitlines()[1]
            if len(first) >= 12 and any(ch.isdigit() for ch in first):
                assert first not in text, t.name


@pytest.mark.skipif(os.geteuid() != 0, reason="the sample check judges in the sandbox; as root here like CI")
def test_nbgrader_validate_and_sample_check(tmp_path):
    """`nbgrader validate` executes every source notebook (reference solution, sample check, test
    cells) and reports success; the check cell shows a per-test table and a picture."""
    paths = [str(notebook_path(i)) for i in IDS]
    r = subprocess.run([str(Path(sys.executable).parent / "nbgrader"), "validate", *paths], cwd=tmp_path,
                       env=nbgrader_env(), capture_output=True, text=True, timeout=1800)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.count("Success! Your notebook passes all the tests.") == len(paths), r.stdout
    from nbclient import NotebookClient

    src = notebook_path("delaunay")
    nb = nbformat.read(src, 4)
    NotebookClient(nb, timeout=600, resources={"metadata": {"path": str(src.parent)}}).execute()
    out = next(c for c in nb.cells if c.metadata["nbgrader"]["grade_id"] == CHECK_ID).outputs
    html = "".join(o.get("data", {}).get("text/html", "") for o in out)
    assert "sample/1-tutorial" in html and "<b>AC</b>" in html and "data:image/png;base64," in html


def test_the_course_notebook_says_what_the_clock_and_validate_are():
    """In the nbgrader course the timed exam's clock is the instructor's due date (not the judge's
    `timed start`), and every notebook says that `nbgrader validate` cannot see wrong code."""
    for p in list_problems():
        nb = build_notebook(p)
        text = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
        assert "nbgrader validate" in text and "sample check" in text, p.id
        if p.timed:
            assert "timed start" not in text and "timed submit" not in text, p.id
            assert "due date" in text and f"{p.timed.get('duration_min', 30)} minutes" in text, p.id
    # the problem package's own statement (the standalone judge) still tells the student to start the clock
    timed = load_problem("bowyer-watson-timed")
    assert "timed start" in (timed.path / "statement" / "problem.en.md").read_text()


@pytest.mark.skipif(os.geteuid() != 0, reason="the sample check judges in the sandbox; as root here like CI")
def test_the_sample_picture_draws_no_empty_answer(tmp_path):
    """The released stub (its top-level raise is CE) gets "no answer of yours to draw (verdict CE ...)", not a drawn
    "received: 0 triangles"; an accepted function's answer is drawn beside the expected one."""
    from grader.course.course_notebooks import CODE_STUB, SOLUTION_ID
    from grader.contest.sample_check import judge_samples, picture_figure

    nb = nbformat.read(notebook_path("delaunay"), 4)
    solution = next(c for c in nb.cells if c.metadata["nbgrader"]["grade_id"] == SOLUTION_ID)
    reference = solution.source
    solution.source = CODE_STUB
    stub = tmp_path / "delaunay.ipynb"
    nbformat.write(nb, str(stub))
    result, problem = judge_samples("delaunay", stub)
    assert result.verdict in ("CE", "RE"), result.verdict
    fig = picture_figure(problem, result)
    right = fig.axes[1]
    texts = [t.get_text() for t in right.texts]
    assert texts and texts[0].startswith("no answer of yours to draw") and f"verdict {result.verdict}" in texts[0], texts
    assert "received" not in right.get_title()

    namespace: dict = {}
    exec(reference.replace("### BEGIN SOLUTION", "").replace("### END SOLUTION", ""), namespace)
    solution.source = reference
    nbformat.write(nb, str(stub))
    result, problem = judge_samples("delaunay", stub)
    assert result.verdict == "AC", result.verdict
    fig = picture_figure(problem, result, namespace["delaunay"])
    assert fig.axes[1].get_title() == "received: 3 triangles"
    assert not any(t.get_text().startswith("no answer") for t in fig.axes[1].texts)
