"""The student edition: one folder with everything a student receives, and nothing hidden.

It holds the lessons (``notebooks/``), the released assignment notebooks (``exercises/<id>/<id>.ipynb``,
solutions replaced by a stub exactly as ``nbgrader generate_assignment`` does), each problem's
statement, samples, input validators and checker (``assignments/<id>/``, with a ``course.yaml``
that keeps only the public sample group), the library (``reference_impl/``) and the judge
(``grader/``) so ``python -m grader judge <id> <file>`` and the notebooks' ``%check_samples``
work on the samples. Left out: ``solutions/``, the nbgrader source notebooks, the test
generators and their seeds, the hidden tests and any cache of them, the tests of this repository.

Run:
    python -m grader.student_edition OUTDIR      # then: cd OUTDIR && python -m grader list

Example:
    >>> public_course_yaml({"entry": "f", "seed": 7, "groups": [{"name": "sample", "points": 0, "data": "data/sample"},
    ...                     {"name": "big", "points": 10, "cases": [{"kind": "uniform", "n": 9}]}]})["groups"]
    [{'name': 'sample', 'points': 0, 'data': 'data/sample'}]
"""

from __future__ import annotations

import argparse
import shutil
import sys
from pathlib import Path

import nbformat

from .course_notebooks import notebook_path
from .problems import REPO, list_problems
from .public_problems import IGNORE, print_or_fail, public_course_yaml, write_public_problem  # noqa: F401

INSTRUCTOR_ONLY = ("course_notebooks.py", "nbgrader_autograde.py", "student_edition.py",  # grader/ modules
                   "similarity.py", "similarity_report.py")

README = """# Delaunay course: student edition

* `notebooks/`: the lessons (open with `jupyter lab notebooks`).
* `exercises/<problem>/<problem>.ipynb`: the assignments. Write the entry function in the first
  code cell, save, and run the "check on the samples" cell.
* `assignments/<problem>/`: statements (`statement/problem.en.md`) and public samples.
* `python -m grader list` and `python -m grader judge <problem> <file.py or .ipynb>`: the local
  judge, on the samples only. Your grade comes from the course's hidden tests. It runs your code
  in a kernel jail (bubblewrap); on a machine without one it refuses unless you add `--trusted`
  (your own code, judged without a jail; the notebooks' check cell does this by itself).

Install once: `python -m venv .venv && .venv/bin/pip install -e .`
"""


def release_notebook(source: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The student version of a source notebook: nbgrader's release preprocessors, in its order."""
    from nbgrader.preprocessors import (CheckCellMetadata, ClearHiddenTests, ClearMarkScheme, ClearOutput,
                                        ClearSolutions, ComputeChecksums, LockCells)

    nb, resources = nbformat.from_dict(source), {}
    for pp in (LockCells, ClearSolutions, ClearOutput, CheckCellMetadata, ComputeChecksums, ClearHiddenTests,
               ClearMarkScheme, ComputeChecksums, CheckCellMetadata):
        nb, resources = pp().preprocess(nb, resources)
    return nb


def write_edition(out: str | Path) -> Path:
    """Write the student edition to ``out`` (which must not exist yet)."""
    out = Path(out)
    if out.exists():
        raise ValueError(f"{out} already exists; give a new directory for the student edition")
    out.mkdir(parents=True)
    for name in ("reference_impl", "grader", "notebooks"):
        shutil.copytree(REPO / name, out / name, ignore=IGNORE)
    for name in INSTRUCTOR_ONLY:
        (out / "grader" / name).unlink()
    shutil.copy(REPO / "pyproject.toml", out / "pyproject.toml")
    (out / "README.md").write_text(README)
    for problem in list_problems():
        write_public_problem(problem.path, out / "assignments" / problem.id)
        src_nb = notebook_path(problem.id)
        if src_nb.is_file():
            ex = out / "exercises" / problem.id
            ex.mkdir(parents=True)
            nbformat.write(release_notebook(nbformat.read(src_nb, 4)), str(ex / src_nb.name))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m grader.student_edition", description="write the student edition")
    ap.add_argument("outdir")
    a = ap.parse_args(argv)
    return print_or_fail(write_edition, a.outdir)


if __name__ == "__main__":
    sys.exit(main())
