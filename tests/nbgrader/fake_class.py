"""A fake class for the nbgrader course: a course copy in a temp dir, a local exchange, and
students whose notebooks are the released notebook with their code written in.

Used by ``test_course_e2e.py`` and ``benchmarks/bench_nbgrader.py``.

Example:
    course = make_course(tmp, "bowyer-watson-timed")      # generate + release
    submit_class(course, "bowyer-watson-timed", students(), deadline)
    run_nbgrader(course.root, "collect", "bowyer-watson-timed")
"""

from __future__ import annotations

import copy
import json
import shutil
from dataclasses import dataclass
from datetime import datetime, timedelta, timezone
from pathlib import Path

import nbformat

from grader.course.nbgrader_autograde import run_nbgrader

REPO = Path(__file__).resolve().parents[2]
SOLUTIONS = REPO / "solutions"
TS_FORMAT = "%Y-%m-%d %H:%M:%S.%f %Z"

WRONG_EMPTY = "def bowyer_watson(points):\n    return []\n"

# Forgeries that beat stock nbgrader (student cells and test cells in one kernel). Each is paired
# with a wrong solution, so any score above the judge's would be a gain.
TRANSFORMER = """try:  # rewrite every later cell (the hidden tests) into `pass`
    get_ipython().input_transformers_cleanup.append(lambda lines: ["pass\\n"])
except NameError:
    pass
""" + WRONG_EMPTY
MONKEYPATCH = """try:  # make whatever the test cells call agree with anything
    import grader.contest.judge, builtins
    grader.contest.judge.Judge.judge_path = lambda *a, **k: None
    builtins.AssertionError = type("Never", (Exception,), {})
except Exception:
    pass
""" + WRONG_EMPTY
GRADEBOOK = """import os, sqlite3, time
try:  # a forked child outlives the kernel and gives everyone full marks
    if os.fork() == 0:
        time.sleep(1)
        for up in ("../../..", "../..", "..", "."):
            try:
                db = sqlite3.connect(up + "/gradebook.db")
                db.execute("UPDATE grade SET manual_score = 100")
                db.commit()
            except Exception:
                pass
        os._exit(0)
except Exception:
    pass
""" + WRONG_EMPTY
HIDDEN_TRACEBACK = """try:  # errors in test cells leave no traceback output
    get_ipython().showtraceback = lambda *a, **k: None
except NameError:
    pass
def bowyer_watson(points):
    raise RuntimeError("no idea")
"""
HOSTILE = """import os
os.system("rm -rf ~ /work")   # and read the answers while at it
print(open("../../../gradebook.db", "rb").read()[:10])
""" + WRONG_EMPTY


@dataclass
class Student:
    name: str
    code: str | None  # None: submits no notebook
    late: bool = False
    extra_cell: str | None = None  # code in a new cell after the check cell
    edit_test_cells: bool = False  # rewrite the locked test cells (source and points)


def _solution(name: str, problem_id: str = "bowyer-watson-timed") -> str:
    """The code of ``solutions/<problem_id>/<name>`` without its ``__main__`` block."""
    text = (SOLUTIONS / problem_id / name).read_text()
    return text.split('\nif __name__ == "__main__":')[0] + "\n"


def students() -> list[Student]:
    """Ten students: right, wrong, slow, hostile, missing, late, and the five forgeries."""
    right = _solution("accepted_scan.py")
    helper, _, rest = right.partition("\ndef delaunay(")
    return [
        Student("right", right),
        Student("wrong", _solution("wrong_tutorial.py")),
        Student("slow", _solution("too_slow_recheck.py")),
        Student("hostile", HOSTILE),
        Student("missing", None),
        Student("late", "def delaunay(" + rest, late=True, extra_cell=helper),
        Student("transformer", TRANSFORMER),
        Student("monkeypatch", MONKEYPATCH),
        Student("gradebook", GRADEBOOK),
        Student("traceback", HIDDEN_TRACEBACK),
        Student("edited", WRONG_EMPTY, edit_test_cells=True),
    ]


@dataclass
class Course:
    root: Path
    exchange: Path

    def nbgrader(self, *args: str, check: bool = True):
        return run_nbgrader(self.root, *args, f"--Exchange.root={self.exchange}", check=check)


def make_course(tmp: Path, problem_id: str) -> Course:
    """A course root in ``tmp`` (this repo's config, one source notebook and its problem package),
    generated and released."""
    root = tmp / "course"
    (root / "source").mkdir(parents=True)
    shutil.copy(REPO / "assignments" / "nbgrader_config.py", root)
    shutil.copytree(REPO / "assignments" / "source" / problem_id, root / "source" / problem_id)
    (root / problem_id).symlink_to(REPO / "assignments" / problem_id)  # the judge reads the course's own package
    exchange = tmp / "exchange"
    exchange.mkdir(mode=0o777)
    course = Course(root, exchange)
    course.nbgrader("generate_assignment", problem_id)
    course.nbgrader("release_assignment", problem_id)
    return course


