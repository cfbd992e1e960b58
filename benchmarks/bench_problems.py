"""Benchmark of the problem set: is each time limit a wide margin over the intended solution?

Per problem (all of them, or the ids given), on its largest group (the group holding the largest
test input):

* ``solve``: the reference answer's time (``generators/generator.py`` ``solve``, best of 3 after
  one warm-up on the first test, so numba compilation is not counted), the slowest test of the group;
* ``accepted``: each accepted solution (every ``AC`` in ``solutions/<id>/expected.yaml``)
  judged in the sandbox, its CPU time on the slowest test of that group, and its CPU time summed
  over the ``exhaustive`` group;
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

from grader.contest.judge import Judge  # noqa: E402
from grader.contest.kattis import expected_verdicts  # noqa: E402
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


def accepted_times(p: Problem, group: str) -> list[tuple[str, float, float, str]]:
    """Per accepted solution of ``expected.yaml``, judged: (file, slowest CPU time in ``group``,
    total CPU time of the ``exhaustive`` group, overall verdict)."""
    rows = []
    for name in [f for f, v in expected_verdicts(p.id).items() if v == "AC"] or ["-"]:
        if name == "-":
            return [("-", float("nan"), float("nan"), "-")]
        result = Judge(p).judge_path(REPO / "solutions" / p.id / name, follow_links=True)
        times = [t.time_s for t in result.tests if t.group == group]
        small = sum(t.time_s for t in result.tests if t.group == "exhaustive")
        rows.append((name, max(times, default=float("nan")), small, str(result.verdict)))
    return rows


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
        for name, acc, small, verdict in accepted_times(p, group):
            rows.append((p.id, group, solve, name, acc, small, verdict, p.time_limit))
            if not a.markdown:
                print(f"{p.id:22} group {group:10} solve {solve:7.3f} s   {name:24} {verdict:3} {acc:7.3f} s   "
                      f"exhaustive {small:6.3f} s   limit {p.time_limit:g} s ({p.time_limit / acc:.0f}x)", flush=True)
    if a.markdown:
        print("| problem | largest group | reference solve (s) | accepted solution | accepted (s, CPU) "
              "| exhaustive group (s, CPU in all) | time limit (s) |")
        print("| --- | --- | --- | --- | --- | --- | --- |")
        for pid, group, solve, name, acc, small, verdict, limit in rows:
            print(f"| `{pid}` | {group} | {solve:.3f} | `{name}` ({verdict}) | {acc:.3f} | {small:.3f} | {limit:g} |")
    return 0

if __name__ == "__main__":
    sys.exit(main())
