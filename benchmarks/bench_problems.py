"""Benchmark of the problem set: is each time limit a wide margin over the intended solution?

Per problem (all of them, or the ids given), on its largest group (the group holding the largest
test input):

* ``solve``: the reference answer's time (``generators/generator.py`` ``solve``, best of 3 after
  one warm-up on the first test, so numba compilation is not counted), the slowest test of the group;
* ``accepted``: the accepted solution (the first ``AC`` in ``solutions/<id>/expected.yaml``)
  judged in the sandbox, its CPU time on the slowest test of that group;
* ``limit``: the time limit per test (``problem.yaml``) and limit / accepted.

Run: .venv/bin/python benchmarks/bench_problems.py [delaunay emst ...] [--markdown]
Prints numbers only; nothing is asserted (tests assert behaviour, not timings).
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from grader.judge import Judge  # noqa: E402
from grader.kattis import expected_verdicts  # noqa: E402
from grader.problems import Problem, list_problems, load_problem  # noqa: E402


def largest_group(p: Problem) -> str:
    """The name of the group holding the longest test input."""
    return max(p.tests(), key=lambda t: len(t.input_text)).group


def solve_time(p: Problem, group: str, repeats: int = 3) -> float:
    """Slowest test of ``group``: best-of-``repeats`` wall time of the reference ``solve``."""
    tests = [t for t in p.tests() if t.group == group]
    p.generator.solve(*p.checker.read_input(p.tests()[0].input_text))  # warm-up (JIT, imports)
    worst = 0.0
    for t in tests:
        args = p.checker.read_input(t.input_text)
        best = float("inf")
        for _ in range(repeats):
            t0 = time.perf_counter()
            p.generator.solve(*args)
            best = min(best, time.perf_counter() - t0)
        worst = max(worst, best)
    return worst


def accepted_time(p: Problem, group: str) -> tuple[str, float, str]:
    """(file, slowest CPU time in ``group``, overall verdict) of the accepted solution, judged."""
    name = next((f for f, v in expected_verdicts(p.id).items() if v == "AC"), None)
    if name is None:
        return "-", float("nan"), "-"
    result = Judge(p).judge_path(REPO / "solutions" / p.id / name)
    times = [t.time_s for t in result.tests if t.group == group]
    return name, max(times, default=float("nan")), str(result.verdict)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("ids", nargs="*", help="problem ids (default: all)")
    ap.add_argument("--markdown", action="store_true", help="print a Markdown table")
    a = ap.parse_args(argv)
    problems = [load_problem(i) for i in a.ids] if a.ids else list_problems()
    rows = []
    for p in problems:
        group = largest_group(p)
        solve = solve_time(p, group)
        name, acc, verdict = accepted_time(p, group)
        rows.append((p.id, group, solve, name, acc, verdict, p.time_limit))
        if not a.markdown:
            print(f"{p.id:22} group {group:10} solve {solve:7.3f} s   {name:24} {verdict:3} {acc:7.3f} s   "
                  f"limit {p.time_limit:g} s ({p.time_limit / acc:.0f}x)", flush=True)
    if a.markdown:
        print("| problem | largest group | reference solve (s) | accepted solution | accepted (s, CPU) | time limit (s) |")
        print("| --- | --- | --- | --- | --- | --- |")
        for pid, group, solve, name, acc, verdict, limit in rows:
            print(f"| `{pid}` | {group} | {solve:.3f} | `{name}` ({verdict}) | {acc:.3f} | {limit:g} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
