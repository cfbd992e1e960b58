"""Results store (SQLite): one row per (student, problem, submission, test), committed as it comes.

An interrupted batch (even ``kill -9``) loses only what it had not committed, and a rerun reads
what is stored and judges only the rest: with :meth:`ResultStore.add_test` (a commit a row) the
test that was running; class grading and the course's autograde write a submission's rows through
:meth:`ResultStore.deferred_tests` (one transaction for the tests finished within a second of each
other, and one at the end of the submission), so there a ``kill -9`` loses at most the running
submission's tests finished since its last commit, never a finished submission (a commit a row
cost 0.02 ms of CPU and 12 system calls, a tenth of a small test's whole round trip). WAL mode and
a busy timeout let parallel workers write. Commits are not flushed to the disk one by one
(``synchronous=NORMAL``: a committed row survives the grader's death, not a power cut; there the
last rows are judged again by the rerun): an ``fsync`` a test cost 0.25 ms of CPU and 8 ms of
wall time here, more than a small test itself.

Example:
    >>> s = ResultStore(":memory:")
    >>> s.begin("ada", "delaunay", "ada/sol.py", "abc", 0.0)
    >>> s.prior("ada", "delaunay", "abc")
    {}
    >>> with s.deferred_tests("ada", "delaunay", "abc") as add:
    ...     add(TestResult("g/1", "g", Verdict.AC))
    >>> list(s.prior("ada", "delaunay", "abc"))
    ['g/1']
"""

from __future__ import annotations

import contextlib
import csv
import json
import sqlite3
import time
from pathlib import Path
from typing import Callable, Iterator

from ..judging.text import clean, csv_cell
from ..judging.verdicts import JudgeResult, TestResult, Verdict

SCHEMA = """
CREATE TABLE IF NOT EXISTS submissions (
    student TEXT, problem TEXT, sha TEXT, file TEXT, submitted_at REAL, status TEXT,
    verdict TEXT, score INTEGER, max_score INTEGER, multiplier REAL DEFAULT 1.0, note TEXT DEFAULT '',
    groups TEXT DEFAULT '', PRIMARY KEY (student, problem, sha));
CREATE TABLE IF NOT EXISTS results (
    student TEXT, problem TEXT, sha TEXT, test TEXT, grp TEXT, verdict TEXT, time_s REAL,
    memory_mb REAL, message TEXT, input_preview TEXT, judged_at REAL, hidden_message TEXT DEFAULT '',
    PRIMARY KEY (student, problem, sha, test));
CREATE TABLE IF NOT EXISTS seen (
    student TEXT, problem TEXT, content TEXT, first_seen REAL, PRIMARY KEY (student, problem, content));
CREATE TABLE IF NOT EXISTS timed (
    student TEXT, problem TEXT, started_at REAL, deadline REAL, submitted_at REAL, elapsed_s REAL,
    sha TEXT, late INTEGER, PRIMARY KEY (student, problem));
CREATE TABLE IF NOT EXISTS regrades (
    problem TEXT, student TEXT, old_sha TEXT, new_sha TEXT, old_score REAL, new_score REAL, old_verdict TEXT,
    new_verdict TEXT, changes TEXT, started_at REAL, done INTEGER DEFAULT 0, PRIMARY KEY (problem, student, new_sha));
CREATE TABLE IF NOT EXISTS counterexamples (
    student TEXT, problem TEXT, sha TEXT, groups TEXT, search TEXT, seconds REAL, searched_at REAL,
    PRIMARY KEY (student, problem, sha));
"""


