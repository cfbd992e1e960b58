"""Benchmark: reference_impl's 3D Delaunay and spherical Delaunay against scipy (Qhull), same process.

    python benchmarks/bench_delaunay3d.py             # 1e3, 1e4, 2e4, 1e5 (about a minute)
    python benchmarks/bench_delaunay3d.py --quick     # 1e3, 1e4, 2e4
    python benchmarks/bench_delaunay3d.py --sizes 50000 --repeat 5

Prints best-of-k wall times and the ratio ours/scipy (below 1.0: we are faster) for

* uniform random points in the unit cube: ``Delaunay3D(p)`` against
  ``scipy.spatial.Delaunay(p)``;
* a k x k x k integer grid (every cube cospherical: the exact stages work), and the same grid
  made with ``linspace`` in the unit cube (ties whose differences are not exact doubles: the
  predicates' fixed-point stage);
* random points on the unit sphere: ``SphericalDelaunay(p)`` against
  ``scipy.spatial.ConvexHull(p)``.

Runs are interleaved (ours, scipy, ours, ...) so machine noise hits both alike;
the first call (numba compile or cache load) is made before timing.  Also
printed: the walk steps and conflict tests per point (insertion-order quality).
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from reference_impl.mesh.delaunay3d import Delaunay3D  # noqa: E402
from reference_impl.structures.spherical import SphericalDelaunay  # noqa: E402


def best_times(runners, repeat):
    best = {name: float("inf") for name, _ in runners}
    out = {}
    for _ in range(repeat):
        for name, fn in runners:
            t = time.perf_counter()
            out[name] = fn()
            best[name] = min(best[name], time.perf_counter() - t)
    return best, out


def row(label, n, best, counts):
    ours, theirs = best["ours"], best["scipy"]
    print(f"{label:<14}{n:>9}{ours:>11.3f}{theirs:>11.3f}{ours / theirs:>9.2f}"
          f"{counts['ours']:>11}{counts['scipy']:>11}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="*", default=None)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    sizes = args.sizes or ([1000, 10_000, 20_000] if args.quick else [1000, 10_000, 20_000, 100_000])
    import scipy.spatial

    Delaunay3D(np.random.default_rng(0).random((50, 3)))          # compile / load the cache
    SphericalDelaunay(np.random.default_rng(0).normal(size=(50, 3)))

    print(f"{'set':<14}{'n':>9}{'ours s':>11}{'scipy s':>11}{'ratio':>9}{'ours m':>11}{'scipy m':>11}")
    for n in sizes:
        p = np.random.default_rng(n).random((n, 3))
        best, counts = best_times([("ours", lambda: len(Delaunay3D(p).simplices)),
                                   ("scipy", lambda: len(scipy.spatial.Delaunay(p).simplices))],
                                  args.repeat if n <= 20_000 else 1)
        row("uniform cube", n, best, counts)
        st = Delaunay3D(p).stats
        print(f"{'':<14}walk steps/point {st['walk_steps'] / n:.2f}, "
              f"conflict tests/point {st['conflict_tests'] / n:.1f}, "
              f"cavity tets/point {st['cavity_tets'] / n:.1f}")
    for k in (10, 20, 30):
        g = np.array(np.meshgrid(*[np.arange(k)] * 3, indexing="ij"), dtype=float).reshape(3, -1).T
        for name, pts in ((f"grid {k}^3", g), (f"linspace {k}^3", g / (k - 1))):
            best, counts = best_times([("ours", lambda: len(Delaunay3D(pts).simplices)),
                                       ("scipy", lambda: len(scipy.spatial.Delaunay(pts).simplices))],
                                      args.repeat)
            row(name, len(pts), best, counts)
    for n in sizes:
        v = np.random.default_rng(n).normal(size=(n, 3))
        v /= np.linalg.norm(v, axis=1, keepdims=True)
        best, counts = best_times([("ours", lambda: len(SphericalDelaunay(v).simplices)),
                                   ("scipy", lambda: len(scipy.spatial.ConvexHull(v).simplices))],
                                  args.repeat if n <= 20_000 else 1)
        row("sphere hull", n, best, counts)
    print("ratio = ours / scipy (below 1.0: ours is faster); m = tetrahedra or triangles")


if __name__ == "__main__":
    main()
