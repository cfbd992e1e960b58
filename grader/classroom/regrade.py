"""Per-group store keys and regrades: what changed in a problem, whose score moved, and why.

A stored result belongs to one group of one problem version. Each group has a **fingerprint**:
a hash of its tests (every test's name, input and answer), of the checker (its file and the
checker library modules it uses), of the judging limits (entry, time/memory/output limits,
forbidden modules) and its points. A submission is stored under ``<content>-<version>``, where
the version hashes every group's fingerprint, so editing a statement (or anything else that no
test, checker or limit reads) changes no key and judges nobody again. When a group's tests or the
checker change, the version changes; the results of the groups whose fingerprint did not change
are carried over from the previous key (:func:`carry_over`) and only the changed groups are
judged. After the class is judged, :func:`diffs` gives each student's old score, new score and
which groups changed and why; :func:`save_diffs` keeps them in the store (table ``regrades``)
and in a CSV.

Stores written before per-group keys (key ``<content>-<package digest>``, no fingerprints): a
student's old results are adopted as they are when the package's digest is still the one they
were judged under (nothing changed since: nobody is judged again); when the package changed
since, nobody can tell which groups changed, so that student is judged again, and the diff says
so ("graded under the previous store keys"). The old rows stay in the store either way.

Example:
    python -m grader regrade delaunay submissions/ --db results.sqlite --diff regrade.csv
    python -m grader regrade delaunay submissions/ --db results.sqlite --student ada   # judge ada again

    >>> why({"tests": "a", "checker": "c", "limits": "l", "points": 10},
    ...     {"tests": "b", "checker": "c", "limits": "l", "points": 20})
    'tests changed, points 10 -> 20'
"""

from __future__ import annotations

import csv
import hashlib
import json
import time
from pathlib import Path

from ..judging import checker_runtime
from ..judging.text import csv_cell
from ..problems import Problem
from .store import ResultStore

#: what a group's fingerprint holds besides its points, in the order :func:`why` names them
PARTS = ("tests", "checker", "limits")


def _h(*chunks: bytes | str) -> str:
    h = hashlib.sha256()
    for c in chunks:
        b = c.encode() if isinstance(c, str) else c
        h.update(len(b).to_bytes(8, "little"))
        h.update(b)
    return h.hexdigest()[:16]


def checker_hash(problem: Problem) -> str:
    """The checker's file and the checker library modules it imports."""
    files = [problem.checker_path] if problem.checker_path.is_file() else []
    if files:
        files += [checker_runtime.library_file(n) for n in checker_runtime.library_names(files[0].read_text())]
    return _h(*(f.read_bytes() for f in files))


def limits_hash(problem: Problem) -> str:
    """What the judge reads besides the tests and the checker: entry, limits, forbidden modules."""
    return _h(json.dumps([problem.entry, problem.time_limit, sorted(problem.time_limits.items()), problem.memory_mb,
                          problem.output_mb, list(problem.forbidden)]))


def fingerprints(problem: Problem) -> dict[str, dict]:
    """group -> ``{"key", "tests", "checker", "limits", "points"}`` for every group judged here."""
    checker, limits = checker_hash(problem), limits_hash(problem)
    tests: dict[str, list[str]] = {}
    for t in problem.tests():
        tests.setdefault(t.group, []).append(_h(t.name, t.input_text, t.answer_text))
    out = {}
    for g in problem.present_groups:
        fp = {"tests": _h(*tests.get(g.name, [])), "checker": checker, "limits": limits, "points": g.points}
        fp["key"] = _h(fp["tests"], fp["checker"], fp["limits"])
        out[g.name] = fp
    return out


def version(fps: dict[str, dict]) -> str:
    """The problem version a submission key ends with: every group's key and points (8 hex digits)."""
    return _h(json.dumps([[g, fp["key"], fp["points"]] for g, fp in sorted(fps.items())]))[:8]


def why(old: dict | None, new: dict | None) -> str:
    """Why a group's result may differ between two fingerprints ('' when it cannot)."""
    if old is None:
        return "new group"
    if new is None:
        return "group removed"
    reasons = [f"{part} changed" for part in PARTS if old.get(part) != new.get(part)]
    if old.get("points") != new.get("points"):
        reasons.append(f"points {old.get('points')} -> {new.get('points')}")
    return ", ".join(reasons)


