"""Timed attempts ("implement Bowyer-Watson in 30 minutes"): the grader records the clock.

``start`` stores the start time and deadline (the grader's clock, never the student's);
``submit`` judges the file, records the elapsed time and applies the late policy from the
problem's ``course.yaml`` ``timed`` section:

    timed: {duration_min: 30, grace_s: 60, late_policy: multiplier, late_multiplier: 0.5}

``late_policy`` is ``multiplier`` (score times ``late_multiplier``), ``reject`` (score 0) or
``accept`` (no penalty, lateness only recorded). A student's extra minutes in the course's
``extensions.yaml`` (:mod:`grader.classroom.extensions`) lengthen their attempt: the deadline is
always the start plus the duration plus their extra time, read when it is shown or applied, so
an extension granted after the start (or after the submission: the scoreboard and the grades
export recompute the late factor) counts too. ``start`` and ``status`` show the student their own
deadline.

Example:
    python -m grader timed start bowyer-watson-timed ada --db exam.sqlite
    python -m grader timed status bowyer-watson-timed ada --db exam.sqlite
    python -m grader timed submit bowyer-watson-timed ada ada.py --db exam.sqlite

    >>> minutes_left(deadline=1800.0, now=600.0)
    20.0
"""

from __future__ import annotations

import hashlib
import time
from dataclasses import dataclass
from pathlib import Path

from ..contest.judge import Judge
from ..problems import load_problem
from . import extensions
from .store import ResultStore
from ..judging.submissions import read_submission_bytes
from ..judging.verdicts import JudgeResult

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
    if not p.timed:
        raise ValueError(f"problem {problem_id!r} has no timed settings (a `timed:` section in its course.yaml); "
                         "timed attempts are only for timed problems")
    t = {"duration_min": 30, "grace_s": 0, "late_policy": "multiplier", "late_multiplier": 0.5, **p.timed}
    if t["late_policy"] not in POLICIES:
        raise ValueError(f"problem {problem_id!r}: late_policy must be one of {POLICIES}, got {t['late_policy']!r}")
    return t


def clock(epoch: float, now: float | None = None) -> str:
    """``epoch`` as local clock time: ``14:05:00 CET (today)``, or with the date on another day."""
    now = time.time() if now is None else now
    t = time.localtime(epoch)
    same_day = time.localtime(now)[:3] == t[:3]
    return time.strftime("%H:%M:%S %Z", t) + " (today)" if same_day else time.strftime("%Y-%m-%d %H:%M:%S %Z", t)


def minutes_left(deadline: float, now: float | None = None) -> float:
    """Minutes until ``deadline`` (negative once it has passed)."""
    return (deadline - (time.time() if now is None else now)) / 60


def deadline_for(problem: str, student: str, started_at: float) -> tuple[float, float]:
    """The attempt's deadline (start + duration + the student's extension) and the extra minutes."""
    t = _settings(problem)
    extra = extensions.extra_seconds(student, problem)
    return started_at + 60 * float(t["duration_min"]) + extra, extra / 60


def late_factor(t: dict, seconds_late: float) -> tuple[float, str]:
    """Score multiplier and note of a submission ``seconds_late`` after its deadline, under the
    timed settings ``t`` (grace period first).

    >>> late_factor({"grace_s": 60, "late_policy": "multiplier", "late_multiplier": 0.5}, 600)
    (0.5, 'late: score x0.5')
    """
    if seconds_late <= float(t.get("grace_s", 0)):
        return 1.0, "on time"
    if t["late_policy"] == "reject":
        return 0.0, "late: rejected"
    if t["late_policy"] == "multiplier":
        return float(t["late_multiplier"]), f"late: score x{t['late_multiplier']}"
    return 1.0, "late (accepted)"


def timed_multiplier(problem: str, student: str, started_at: float, submitted_at: float) -> float:
    """The late factor of a timed submission, from the deadline as it is now (extensions included)."""
    deadline, _ = deadline_for(problem, student, started_at)
    return late_factor(_settings(problem), submitted_at - deadline)[0]


