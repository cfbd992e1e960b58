"""The nbgrader course's source notebooks, generated from the problem packages.

Every problem ``assignments/<id>/`` becomes ``assignments/source/<id>/<id>.ipynb``: the statement,
a solution cell (the problem's accepted reference solution between ``### BEGIN SOLUTION`` and
``### END SOLUTION``), a "check on the samples" cell that runs the local sandboxed judge on the
sample group, and one autograded test cell per scored group carrying that group's points. The
test cells hold no test data: the course's autograde preprocessor (``grader.course.nbgrader_autograde``)
judges the student's code on the hidden tests on the grader's side and writes each group's
verdict into its cell. Output is deterministic (fixed cell ids, no timestamps), so rerunning the
script after a problem changed is the way to keep statement and notebook in step.

Run:
    python -m grader.course_notebooks            # (re)write every source notebook
    python -m grader.course_notebooks --check    # exit 1 if a committed notebook is stale

Example:
    >>> nb = build_notebook(load_problem("delaunay"))
    >>> sum(c.metadata["nbgrader"].get("points", 0) for c in nb.cells)
    100
"""

from __future__ import annotations

import argparse
import ast
import re
import sys
from pathlib import Path

import nbformat

from .course_markdown import notebook_markdown
from ..problems import Group, Problem, list_problems, load_problem, problems_root  # noqa: F401 (load_problem: the doctest)
from ..contest.sample_check import is_sample_group
from ..judging.submissions import CODE_STUB  # noqa: F401 - the course's nbgrader_config.py imports it from here
from ..problems.cache import load_yaml_text


SOLUTIONS = Path(__file__).resolve().parent.parent.parent / "solutions"
SOLUTION_ID = "solution"
CHECK_ID = "check_samples"
_GRADE_ID_BAD = re.compile(r"[^A-Za-z0-9_-]")


def group_cell_id(group: str) -> str:
    """The nbgrader ``grade_id`` of the test cell of ``group`` (how the autograder maps cells to groups).

    >>> group_cell_id("large")
    'group_large'
    """
    return "group_" + _GRADE_ID_BAD.sub("_", group)


def scored_groups(problem: Problem) -> list[Group]:
    """The groups that earn points: one autograded test cell each."""
    return [g for g in problem.groups if g.points > 0]


def group_test_count(problem: Problem, group: Group) -> int:
    """Number of tests in ``group`` without generating them."""
    n = len(group.cases)
    if group.data:
        n += len(list((problem.path / group.data).glob("*.in")))
    return n


def reference_solution(problem: Problem, solutions: Path = SOLUTIONS) -> Path:
    """The accepted reference solution of ``problem`` (first ``AC`` in ``solutions/<id>/expected.yaml``)."""
    expected = solutions / problem.id / "expected.yaml"
    if not expected.is_file():
        raise ValueError(f"problem {problem.id!r}: {expected} is missing (no reference solution to put in the notebook)")
    verdicts = load_yaml_text(expected.read_text()) or {}
    accepted = [f for f, v in verdicts.items() if str(v) == "AC"]
    if not accepted:
        raise ValueError(f"problem {problem.id!r}: {expected} names no AC solution")
    return solutions / problem.id / accepted[0]


def strip_main_guard(source: str) -> str:
    """Drop top-level ``if __name__ == "__main__":`` blocks (in a kernel ``__name__`` is ``__main__``).

    >>> strip_main_guard('def f():\\n    pass\\n\\nif __name__ == "__main__":\\n    f()\\n')
    'def f():\\n    pass\\n'
    """
    tree = ast.parse(source)
    lines = source.splitlines(keepends=True)
    for node in reversed(tree.body):
        if isinstance(node, ast.If) and isinstance(node.test, ast.Compare) and \
                isinstance(node.test.left, ast.Name) and node.test.left.id == "__name__":
            del lines[node.lineno - 1:node.end_lineno]
    return "".join(lines).rstrip() + "\n"


def entry_signature(source: str, entry: str) -> str:
    """``entry(arg, ...)`` as the reference solution declares it.

    >>> entry_signature("def delaunay(points):\\n    return []\\n", "delaunay")
    'delaunay(points)'
    """
    body = ast.parse(source).body
    defs = {n.name: n for n in body if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))}
    aliases = {t.id: n.value.id for n in body if isinstance(n, ast.Assign) and isinstance(n.value, ast.Name)
               for t in n.targets if isinstance(t, ast.Name)}
    name = entry if entry in defs else aliases.get(entry)  # also `bowyer_watson = delaunay`
    if name in defs:
        return f"{entry}({ast.unparse(defs[name].args)})"
    raise ValueError(f"the reference solution does not define {entry}(...) at top level")


def _meta(grade_id: str, *, solution: bool = False, grade: bool = False, locked: bool = False,
          points: int | None = None) -> dict:
    nbg = {"grade": grade, "grade_id": grade_id, "locked": locked, "schema_version": 3, "solution": solution,
           "task": False}
    if points is not None:
        nbg["points"] = points
    return {"nbgrader": nbg}


def _markdown(cell_id: str, text: str, pictures: Path | None = None, **meta) -> nbformat.NotebookNode:
    """A locked markdown cell; maths, tables and pictures rewritten to show without MathJax or CSS
    (formgrader and the feedback page have neither offline; see :mod:`grader.course.course_markdown`)."""
    source, attachments = notebook_markdown(text, pictures)
    cell = nbformat.v4.new_markdown_cell(source, id=cell_id.replace("_", "-"), metadata=_meta(cell_id, **meta))
    if attachments:
        cell.attachments = attachments
    return cell


