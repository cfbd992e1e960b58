"""A simulated semester: 3 assignments, 12 students, extensions, a late and a missing student, a
test fixed mid-term and regraded with its diff, grades exported for Canvas and Moodle.

* ``hw1`` (graded as a class folder): s12 submitted nothing; after grading, the instructor fixes
  the too-weak ``gen`` group (adds a case with 8 points). Regrading judges only ``gen`` (the
  ``easy`` group's results are carried over, not judged again), and the diff names the students
  whose score moved (the ones right only on 5 points) and why (``gen: tests changed``).
* ``exam`` (timed, 30 minutes, late score x0.5): s01 has 15 extra minutes in ``extensions.yaml``
  and sees them in ``timed status``; s11 submits 10 minutes late; both submit at minute 40.
* ``hw2`` (nbgrader, scores in a gradebook): s02 has a 2-day extension and submits a day late;
  the late penalty is nbgrader's ``zero`` method through :class:`CourseLatePolicy`.
* the export: Canvas and Moodle files checked against fixture files in the documented import
  formats (``tests/grader/fixtures/lms/``): identifier columns, ids, points, every student.

Run: .venv/bin/python -m pytest tests/grader/test_semester.py -q
"""
from __future__ import annotations

import csv
import shutil
import sqlite3
from datetime import datetime, timedelta

import pytest

from grader.classroom import regrade, scoreboard, timed
from grader.classroom.classgrade import grade_class
from grader.classroom.store import ResultStore

from .conftest import HERE, REPO

ACCEPTED = (REPO / "solutions" / "delaunay" / "accepted_walk.py").read_text()
#: right on up to 5 points, an empty answer above: passes the weak gen group, fails the fixed one
SMALL_ONLY = ACCEPTED + "\n_inner = delaunay\n\ndef delaunay(points):\n    return _inner(points) if len(points) <= 5 else []\n"
STUDENTS = [f"s{k:02d}" for k in range(1, 13)]
SMALL = {"s04", "s07"}
LMS = HERE / "fixtures" / "lms"

HW = """entry: delaunay
forbidden: [scipy.spatial, matplotlib.tri, triangle, shapely]
checker: {repo}/assignments/delaunay/output_validator/checker.py
generator: {repo}/assignments/delaunay/generators/generator.py
seed: 7
groups:
  - name: easy
    points: 40
    data: data/sample
  - name: gen
    points: 60
    cases:
      - {{kind: points, points: [[0, 0], [2, 0], [2, 2], [0, 2], [1, 1]]}}
"""
EXAM = """entry: delaunay
checker: {repo}/assignments/delaunay/output_validator/checker.py
timed: {{duration_min: 30, grace_s: 0, late_policy: multiplier, late_multiplier: 0.5}}
groups:
  - name: all
    points: 100
    data: data/sample
"""


@pytest.fixture
def course(tmp_path, monkeypatch):
    root = tmp_path / "course"
    for pid, text in (("hw1", HW), ("hw2", HW), ("exam", EXAM)):
        shutil.copytree(HERE / "fixtures" / "tiny-delaunay", root / pid)
        (root / pid / "course.yaml").write_text(text.format(repo=REPO))
    (root / "extensions.yaml").write_text("s01:\n  exam: 15 minutes\ns02:\n  hw2: 2 days\n")
    monkeypatch.setenv("GRADER_PROBLEMS", str(root))
    return root


