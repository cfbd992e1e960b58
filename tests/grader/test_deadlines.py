"""Each student sees their own deadline where the instructor's files are private (the hub).

Root publishes the deadlines of a course (a gradebook with a due date, a timed problem, an
extension for one student) for two real accounts; then, as those accounts:

* ``deadlines show`` prints the student's own due date and exam duration, the extension included
  for the student who has one and absent for the other;
* a student can neither read the other's file nor list the folder (who has an extension is
  nobody else's business).

Run: .venv/bin/python -m pytest tests/grader/test_deadlines.py -q   (as root: it needs real accounts)
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from datetime import datetime
from pathlib import Path

import pytest

from grader.course import deadlines

from . import ordinary_user
from .conftest import REPO

ADA, BOB = "semester-ada", "semester-bob"


@pytest.fixture
def shared():
    path = Path(tempfile.mkdtemp(prefix="deadlines-"))
    path.chmod(0o755)
    yield path
    shutil.rmtree(path, ignore_errors=True)


def course(root: Path) -> Path:
    from nbgrader.api import Gradebook

    from grader.course.nbgrader_autograde import nbgrader_env

    for pid in ("delaunay", "bowyer-watson-timed"):
        shutil.copytree(REPO / "assignments" / pid, root / pid, symlinks=True,
                        ignore=shutil.ignore_patterns("data", "__pycache__"))
    (root / "extensions.yaml").write_text(f"{ADA}:\n  delaunay: 2 days\n  bowyer-watson-timed: 15 minutes\n")
    os.environ["PATH"] = nbgrader_env()["PATH"]
    with Gradebook(f"sqlite:///{root / 'gradebook.db'}") as gb:
        gb.add_assignment("delaunay", duedate=datetime(2026, 12, 1, 12, 0))
        for s in (ADA, BOB):
            gb.add_student(s)
    return root


def test_deadlines_rows_without_accounts(tmp_path):
    rows = deadlines.student_deadlines(course(tmp_path / "course"))
    assert rows[ADA] == [{"assignment": "bowyer-watson-timed", "duration_min": 45.0, "extension": "15 minutes"},
                         {"assignment": "delaunay", "due": "2026-12-03T12:00:00+00:00", "extension": "2 days"}]
    assert rows[BOB] == [{"assignment": "bowyer-watson-timed", "duration_min": 30.0},
                         {"assignment": "delaunay", "due": "2026-12-01T12:00:00+00:00"}]


def test_each_student_reads_only_their_own(shared):
    if why := ordinary_user.can_run():
        pytest.skip(f"needs real accounts: {why}")
    for s in (ADA, BOB):
        ordinary_user.ensure_user(s)
    root = course(shared / "course")
    folder = shared / "deadlines"
    written, skipped = deadlines.publish(root, folder)
    assert sorted(p.name for p in written) == [f"{ADA}.json", f"{BOB}.json"] and skipped == []

    def as_user(user: str, *argv: str) -> subprocess.CompletedProcess:
        return ordinary_user.run_as_user(list(argv), user=user, timeout=300)

    ada = as_user(ADA, sys.executable, "-m", "grader", "deadlines", "show", str(folder))
    assert ada.returncode == 0, ada.stderr
    assert "delaunay: due 2026-12-03T12:00:00+00:00 (with your extension of 2 days)" in ada.stdout
    assert "bowyer-watson-timed: 45 minutes from your start (with your extension of 15 minutes)" in ada.stdout
    bob = as_user(BOB, sys.executable, "-m", "grader", "deadlines", "show", str(folder))
    assert bob.returncode == 0, bob.stderr
    assert "delaunay: due 2026-12-01T12:00:00+00:00" in bob.stdout and "extension" not in bob.stdout
    assert as_user(BOB, "cat", str(folder / f"{ADA}.json")).returncode != 0
    assert as_user(BOB, "ls", str(folder)).returncode != 0
