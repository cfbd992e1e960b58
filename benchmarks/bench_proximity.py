"""Benchmark: proximity graphs and Lawson flips against their scipy / Triangle anchors, same process.

    python benchmarks/bench_proximity.py                  # 1e4 and 1e5 points, best of 3
    python benchmarks/bench_proximity.py --sizes 100000 --repeat 5
    python benchmarks/bench_proximity.py --quick          # 1e4 only, best of 1

For uniform random points (and, at the largest size, the integer grid, where
every length decision is a tie and the exact paths run), prints the best-of-k
wall time of

* ``euclidean_mst``   vs scipy.spatial.Delaunay + scipy.sparse.csgraph.minimum_spanning_tree
* ``closest_pair``    vs scipy.spatial.cKDTree(p).query(p, k=2) and an argmin
* ``gabriel_graph``   vs scipy Delaunay edges + a vectorised float apex test (not exact)
* ``relative_neighborhood_graph`` vs scipy.spatial.Delaunay alone (there is no library RNG)
* ``lawson_flip``     from Triangle's constrained triangulation of an x-monotone polyline
                      (far from Delaunay: about n^1.5 flips) vs Triangle's own Delaunay

and the ratio ours / anchor (below 1.0 means ours is faster).  Points on a
circle (all near-ties) are timed against our own function on uniform points of
the same size, the cost of the exact paths: Qhull is quadratic on cocircular
input (85 s for 30,000 points here), so scipy is no anchor there.  Runs are
interleaved (ours, anchor, ours, ...) so machine noise hits both sides; numba
compilation is done before timing.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import scipy.sparse  # noqa: E402
import scipy.sparse.csgraph  # noqa: E402
import scipy.spatial  # noqa: E402
import triangle  # noqa: E402

from reference_impl.structures.flips import lawson_flip  # noqa: E402
from reference_impl.structures.proximity import (closest_pair, euclidean_mst, gabriel_graph,  # noqa: E402
                                      relative_neighborhood_graph)


# ----------------------------------------------------------------------------- anchors
def _scipy_edges(p):
    tri = scipy.spatial.Delaunay(p)
    ind, nb = tri.vertex_neighbor_vertices
    rows = np.repeat(np.arange(len(p)), np.diff(ind))
    return tri, rows, nb


def scipy_mst(p):
    _, rows, nb = _scipy_edges(p)
    w = np.linalg.norm(p[rows] - p[nb], axis=1)
    m = scipy.sparse.csgraph.minimum_spanning_tree(scipy.sparse.csr_matrix((w, (rows, nb)), shape=(len(p),) * 2))
    return m.nnz


def kdtree_closest(p):
    d, k = scipy.spatial.cKDTree(p).query(p, k=2)
    i = int(np.argmin(d[:, 1]))
    return i, int(k[i, 1])


def scipy_gabriel(p):
    tri = scipy.spatial.Delaunay(p)
    s = tri.simplices
    keep = []
    for k in range(3):
        u, v, r = s[:, (k + 1) % 3], s[:, (k + 2) % 3], s[:, k]
        ok = np.einsum("ij,ij->i", p[u] - p[r], p[v] - p[r]) > 0
        keep.append(np.c_[np.minimum(u, v), np.maximum(u, v), ok])
    e = np.concatenate(keep)
    bad = np.unique(e[e[:, 2] == 0][:, :2], axis=0)
    return len(np.unique(e[:, :2], axis=0)) - len(bad)


def scipy_delaunay(p):
    return len(scipy.spatial.Delaunay(p).simplices)


def constrained_start(p):
    order = np.argsort(p[:, 0], kind="stable")
    out = triangle.triangulate({"vertices": p, "segments": np.c_[order[:-1], order[1:]]}, "pcQ")
    assert len(out["vertices"]) == len(p)
    return out["triangles"]


def triangle_delaunay(p):
    return len(triangle.triangulate({"vertices": p}, "Q")["triangles"])


# ----------------------------------------------------------------------------- timing
def best_pair(ours, anchor, repeat):
    best = [float("inf"), float("inf")]
    for _ in range(repeat):
        for k, fn in enumerate((ours, anchor)):
            t = time.perf_counter()
            fn()
            best[k] = min(best[k], time.perf_counter() - t)
    return best


def rows_for(name, p, repeat, with_flips=True):
    if name.startswith("circle"):
        u = np.random.default_rng(0).random(p.shape)
        cases = [(label, lambda f=f: f(p), "same on uniform", lambda f=f: f(u))
                 for label, f in (("euclidean_mst", euclidean_mst), ("closest_pair", closest_pair),
                                  ("gabriel_graph", gabriel_graph),
                                  ("relative_neighborhood", relative_neighborhood_graph))]
        cases[1] = ("closest_pair", lambda: closest_pair(p), "cKDTree query k=2", lambda: kdtree_closest(p))
        return _print_rows(name, cases, repeat)
    cases = [
        ("euclidean_mst", lambda: euclidean_mst(p), "scipy Delaunay+csgraph MST", lambda: scipy_mst(p)),
        ("closest_pair", lambda: closest_pair(p), "cKDTree query k=2", lambda: kdtree_closest(p)),
        ("gabriel_graph", lambda: gabriel_graph(p), "scipy Delaunay+float test", lambda: scipy_gabriel(p)),
        ("relative_neighborhood", lambda: relative_neighborhood_graph(p), "scipy Delaunay",
         lambda: scipy_delaunay(p)),
    ]
    if with_flips:
        start = constrained_start(p)
        n_flips = len(lawson_flip(p, start)[1])
        cases.append((f"lawson {n_flips:,} flips", lambda: lawson_flip(p, start), "Triangle Delaunay",
                      lambda: triangle_delaunay(p)))
    _print_rows(name, cases, repeat)


def _print_rows(name, cases, repeat):
    for label, ours, anchor_label, anchor in cases:
        a, b = best_pair(ours, anchor, repeat)
        print(f"{name:<16} | {label:<23} | {a:8.3f} | {anchor_label:<27} | {b:8.3f} | {a / b:6.2f}",
              flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[10_000, 100_000])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="1e4 points, best of 1")
    args = ap.parse_args()
    sizes, repeat = ([10_000], 1) if args.quick else (args.sizes, args.repeat)

    warm = np.random.default_rng(1).random((200, 2))          # compile (or load) numba first
    for f in (euclidean_mst, closest_pair, gabriel_graph, relative_neighborhood_graph):
        f(warm)
    lawson_flip(warm, constrained_start(warm))

    print(f"{'input':<16} | {'ours':<23} | {'time s':>8} | {'anchor':<27} | {'time s':>8} | {'ratio':>6}")
    print("-" * 104)
    for n in sizes:
        rows_for(f"uniform {n:,}", np.random.default_rng(0).random((n, 2)), repeat)
    n = max(sizes)
    k = int(round(np.sqrt(n)))
    grid = np.array([(i, j) for i in range(k) for j in range(k)], dtype=float)
    rows_for(f"grid {k}x{k}", grid, repeat, with_flips=False)
    t = 2 * np.pi * np.arange(n) / n
    rows_for(f"circle {n:,}", np.c_[np.cos(t), np.sin(t)], repeat, with_flips=False)


if __name__ == "__main__":
    main()
