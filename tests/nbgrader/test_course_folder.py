"""One rule for "which course": commands act on the course folder they are run in.

`python -m grader.nbgrader_autograde deadline` run in a copy of the course writes that copy's
gradebook (with the copy's own duration), never the installed checkout's; a mismatch between the
judge's problems and nbgrader's course is refused with a message naming both folders.

    .venv/bin/python -m pytest tests/nbgrader/test_course_folder.py -n 0 -q
"""

from __future__ import annotations

import os
import shutil
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from grader.problems import REPO, check_course, course_folder, problems_root

TIMED = "bowyer-watson-timed"


def _copy_course(tmp: Path, problems=("delaunay", TIMED), duration: int | None = 45) -> Path:
    """A copy of the course outside the checkout: config and problem packages (symlinks kept)."""
    course = tmp / "course" / "assignments"
    course.mkdir(parents=True)
    shutil.copy(REPO / "assignments" / "nbgrader_config.py", course)
    for pid in problems:
        shutil.copytree(REPO / "assignments" / pid, course / pid, symlinks=True)
    if duration is not None and TIMED in problems:
        f = course / TIMED / "course.yaml"
        data = yaml.safe_load(f.read_text())
        data["timed"]["duration_min"] = duration
        f.write_text(yaml.safe_dump(data, sort_keys=False))
    return course


def _deadline(cwd: Path, *extra: str, env: dict | None = None) -> subprocess.CompletedProcess:
    base = {k: v for k, v in os.environ.items() if k != "GRADER_PROBLEMS"}
    return subprocess.run([sys.executable, "-m", "grader.nbgrader_autograde", "deadline", TIMED,
                           "2026-12-01T09:00:00+00:00", *extra], cwd=cwd, env={**base, **(env or {})},
                          capture_output=True, text=True, timeout=120)


def _due(gradebook: Path) -> str | None:
    with sqlite3.connect(gradebook) as db:
        row = db.execute("select duedate from assignment where name = ?", (TIMED,)).fetchone()
    return row[0] if row else None


def _checkout_gradebook() -> tuple[bool, float]:
    f = REPO / "assignments" / "gradebook.db"
    return f.exists(), f.stat().st_mtime if f.exists() else 0.0


@pytest.mark.parametrize("where", ["course", "above"])
def test_deadline_in_a_course_copy_sets_that_copys_due_date(tmp_path, where):
    course = _copy_course(tmp_path)
    before = _checkout_gradebook()
    r = _deadline(course if where == "course" else course.parent)
    assert r.returncode == 0, r.stderr
    assert str(course / "gradebook.db") in r.stdout  # it says which gradebook it wrote
    assert _due(course / "gradebook.db").startswith("2026-12-01 09:45:00")  # the copy's own 45 minutes
    assert _checkout_gradebook() == before  # the installed checkout's gradebook is untouched


def test_deadline_with_course_option_from_elsewhere(tmp_path):
    course = _copy_course(tmp_path, duration=50)
    r = _deadline(tmp_path, "--course", str(course))
    assert r.returncode == 0, r.stderr
    assert _due(course / "gradebook.db").startswith("2026-12-01 09:50:00")


def test_deadline_outside_any_course_says_so(tmp_path):
    r = _deadline(tmp_path)
    assert r.returncode == 2 and "no nbgrader course here" in r.stderr and "--course" in r.stderr


def test_a_mismatch_between_judge_problems_and_course_is_refused(tmp_path):
    course = _copy_course(tmp_path)
    r = _deadline(course, env={"GRADER_PROBLEMS": str(REPO / "assignments")})
    assert r.returncode == 2
    assert "nbgrader's course is" in r.stderr and str(course) in r.stderr and str(REPO / "assignments") in r.stderr
    assert not (course / "gradebook.db").exists()


def test_a_course_without_the_problem_packages_is_refused(tmp_path):
    course = _copy_course(tmp_path, problems=())
    r = _deadline(course)
    assert r.returncode == 2 and f"has no problem package {TIMED!r}" in r.stderr
    assert not (course / "gradebook.db").exists()


def test_problems_follow_the_course_folder(tmp_path, monkeypatch):
    course = _copy_course(tmp_path)
    monkeypatch.delenv("GRADER_PROBLEMS", raising=False)
    monkeypatch.chdir(course.parent)
    assert course_folder() == course.resolve() and problems_root() == course.resolve()
    assert check_course(course, TIMED) == course.resolve()
    with pytest.raises(ValueError, match="no problem package 'emst'"):
        check_course(course, "emst")
    monkeypatch.chdir(REPO)
    with pytest.raises(ValueError, match="run the command in"):
        check_course(course)
    bare = _copy_course(tmp_path / "bare", problems=())
    monkeypatch.chdir(bare)  # nbgrader's course without packages: the judge would fall back to the checkout
    with pytest.raises(ValueError, match=f"{bare} holds no problem package"):
        check_course(bare, TIMED)
