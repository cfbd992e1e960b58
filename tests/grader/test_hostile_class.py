"""A hostile class folder: links to another student's file, to a root-only file and to another
student's folder, a 2 GiB sparse file, student folders named like a spreadsheet formula, with
ANSI escapes, or with bytes that are not UTF-8; and a ``kill -9`` of ``grade`` itself.
Grading credits nothing it should not, leaks nothing, lists every student, and leaves no worker.

Run: .venv/bin/python -m pytest tests/grader/test_hostile_class.py -q
"""
from __future__ import annotations

import csv
import os
import resource
import signal
import sqlite3
import subprocess
import sys
import time

import pytest

from grader.classroom.classgrade import grade_class

from .conftest import HERE, REPO

ACCEPTED = (REPO / "solutions" / "delaunay" / "accepted_walk.py").read_text()
SECRET = "SECRET-LINE-do-not-leak-4711"
FORMULA = '=HYPERLINK("evil.example","click")'
ANSI = "\x1b[31mred\x1b[0m"


@pytest.fixture
def fixture_problems(monkeypatch):
    monkeypatch.setenv("GRADER_PROBLEMS", str(HERE / "fixtures"))
    return "tiny-delaunay"


def hostile_class(tmp_path):
    root = tmp_path / "class"
    secret = tmp_path / "secret.py"
    secret.write_text(f"# {SECRET}\ndef delaunay(points):\n    return []\n")
    secret.chmod(0o600)
    for name in ("bob", FORMULA, ANSI):
        (root / name).mkdir(parents=True)
        (root / name / "delaunay.py").write_text(ACCEPTED)
    (root / "mallory").mkdir()
    (root / "mallory" / "delaunay.py").symlink_to("../bob/delaunay.py")  # bob's AC
    (root / "trudy").mkdir()
    (root / "trudy" / "delaunay.py").symlink_to(secret)  # a root-only file: its first line must not leak
    (root / "eve").symlink_to("bob")  # a whole folder linked
    (root / "oscar").mkdir()
    with open(root / "oscar" / "delaunay.py", "wb") as f:  # 2 GiB, sparse: costs nothing on disk
        f.truncate(2 << 30)
    os.mkdir(os.fsencode(root) + b"/bad\xffname")
    (root / "bad\udcffname" / "delaunay.py").write_text(ACCEPTED)
    return root


def test_hostile_class_credits_nothing_leaks_nothing_lists_everyone(tmp_path, fixture_problems):
    root = hostile_class(tmp_path)
    db, grades, reports = tmp_path / "r.sqlite", tmp_path / "grades.csv", tmp_path / "reports"
    out = grade_class(fixture_problems, root, db, jobs=2, csv_path=grades, report_dir=reports, progress=False)
    verdicts = {s["student"]: s["verdict"] for s in out}
    ansi, bad = "\\x1b[31mred\\x1b[0m", "bad\\udcffname"
    assert verdicts == {"bob": "AC", FORMULA: "AC", ansi: "AC", bad: "AC", "mallory": "CE", "trudy": "CE",
                        "eve": "CE", "oscar": "CE"}
    con = sqlite3.connect(db)
    messages = dict(con.execute("SELECT student, message FROM results WHERE test = 'tiny/1-tutorial'").fetchall())
    assert "symbolic link" in messages["mallory"] and "symbolic link" in messages["trudy"]
    assert "the folder of delaunay.py is a symbolic link" in messages["eve"]
    assert "larger than" in messages["oscar"]
    rows = list(csv.reader(open(grades, newline="")))
    assert len(rows) == 1 + 8  # every student listed once
    scores = {r[0]: r[2] for r in rows[1:]}
    assert scores == {"bob": "100.0", "'" + FORMULA: "100.0", ansi: "100.0", bad: "100.0", "mallory": "0.0",
                      "trudy": "0.0", "eve": "0.0", "oscar": "0.0"}  # the formula is text, with a quote
    dump = "\n".join(con.iterdump())
    everything = [dump, open(grades).read(), repr(out)] + [p.read_text() for p in reports.rglob("*.html")]
    assert not any(SECRET in text for text in everything), "a linked file's content leaked"
    assert not any("\x1b" in text for text in everything), "an ANSI escape reached an output"
    # the sparse file was never read (it used to cost 2.1 GB): no child of this process reached its
    # 2 GiB. (Not 1 GiB: RUSAGE_CHILDREN is the worker's whole history, and a jailed program, a
    # direct child of bubblewrap since it runs as pid 1, may have used up to its 1 GiB limit in an
    # earlier test of the same worker, e.g. a memory bomb: 1.07 GiB was seen in CI.)
    assert resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss < (2 << 30) >> 10


def descendants(pid: int) -> set[int]:
    parent = {}
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                with open(f"/proc/{d}/stat") as f:
                    parent[int(d)] = int(f.read().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
    out, todo = set(), [pid]
    while todo:
        p = todo.pop()
        kids = [c for c, pp in parent.items() if pp == p]
        out.update(kids)
        todo += kids
    return out


def alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def test_kill_9_of_grade_leaves_no_worker_and_resumes(tmp_path):
    root = tmp_path / "class"
    slow = "\nimport time\n_inner = delaunay\ndef delaunay(points):\n    time.sleep(0.3)\n    return _inner(points)\n"
    for k in range(6):
        (root / f"s{k}").mkdir(parents=True)
        (root / f"s{k}" / "delaunay.py").write_text(ACCEPTED + slow)
    db = tmp_path / "r.sqlite"
    env = {**os.environ, "GRADER_PROBLEMS": str(HERE / "fixtures")}
    cmd = [sys.executable, "-m", "grader", "grade", "tiny-delaunay", str(root), "--db", str(db), "--jobs", "2", "--quiet"]
    proc = subprocess.Popen(cmd, cwd=REPO, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    workers: set[int] = set()
    deadline = time.time() + 90
    while time.time() < deadline:
        time.sleep(0.1)
        workers |= descendants(proc.pid)
        try:
            n = sqlite3.connect(db).execute("SELECT count(*) FROM results").fetchone()[0]
        except sqlite3.Error:
            continue
        if n >= 3:
            break
    workers |= descendants(proc.pid)
    os.kill(proc.pid, signal.SIGKILL)  # the grading process only, not its process group
    proc.wait()
    assert workers, "no pool worker was seen"
    end = time.time() + 30
    while time.time() < end and any(alive(p) for p in workers):
        time.sleep(0.2)
    assert not [p for p in workers if alive(p)], "pool workers outlived the killed grade process"
    before = sqlite3.connect(db).execute("SELECT student, test, judged_at FROM results").fetchall()
    assert 3 <= len(before) < 18, "kill came too late to test resuming"
    subprocess.run(cmd, cwd=REPO, env=env, check=True, capture_output=True, timeout=300)
    con = sqlite3.connect(db)
    after = con.execute("SELECT student, test, judged_at FROM results").fetchall()
    assert len(after) == 18 == len({(s, t) for s, t, _ in after})  # nothing lost, nothing duplicated
    assert set(before) <= set(after)
    assert {r[0] for r in con.execute("SELECT status FROM submissions")} == {"done"}
