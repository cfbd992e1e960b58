"""Issue 23's class-grading holes: reports, resume, re-judging, submission times.

* a folder named ``javascript:alert(1)`` gets a relative, URL-quoted link under ``students/``;
  one named ``index`` does not overwrite the class index; ``bob<ESC>`` and ``bob\\x1b`` (both
  shown as ``bob\\x1b``) stay two students, two CSV rows, two reports, and the collision is said;
* a student marked done whose report is missing (what a ``kill -9`` between the two used to
  leave) gets the report rebuilt on resume and a link in the index;
* changing the problem's points rescores everyone without judging a test again, and says so (stderr, CSV note);
* a file dated 2020-01-01 is not "submitted" in 2020: times are the grader's first sight of the
  content, and the scoreboard and the choice between files use them.

Run: .venv/bin/python -m pytest tests/grader/test_class_store.py -q
"""
from __future__ import annotations

import csv
import os
import shutil
import sqlite3

import pytest

from grader.classroom import scoreboard
from grader.classroom.classgrade import grade_class
from grader.contest.report import report_name, student_report_path
from grader.classroom.store import ResultStore

from .conftest import HERE, REPO

ACCEPTED = (REPO / "solutions" / "delaunay" / "accepted_walk.py").read_text()
WRONG = "def delaunay(points):\n    return []\n"
JAN_2020 = 1577836800.0


@pytest.fixture
def problems(monkeypatch, tmp_path):
    """A private copy of the fixture problems (so a test may change the points)."""
    root = tmp_path / "problems"
    shutil.copytree(HERE / "fixtures", root)
    course = root / "tiny-delaunay" / "course.yaml"
    course.write_text(course.read_text().replace("../../../../", f"{REPO}/"))
    monkeypatch.setenv("GRADER_PROBLEMS", str(root))
    return root


def student(root, name: str | bytes, source: str = ACCEPTED, mtime: float | None = None):
    d = os.path.join(os.fsencode(root), name if isinstance(name, bytes) else os.fsencode(name))
    os.makedirs(d, exist_ok=True)
    f = os.path.join(d, b"tiny-delaunay.py")
    with open(f, "w") as fh:
        fh.write(source)
    if mtime is not None:
        os.utime(f, (mtime, mtime))


def test_report_names_links_and_colliding_ids(tmp_path, problems, capsys):
    root, reports = tmp_path / "class", tmp_path / "reports"
    for name in ("javascript:alert(1)", "index", "bob\x1b", "bob\\x1b", "up", "a b&c"):
        student(root, name)
    out = grade_class("tiny-delaunay", root, tmp_path / "r.sqlite", csv_path=tmp_path / "g.csv", report_dir=reports,
                      progress=False)
    err = capsys.readouterr().err
    assert "2 student folders read as 'bob\\\\x1b': kept apart as" in err, err
    ids = sorted(s["student"] for s in out)
    assert len(ids) == 6 and len(set(ids)) == 6 and "bob\\x1b" in ids
    rows = list(csv.DictReader(open(tmp_path / "g.csv")))
    assert len(rows) == 6 and len({r["student"] for r in rows}) == 6
    index = (reports / "index.html").read_text()
    assert "<h1>tiny-delaunay: 6 students</h1>" in index  # the index was not overwritten by a report
    assert 'href="javascript' not in index and "href='javascript" not in index
    assert f'href="students/{report_name("javascript:alert(1)")}"' in index
    assert f'href="students/{report_name("a b&c")}"' in index and " " not in report_name("a b&c")
    files = sorted(p.name for p in (reports / "students").iterdir())
    assert len(files) == 6 and "index.html" not in files
    for sid in ids:
        assert student_report_path(reports, sid).is_file()


def test_a_done_student_without_report_gets_it_on_resume(tmp_path, problems, capsys):
    root, reports, db = tmp_path / "class", tmp_path / "reports", tmp_path / "r.sqlite"
    student(root, "ada")
    student(root, "bob", WRONG)
    grade_class("tiny-delaunay", root, db, report_dir=reports, progress=False)
    lost = student_report_path(reports, "bob")
    lost.unlink()  # the state a kill -9 between store.finish and the report used to leave
    again = grade_class("tiny-delaunay", root, db, report_dir=reports, progress=True)
    assert all(s.get("skipped") == "already graded" for s in again)
    assert lost.is_file() and "WA" in lost.read_text()
    assert "1 reports rebuilt from the store" in capsys.readouterr().err
    assert f'href="students/{report_name("bob")}"' in (reports / "index.html").read_text()


