"""Benchmark: constrained Delaunay and navigation-mesh shortest paths, against anchors in the same process.

    python benchmarks/bench_navmesh.py             # CDT at 1e3 and 1e4 segments, then path queries
    python benchmarks/bench_navmesh.py --sizes 1000 10000 100000 --repeat 5

Part 1, the CDT (best-of-k wall time, runs interleaved so noise hits both alike):

* ``polygon``: a random star-shaped polygon with k vertices (most of its edges
  are not Delaunay edges, so they really are inserted):
  ``polygon_triangulation(boundary)`` against
  ``triangle.triangulate({'vertices', 'segments'}, 'p')`` (which also removes the
  triangles outside, as we do);
* ``chain``: k random points joined in x order (a long non-Delaunay polyline):
  ``ConstrainedDelaunay(points, segments)`` against Triangle with ``'pc'``;
* ``holes``: a star polygon with k/2 vertices and k/8 square holes.

Part 2, shortest paths on a star polygon with 2000 vertices and 50 hexagonal
holes: building the ``NavMesh``, then per query ``shortest_path`` (optimal)
against ``channel_path`` (channel + funnel only, the usual game-engine answer,
not always optimal with holes), and the one-call ``NavMesh(boundary,
holes).shortest_path(start, goal)``.  Then, on a small polygon, the optimal query against the
test oracle (visibility graph with shapely + networkx Dijkstra).
Ratios below 1.0 mean ours is faster.
"""
from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from reference_impl.structures.constrained import ConstrainedDelaunay  # noqa: E402
from reference_impl.structures.navmesh import NavMesh  # noqa: E402
from reference_impl.structures.polygon import polygon_triangulation  # noqa: E402


def star(rng, k, rmin=0.5):
    ang = (np.arange(k) + rng.uniform(-0.4, 0.4, k)) * 2 * np.pi / k
    r = rng.uniform(rmin, 1.0, k)
    return np.stack([r * np.cos(ang), r * np.sin(ang)], axis=1)


def ring_segments(sizes):
    out, start = [], 0
    for m in sizes:
        idx = np.arange(start, start + m)
        out.append(np.stack([idx, np.roll(idx, -1)], axis=1))
        start += m
    return np.concatenate(out)


