"""Timed attempts ("implement Bowyer-Watson in 30 minutes"): the grader records the clock.

``start`` stores the start time and deadline (the grader's clock, never the student's);
``submit`` judges the file, records the elapsed time and applies the late policy from the
problem's ``course.yaml`` ``timed`` section:

    timed: {duration_min: 30, grace_s: 60, late_policy: multiplier, late_multiplier: 0.5}

``late_policy`` is ``multiplier`` (score times ``late_multiplier``), ``reject`` (score 0) or
``accept`` (no penalty, lateness only recorded).

Example:
    python -m grader timed start bowyer-watson-timed ada --db exam.sqlite
    python -m grader timed submit bowyer-watson-timed ada ada.py --db exam.sqlite
"""

from __future__ import annotations

import hashlib
import time
from dataclasses import dataclass
from pathlib import Path

from .judge import Judge
from .problems import load_problem
from .store import ResultStore
from .submissions import read_submission_bytes
from .verdicts import JudgeResult

POLICIES = ("multiplier", "reject", "accept")


@dataclass
class TimedOutcome:
    result: JudgeResult
    elapsed_s: float
    late: bool
    multiplier: float
    final_score: float
    note: str


def _settings(problem_id: str) -> dict:
    p = load_problem(problem_id)
    t = {"duration_min": 30, "grace_s": 0, "late_policy": "multiplier", "late_multiplier": 0.5, **p.timed}
    if t["late_policy"] not in POLICIES:
        raise ValueError(f"problem {problem_id!r}: late_policy must be one of {POLICIES}, got {t['late_policy']!r}")
    return t


def start(problem: str, student: str, store: ResultStore, now: float | None = None) -> dict:
    """Start the clock (idempotent: a second start keeps the first start time)."""
    t = _settings(problem)
    now = time.time() if now is None else now
    row = store.db.execute("SELECT started_at, deadline FROM timed WHERE student=? AND problem=?",
                           (student, problem)).fetchone()
    if row is None:
        deadline = now + 60 * float(t["duration_min"])
        store.db.execute("INSERT INTO timed (student, problem, started_at, deadline) VALUES (?,?,?,?)",
                         (student, problem, now, deadline))
        row = (now, deadline)
    return {"student": student, "problem": problem, "started_at": row[0], "deadline": row[1],
            "duration_min": t["duration_min"]}


def submit(problem: str, student: str, path: str | Path, store: ResultStore, now: float | None = None,
           judge: Judge | None = None) -> TimedOutcome:
    """Judge a timed submission; the elapsed time is measured from the recorded start."""
    t = _settings(problem)
    now = time.time() if now is None else now
    row = store.db.execute("SELECT started_at, deadline FROM timed WHERE student=? AND problem=?",
                           (student, problem)).fetchone()
    if row is None:
        raise ValueError(f"{student} has not started a timed attempt at {problem!r} (run `timed start` first)")
    started, deadline = row
    elapsed = now - started
    late = now > deadline + float(t["grace_s"])
    path = Path(path)
    sha = hashlib.sha256(read_submission_bytes(path, follow_links=True)).hexdigest()[:16]  # a file named by the caller
    judge = judge or Judge(problem, hide=[str(path.resolve().parent), str(Path(store.path).resolve().parent)])
    store.begin(student, problem, str(path), sha, now)
    result = judge.judge_path(path, on_test=lambda r: store.add_test(student, problem, sha, r),
                              prior=store.prior(student, problem, sha), follow_links=True)
    multiplier, note = 1.0, f"elapsed {elapsed / 60:.1f} min"
    if late:
        over = (now - deadline) / 60
        if t["late_policy"] == "reject":
            multiplier, note = 0.0, f"late by {over:.1f} min: rejected"
        elif t["late_policy"] == "multiplier":
            multiplier, note = float(t["late_multiplier"]), f"late by {over:.1f} min: score x{t['late_multiplier']}"
        else:
            note = f"late by {over:.1f} min (accepted)"
    store.finish(student, problem, sha, result, multiplier, note)
    store.db.execute("UPDATE timed SET submitted_at=?, elapsed_s=?, sha=?, late=? WHERE student=? AND problem=?",
                     (now, elapsed, sha, int(late), student, problem))
    return TimedOutcome(result, elapsed, late, multiplier, result.score * multiplier, note)
