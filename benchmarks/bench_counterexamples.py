"""Counterexamples for every wrong solution: how many are found, how small, how fast (issue 43).

For every wrong solution under ``solutions/`` (``expected.yaml`` / ``expected_cpp.yaml`` verdict
WA, RE or PE; the C++ ones too) and every file of the counterexample zoo
(``tests/grader/fixtures/cx_zoo/<problem>/``), runs
``grader.contest.counterexample.search(problem, file, seconds)`` and prints per problem: files,
found, found with at most 10 points (polygon vertices for navmesh, operations for
dynamic-network), found with an exact certificate (``certify``: a kind other than ``differs``),
median and max seconds of a search; then the totals and the share found small within the
budget (the aim: at least 90%). A last line searches the accepted and slow-only (TLE) solutions:
none should be found. A benchmark prints; tests never assert its timings.

Run:
    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_counterexamples.py [--problems emst closest-pair]
        [--seconds 10] [--no-controls] [--json out.json]

Example line:
    emst                   8 files   8 found   8 <= 10   7 certified   median   1.9 s   max   4.2 s
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Callable

ROOT = Path(__file__).resolve().parent.parent
ZOO = ROOT / "tests" / "grader" / "fixtures" / "cx_zoo"
WRONG = {"WA", "RE", "PE"}
CONTROL = {"AC", "TLE"}
SMALL = 10


@dataclass
class Row:
    """One searched file: its problem, path, group (``wrong``, ``zoo`` or ``control``) and outcome."""

    problem: str
    path: str
    group: str
    found: bool = False
    size: int | None = None
    seconds: float = 0.0
    kind: str | None = None
    verdict: str | None = None


def subjects(problems: list[str]) -> list[Row]:
    """The files to search: wrong solutions, zoo files and controls (accepted or only slow)."""
    from grader.contest.kattis import expected_cpp, expected_verdicts

    rows = []
    for p in problems:
        folder = ROOT / "solutions" / p
        listed = dict(expected_verdicts(p))
        listed.update({f: v for f, (v, _) in expected_cpp(p).items()})
        for name, verdict in sorted(listed.items()):
            if (folder / name).is_file() and verdict in WRONG | CONTROL:
                rows.append(Row(p, str(folder / name), "wrong" if verdict in WRONG else "control"))
        rows += [Row(p, str(f), "zoo") for f in sorted((ZOO / p).glob("*.py"))]
    return rows


def run(rows: list[Row], seconds: float, search: Callable, certify: Callable | None,
        out=sys.stdout) -> list[Row]:
    """Search each row's file (``search(problem, path, seconds=...)``, the counterexample API)."""
    for r in rows:
        t = time.monotonic()
        try:
            cx = search(r.problem, r.path, seconds=seconds)
        except Exception as e:  # a benchmark reports, it does not stop
            cx, r.kind = None, f"error: {type(e).__name__}: {e}"
        r.seconds = round(time.monotonic() - t, 2)
        if cx is not None:
            r.found, r.size, r.verdict = True, cx.size, cx.verdict
            cert = cx.certificate
            if cert is None and certify is not None:
                try:
                    cert = certify(r.problem, cx.input, cx.answer)
                except Exception as e:  # a benchmark reports, it does not stop
                    cert = {"kind": f"error: {type(e).__name__}"}
            r.kind = cert["kind"] if cert else None
        print(f"  {r.problem:22s} {Path(r.path).name:32s} {r.group:7s} "
              f"{'found ' + str(r.size) + ' ' + str(r.verdict) + ' ' + str(r.kind) if r.found else (r.kind or 'none')}"
              f"  {r.seconds:.1f} s", file=out, flush=True)
    return rows


def summarize(rows: list[Row]) -> dict:
    """Per problem and in total: files, found, found small, certified, median/max seconds; controls."""
    table: dict = {}
    for r in rows:
        if r.group == "control":
            continue
        s = table.setdefault(r.problem, {"files": 0, "found": 0, "small": 0, "certified": 0, "seconds": []})
        s["files"] += 1
        s["found"] += r.found
        s["small"] += r.found and r.size is not None and r.size <= SMALL
        s["certified"] += r.found and r.kind not in (None, "differs") and not str(r.kind).startswith("error")
        s["seconds"].append(r.seconds)
    total = {k: sum(s[k] for s in table.values()) for k in ("files", "found", "small", "certified")}
    total["seconds"] = [x for s in table.values() for x in s["seconds"]]
    controls = [r for r in rows if r.group == "control"]
    return {"problems": table, "total": total,
            "controls": {"files": len(controls), "found": sum(r.found for r in controls),
                         "which": [r.path for r in controls if r.found]}}


def _line(name: str, s: dict) -> str:
    secs = s["seconds"] or [0.0]
    return (f"{name:22s} {s['files']:3d} files {s['found']:3d} found {s['small']:3d} <= {SMALL} "
            f"{s['certified']:3d} certified   median {statistics.median(secs):5.1f} s   max {max(secs):5.1f} s")


def report(summary: dict) -> str:
    """The table as text."""
    lines = [_line(p, s) for p, s in sorted(summary["problems"].items())]
    t = summary["total"]
    lines.append(_line("total", t))
    share = t["small"] / t["files"] if t["files"] else 0.0
    lines.append(f"found with <= {SMALL} points within the budget: {t['small']}/{t['files']} = {share:.0%}")
    c = summary["controls"]
    lines.append(f"accepted and slow-only solutions: {c['files']} searched, {c['found']} found (expected 0)"
                 + (f": {', '.join(c['which'])}" if c["which"] else ""))
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--problems", nargs="*", help="problem ids (default: all)")
    ap.add_argument("--seconds", type=float, default=10.0, help="the search budget per file (default 10)")
    ap.add_argument("--no-controls", action="store_true", help="skip the accepted and slow-only solutions")
    ap.add_argument("--json", help="write the rows and the summary to this file")
    a = ap.parse_args(argv)
    from grader.contest.certificate import certify
    from grader.contest.counterexample import search
    from grader.problems import list_problems

    known = [p.id for p in list_problems()]
    problems = a.problems or known
    unknown = [p for p in problems if p not in known]
    if unknown:
        ap.error(f"unknown problem(s): {', '.join(unknown)}")
    rows = [r for r in subjects(problems) if not (a.no_controls and r.group == "control")]
    t = time.monotonic()
    run(rows, a.seconds, search, certify)
    summary = summarize(rows)
    print(report(summary))
    print(f"wall time {time.monotonic() - t:.0f} s, budget {a.seconds:g} s a file")
    if a.json:
        Path(a.json).write_text(json.dumps({"rows": [asdict(r) for r in rows], "summary": summary}, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