def previous(store: ResultStore, student: str, problem: str, content: str, key: str) -> dict | None:
    """The last finished submission of the same content under another key (an older problem version)."""
    rows = [s for s in store.submissions(problem) if s["student"] == student and s["status"] == "done"
            and s["sha"].startswith(content + "-") and s["sha"] != key]
    return rows[-1] if rows else None


def carry_over(store: ResultStore, student: str, problem: Problem, content: str, key: str,
               fps: dict[str, dict]) -> tuple[dict | None, dict[str, str]]:
    """Copy into ``key`` the stored results of every group whose fingerprint is unchanged since the
    same content was last judged; returns that earlier submission (None if never) and the groups
    to judge again with the reason. Results already under ``key`` (an interrupted run) stay."""
    if forced(store, problem.id, student, key):  # judged again from scratch on demand: nothing carried
        return None, {}
    prev = previous(store, student, problem.id, content, key)
    if prev is None:
        return None, {}
    old_fps = json.loads(prev["groups"]) if prev["groups"] else None
    if old_fps is None:  # a store from before per-group keys: the whole package's digest
        if prev["sha"].split("-", 1)[1] == problem.digest()[:8]:
            reuse, changed = set(fps), {}
        else:
            reuse = set()
            changed = {g: "graded under the previous store keys and the package changed since" for g in fps}
    else:
        reuse = {g for g in fps if g in old_fps and old_fps[g]["key"] == fps[g]["key"]}
        changed = {g: why(old_fps.get(g), fps[g]) for g in fps if g not in reuse}
        changed.update({g: "group removed" for g in old_fps if g not in fps})
        changed.update({g: why(old_fps[g], fps[g]) for g in reuse if old_fps[g]["points"] != fps[g]["points"]})
    cols = "test, grp, verdict, time_s, memory_mb, message, input_preview, judged_at, hidden_message"
    for g in sorted(reuse):  # copies keep when they were judged; rows already under key stay
        store.db.execute(f"INSERT OR IGNORE INTO results (student, problem, sha, {cols}) SELECT student, problem, ?, "
                         f"{cols} FROM results WHERE student=? AND problem=? AND sha=? AND grp=?",
                         (key, student, problem.id, prev["sha"], g))
    return prev, changed


def final(row: dict | None) -> float:
    """A stored submission's score after its multiplier (0 for none)."""
    if row is None or row.get("score") is None:
        return 0.0
    mult = 1.0 if row.get("multiplier") is None else float(row["multiplier"])
    return round(row["score"] * mult, 2)


def start(store: ResultStore, problem: str, student: str, old: dict | None, new_sha: str,
          changes: dict[str, str]) -> None:
    """Note a regrade before judging (kept if already noted: an interrupted regrade resumes)."""
    if pending(store, problem, student, new_sha):
        return
    store.db.execute("INSERT OR REPLACE INTO regrades (problem, student, old_sha, new_sha, old_score, old_verdict, "
                     "changes, started_at) VALUES (?,?,?,?,?,?,?,?)",
                     (problem, student, old["sha"] if old else "", new_sha, final(old), old["verdict"] if old else "",
                      json.dumps(changes), time.time()))


def pending(store: ResultStore, problem: str, student: str, sha: str) -> bool:
    """Is a regrade of this submission noted and not finished?"""
    return store.db.execute("SELECT 1 FROM regrades WHERE problem=? AND student=? AND new_sha=? AND done=0",
                            (problem, student, sha)).fetchone() is not None


def forced(store: ResultStore, problem: str, student: str, sha: str) -> bool:
    """Is an on-demand regrade of this very submission unfinished (:func:`force`)?"""
    return store.db.execute("SELECT 1 FROM regrades WHERE problem=? AND student=? AND new_sha=? AND old_sha=? "
                            "AND done=0", (problem, student, sha, sha)).fetchone() is not None