def test_semester(tmp_path, course, capsys):
    # -- hw1: a class folder, graded; s12 submitted nothing
    klass, db = tmp_path / "hw1-submissions", tmp_path / "results.sqlite"
    for s in STUDENTS:
        (klass / s).mkdir(parents=True)
        if s != "s12":
            (klass / s / "hw1.py").write_text(SMALL_ONLY if s in SMALL else ACCEPTED)
    first = {r["student"]: r for r in grade_class("hw1", klass, db, jobs=2, progress=False)}
    assert {s: first[s]["score"] for s in STUDENTS} == {s: 0 if s == "s12" else 100 for s in STUDENTS}
    assert "no submission" in first["s12"]["skipped"]
    judged = dict(sqlite3.connect(db).execute("SELECT student || test, judged_at FROM results"))

    # a statement edit changes no key: nobody is judged again
    (course / "hw1" / "statement" / "problem.en.md").write_text("# hw1\n\nReworded.\n")
    assert all(r.get("skipped") for r in grade_class("hw1", klass, db, progress=False))

    # mid-term: the gen group was too weak; the fix adds an 8-point case, and the class is regraded
    yaml = course / "hw1" / "course.yaml"
    yaml.write_text(yaml.read_text() + "      - {kind: uniform, n: 8}\n")
    capsys.readouterr()
    diff_csv = tmp_path / "hw1-diff.csv"
    after = {r["student"]: r for r in grade_class("hw1", klass, db, jobs=2, progress=False, diff_path=diff_csv)}
    err = capsys.readouterr().err
    assert {s: after[s]["score"] for s in STUDENTS if s != "s12"} == {s: 40 if s in SMALL else 100
                                                                      for s in STUDENTS if s != "s12"}
    for s in SMALL:
        assert f"{s}: 100 -> 40 (AC -> WA); gen: tests changed" in err, err
    rows = {r["student"]: r for r in csv.DictReader(open(diff_csv))}
    assert set(rows) == set(STUDENTS) - {"s12"}  # everyone judged again is in the diff, moved or not
    assert rows["s04"]["delta"] == "-60.0" and rows["s01"]["delta"] == "0.0" and "gen: tests changed" in rows["s01"]["changes"]
    assert "easy" not in rows["s01"]["changes"]
    con = sqlite3.connect(db)
    for s in STUDENTS[:11]:  # the unchanged group was carried over, not judged again
        new_key = con.execute("SELECT sha FROM submissions WHERE student=? ORDER BY rowid DESC", (s,)).fetchone()[0]
        easy = con.execute("SELECT test, judged_at FROM results WHERE student=? AND sha=? AND grp='easy'",
                           (s, new_key)).fetchall()
        assert easy and all(judged[s + t] == at for t, at in easy)
        gen = con.execute("SELECT verdict FROM results WHERE student=? AND sha=? AND grp='gen' ORDER BY test",
                          (s, new_key)).fetchall()
        assert [v for v, in gen] == (["AC", "WA"] if s in SMALL else ["AC", "AC"])
    assert len(regrade.history(ResultStore(db), "hw1")) == 11

    # -- the exam: s01 has 15 extra minutes, s11 is 10 minutes late, s12 never starts
    exam = ResultStore(tmp_path / "exam.sqlite")
    t0 = 1_000_000.0
    for s in STUDENTS[:11]:
        timed.start("exam", s, exam, now=t0)
    status = timed.status("exam", "s01", exam, now=t0 + 60)
    assert status["extra_min"] == 15 and status["deadline"] == t0 + 45 * 60
    assert "+ 15 extra (your extension)" in timed.describe(status, now=t0 + 60)
    assert timed.status("exam", "s11", exam, now=t0)["deadline"] == t0 + 30 * 60
    sol = tmp_path / "exam.py"
    sol.write_text(ACCEPTED)
    outcomes = {s: timed.submit("exam", s, sol, exam, now=t0 + (40 if s in ("s01", "s11") else 20) * 60)
                for s in STUDENTS[:11]}
    assert not outcomes["s01"].late and outcomes["s01"].final_score == 100
    assert outcomes["s11"].late and outcomes["s11"].final_score == 50
    board = {r["student"]: r for r in scoreboard.compute(exam)}
    assert board["s01"]["points"] == 100 and board["s11"]["points"] == 50 and board["s11"]["problems"]["exam"]["late"]
    exam.close()

    # -- hw2 in nbgrader's gradebook; s02 a day late with a 2-day extension, s03 a day late without
    gradebook = tmp_path / "gradebook.db"
    penalties = hw2_gradebook(gradebook, late={"s02": 86400.0, "s03": 86400.0})
    assert penalties == {"s02": 0.0, "s03": 100.0}

    # -- grades out
    from grader.course.grades_export import export

    roster = tmp_path / "roster.csv"
    with open(roster, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["course_id", "lms_id", "name", "email", "section"])
        for k, s in enumerate(STUDENTS):
            w.writerow([s, str(5000 + k), f"Student, {s.upper()}", f"{s}@example.edu", "A"])
    amap = tmp_path / "lms-map.csv"
    amap.write_text("assignment,canvas,moodle,points\nhw1,Homework 1 (901),Homework 1,10\n"
                    "hw2,Homework 2 (902),Homework 2,\nexam,Exam (903),Exam,100\n")
    out = tmp_path / "grades"
    report = export(roster, amap, out, gradebook=gradebook, stores=[db, tmp_path / "exam.sqlite"])
    assert sorted(report["missing_grades"]) == [("s12", "exam"), ("s12", "hw1"), ("s12", "hw2")]
    assert report["not_on_roster"] == report["not_in_map"] == []
    expected = {s: {"hw1": "4" if s in SMALL else "10", "hw2": "0" if s == "s03" else "100",
                    "exam": "50" if s == "s11" else "100"} for s in STUDENTS}
    expected["s12"] = {"hw1": "0", "hw2": "0", "exam": "0"}
    check_canvas(out / "canvas.csv", expected)
    check_moodle(out / "moodle.csv", expected)
    assert "s12: no grade for hw1 (exported as 0)" in (out / "missing.txt").read_text()

    # a roster without s10 and a map without the exam: both are listed, and kept in the long CSV
    short = tmp_path / "short-roster.csv"
    short.write_text("".join(ln for ln in roster.read_text().splitlines(True) if not ln.startswith("s10,")))
    amap2 = tmp_path / "map2.csv"
    amap2.write_text("\n".join(amap.read_text().splitlines()[:3]) + "\n")
    report = export(short, amap2, tmp_path / "g2", gradebook=gradebook, stores=[db, tmp_path / "exam.sqlite"])
    assert report["not_on_roster"] == ["s10"] and report["not_in_map"] == ["exam"]
    long = list(csv.DictReader(open(tmp_path / "g2" / "grades-long.csv")))
    assert {(r["course_id"], r["assignment"]) for r in long if r["note"].startswith("not ")} >= {("s10", "hw1"),
                                                                                                 ("s01", "exam")}