def _code(cell_id: str, text: str, **meta) -> nbformat.NotebookNode:
    return nbformat.v4.new_code_cell(text, id=cell_id.replace("_", "-"), metadata=_meta(cell_id, **meta))


def course_statement(problem: Problem, statement: str) -> str:
    """The statement as the nbgrader course gives it: for a timed problem, the clock is the due date.

    The problem package's statement tells a student on their own to start the clock with
    ``python -m grader timed start``; in the nbgrader course the instructor's due date is the clock
    (``python -m grader.nbgrader_autograde deadline``) and nbgrader records the submission time.

    >>> text = course_statement(load_problem("bowyer-watson-timed"),
    ...     (load_problem("bowyer-watson-timed").path / "statement" / "problem.en.md").read_text())
    >>> "timed start" in text, "due date" in text
    (False, True)
    """
    if not problem.timed:
        return statement
    t = problem.timed
    minutes = t.get("duration_min", 30)
    paragraphs = statement.split("\n\n")
    for k, para in enumerate(paragraphs):
        if "timed start" in para and not para.lstrip().startswith(("-", "#")):
            paragraphs[k] = (f"A timed exercise: implement `{problem.entry}` and submit this notebook before the "
                             f"**due date** your instructor set ({minutes} minutes from the exam's start; the "
                             f"Assignments tab shows it). nbgrader records when you submit; your last "
                             f"submission counts.")
    text = "\n\n".join(paragraphs)
    return re.sub(r"\d+ minutes from `timed start` \(plus (\d+) s grace\)",
                  lambda m: f"due {minutes} minutes after the exam's start (plus {m.group(1)} s grace)",
                  text)


def build_notebook(problem: Problem, solutions: Path = SOLUTIONS) -> nbformat.NotebookNode:
    """The source notebook of ``problem`` (see the module docstring)."""
    ref = strip_main_guard(reference_solution(problem, solutions).read_text())
    signature = entry_signature(ref, problem.entry)
    statement = course_statement(problem, (problem.path / "statement" / "problem.en.md").read_text().strip())
    scored = scored_groups(problem)
    rows = "\n".join(f"| `{g.name}` | {g.points} | {group_test_count(problem, g)} | "
                     f"{'public (below)' if is_sample_group(g) else 'hidden'} |" for g in problem.groups)
    forbidden = ", ".join(f"`{m}`" for m in problem.forbidden)
    how = f"""## How this assignment is graded

Write `{signature}` in the **first code cell below** (helper functions may go in the same cell).
It is judged like a contest submission: by the course's sandboxed judge, on tests you do not
see, in a separate process with limits of {problem.time_limit:g} s CPU time per test and
{problem.memory_mb} MiB of memory. Importing any of {forbidden} is a security violation (`SV`).

Points are per group: a group earns its points only when every one of its tests is accepted.

| group | points | tests | data |
| --- | --- | --- | --- |
{rows}

The autograded cells at the end show each group's verdict after grading. Running them yourself
does nothing: the hidden tests stay with the grader. For the same reason `nbgrader validate` (the
Assignments tab's *Validate* button) says "Success" for any notebook that runs: it checks that the
cells run, not that your code is right. The check that means something is the sample check below."""
    check = """## Check on the samples

Save the notebook first (Ctrl+S): the next cell judges the code cells of the saved file, the same
way the grader does, on the public sample tests, and shows one line per test and a picture."""
    cells = [
        _markdown("statement", statement, pictures=problem.path / "statement", locked=True),
        _markdown("grading", how, locked=True),
        _code(SOLUTION_ID, f"# Define {signature} in this cell.\n### BEGIN SOLUTION\n{ref}### END SOLUTION\n",
              solution=True),
        _markdown("check_intro", check, locked=True),
        _code(CHECK_ID, f"%load_ext grader.sample_check\n%check_samples {problem.id}", locked=True),
    ]
    for g in scored:
        n = group_test_count(problem, g)
        cells.append(_code(group_cell_id(g.name),
                           f"# Autograded: group {g.name!r}, {g.points} points, {n} hidden tests.\n"
                           "# At grading time the sandboxed judge runs your solution on them and writes the\n"
                           "# group's verdict here (full points only if every test is accepted).",
                           grade=True, locked=True, points=g.points))
    nb = nbformat.v4.new_notebook(cells=cells)
    nb.metadata = {"kernelspec": {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"},
                   "language_info": {"name": "python"}}
    nb.nbformat_minor = 5
    return nb


def notebook_path(problem_id: str, course_root: Path | None = None) -> Path:
    """``assignments/source/<id>/<id>.ipynb`` (the course layout)."""
    root = course_root or problems_root()
    return root / "source" / problem_id / f"{problem_id}.ipynb"


def render(problem: Problem, solutions: Path = SOLUTIONS) -> str:
    """The notebook file's text (what is committed)."""
    return nbformat.writes(build_notebook(problem, solutions)) + "\n"


def write_all(course_root: Path | None = None, check: bool = False) -> list[str]:
    """Write (or, with ``check``, compare) every problem's source notebook; returns the stale/written paths."""
    changed = []
    for problem in list_problems():
        path = notebook_path(problem.id, course_root)
        text = render(problem)
        if path.is_file() and path.read_text() == text:
            continue
        changed.append(str(path))
        if not check:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
    return changed


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m grader.course_notebooks", description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true", help="only report notebooks that differ from a fresh build")
    a = ap.parse_args(argv)
    changed = write_all(check=a.check)
    for p in changed:
        print(("stale: " if a.check else "wrote: ") + p)
    if not changed:
        print("all source notebooks are current")
    return 1 if a.check and changed else 0


if __name__ == "__main__":
    sys.exit(main())
