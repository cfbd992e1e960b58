"""ICPC-style scoreboard from the results store: problems solved, then penalty time.

Penalty for a solved problem = minutes from the start to the first AC submission plus 20 minutes
for each rejected submission before it. The start is ``--start`` (epoch seconds or ISO time), else
the student's timed start for that problem, else the first submission in the store.

A timed problem's late policy applies: a submission rejected for lateness (multiplier 0) does
not solve the problem, and the ``points`` column sums each problem's best score after the late
multiplier (an AC worth 100 submitted late under ``late_multiplier: 0.5`` counts 50, marked
``late`` in its cell). That multiplier is recomputed from the deadline as it is now: a student's
extension (:mod:`grader.classroom.extensions`) granted after the submission counts.

Example:
    >>> rows = compute(ResultStore(":memory:"))
    >>> rows
    []
"""

from __future__ import annotations

import datetime as dt

from .store import ResultStore

PENALTY_MIN = 20


def parse_start(text: str | None) -> float | None:
    """Epoch seconds or an ISO 8601 time; None stays None."""
    if text is None:
        return None
    try:
        return float(text)
    except ValueError:
        try:
            return dt.datetime.fromisoformat(text).timestamp()
        except ValueError:
            raise ValueError(f"--start must be epoch seconds or an ISO time, got {text!r}") from None


def final_multiplier(sub: dict, timed_starts: dict[tuple[str, str], float]) -> float:
    """A stored submission's late factor: for a timed attempt, recomputed from its deadline as it is
    now (extensions included); otherwise the stored one."""
    from .timed import timed_multiplier

    key = (sub["student"], sub["problem"])
    if key in timed_starts and sub.get("submitted_at") is not None:
        try:
            return timed_multiplier(sub["problem"], sub["student"], timed_starts[key], sub["submitted_at"])
        except ValueError:  # the problem is gone or no longer timed: what was stored
            pass
    return 1.0 if sub["multiplier"] is None else float(sub["multiplier"])


def compute(store: ResultStore, start: float | None = None, problems: list[str] | None = None) -> list[dict]:
    subs = [s for s in store.submissions() if s["status"] == "done" and (not problems or s["problem"] in problems)]
    # one try per content: a file judged again after the problem's tests changed (key content-digest)
    # keeps its place (first seen) with its latest result
    latest = {(s["student"], s["problem"], s["sha"].split("-")[0]): s for s in subs}
    subs = [s for s in subs if latest[(s["student"], s["problem"], s["sha"].split("-")[0])] is s]
    if not subs:
        return []
    first = min(s["submitted_at"] for s in subs)
    timed = {(r[0], r[1]): r[2] for r in store.db.execute("SELECT student, problem, started_at FROM timed")}
    board: dict[str, dict] = {}
    for s in subs:  # in submission order
        row = board.setdefault(s["student"], {"student": s["student"], "solved": 0, "penalty": 0, "points": 0.0,
                                              "problems": {}})
        cell = row["problems"].setdefault(s["problem"], {"tries": 0, "solved_at_min": None, "points": 0.0,
                                                         "late": False})
        mult = final_multiplier(s, timed)
        final = round((s["score"] or 0) * mult, 2)
        if final > cell["points"]:
            row["points"] = round(row["points"] - cell["points"] + final, 2)
            cell["points"], cell["late"] = final, mult < 1.0
        if cell["solved_at_min"] is not None:
            continue
        cell["tries"] += 1
        if s["verdict"] == "AC" and mult > 0:
            t0 = start if start is not None else timed.get((s["student"], s["problem"]), first)
            minutes = int(max(0.0, s["submitted_at"] - t0) // 60)
            cell["solved_at_min"] = minutes
            row["solved"] += 1
            row["penalty"] += minutes + PENALTY_MIN * (cell["tries"] - 1)
    rows = sorted(board.values(), key=lambda r: (-r["solved"], r["penalty"], r["student"]))
    for rank, r in enumerate(rows, 1):
        r["rank"] = rank
    return rows


def format_board(rows: list[dict]) -> str:
    problems = sorted({p for r in rows for p in r["problems"]})
    head = ["rank", "student", "solved", "penalty", "points", *problems]
    table = [head]
    for r in rows:
        cells = []
        for p in problems:
            c = r["problems"].get(p)
            if c is None:
                cells.append("")
            elif c["solved_at_min"] is not None:
                cells.append(f"+{c['tries'] - 1 or ''} {c['solved_at_min']}'".replace("+ ", "+")
                             + (f" late {c['points']:g}" if c["late"] else ""))
            else:
                cells.append(f"-{c['tries']}" + (f" late {c['points']:g}" if c["late"] else ""))
        table.append([str(r["rank"]), r["student"], str(r["solved"]), str(r["penalty"]), f"{r['points']:g}", *cells])
    widths = [max(len(row[i]) for row in table) for i in range(len(head))]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(row, widths)) for row in table)