def square_holes(count, half_width):
    """count small squares on a grid inside the disk of radius 0.45 (disjoint, inside any star(rmin=0.5))."""
    side = int(math.ceil(math.sqrt(count)))
    step = 0.6 / side
    s = min(half_width, step / 3)
    holes = []
    for i in range(count):
        cx, cy = -0.3 + step * (i % side + 0.5), -0.3 + step * (i // side + 0.5)
        holes.append(np.array([(cx - s, cy - s), (cx + s, cy - s), (cx + s, cy + s), (cx - s, cy + s)]))
    return holes


def length(path):
    return sum(math.dist(p, q) for p, q in zip(path, path[1:]))


def best_of(repeat, *funcs):
    """Interleave the functions ``repeat`` times; return each one's best wall time."""
    best = [math.inf] * len(funcs)
    for _ in range(repeat):
        for i, f in enumerate(funcs):
            t = time.perf_counter()
            f()
            best[i] = min(best[i], time.perf_counter() - t)
    return best


def bench_cdt(sizes, repeat):
    import triangle
    rng = np.random.default_rng(1)
    print("part 1: constrained Delaunay, ours vs Triangle (best of %d)" % repeat)
    print(f"{'case':8} {'segments':>9} {'ours s':>9} {'Triangle s':>11} {'ratio':>7}")
    polygon_triangulation(star(rng, 50))                       # JIT / cache warm-up
    for k in sizes:
        b = star(rng, k)
        seg = ring_segments([k])
        cases = [("polygon", lambda: polygon_triangulation(b),
                  lambda: triangle.triangulate({"vertices": b, "segments": seg}, "p"), k)]
        pts = rng.random((k, 2))
        pts = pts[np.argsort(pts[:, 0])]
        chain = np.stack([np.arange(k - 1), np.arange(1, k)], axis=1)
        cases.append(("chain", lambda: ConstrainedDelaunay(pts, chain),
                      lambda: triangle.triangulate({"vertices": pts, "segments": chain}, "pc"), k - 1))
        hb = star(rng, k // 2)
        holes = square_holes(max(1, k // 8), 0.01)
        verts = np.vstack([hb] + holes)
        hseg = ring_segments([len(hb)] + [4] * len(holes))
        centres = np.array([h.mean(axis=0) for h in holes])
        cases.append(("holes", lambda: polygon_triangulation(hb, holes),
                      lambda: triangle.triangulate({"vertices": verts, "segments": hseg, "holes": centres}, "p"),
                      len(hseg)))
        for name, ours, theirs, nseg in cases:
            t_ours, t_tri = best_of(repeat, ours, theirs)
            print(f"{name:8} {nseg:9d} {t_ours:9.4f} {t_tri:11.4f} {t_ours / t_tri:7.2f}")


def bench_paths(repeat, queries):
    rng = np.random.default_rng(2)
    k, h = 2000, 50
    boundary = star(rng, k, rmin=0.85)
    holes = []
    for i in range(h):
        cx, cy = -0.54 + 0.12 * (i % 10), -0.24 + 0.12 * (i // 10)
        a = np.arange(6) * np.pi / 3 + rng.uniform(0, 1)
        holes.append(np.stack([cx + 0.045 * np.cos(a), cy + 0.045 * np.sin(a)], axis=1))
    print(f"\npart 2: shortest paths, star polygon with {k} vertices and {h} holes")
    t = time.perf_counter()
    nav = NavMesh(boundary, holes)
    print(f"NavMesh build: {time.perf_counter() - t:.3f} s  ({nav!r})")
    starts = [(rng.uniform(-0.75, -0.65), rng.uniform(-0.3, 0.3)) for _ in range(queries)]
    goals = [(rng.uniform(0.65, 0.75), rng.uniform(-0.3, 0.3)) for _ in range(queries)]
    longer = 0
    t_opt = t_fun = 0.0
    for s, g in zip(starts, goals):
        a, b = best_of(repeat, lambda: nav.shortest_path(s, g), lambda: nav.channel_path(s, g))
        t_opt += a
        t_fun += b
        longer += length(nav.channel_path(s, g)) > length(nav.shortest_path(s, g)) * (1 + 1e-9)
    print(f"{queries} queries across the holes: optimal {t_opt / queries * 1e3:.1f} ms/query, "
          f"funnel only {t_fun / queries * 1e3:.1f} ms/query, ratio {t_opt / t_fun:.2f}; "
          f"the funnel path was longer than optimal in {longer} of {queries}")
    t = time.perf_counter()
    NavMesh(boundary, holes).shortest_path(starts[0], goals[0])
    print(f"one call NavMesh(boundary, holes).shortest_path(start, goal): {time.perf_counter() - t:.3f} s")

    sys.path[:0] = [str(ROOT / "tests" / "structures"), str(ROOT / "tests")]
    from test_navmesh import oracle_length                        # the test oracle
    small_b, small_h = star(rng, 100, rmin=0.85), holes[::10]
    nav_small = NavMesh(small_b, small_h)
    s, g = starts[0], goals[0]
    a, b = best_of(1, lambda: nav_small.shortest_path(s, g), lambda: oracle_length(small_b, small_h, s, g))
    print(f"small polygon (100 vertices, {len(small_h)} holes): optimal query {a * 1e3:.1f} ms, "
          f"visibility-graph oracle (shapely + networkx) {b * 1e3:.0f} ms, ratio {a / b:.4f}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--queries", type=int, default=10)
    args = ap.parse_args()
    bench_cdt(args.sizes, args.repeat)
    bench_paths(args.repeat, args.queries)


if __name__ == "__main__":
    main()