def describe(info: dict, now: float | None = None) -> str:
    """One line for a student: start, deadline as local time, minutes left (or how late)."""
    left = minutes_left(info["deadline"], now)
    when = f"{left:.1f} minutes left" if left >= 0 else f"deadline passed {-left:.1f} minutes ago"
    head = (f"{info['student']}: {info['problem']} already started at {clock(info['started_at'], now)}"
            if info.get("already") else
            f"{info['student']}: {info['problem']} started at {clock(info['started_at'], now)}")
    tail = f"; submitted {clock(info['submitted_at'], now)}" if info.get("submitted_at") else ""
    extra = f" + {info['extra_min']:g} extra (your extension)" if info.get("extra_min") else ""
    return f"{head}; {info['duration_min']} minutes{extra}, deadline {clock(info['deadline'], now)}: {when}{tail}"


def status(problem: str, student: str, store: ResultStore, now: float | None = None) -> dict:
    """The recorded attempt: start, deadline, minutes left, last submission (``ValueError`` if none)."""
    t = _settings(problem)
    row = store.db.execute("SELECT started_at, deadline, submitted_at FROM timed WHERE student=? AND problem=?",
                           (student, problem)).fetchone()
    if row is None:
        raise ValueError(f"{student} has not started a timed attempt at {problem!r} (run `timed start` first)")
    deadline, extra = deadline_for(problem, student, row[0])
    return {"student": student, "problem": problem, "started_at": row[0], "deadline": deadline,
            "submitted_at": row[2], "duration_min": t["duration_min"], "extra_min": extra,
            "minutes_left": round(minutes_left(deadline, now), 2)}


def start(problem: str, student: str, store: ResultStore, now: float | None = None) -> dict:
    """Start the clock (idempotent: a second start keeps the first start time, ``already`` is True)."""
    t = _settings(problem)
    now = time.time() if now is None else now
    row = store.db.execute("SELECT started_at, deadline FROM timed WHERE student=? AND problem=?",
                           (student, problem)).fetchone()
    if row is None:
        deadline, _ = deadline_for(problem, student, now)
        store.db.execute("INSERT INTO timed (student, problem, started_at, deadline) VALUES (?,?,?,?)",
                         (student, problem, now, deadline))
        row, already = (now, deadline), False
    else:
        already = True
    deadline, extra = deadline_for(problem, student, row[0])
    return {"student": student, "problem": problem, "started_at": row[0], "deadline": deadline,
            "duration_min": t["duration_min"], "extra_min": extra, "already": already,
            "minutes_left": round(minutes_left(deadline, now), 2)}


def submit(problem: str, student: str, path: str | Path, store: ResultStore, now: float | None = None,
           judge: Judge | None = None) -> TimedOutcome:
    """Judge a timed submission; the elapsed time is measured from the recorded start."""
    t = _settings(problem)
    now = time.time() if now is None else now
    row = store.db.execute("SELECT started_at, deadline FROM timed WHERE student=? AND problem=?",
                           (student, problem)).fetchone()
    if row is None:
        raise ValueError(f"{student} has not started a timed attempt at {problem!r} (run `timed start` first)")
    started = row[0]
    deadline, _ = deadline_for(problem, student, started)
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
        multiplier, why = late_factor(t, now - deadline)
        note = f"{note}, late by {over:.1f} min: " + {"late: rejected": "rejected",
                                                      "late (accepted)": "(accepted)"}.get(why, why[len("late: "):])
    store.finish(student, problem, sha, result, multiplier, note)
    store.db.execute("UPDATE timed SET submitted_at=?, elapsed_s=?, sha=?, late=? WHERE student=? AND problem=?",
                     (now, elapsed, sha, int(late), student, problem))
    return TimedOutcome(result, elapsed, late, multiplier, result.score * multiplier, note)
