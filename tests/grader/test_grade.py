"""Class grading: parallel, resumable after kill -9, CSV for an LMS, progress, Dask distributed.

Run: .venv/bin/python -m pytest tests/grader/test_grade.py -q
"""
from __future__ import annotations

import csv
import os
import signal
import sqlite3
import subprocess
import sys
import time

import pytest

from grader.classroom.classgrade import discover, grade_class
from grader.contest.report import report_name, student_report_path

from .conftest import HERE, REPO

ACCEPTED = (REPO / "solutions" / "delaunay" / "accepted_walk.py").read_text()
WRONG = (REPO / "solutions" / "delaunay" / "wrong_tutorial.py").read_text()


@pytest.fixture
def fixture_problems(monkeypatch):
    monkeypatch.setenv("GRADER_PROBLEMS", str(HERE / "fixtures"))
    return "tiny-delaunay"


def make_class(root, sleep: float = 0.0, n: int = 4):
    slow = f"\nimport time\n_inner = delaunay\ndef delaunay(points):\n    time.sleep({sleep})\n    return _inner(points)\n"
    files = {"ada": ACCEPTED, "bob": WRONG, "cy": "def delaunay(points)\n", "dee": ACCEPTED}
    for k in range(n):
        name = list(files)[k] if k < len(files) else f"s{k:02d}"
        d = root / name
        d.mkdir(parents=True)
        (d / "solution.py").write_text((files.get(name, ACCEPTED)) + (slow if sleep else ""))
    return root


def test_grade_class_parallel_with_csv_and_reports(tmp_path, fixture_problems, capsys):
    root = make_class(tmp_path / "class")
    db = tmp_path / "results.sqlite"
    out = grade_class(fixture_problems, root, db, jobs=2, csv_path=tmp_path / "grades.csv", report_dir=tmp_path / "reports")
    verdicts = {s["student"]: s["verdict"] for s in out}
    assert verdicts == {"ada": "AC", "bob": "WA", "cy": "CE", "dee": "AC"}
    rows = list(csv.DictReader(open(tmp_path / "grades.csv")))
    assert {r["student"]: r["score"] for r in rows} == {"ada": "100.0", "bob": "0.0", "cy": "0.0", "dee": "100.0"}
    assert student_report_path(tmp_path / "reports", "bob").read_text().count("data:image/png") == 1
    assert "graded 4/4" in capsys.readouterr().err  # plain progress lines when stderr is not a TTY
    again = grade_class(fixture_problems, root, db, jobs=2)
    assert all(s.get("skipped") for s in again)


