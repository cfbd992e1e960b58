"""The student edition: one folder with everything a student receives, and nothing hidden.

It holds the lessons (``notebooks/``), the released assignment notebooks (``exercises/<id>/<id>.ipynb``,
solutions replaced by a stub exactly as ``nbgrader generate_assignment`` does), each problem's
statement, samples, input validators and checker (``assignments/<id>/``, with a ``course.yaml``
whose scored groups are ``withheld``: names, points and kinds of input, no tests), the library
(``reference_impl/``) and the judge (``grader/``) so ``python -m grader judge <id> <file>`` and the
notebooks' ``%check_samples`` work on the samples, and the one file of ``solutions/`` that a lesson
judges (the original tutorial's wrong code). Its README (``student_edition.md`` here) is the path a
student follows on a fresh machine. Left out: the other solutions, the nbgrader source notebooks,
the test generators and their seeds, the hidden tests and any cache of them, the tests of this
repository.

Run:
    python -m grader.student_edition OUTDIR      # then: cd OUTDIR and follow its README.md

Example:
    >>> import tempfile
    >>> out = write_edition(Path(tempfile.mkdtemp()) / "student")
    >>> sorted(p.name for p in out.iterdir())
    ['README.md', 'assignments', 'exercises', 'grader', 'notebooks', 'pyproject.toml', 'reference_impl', 'solutions']
    >>> [(g.name, g.points, g.withheld) for g in load_problem("delaunay", out / "assignments").groups][:2]
    [('sample', 0, False), ('tiny', 15, True)]
"""

from __future__ import annotations

import argparse
import shutil
import sys
from pathlib import Path

import nbformat

from .course_notebooks import notebook_path
from ..problems import REPO, list_problems, load_problem  # noqa: F401 (load_problem: the doctest)
from .public_problems import IGNORE, print_or_fail, write_public_problem
from ..problems.cache import load_yaml_text

INSTRUCTOR_ONLY = ("course/course_notebooks.py", "course/nbgrader_autograde.py",  # grader/ files (and their aliases)
                   "course/student_edition.py", "course/student_edition.md", "classroom/similarity.py",
                   "classroom/similarity_report.py", "course_notebooks.py", "nbgrader_autograde.py", "student_edition.py")
README = Path(__file__).with_name("student_edition.md")
"""The edition's README.md: what is in it and the steps on a fresh machine."""
LESSON_SOLUTIONS = {"delaunay": ("wrong_tutorial.py",)}
"""The files of ``solutions/`` that a lesson judges (lesson 10): wrong ones only, never an accepted one."""

def release_notebook(source: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The student version of a source notebook: nbgrader's release preprocessors, in its order."""
    from nbgrader.preprocessors import (CheckCellMetadata, ClearHiddenTests, ClearMarkScheme, ClearOutput,
                                        ClearSolutions, ComputeChecksums, LockCells)

    nb, resources = nbformat.from_dict(source), {}
    for pp in (LockCells, ClearSolutions, ClearOutput, CheckCellMetadata, ComputeChecksums, ClearHiddenTests,
               ClearMarkScheme, ComputeChecksums, CheckCellMetadata):
        nb, resources = pp().preprocess(nb, resources)
    return nb


def lesson_solutions(out: Path, solutions: Path = REPO / "solutions") -> list[Path]:
    """Copy the solution files the lessons judge (:data:`LESSON_SOLUTIONS`) into ``out/solutions``.

    Each must be listed in its ``expected.yaml`` with a verdict other than ``AC``: an accepted
    solution would hand students the answer.
    """
    copied = []
    for problem_id, names in LESSON_SOLUTIONS.items():
        expected = load_yaml_text((solutions / problem_id / "expected.yaml").read_text()) or {}
        for name in names:
            verdict = (str(expected.get(name) or "").split() or [""])[0]   # "WA" or "WA exhaustive"
            if verdict in ("", "AC"):
                raise ValueError(f"solutions/{problem_id}/{name} is {verdict or 'not listed'} in expected.yaml; "
                                 "the student edition ships wrong solutions only")
            dest = out / "solutions" / problem_id / name
            dest.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(solutions / problem_id / name, dest)
            copied.append(dest)
    (out / "solutions" / "README.md").write_text(
        "# solutions/\n\nOnly the files the lessons judge, and none of them is accepted: "
        + ", ".join(f"`{p.relative_to(out / 'solutions')}`" for p in copied)
        + " (lesson 10 judges it and shows where it fails). The reference solutions stay with the course.\n")
    return copied


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
    shutil.copy(README, out / "README.md")
    lesson_solutions(out)
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
