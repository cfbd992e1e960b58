"""Benchmark: Voronoi cells, convex hull, largest empty circle and clearance against scipy.

    python benchmarks/bench_voronoi.py                 # 1e4 and 1e5 points (about a minute)
    python benchmarks/bench_voronoi.py --sizes 100000 --repeat 5

For uniform random points in the unit square, prints the best-of-k wall time of
each function of ours next to its natural anchor, run in the same process and
interleaved (ours, anchor, ours, ...) so that machine noise hits both alike:

* ``voronoi(p, bbox)``             vs ``scipy.spatial.Voronoi(p)`` (cells not clipped, rays
  not closed: the anchor does less work than we do)
* ``convex_hull(p)``               vs ``scipy.spatial.ConvexHull(p).vertices``
* ``largest_empty_circle(p)``      vs ``scipy.spatial.Voronoi(p)`` (the diagram it needs)
* ``max_clearance(p, s, g)``       vs ``scipy.spatial.Delaunay(p)`` (the triangulation it needs)

and the ratio ours/anchor (below 1.0 means we are faster).  The numba functions
are compiled (or loaded from the cache) by a warm-up call before timing.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from scipy.spatial import ConvexHull, Delaunay as ScipyDelaunay, Voronoi  # noqa: E402

from reference_impl.structures.clearance import max_clearance  # noqa: E402
from reference_impl.structures.empty_circle import largest_empty_circle  # noqa: E402
from reference_impl.structures.hull import convex_hull  # noqa: E402
from reference_impl.structures.voronoi import voronoi  # noqa: E402

BOX = (-0.1, -0.1, 1.1, 1.1)


def cases(points):
    s, g = np.array([0.5, 0.5]), np.array([0.05, 0.93])
    return [
        ("voronoi", lambda: len(voronoi(points, BOX)), "scipy Voronoi", lambda: len(Voronoi(points).vertices)),
        ("convex_hull", lambda: len(convex_hull(points)), "scipy ConvexHull",
         lambda: len(ConvexHull(points).vertices)),
        ("largest_empty_circle", lambda: largest_empty_circle(points)[2], "scipy Voronoi",
         lambda: len(Voronoi(points).vertices)),
        ("max_clearance", lambda: max_clearance(points, s, g), "scipy Delaunay",
         lambda: len(ScipyDelaunay(points).simplices)),
    ]


def best_of(pairs, repeat):
    best = [[float("inf"), float("inf")] for _ in pairs]
    for _ in range(repeat):
        for k, (_, ours, _, anchor) in enumerate(pairs):
            for j, fn in enumerate((ours, anchor)):
                t = time.perf_counter()
                fn()
                best[k][j] = min(best[k][j], time.perf_counter() - t)
    return best


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[10_000, 100_000])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args(argv)
    warm = np.random.default_rng(1).random((50, 2))
    for _, ours, _, _ in cases(warm):
        ours()
    print(f"{'n':>8}  {'function':<22}{'ours s':>9}  {'anchor':<18}{'anchor s':>9}  {'ours/anchor':>11}")
    for n in args.sizes:
        points = np.random.default_rng(n).random((n, 2))
        pairs = cases(points)
        for (name, _, anchor_name, _), (t_ours, t_anchor) in zip(pairs, best_of(pairs, args.repeat)):
            print(f"{n:>8}  {name:<22}{t_ours:>9.4f}  {anchor_name:<18}{t_anchor:>9.4f}  {t_ours / t_anchor:>11.2f}")


if __name__ == "__main__":
    main()