def force(store: ResultStore, problem: str, student: str, sha: str, reason: str) -> None:
    """Judge a finished submission again from scratch (on demand). Resumable: the old score is
    noted first, and a second call while that regrade is unfinished changes nothing."""
    if pending(store, problem, student, sha):
        return
    row = next((s for s in store.submissions(problem) if s["student"] == student and s["sha"] == sha), None)
    if row is None or row["status"] != "done":
        return
    with store.db:  # one transaction: the note, the reset
        store.db.execute("BEGIN")
        groups = json.loads(row["groups"]) if row["groups"] else {}
        start(store, problem, student, row, sha, {g: reason for g in groups} or {"*": reason})
        store.db.execute("DELETE FROM results WHERE student=? AND problem=? AND sha=?", (student, problem, sha))
        store.db.execute("UPDATE submissions SET status='running' WHERE student=? AND problem=? AND sha=?",
                         (student, problem, sha))


def finish(store: ResultStore, problem: str) -> list[dict]:
    """Close every noted regrade of ``problem`` whose submission is done; returns their diffs
    (student, old_score, new_score, old_verdict, new_verdict, changes: group -> why)."""
    rows = store.db.execute("SELECT student, new_sha, old_score, old_verdict, changes FROM regrades "
                            "WHERE problem=? AND done=0", (problem,)).fetchall()
    subs = {(s["student"], s["sha"]): s for s in store.submissions(problem)}
    out = []
    for student, sha, old_score, old_verdict, changes in rows:
        new = subs.get((student, sha))
        if new is None or new["status"] != "done":
            continue
        store.db.execute("UPDATE regrades SET new_score=?, new_verdict=?, done=1 WHERE problem=? AND student=? "
                         "AND new_sha=?", (final(new), new["verdict"], problem, student, sha))
        out.append({"student": student, "old_score": old_score, "new_score": final(new), "old_verdict": old_verdict,
                    "new_verdict": new["verdict"], "changes": json.loads(changes)})
    return sorted(out, key=lambda d: d["student"])


def diff_line(d: dict) -> str:
    """One student's diff for a terminal.

    >>> diff_line({"student": "ada", "old_score": 100, "new_score": 60, "old_verdict": "AC", "new_verdict": "WA",
    ...            "changes": {"large": "tests changed"}})
    'ada: 100 -> 60 (AC -> WA); large: tests changed'
    """
    moved = f"{d['old_score']:g} -> {d['new_score']:g}" if d["old_score"] != d["new_score"] else \
        f"{d['new_score']:g} (unchanged)"
    verdicts = f" ({d['old_verdict']} -> {d['new_verdict']})" if d["old_verdict"] != d["new_verdict"] else ""
    groups = "; ".join(f"{g}: {w}" for g, w in sorted(d["changes"].items()) if w)
    return f"{d['student']}: {moved}{verdicts}" + (f"; {groups}" if groups else "")


def write_diff_csv(diffs: list[dict], problem: str, path: str | Path) -> None:
    """The diff as CSV: student, problem, old_score, new_score, delta, old_verdict, new_verdict, changes."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["student", "problem", "old_score", "new_score", "delta", "old_verdict", "new_verdict", "changes"])
        for d in diffs:
            changes = "; ".join(f"{g}: {w_}" for g, w_ in sorted(d["changes"].items()) if w_)
            w.writerow([csv_cell(v) for v in (d["student"], problem, d["old_score"], d["new_score"],
                                              round(d["new_score"] - d["old_score"], 2), d["old_verdict"],
                                              d["new_verdict"], changes)])


def history(store: ResultStore, problem: str | None = None) -> list[dict]:
    """Every finished regrade in the store, oldest first."""
    q = ("SELECT problem, student, old_score, new_score, old_verdict, new_verdict, changes, started_at FROM regrades "
         "WHERE done=1" + (" AND problem=?" if problem else "") + " ORDER BY started_at, rowid")
    keys = ("problem", "student", "old_score", "new_score", "old_verdict", "new_verdict", "changes", "started_at")
    rows = [dict(zip(keys, r)) for r in store.db.execute(q, (problem,) if problem else ())]
    for r in rows:
        r["changes"] = json.loads(r["changes"])
    return rows
