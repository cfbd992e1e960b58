"""nbgrader submissions are timed by nbgrader's collection timestamp, never by file mtimes (issue 23)."""

from __future__ import annotations

import os
import shutil

from grader.course.nbgrader_autograde import collection_time, judge_notebook_file
from grader.problems import REPO
from grader.classroom.store import ResultStore


def test_nbgrader_submission_time_is_the_collection_timestamp(tmp_path):
    """Not the notebook's modification time (the student's to set): nbgrader's timestamp.txt."""
    folder = tmp_path / "submitted" / "ada" / "closest-pair"
    folder.mkdir(parents=True)
    nb = folder / "closest-pair.ipynb"
    shutil.copy(REPO / "assignments" / "source" / "closest-pair" / "closest-pair.ipynb", nb)
    os.utime(nb, (1e9, 1e9))
    (folder / "timestamp.txt").write_text("2026-12-01 09:12:00.000000 UTC\n")
    when = collection_time(folder)
    assert when == 1796116320.0
    assert collection_time(tmp_path) is None
    judge_notebook_file("closest-pair", nb, "ada", tmp_path / "judged.sqlite", submitted_at=when)
    (row,) = ResultStore(tmp_path / "judged.sqlite").submissions()
    assert row["submitted_at"] == when
