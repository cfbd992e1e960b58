"""Timed attempts (grader's clock, deadline, late policies) and the ICPC scoreboard.

Run: .venv/bin/python -m pytest tests/grader/test_timed_scoreboard.py -q
"""
from __future__ import annotations

import subprocess
import sys

import pytest

from grader import scoreboard, timed
from grader.store import ResultStore
from grader.verdicts import JudgeResult, TestResult, Verdict

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
                                    capture_output=True, text=True, cwd=REPO, check=True).stdout
    assert "30 minutes" in run("start", "bowyer-watson-timed", "ada")
    assert "elapsed" in run("submit", "bowyer-watson-timed", "ada", str(SOL / "wrong_tutorial.py"))


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