def add_roster(root: Path, names: list[str]) -> None:
    """The instructor's student list (``nbgrader db student add``), so absentees export as 0."""
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{root / 'gradebook.db'}") as gb:
        for name in names:
            gb.update_or_create_student(name)


def student_notebook(released: nbformat.NotebookNode, s: Student) -> nbformat.NotebookNode:
    """The released notebook with ``s``'s code in the first solution cell (and an extra cell)."""
    nb = copy.deepcopy(released)
    sol = next(i for i, c in enumerate(nb.cells) if c.metadata.get("nbgrader", {}).get("solution"))
    nb.cells[sol].source = "# my solution\n" + (s.code or "")
    if s.extra_cell:
        check = next(i for i, c in enumerate(nb.cells) if c.metadata.get("nbgrader", {}).get("grade_id") == "check_samples")
        nb.cells.insert(check + 1, nbformat.v4.new_code_cell(s.extra_cell, id=f"extra-{s.name}"))
    if s.edit_test_cells:
        for c in nb.cells:
            nbg = c.metadata.get("nbgrader", {})
            if nbg.get("grade"):
                c.source = "pass  # nothing to see"
                nbg["points"] = 1000
    return nb


def submit_class(course: Course, problem_id: str, klass: list[Student], deadline: datetime) -> None:
    """Put every student's submission in the exchange's inbound folder, as ``nbgrader submit`` does."""
    released = nbformat.read(course.exchange / "delaunay-course" / "outbound" / problem_id / f"{problem_id}.ipynb", 4)
    inbound = course.exchange / "delaunay-course" / "inbound"
    for k, s in enumerate(klass):
        when = deadline + timedelta(minutes=20) if s.late else deadline - timedelta(minutes=10, seconds=k)
        stamp = when.astimezone(timezone.utc).strftime(TS_FORMAT)
        d = inbound / f"{s.name}+{problem_id}+{stamp}+r{k}"
        d.mkdir(parents=True)
        (d / "timestamp.txt").write_text(stamp)
        if s.code is None:
            (d / "notes.txt").write_text("I could not finish\n")
            continue
        nbformat.write(student_notebook(released, s), str(d / f"{problem_id}.ipynb"))


def collected_class(tmp: Path, problem_id: str, klass: list[Student], started_min_ago: float = 25) -> Course:
    """A course in ``tmp`` with ``klass`` on the roster, the exam started ``started_min_ago`` minutes ago
    (its due date set from that start; a problem that is not timed has no due date, and its
    submissions are dated a few minutes ago), every submission in the exchange and collected."""
    from grader.course.nbgrader_autograde import set_exam_deadline
    from grader.problems import load_problem

    course = make_course(tmp, problem_id)
    add_roster(course.root, [s.name for s in klass])
    start = datetime.now(timezone.utc) - timedelta(minutes=started_min_ago)
    due = set_exam_deadline(course.root, problem_id, start) if load_problem(problem_id).timed else start
    submit_class(course, problem_id, klass, due)
    course.nbgrader("collect", problem_id)
    return course


def gradebook_scores(root: Path, problem_id: str) -> dict[str, dict]:
    """Per student: score (after late penalty), raw score, penalty, and any manual scores set."""
    from nbgrader.api import Gradebook

    from nbgrader.api import MissingEntry

    out = {}
    with Gradebook(f"sqlite:///{root / 'gradebook.db'}") as gb:
        for student in gb.students:
            try:
                sub = gb.find_submission(problem_id, student.id)
            except MissingEntry:
                out[student.id] = {"score": 0.0, "raw": 0.0, "penalty": 0.0, "manual": [], "cells": {}}
                continue
            nb = sub.notebooks[0]
            penalty = nb.late_submission_penalty or 0.0
            out[sub.student.id] = {"score": nb.score - penalty, "raw": nb.score, "penalty": nb.late_submission_penalty or 0.0,
                                   "manual": [g.manual_score for g in nb.grades if g.manual_score is not None],
                                   "cells": {g.name: g.auto_score for g in nb.grades}}
    return out


def judge_json(problem_id: str, path: Path) -> dict:
    """``python -m grader judge PROBLEM PATH --json --counterexample-seconds 0`` (the CLI's own code,
    in this process). CI time: no counterexample search after a failing group (up to 10 s a
    submission by default); the verdicts and scores compared with the gradebook do not depend on it,
    and the search is tested in tests/grader/test_counterexample.py."""
    import contextlib
    import io

    from grader.cli import main

    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        assert main(["judge", problem_id, str(path), "--json", "--counterexample-seconds", "0"]) in (0, 1)  # 1: not AC
    return json.loads(buf.getvalue())


def utc(dt: datetime) -> datetime:
    return dt.astimezone(timezone.utc)
