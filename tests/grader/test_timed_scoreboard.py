"""Timed attempts (grader's clock, deadline, late policies) and the ICPC scoreboard.

Run: .venv/bin/python -m pytest tests/grader/test_timed_scoreboard.py -q
"""
from __future__ import annotations

import subprocess
import sys

import pytest

from grader.classroom import scoreboard
from grader.classroom import timed
from grader.classroom.store import ResultStore
from grader.judging.verdicts import JudgeResult, TestResult, Verdict

from .conftest import REPO

SOL = REPO / "solutions" / "bowyer-watson-timed"


def test_timed_attempt_on_time_and_late(tmp_path):
    store = ResultStore(tmp_path / "t.sqlite")
    info = timed.start("bowyer-watson-timed", "ada", store, now=1000.0)
    assert info["deadline"] == 1000.0 + 30 * 60
    assert timed.start("bowyer-watson-timed", "ada", store, now=5000.0)["started_at"] == 1000.0  # no restart
    out = timed.submit("bowyer-watson-timed", "ada", SOL / "accepted_scan.py", store, now=1000.0 + 20 * 60)
    assert out.result.verdict == "AC" and not out.late and out.final_score == 100
    assert abs(out.elapsed_s - 1200) < 1e-6
    timed.start("bowyer-watson-timed", "bob", store, now=0.0)
    late = timed.submit("bowyer-watson-timed", "bob", SOL / "accepted_scan.py", store, now=45 * 60.0)
    assert late.late and late.multiplier == 0.5 and late.final_score == 50
    with pytest.raises(ValueError, match="has not started"):
        timed.submit("bowyer-watson-timed", "cy", SOL / "accepted_scan.py", store)
    store.export_csv("bowyer-watson-timed", tmp_path / "t.csv")
    assert "bob,bowyer-watson-timed,50.0" in (tmp_path / "t.csv").read_text()


def test_timed_cli(tmp_path):
    db = str(tmp_path / "c.sqlite")
    run = lambda *a: subprocess.run([sys.executable, "-m", "grader", "timed", *a, "--db", db],  # noqa: E731
                                    capture_output=True, text=True, cwd=REPO)
    assert "30 minutes" in run("start", "bowyer-watson-timed", "ada").stdout
    wrong = run("submit", "bowyer-watson-timed", "ada", str(SOL / "wrong_tutorial.py"))
    assert wrong.returncode == 1  # not AC
    assert wrong.stdout.count("elapsed") == 1, wrong.stdout
    assert "final score 0/100" in wrong.stdout


def test_timed_needs_timed_settings(tmp_path):
    store = ResultStore(tmp_path / "t.sqlite")
    with pytest.raises(ValueError, match="no timed settings"):
        timed.start("delaunay", "ada", store)
    assert store.db.execute("SELECT COUNT(*) FROM timed").fetchone()[0] == 0


def test_status_and_clock_text(tmp_path):
    store = ResultStore(tmp_path / "t.sqlite")
    first = timed.start("bowyer-watson-timed", "ada", store, now=1000.0)
    again = timed.start("bowyer-watson-timed", "ada", store, now=1600.0)
    assert not first["already"] and again["already"] and again["minutes_left"] == 20.0
    st = timed.status("bowyer-watson-timed", "ada", store, now=1600.0)
    assert st["minutes_left"] == 20.0 and st["deadline"] == 1000.0 + 1800
    text = timed.describe(again, now=1600.0)
    assert "already started at" in text and "20.0 minutes left" in text and timed.clock(1000.0, now=1600.0) in text
    assert "deadline passed 5.0 minutes ago" in timed.describe(st, now=1000.0 + 2100)
    with pytest.raises(ValueError, match="has not started"):
        timed.status("bowyer-watson-timed", "bob", store)


def _result(problem: str, verdict: Verdict) -> JudgeResult:
    return JudgeResult(problem, "x.py", [TestResult("t/1", "t", verdict)], {"t": 1})


def test_icpc_scoreboard(tmp_path):
    store = ResultStore(tmp_path / "s.sqlite")
    subs = [("ann", "p1", Verdict.WA, 60), ("ann", "p1", Verdict.AC, 600), ("ann", "p2", Verdict.AC, 1200),
            ("ben", "p1", Verdict.AC, 300), ("ben", "p2", Verdict.AC, 900), ("cat", "p1", Verdict.TLE, 100)]
    for k, (who, prob, v, t) in enumerate(subs):
        store.begin(who, prob, "f.py", f"sha{k}", t)
        store.finish(who, prob, f"sha{k}", _result(prob, v))
    rows = scoreboard.compute(store, start=0.0)
    assert [(r["student"], r["solved"], r["penalty"]) for r in rows] == [("ben", 2, 5 + 15), ("ann", 2, 10 + 20 + 20),
                                                                          ("cat", 0, 0)]
    text = scoreboard.format_board(rows)
    assert text.splitlines()[1].split()[:2] == ["1", "ben"]


def test_scoreboard_applies_the_late_multiplier(tmp_path):
    """A late AC under `late_multiplier: 0.5` is worth half its points; a rejected-late one solves nothing."""
    store = ResultStore(tmp_path / "s.sqlite")
    result = JudgeResult("p", "x.py", [TestResult("t/1", "t", Verdict.AC)], {"t": 100})
    for k, (who, mult, note) in enumerate([("ann", 1.0, "elapsed 10 min"), ("bo", 0.5, "late by 3 min: score x0.5"),
                                           ("cid", 0.0, "late by 9 min: rejected")]):
        store.begin(who, "p", "f.py", f"sha{k}", 60.0 * (k + 1))
        store.finish(who, "p", f"sha{k}", result, mult, note)
    rows = {r["student"]: r for r in scoreboard.compute(store, start=0.0)}
    assert (rows["ann"]["points"], rows["bo"]["points"], rows["cid"]["points"]) == (100, 50, 0)
    assert rows["bo"]["problems"]["p"]["late"] and rows["bo"]["solved"] == 1 and rows["cid"]["solved"] == 0
    line = next(ln for ln in scoreboard.format_board(list(rows.values())).splitlines() if " bo " in f" {ln} ")
    assert "late 50" in line and line.split()[4] == "50"
