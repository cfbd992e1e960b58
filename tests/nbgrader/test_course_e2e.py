"""End to end: the nbgrader course with a fake class of eleven students on the timed exam.

generate_assignment -> release to a local exchange -> submissions (right, wrong, slow, hostile,
missing, late, and five forgeries) -> collect -> autograde -> generate_feedback -> export; then
the same class in a second course copy through the parallel path (``python -m grader grade
--nbgrader``). Checks: every gradebook score equals ``python -m grader judge``'s on the autograded
notebook (times the late policy), forgeries score what their wrong code scores, nobody's manual
score is set, no feedback file holds a hidden test input, and both paths write the same gradebook.

Run: .venv/bin/python -m pytest tests/nbgrader/test_course_e2e.py -x -q   (a few minutes; as root, and
tests/grader/test_jail_user.py runs it as an ordinary instructor account too)
"""

from __future__ import annotations

import contextlib
import csv
import io
import os
import re
import shutil
import time
from datetime import datetime, timedelta, timezone
from pathlib import Path

import pytest

from fake_class import add_roster, gradebook_scores, judge_json, make_course, students, submit_class
from grader.cli import main as grader_main
from grader.jail import jail_kind
from grader.course.nbgrader_autograde import late_factor, set_exam_deadline
from grader.judging.submissions import Submission
from grader.problems import load_problem

PROBLEM = "bowyer-watson-timed"
pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("nbgrader-e2e"),  # one worker builds the class once
              pytest.mark.skipif(os.geteuid() != 0 and jail_kind() == "none",
                                 reason="this account has no kernel jail (no bubblewrap or user namespaces): grading "
                                        "refuses; as root, or as an ordinary user in tests/grader/test_jail_user.py")]


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("nbcourse")
    course = make_course(tmp, PROBLEM)
    add_roster(course.root, [s.name for s in students()])
    start = datetime.now(timezone.utc) - timedelta(minutes=25)
    due = set_exam_deadline(course.root, PROBLEM, start)
    submit_class(course, PROBLEM, students(), due)
    course.nbgrader("collect", PROBLEM)
    twin = tmp / "twin"
    shutil.copytree(course.root, twin)  # the same class, for the parallel path
    t0 = time.perf_counter()
    course.nbgrader("autograde", PROBLEM)
    t1 = time.perf_counter()
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        assert grader_main(["grade", PROBLEM, str(twin / "submitted"), "--nbgrader", "--jobs", "2"]) == 0
    t2 = time.perf_counter()
    (tmp / "grade-nbgrader.out").write_text(out.getvalue())
    (tmp / "grade-nbgrader.err").write_text(err.getvalue())
    print(f"autograde one by one {t1 - t0:.1f} s, grade --nbgrader --jobs 2 {t2 - t1:.1f} s")  # shown with -s
    course.nbgrader("generate_feedback", PROBLEM)
    course.nbgrader("export", "--to", str(tmp / "grades.csv"))
    return course, twin, tmp


@pytest.fixture(scope="module")
def judged():
    """``judged(path)``: ``python -m grader judge PROBLEM path --json``, run once per distinct code. The
    judge sees only the code cells (:func:`notebook_code`), so two notebooks with the same code get the
    same verdict; judging each code once (the class's submitted and autograded copies, the forgeries'
    verdicts) leaves what the tests compare unchanged and saves a judging of the whole problem per copy
    (the slow student's TLE alone costs its 6 s time limit each time)."""
    done: dict[str, dict] = {}

    def judge(path: Path) -> dict:
        code = Submission.from_path(path, follow_links=True).source
        if code not in done:
            done[code] = judge_json(PROBLEM, path)
        return done[code]
    return judge


def _expected(course, judged) -> dict[str, float]:
    """Per student: the judge's score of the autograded notebook times the late policy."""
    out = {}
    for d in sorted((course.root / "submitted").iterdir()):
        nb = course.root / "autograded" / d.name / PROBLEM / f"{PROBLEM}.ipynb"
        if not nb.is_file():
            out[d.name] = 0.0
            continue
        factor = late_factor(PROBLEM, 1200)[0] if d.name == "late" else 1.0  # submitted 20 min late
        out[d.name] = judged(nb)["score"] * factor
        out[d.name + ":submitted"] = judged(d / PROBLEM / f"{PROBLEM}.ipynb")["score"] * factor
    return out