def test_changed_points_judge_again_and_say_so(tmp_path, problems, capsys):
    root, db = tmp_path / "class", tmp_path / "r.sqlite"
    student(root, "ada")
    grade_class("tiny-delaunay", root, db, progress=False)
    assert all(s.get("skipped") for s in grade_class("tiny-delaunay", root, db, progress=False))
    course = problems / "tiny-delaunay" / "course.yaml"
    course.write_text(course.read_text().replace("points: 100", "points: 50"))
    capsys.readouterr()
    out = grade_class("tiny-delaunay", root, db, csv_path=tmp_path / "g.csv", progress=False)
    assert out[0]["score"] == 50 and not out[0].get("skipped")
    err = capsys.readouterr().err
    assert "1 submissions judged again: the problem's tests, checker, limits or points changed" in err
    assert "ada: 100 -> 50; tiny: points 100 -> 50" in err  # the diff: no test changed, none judged again
    row = next(csv.DictReader(open(tmp_path / "g.csv")))
    assert row["score"] == "50.0" and "judged again: tiny (points 100 -> 50)" in row["note"]
    runs = sqlite3.connect(db).execute("SELECT COUNT(*), COUNT(DISTINCT judged_at) FROM results").fetchone()
    assert runs[0] == 6 and runs[1] == 3  # 3 tests, each judged once: the second key's rows are copies
    # the scoreboard counts that file once
    board = scoreboard.compute(ResultStore(db))
    assert board[0]["problems"]["tiny-delaunay"]["tries"] == 1


def test_submission_times_are_the_graders_not_the_files(tmp_path, problems):
    root, db = tmp_path / "class", tmp_path / "r.sqlite"
    student(root, "ada")
    grade_class("tiny-delaunay", root, db, progress=False)
    student(root, "mallory", mtime=JAN_2020)  # arrives later, dated 2020-01-01
    grade_class("tiny-delaunay", root, db, progress=False)
    times = dict(sqlite3.connect(db).execute("SELECT student, submitted_at FROM submissions").fetchall())
    assert times["mallory"] >= times["ada"] > JAN_2020 + 86400 * 365
    board = scoreboard.compute(ResultStore(db))
    assert [r["student"] for r in board] == ["ada", "mallory"]  # ties broken by name, not by a forged date
    # a rejected try dated in the past still counts as the earlier try only if the grader saw it first
    student(root, "mallory", WRONG, mtime=JAN_2020 - 1)
    grade_class("tiny-delaunay", root, db, progress=False)
    subs = [s for s in ResultStore(db).submissions() if s["student"] == "mallory"]
    assert [s["verdict"] for s in subs] == ["AC", "WA"]  # in the order the grader saw them


def test_deferred_tests_commit_together_and_on_error(tmp_path, monkeypatch):
    """Class grading's rows: none visible to another connection until a commit, one commit for the
    tests finished within ``every_s`` of the first pending one, the rest at the end of the block,
    also when the block ends by an exception (those tests were finished)."""
    from grader.classroom import store as store_module
    from grader.judging.verdicts import TestResult, Verdict

    clock = [100.0]
    monkeypatch.setattr(store_module.time, "monotonic", lambda: clock[0])
    db = tmp_path / "r.sqlite"
    store = ResultStore(db)
    other = sqlite3.connect(db)

    def seen() -> int:
        return other.execute("SELECT COUNT(*) FROM results WHERE student='ada'").fetchone()[0]

    with store.deferred_tests("ada", "p", "s1", every_s=1.0) as add:
        add(TestResult("g/1", "g", Verdict.AC))
        clock[0] += 0.5
        add(TestResult("g/2", "g", Verdict.WA, message="wrong"))
        assert seen() == 0  # within a second of the first pending row: not written yet
        clock[0] += 0.6
        add(TestResult("g/3", "g", Verdict.AC))
        assert seen() == 3  # a second after the first pending row: all three in one commit
        add(TestResult("g/4", "g", Verdict.AC))
        assert seen() == 3
    assert seen() == 4
    with pytest.raises(RuntimeError):
        with store.deferred_tests("ada", "p", "s2") as add:
            add(TestResult("h/1", "h", Verdict.AC))
            raise RuntimeError("the judge stopped")
    assert other.execute("SELECT test FROM results WHERE sha='s2'").fetchall() == [("h/1",)]
    assert store.prior("ada", "p", "s1")["g/2"].verdict == Verdict.WA
    with pytest.raises(ValueError, match="every_s"):
        with store.deferred_tests("ada", "p", "s3", every_s=-1):
            pass
    other.close()
    store.close()
