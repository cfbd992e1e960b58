"""Benchmark: the dynamic network (incremental joins and failures) against rebuilding per query.

    python benchmarks/bench_dynamic.py                 # 1e4 nodes, then 1e4 mixed operations
    python benchmarks/bench_dynamic.py --quick         # 2e3 nodes, 2e3 operations
    python benchmarks/bench_dynamic.py --nodes 100000 --ops 10000 --sample 50

Workload (seeded): ``--nodes`` joins at uniform random positions in the unit square, then
``--ops`` operations: 40% joins, 30% failures of a random live node, 30% neighbour
queries of a random live node.  Three ways to answer it:

* ``incremental``: ``reference_impl.DynamicNetwork`` (one Bowyer-Watson insertion per
  join, one star re-triangulation per failure, a walk around the node per query);
* ``rebuild``: a fresh ``reference_impl.Delaunay`` of the live nodes for every query;
* ``scipy``: a fresh ``scipy.spatial.Delaunay`` (Qhull) of the live nodes for every query.

The rebuild baselines are timed on every ``--sample``-th query only (each rebuild is
O(n log n)) and scaled to all queries; their answers on those queries are checked against
the incremental ones.  Prints the times and the ratios rebuild / incremental.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def workload(nodes: int, ops: int, seed: int) -> list:
    rng = np.random.default_rng(seed)
    out, live, joined = [], [], 0
    for x, y in rng.random((nodes, 2)).tolist():
        out.append(["join", x, y])
        live.append(joined)
        joined += 1
    for _ in range(ops):
        r = rng.random()
        if r < 0.4 or len(live) < 4:
            out.append(["join", float(rng.random()), float(rng.random())])
            live.append(joined)
            joined += 1
        elif r < 0.7:
            j = int(rng.integers(len(live)))
            out.append(["fail", live[j]])
            live[j] = live[-1]
            live.pop()
        else:
            out.append(["neighbors", live[int(rng.integers(len(live)))]])
    return out


def rebuild_per_query(ops: list, sample: int, which: str) -> tuple[float, int, dict]:
    """Time (scaled to every query) of answering queries by rebuilding; sampled answers."""
    from reference_impl import Delaunay
    import scipy.spatial
    pos = np.array([op[1:] for op in ops if op[0] == "join"], dtype=float)
    alive = np.zeros(len(pos), dtype=bool)
    joined = 0
    spent, nq, answers = 0.0, 0, {}
    for k, op in enumerate(ops):
        if op[0] == "join":
            alive[joined] = True
            joined += 1
        elif op[0] == "fail":
            alive[op[1]] = False
        elif op[0] == "neighbors":
            nq += 1
            if nq % sample:
                continue
            t = time.perf_counter()
            live = np.flatnonzero(alive)
            where = int(np.searchsorted(live, op[1]))
            pts = pos[live]
            if which == "rebuild":
                nb = Delaunay(pts).vertex_neighbors(where, strict=True)
            else:
                ptr, idx = scipy.spatial.Delaunay(pts).vertex_neighbor_vertices
                nb = np.sort(idx[ptr[where]:ptr[where + 1]])
            answers[k] = live[nb].tolist()
            spent += time.perf_counter() - t
    return spent * sample, nq, answers


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--nodes", type=int, default=10_000)
    ap.add_argument("--ops", type=int, default=10_000)
    ap.add_argument("--sample", type=int, default=20, help="time every k-th query of the baselines")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    if args.quick:
        args.nodes, args.ops, args.sample = 2000, 2000, 10

    from grader.problems import load_problem
    from reference_impl.structures.dynamic import DynamicNetwork
    process = load_problem("dynamic-network").generator.process   # the problem's adapter
    process(workload(50, 50, 1))                       # JIT warm-up (cached after the first run)
    ops = workload(args.nodes, args.ops, args.seed)
    net = DynamicNetwork()
    t = time.perf_counter()
    for _, x, y in ops[:args.nodes]:
        net.join(x, y)
    t_joins = time.perf_counter() - t
    answers = {}
    t = time.perf_counter()
    for k in range(args.nodes, len(ops)):              # the same calls process() makes
        op = ops[k]
        if op[0] == "join":
            net.join(op[1], op[2])
        elif op[0] == "fail":
            net.fail(op[1])
        else:
            answers[k] = net.neighbors(op[1])
    t_mixed = time.perf_counter() - t

    counts = {name: sum(op[0] == name for op in ops[args.nodes:]) for name in ("join", "fail", "neighbors")}
    print(f"workload: {args.nodes:,} initial joins, then {args.ops:,} operations "
          f"({counts['join']:,} joins, {counts['fail']:,} failures, {counts['neighbors']:,} queries)")
    print(f"incremental  initial joins {t_joins:8.3f} s   mixed operations {t_mixed:8.3f} s "
          f"({1e6 * t_mixed / args.ops:.1f} us per operation)")
    for which in ("rebuild", "scipy"):
        spent, nq, sampled = rebuild_per_query(ops, args.sample, which)
        if which == "rebuild":
            wrong = [k for k, a in sampled.items() if answers[k] != a]
            assert not wrong, f"answers differ at operations {wrong[:5]}"
        print(f"{which:<12} {nq:,} queries, each rebuilding: {spent:8.3f} s (timed on every "
              f"{args.sample}th query, scaled)   ratio {which}/incremental {spent / t_mixed:8.1f}x")


if __name__ == "__main__":
    main()