class ResultStore:
    """Thin wrapper over the SQLite file; each method commits."""

    def __init__(self, path: str | Path):
        self.path = str(path)
        self.db = sqlite3.connect(self.path, timeout=60, isolation_level=None)
        if self.path != ":memory:":
            self.db.execute("PRAGMA journal_mode=WAL")
            self.db.execute("PRAGMA synchronous=NORMAL")  # WAL: safe from kill -9, no fsync per commit
        self.db.execute("PRAGMA busy_timeout=60000")
        self.db.executescript(SCHEMA)
        self._migrate()

    def _migrate(self) -> None:
        """Columns added since a store was created (an older store keeps its rows)."""
        have = {r[1] for r in self.db.execute("PRAGMA table_info(results)")}
        if "hidden_message" not in have:
            self.db.execute("ALTER TABLE results ADD COLUMN hidden_message TEXT DEFAULT ''")
        if "groups" not in {r[1] for r in self.db.execute("PRAGMA table_info(submissions)")}:
            # stores made before per-group keys: their rows keep the whole-package digest key
            self.db.execute("ALTER TABLE submissions ADD COLUMN groups TEXT DEFAULT ''")

    def close(self) -> None:
        self.db.close()

    def begin(self, student: str, problem: str, file: str, sha: str, submitted_at: float, groups: str = "") -> None:
        """Record a submission about to be judged (``groups``: the JSON of the per-group keys it is
        judged under, :func:`grader.classroom.regrade.fingerprints`)."""
        self.db.execute("INSERT OR IGNORE INTO submissions (student, problem, sha, file, submitted_at, status, groups) "
                        "VALUES (?, ?, ?, ?, ?, 'running', ?)",
                        (student, problem, sha, clean(file, 1000), submitted_at, groups))

    def first_seen(self, student: str, problem: str, content: str, now: float | None = None) -> float:
        """When the grader first saw this content (a file's SHA-256) from this student: the time of
        a submission, on the grader's clock (file modification times are the student's to set)."""
        self.db.execute("INSERT OR IGNORE INTO seen VALUES (?, ?, ?, ?)",
                        (student, problem, content, time.time() if now is None else now))
        return self.db.execute("SELECT first_seen FROM seen WHERE student=? AND problem=? AND content=?",
                               (student, problem, content)).fetchone()[0]

    _ADD_TEST = ("INSERT OR REPLACE INTO results (student, problem, sha, test, grp, verdict, time_s, memory_mb, "
                 "message, input_preview, judged_at, hidden_message) VALUES (?,?,?,?,?,?,?,?,?,?,?,?)")

    @staticmethod
    def _test_row(student: str, problem: str, sha: str, r: TestResult) -> tuple:
        return (student, problem, sha, r.name, r.group, str(r.verdict), r.time_s, r.memory_mb,
                r.message[:4000], r.input_preview[:4000], time.time(), r.hidden_message[:1000])

    def add_test(self, student: str, problem: str, sha: str, r: TestResult) -> None:
        """Store one test's result (committed at once)."""
        self.db.execute(self._ADD_TEST, self._test_row(student, problem, sha, r))

    @contextlib.contextmanager
    def deferred_tests(self, student: str, problem: str, sha: str,
                       every_s: float = 1.0) -> Iterator[Callable[[TestResult], None]]:
        """A callable storing one test's result of this submission (``on_test``), its rows
        committed together: when a test finishes ``every_s`` seconds or more after the first row
        not yet written, and when the block ends (by an exception too: those tests were
        finished). A ``kill -9`` loses at most this submission's tests finished since its last
        commit (a rerun judges them again); each commit is one short transaction, so parallel
        workers wait for none."""
        if every_s < 0:
            raise ValueError(f"every_s must be >= 0 seconds, not {every_s!r}")
        rows: list[tuple] = []
        since = 0.0

        def flush() -> None:
            if rows:
                self.db.execute("BEGIN IMMEDIATE")
                try:
                    self.db.executemany(self._ADD_TEST, rows)
                except BaseException:
                    self.db.execute("ROLLBACK")
                    raise
                self.db.execute("COMMIT")
                rows.clear()

        def add(r: TestResult) -> None:
            nonlocal since
            now = time.monotonic()
            if not rows:
                since = now
            rows.append(self._test_row(student, problem, sha, r))
            if now - since >= every_s:
                flush()

        try:
            yield add
        finally:
            flush()

    def prior(self, student: str, problem: str, sha: str) -> dict[str, TestResult]:
        rows = self.db.execute("SELECT test, grp, verdict, time_s, memory_mb, message, input_preview, hidden_message "
                               "FROM results WHERE student=? AND problem=? AND sha=?", (student, problem, sha)).fetchall()
        return {r[0]: TestResult(r[0], r[1], Verdict(r[2]), r[3], r[4], r[5], r[6], r[7] or "") for r in rows}

    def finish(self, student: str, problem: str, sha: str, result: JudgeResult, multiplier: float = 1.0,
               note: str = "") -> None:
        self.db.execute("UPDATE submissions SET status='done', verdict=?, score=?, max_score=?, multiplier=?, note=? "
                        "WHERE student=? AND problem=? AND sha=?",
                        (result.verdict, result.score, result.max_score, multiplier, note, student, problem, sha))

    def add_counterexamples(self, student: str, problem: str, sha: str, result: JudgeResult) -> None:
        """Keep the counterexample search of a judged submission (``result.counterexamples`` and
        ``result.extra["counterexample_search"]``, :mod:`grader.contest.counterexample`)."""
        search = result.extra.get("counterexample_search") or {}
        self.db.execute("INSERT OR REPLACE INTO counterexamples VALUES (?,?,?,?,?,?,?)",
                        (student, problem, sha, json.dumps(result.counterexamples), json.dumps(search),
                         float(search.get("seconds", 0.0)), time.time()))

    def counterexamples(self, student: str, problem: str, sha: str) -> tuple[dict, dict] | None:
        """The stored search of a submission: (group -> counterexample or None, the search's
        summary), or None when none was stored."""
        row = self.db.execute("SELECT groups, search FROM counterexamples WHERE student=? AND problem=? AND sha=?",
                              (student, problem, sha)).fetchone()
        return None if row is None else (json.loads(row[0]), json.loads(row[1]))

    def counterexample_seconds(self, problem: str) -> tuple[int, float]:
        """How many searches are stored for ``problem`` and their total seconds."""
        n, total = self.db.execute("SELECT COUNT(*), COALESCE(SUM(seconds), 0) FROM counterexamples WHERE problem=?",
                                   (problem,)).fetchone()
        return int(n), float(total)

    def is_done(self, student: str, problem: str, sha: str) -> bool:
        row = self.db.execute("SELECT status FROM submissions WHERE student=? AND problem=? AND sha=?",
                              (student, problem, sha)).fetchone()
        return bool(row) and row[0] == "done"

    def submissions(self, problem: str | None = None) -> list[dict]:
        q = ("SELECT student, problem, sha, file, submitted_at, status, verdict, score, max_score, multiplier, note, "
             "groups FROM submissions")
        rows = self.db.execute(q + (" WHERE problem=?" if problem else "") + " ORDER BY submitted_at, rowid",
                               (problem,) if problem else ()).fetchall()
        keys = ["student", "problem", "sha", "file", "submitted_at", "status", "verdict", "score", "max_score",
                "multiplier", "note", "groups"]
        return [dict(zip(keys, r)) for r in rows]

    def latest(self, problem: str) -> dict[str, dict]:
        """The last finished submission of every student for ``problem``."""
        out: dict[str, dict] = {}
        for s in self.submissions(problem):
            if s["status"] == "done":
                out[s["student"]] = s
        return out

    def export_csv(self, problem: str, path: str | Path) -> int:
        """One row per student (LMS import): student, problem, score, max_score, verdict, file.
        Text cells are formula-escaped (a folder named ``=HYPERLINK(...)`` stays text)."""
        latest = self.latest(problem)
        with open(path, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["student", "problem", "score", "max_score", "verdict", "file", "note"])
            for student in sorted(latest):
                s = latest[student]
                score = round(s["score"] * (s["multiplier"] if s["multiplier"] is not None else 1.0), 2)
                w.writerow([csv_cell(v) for v in (student, problem, score, s["max_score"], s["verdict"], s["file"],
                                                  s["note"])])
        return len(latest)