def test_resume_after_kill_9(tmp_path):
    root = make_class(tmp_path / "class", sleep=0.25, n=5)
    db = tmp_path / "r.sqlite"
    env = {**os.environ, "GRADER_PROBLEMS": str(HERE / "fixtures")}
    cmd = [sys.executable, "-m", "grader", "grade", "tiny-delaunay", str(root), "--db", str(db), "--jobs", "1", "--quiet"]
    proc = subprocess.Popen(cmd, cwd=REPO, env=env, start_new_session=True, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    before = []
    deadline = time.time() + 60
    while time.time() < deadline:
        time.sleep(0.1)
        try:
            before = sqlite3.connect(db).execute("SELECT student, test, judged_at FROM results").fetchall()
        except sqlite3.Error:
            continue
        if len(before) >= 4:
            break
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    assert 4 <= len(before) < 15, "kill came too late to test resuming"
    subprocess.run(cmd, cwd=REPO, env=env, check=True, capture_output=True)
    con = sqlite3.connect(db)
    after = con.execute("SELECT student, test, judged_at FROM results").fetchall()
    assert len(after) == 15 == len(set((s, t) for s, t, _ in after))  # nothing lost, nothing duplicated
    assert set(before) <= set(after)  # results committed before the kill were kept, not redone
    assert {r[0] for r in con.execute("SELECT status FROM submissions")} == {"done"}


def test_grade_on_dask_local_cluster(tmp_path, fixture_problems):
    distributed = pytest.importorskip("distributed")
    root = make_class(tmp_path / "class", n=3)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        out = grade_class(fixture_problems, root, tmp_path / "d.sqlite", scheduler=cluster.scheduler_address,
                          csv_path=tmp_path / "d.csv", progress=False)
    assert {s["student"]: s["verdict"] for s in out} == {"ada": "AC", "bob": "WA", "cy": "CE"}
    assert len(list(csv.DictReader(open(tmp_path / "d.csv")))) == 3


def test_empty_folder_and_several_candidates(tmp_path, fixture_problems, capsys):
    """An empty folder still gets a CSV row (score 0, "no submission"); with several candidate
    files the note (in the CSV and on stderr) says which one was judged and why."""
    root = tmp_path / "class"
    (root / "eve").mkdir(parents=True)
    (root / "eve" / "notes.txt").write_text("not code")
    (root / "fay").mkdir()
    (root / "fay" / "scratch.py").write_text("def delaunay(points):\n    return []\n")
    (root / "fay" / f"{fixture_problems}.py").write_text(ACCEPTED)
    os.utime(root / "fay" / "scratch.py")  # newer, but the file named after the problem wins
    (root / "gus").mkdir()
    (root / "gus" / "old.py").write_text("def delaunay(points):\n    return []\n")
    grade_class(fixture_problems, root, tmp_path / "r.sqlite", progress=False)  # the grader sees old.py first
    capsys.readouterr()
    (root / "gus" / "new.py").write_text(ACCEPTED)
    os.utime(root / "gus" / "new.py", (1e9, 1e9))  # dated 2001: the grader's first sight counts, not the mtime
    out = grade_class(fixture_problems, root, tmp_path / "r.sqlite", csv_path=tmp_path / "g.csv",
                      report_dir=tmp_path / "reports")
    rows = {r["student"]: r for r in csv.DictReader(open(tmp_path / "g.csv"))}
    assert list(rows) == ["eve", "fay", "gus"]
    assert rows["eve"]["score"] == "0" and rows["eve"]["note"].startswith("no submission")
    assert rows["fay"]["score"] == "100.0" and "named after the problem" in rows["fay"]["note"]
    assert f"judged {fixture_problems}.py of 2 files" in rows["fay"]["note"]
    assert rows["gus"]["file"].endswith("new.py") and "the one the grader saw last" in rows["gus"]["note"]
    err = capsys.readouterr().err
    assert "eve: no submission" in err and "gus: judged new.py of 2 files" in err
    assert "3 student folders: 1 to judge, 1 already graded, 1 without a submission" in err, err
    assert "1 reports rebuilt from the store" in err  # fay's, graded by the first run without --reports
    assert {s["student"] for s in out} == {"eve", "fay", "gus"}
    index = (tmp_path / "reports" / "index.html").read_text()
    assert f'<a href="students/{report_name("fay")}">fay</a>' in index
    assert f'<a href="students/{report_name("gus")}">gus</a>' in index
    assert "eve</td><td>-</td><td>0</td><td>no submission" in index


def test_progress_counts_tests_and_resumed_results(tmp_path, fixture_problems, capsys):
    root = make_class(tmp_path / "class", n=2)
    db = tmp_path / "p.sqlite"
    from grader.classroom.store import ResultStore
    from grader.judging.verdicts import TestResult, Verdict

    from grader.classroom.regrade import fingerprints, version
    from grader.problems import load_problem

    store = ResultStore(db)  # as if a killed batch had stored ada's first test
    key = version(fingerprints(load_problem(fixture_problems)))
    ada = next(j for j in discover(root, fixture_problems, store, key)
               if j.student == "ada")
    store.begin("ada", fixture_problems, ada.path, ada.sha, ada.submitted_at)
    store.add_test("ada", fixture_problems, ada.sha, TestResult("tiny/1-tutorial", "tiny", Verdict.AC, 0.01, 30.0))
    store.close()
    grade_class(fixture_problems, root, db, jobs=1)
    err = capsys.readouterr().err
    assert "1 test results resumed from the store" in err
    assert "graded 2/2" in err and "tests 6/6, 1 resumed from the store" in err, err


def test_live_progress_names_who_is_judged(tmp_path, fixture_problems):
    """On a terminal the bar shows who is being judged and their tests done, while they run."""
    import io

    from grader.classroom.classgrade import Progress
    from grader.classroom.store import ResultStore

    class Tty(io.StringIO):
        def isatty(self):
            return True

    store = ResultStore(tmp_path / "x.sqlite")
    store.begin("ada", "p", "a.py", "s1", 0.0)
    from grader.judging.verdicts import TestResult, Verdict

    for k in range(2):
        store.add_test("ada", "p", "s1", TestResult(f"g/{k}", "g", Verdict.AC))
    out = Tty()
    bar = Progress(2, stream=out, tests_per_student=3)
    bar.poll(store, "p", {"ada": "s1", "bob": "s2"}, set())
    assert "judging ada 2/3" in out.getvalue() and "tests 2/6" in out.getvalue()


def test_already_graded_students_keep_their_stored_score():
    """After a resume the table shows a student graded earlier with the stored verdict and the
    late-adjusted score, not an empty row."""
    from grader.classroom.classgrade import _graded_summary

    row = {"verdict": "WA", "score": 40, "max_score": 100, "multiplier": 0.5}
    assert _graded_summary("ann", row, 100) == {"student": "ann", "verdict": "WA", "score": 20.0,
                                                "max_score": 100, "skipped": "already graded"}
    assert _graded_summary("bob", None, 100)["skipped"] == "already graded"