def hw2_gradebook(path, late: dict[str, float]) -> dict[str, float]:
    """A gradebook as nbgrader autograde leaves it: hw2, every student but s12 at 100 points, the
    late penalty of each late student from CourseLatePolicy (nbgrader's ``zero`` method)."""
    import os

    from nbgrader.api import Gradebook
    from traitlets.config import Configurable

    from grader.course.nbgrader_autograde import CourseLatePolicy, nbgrader_env

    os.environ["PATH"] = nbgrader_env()["PATH"]
    parent = Configurable()
    parent.assignment_id = "hw2"
    policy = CourseLatePolicy(parent=parent, penalty_method="zero")
    due = datetime(2026, 10, 1, 12, 0)
    out = {}
    with Gradebook(f"sqlite:///{path}") as gb:
        gb.add_assignment("hw2", duedate=due)
        gb.add_notebook("hw2", "hw2")
        gb.add_grade_cell("group-easy", "hw2", "hw2", max_score=100, cell_type="code")
        for s in STUDENTS[:11]:
            gb.add_student(s)
            sub = gb.add_submission("hw2", s, timestamp=due + timedelta(seconds=late.get(s, -3600)))
            grade = gb.find_grade("group-easy", "hw2", "hw2", s)
            grade.auto_score = 100
            if s in late:
                penalty = policy.late_submission_penalty(s, 100.0, late[s])
                sub.notebooks[0].late_submission_penalty = penalty
                out[s] = penalty
            gb.db.commit()
    return out


def check_canvas(path, expected: dict) -> None:
    """The Canvas rules, as the fixture shows them: the 5 identifier columns, then ``Name (id)``
    columns; the Points Possible row; one row per roster student, numbers only in grade cells."""
    fixture = list(csv.reader(open(LMS / "canvas-import.csv")))
    rows = list(csv.reader(open(path)))
    assert rows[0][:5] == fixture[0][:5]
    assert rows[0][5:] == ["Homework 1 (901)", "Homework 2 (902)", "Exam (903)"]
    assert rows[1][0].strip() == fixture[1][0].strip() == "Points Possible" and rows[1][5:] == ["10", "100", "100"]
    body = {r[1]: r for r in rows[2:]}
    assert sorted(body) == [str(5000 + k) for k in range(12)]  # every student, by LMS id
    for k, s in enumerate(STUDENTS):
        r = body[str(5000 + k)]
        assert r[0] == f"Student, {s.upper()}" and r[4] == "A"
        assert r[5:] == [expected[s]["hw1"], expected[s]["hw2"], expected[s]["exam"]], (s, r)
        assert all(float(x) >= 0 for x in r[5:])


def check_moodle(path, expected: dict) -> None:
    """The Moodle rules: an identifier column as in the fixture, one column per grade item, numbers."""
    fixture = list(csv.reader(open(LMS / "moodle-import.csv")))
    rows = list(csv.reader(open(path)))
    assert rows[0][:2] == fixture[0][:2] and rows[0][2:] == ["Homework 1", "Homework 2", "Exam"]
    body = {r[0]: r for r in rows[1:]}
    assert sorted(body) == sorted(f"{s}@example.edu" for s in STUDENTS)
    for s in STUDENTS:
        assert body[f"{s}@example.edu"][2:] == [expected[s]["hw1"], expected[s]["hw2"], expected[s]["exam"]]