def test_scores_equal_the_judge(graded, judged):
    course, _, _ = graded
    got = gradebook_scores(course.root, PROBLEM)
    expected = _expected(course, judged)
    assert set(got) == {s.name for s in students()}
    for student, g in got.items():
        assert g["score"] == pytest.approx(expected[student]), (student, g, expected[student])
        if student != "missing":  # the code as submitted scores the same (edited test cells hold no code)
            assert expected[student + ":submitted"] == expected[student]
        assert g["manual"] == [], f"{student}: a manual score appeared: {g['manual']}"
    # what each kind of student gets (the judge decides; these pin the class composition)
    assert got["right"]["score"] == 100
    assert got["late"]["raw"] == 100 and got["late"]["score"] == 50 == 100 * late_factor(PROBLEM, 1200)[0]
    assert 0 < got["slow"]["score"] < 100  # correct on the small groups, TLE on the largest
    for s in ("wrong", "hostile", "missing", "transformer", "monkeypatch", "gradebook", "traceback", "edited"):
        assert got[s]["score"] == 0, (s, got[s])
    # the test cells edited in the submitted copy were restored before judging
    assert expected["edited:submitted"] == expected["edited"] == 0


def test_forgeries_get_their_verdicts(graded, judged):
    course, _, _ = graded
    verdicts = {}
    for s in ("transformer", "monkeypatch", "gradebook", "traceback", "hostile"):
        nb = course.root / "autograded" / s / PROBLEM / f"{PROBLEM}.ipynb"
        verdicts[s] = judged(nb)["verdict"]
    assert verdicts == {"transformer": "WA", "monkeypatch": "SV", "gradebook": "SV", "traceback": "RE", "hostile": "SV"}


def test_export_and_parallel_gradebook_agree(graded):
    course, twin, tmp = graded
    with open(tmp / "grades.csv") as f:
        exported = {r["student_id"]: float(r["score"]) for r in csv.DictReader(f)}
    one_by_one = gradebook_scores(course.root, PROBLEM)
    parallel = gradebook_scores(twin, PROBLEM)
    assert exported == {s: g["score"] for s, g in one_by_one.items()}
    assert parallel == one_by_one


def _hidden_tokens() -> set[str]:
    """Distinctive numbers of every hidden test input (coordinates as the input text writes them)."""
    tokens = set()
    for t in load_problem(PROBLEM).tests():
        if t.group == "sample":
            continue
        for tok in re.findall(r"[-+0-9.eE]+", t.input_text):
            if len(tok.strip("-+")) >= 6:
                tokens.add(tok)
    return tokens


def test_feedback_shows_verdicts_not_hidden_inputs(graded):
    course, _, _ = graded
    files = sorted((course.root / "feedback").rglob("*.html"))
    assert {f.parts[-3] for f in files} == {s.name for s in students() if s.code is not None}
    tokens = _hidden_tokens()
    assert len(tokens) > 100
    for f in files:
        text = f.read_text()
        leaked = [t for t in tokens if t in text]
        assert not leaked, f"{f}: hidden input numbers {leaked[:5]}"
    wrong = (course.root / "feedback" / "wrong" / PROBLEM / f"{PROBLEM}.html").read_text()
    assert "group tiny" in wrong and "WA" in wrong
    right = (course.root / "feedback" / "right" / PROBLEM / f"{PROBLEM}.html").read_text()
    tiny = next(g for g in load_problem(PROBLEM).groups if g.name == "tiny")
    assert f"group tiny: all {len(tiny.cases)} tests accepted" in right


def test_student_edition_releases_what_nbgrader_releases(graded):
    """The student edition's notebooks are nbgrader's own release (same cells, stubs, checksums)."""
    import nbformat

    from grader.course.student_edition import release_notebook

    course, _, _ = graded
    ours = release_notebook(nbformat.read(course.root / "source" / PROBLEM / f"{PROBLEM}.ipynb", 4))
    theirs = nbformat.read(course.root / "release" / PROBLEM / f"{PROBLEM}.ipynb", 4)
    assert [(c.source, c.metadata) for c in ours.cells] == [(c.source, c.metadata) for c in theirs.cells]


def test_grade_nbgrader_shows_progress_and_the_late_penalty(graded):
    """``grade --nbgrader`` says on stderr which notebook it judged (k/N) and when nbgrader runs, and
    its table shows the gradebook's score where the late policy changed it."""
    course, twin, tmp = graded
    err = (tmp / "grade-nbgrader.err").read_text()
    table = {ln.split()[0]: ln for ln in (tmp / "grade-nbgrader.out").read_text().splitlines() if ln.strip()}
    collected = sorted(d.name for d in (twin / "submitted").iterdir() if (d / PROBLEM / f"{PROBLEM}.ipynb").is_file())
    n = len(collected)
    assert f"judging {n} collected notebook(s)" in err, err
    for k in range(1, n + 1):
        assert re.search(rf"^\[{k}/{n}\] \S+: ", err, re.M), err
    assert {m for m in re.findall(rf"^\[\d+/{n}\] (\S+):", err, re.M)} == set(collected)
    assert "nbgrader autograde" in err and "gradebook written" in err, err
    book = gradebook_scores(twin, PROBLEM)
    assert book["late"]["penalty"] > 0
    assert f"gradebook: {book['late']['score']:g} (late penalty -{book['late']['penalty']:g})" in table["late"], table
    on_time = [s for s, g in book.items() if not g["penalty"] and s in table]
    assert on_time and all("gradebook:" not in table[s] for s in on_time), table
