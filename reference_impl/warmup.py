"""Warm-up: compile every numba kernel of the library into numba's on-disk cache, once.

    python -m reference_impl warm          # what `make warm` runs (about a minute cold, 2 CPUs)

A numba kernel compiles on its first call in a process whose cache holds no
machine code for it; later processes load it from the cache.  Without a warm-up
a student's first cell in a lesson would stall for seconds (the 2D kernel alone
takes several), and so would the first voronoi(), the first NavMesh, ... each on
its own.  ``warm()`` calls every public feature on a tiny input, which compiles
(or loads) every kernel behind it, in the cache location numba uses at run time
(``__pycache__`` beside the sources, ``$NUMBA_CACHE_DIR``, or ``~/.cache/numba``
when the package directory is read-only: the same rule as ``_jitcache``).  It first
drops cached code compiled against modules edited since (``_jitcache.purge_stale_cache``).

The features are run in a fixed list (``FEATURES``) and each is timed, so the
output says where compile time goes.  On a cold cache they are first compiled in worker
processes side by side (``PHASES``: the 2D and 3D predicates, then the 2D and 3D kernels,
then the rest), which divides the wait by about the number of CPUs, down to the longest
feature.  ``not_cached()`` names the kernels that the cache does not hold
(tests/test_warmup.py keeps it empty after a warm-up).

>>> seconds = warm(progress=None)          # (already cached here: fast)
>>> sorted(seconds)[:3]
['2d delaunay', '2d predicates', '2d updates']
"""
from __future__ import annotations

import importlib
import os
import sys
import time
from pathlib import Path
from typing import Callable

import numpy as np

__all__ = ["FEATURES", "PHASES", "default_jobs", "warm", "not_cached", "kernels"]


def _delaunay() -> None:
    from reference_impl.mesh.delaunay import Delaunay
    rng = np.random.default_rng(0)
    for pts in (rng.random((100, 2)), rng.random((5000, 2)),          # small and large ordering paths
                np.array([(i % 5, i // 5) for i in range(25)], float),  # integer ties
                np.array([(0, 0), (1, 1), (2, 2)], float), np.zeros((0, 2))):
        d = Delaunay(pts)
        d.simplices, d.neighbors, d.hull, d.index_map, d.edges()
    d.find_simplex((0.5, 0.5)), d.find_simplex(rng.random((100, 2)))


def _updates() -> None:
    from reference_impl.mesh.delaunay import Delaunay
    d = Delaunay(np.random.default_rng(1).random((30, 2)))
    d.insert((0.5, 0.25)), d.insert((0.5, 0.25)), d.insert((3.0, 3.0))
    d.vertex_neighbors(0), d.vertex_neighbors(1, strict=True)
    for i in range(5):
        d.remove(i)
    d.simplices, d.neighbors, d.hull


def _exact() -> None:
    from reference_impl.exact.predicates import incircle, orient2d
    for s in (1.0, 1e-300, 1e300):
        orient2d((0, 0), (s, s), (2 * s, 2 * s)), incircle((0, 0), (s, 0), (0, s), (s, s))
    orient2d((0.5, 0.5000000000000001), (12, 12), (24, 24))
    incircle((1e-300, 0), (1, 0), (0, 1), (1e300, 1))
    from reference_impl.exact.fixed import SCRATCH, incircle_fixed, orient_fixed   # (float ties)
    iw = np.zeros(SCRATCH, dtype=np.int64)
    orient_fixed(0.1, 0.2, 0.2, 0.4, 0.3, 0.6, iw), incircle_fixed(0.1, 0.1, 0.3, 0.1, 0.3, 0.3, 0.1, 0.3, iw)


def _exact3d() -> None:
    from reference_impl.exact.predicates3d import insphere, insphere_batch, orient3d, orient3d_batch
    for s in (1.0, 1e-300, 1e300):
        orient3d((0, 0, 0), (s, 0, 0), (0, s, 0), (s, s, 0))
        insphere((0, 0, 0), (s, 0, 0), (0, s, 0), (0, 0, s), (s, s, s))
    orient3d_batch([[0, 0, 0]], [[1, 0, 0]], [[0, 1, 0]], [[0, 0, 1]])
    insphere_batch([[0, 0, 0]], [[1, 0, 0]], [[0, 1, 0]], [[0, 0, -1]], [[5, 5, 5]])


def _voronoi() -> None:
    from reference_impl.structures.hull import convex_hull
    from reference_impl.structures.voronoi import voronoi
    pts = np.random.default_rng(2).random((50, 2))
    voronoi(pts, (0, 0, 1, 1)), convex_hull(pts), convex_hull(pts, collinear=True)
    voronoi([(0.1, 0.1), (0.5, 0.5), (0.9, 0.9)], (0, 0, 1, 1))            # collinear sites


def _proximity() -> None:
    from reference_impl.structures.clearance import max_clearance
    from reference_impl.structures.empty_circle import largest_empty_circle
    from reference_impl.structures.proximity import closest_pair, euclidean_mst, gabriel_graph, relative_neighborhood_graph
    grid = np.array([(i % 6, i // 6) for i in range(36)], float)       # equal lengths: the exact sort
    for pts in (np.random.default_rng(3).random((60, 2)), grid):
        euclidean_mst(pts), closest_pair(pts), gabriel_graph(pts), relative_neighborhood_graph(pts)
        largest_empty_circle(pts), max_clearance(pts, (0.3, 0.2), (4.6, 4.7))


def _flips() -> None:
    from reference_impl.structures.flips import apply_flips, flip_to_delaunay, laplacian_smooth, lawson_flip, mesh_quality, validate_triangulation
    fan = np.array([(0, 0), (2, 0), (2, 2), (0, 2), (1.0, 0.5)])
    tris = np.array([(0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)])
    validate_triangulation(fan, tris), lawson_flip(fan, tris)
    apply_flips(fan, tris, flip_to_delaunay(fan, tris))
    laplacian_smooth(fan, tris), mesh_quality(fan, tris)


def _meshes() -> None:
    from reference_impl.structures.constrained import ConstrainedDelaunay, constrained_delaunay
    from reference_impl.structures.navmesh import NavMesh
    from reference_impl.structures.polygon import polygon_triangulation
    square = [(0, 0), (4, 0), (4, 4), (0, 4), (1, 1), (3, 3), (1, 3), (3, 1)]
    cd = ConstrainedDelaunay(square, [(4, 5)])
    cd.simplices, cd.neighbors, cd.constrained, cd.edges(), cd.constraint_edges()
    constrained_delaunay(square, [(4, 5), (0, 1)])
    polygon_triangulation([(0, 0), (6, 0), (6, 6), (0, 6)], [[(2, 2), (4, 2), (4, 4), (2, 4)]])
    nav = NavMesh([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
    nav.shortest_path((0.5, 3), (3.5, 3)), nav.locate((2, 3)), nav.is_visible((0.5, 3), (3.5, 3))


def _dynamic() -> None:
    from reference_impl.structures.dynamic import DynamicNetwork
    net = DynamicNetwork()
    ids = [net.join(x, y) for x, y in ((0, 0), (1, 0), (0, 1), (1, 1), (0.5, 0.4))]
    net.fail(ids[-1]), net.neighbors(ids[0]), net.links()


def _space() -> None:
    from reference_impl.mesh.delaunay3d import Delaunay3D
    from reference_impl.structures.spherical import SphericalDelaunay, lonlat_to_xyz
    rng = np.random.default_rng(4)
    d3 = Delaunay3D(rng.random((60, 3)))
    d3.simplices, d3.neighbors, d3.hull_facets, d3.find_simplex((0.5, 0.5, 0.5))
    Delaunay3D(np.array([(i, j, k) for i in range(3) for j in range(3) for k in range(3)], float)).simplices
    sd = SphericalDelaunay(lonlat_to_xyz(np.column_stack([rng.uniform(-180, 180, 40), rng.uniform(-80, 80, 40)])))
    sd.simplices, sd.neighbors


def _checkers() -> None:
    from reference_impl.mesh.delaunay import Delaunay
    from reference_impl.exact.verify import check_delaunay
    pts = np.random.default_rng(5).random((30, 2))
    check_delaunay(pts, Delaunay(pts).simplices)
    from reference_impl.exact.flip_kernel import replay     # edge-flip's compiled topology replay
    replay(4, np.array([[0, 1, 3], [1, 2, 3]]), np.array([[1, 3]]))


FEATURES: dict[str, Callable[[], None]] = {
    "2d predicates": _exact, "3d predicates": _exact3d, "2d delaunay": _delaunay, "2d updates": _updates,
    "voronoi and hull": _voronoi, "proximity": _proximity, "meshes and paths": _meshes,
    "flips and quality": _flips, "dynamic network": _dynamic, "3d delaunay": _space,
    "checkers": _checkers,
}

# A cold compile runs the features in processes side by side, phase after phase: every
# feature calls the exact predicates, and most call the 2D kernel, so those are compiled
# (and saved to the cache) before the features that would otherwise each compile them again.
PHASES: tuple[tuple[str, ...], ...] = (
    ("2d predicates", "3d predicates"),
    ("2d delaunay", "3d delaunay"),
    ("meshes and paths", "2d updates", "proximity", "flips and quality", "voronoi and hull",
     "dynamic network", "checkers"),                                  # (longest first)
)


def _run(name: str) -> float:
    """Run feature ``name`` (in a worker process of ``_compile_side_by_side``); its seconds."""
    t = time.perf_counter()
    FEATURES[name]()
    return time.perf_counter() - t


def _compile_side_by_side(jobs: int, progress: Callable[[str], None] | None) -> bool:
    """Compile every feature into the cache in ``jobs`` worker processes, ``PHASES`` in turn.
    False when worker processes cannot be started here (then the caller compiles alone)."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures.process import BrokenProcessPool
    try:
        with ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("spawn")) as pool:
            for phase in PHASES:
                t = time.perf_counter()
                done = dict(zip(phase, pool.map(_run, phase)))
                if progress:
                    each = ", ".join(f"{name} {s:.1f} s" for name, s in done.items())
                    progress(f"  compiled side by side in {time.perf_counter() - t:5.1f} s: {each}")
    except (OSError, BrokenProcessPool) as exc:
        if progress:
            progress(f"  (no worker processes: {exc}; compiling in this process)")
        return False
    return True


def default_jobs() -> int:
    """Worker processes for a cold compile: the CPUs this process may use, at most 4."""
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    return max(1, min(4, cpus))


def warm(progress: Callable[[str], None] | None = print, jobs: int | None = None) -> dict[str, float]:
    """Run every feature once on a tiny input; return seconds per feature (compile or load).

    ``progress`` receives one line per feature as it finishes (``None``: silent).  When most
    kernels are missing from the cache (a cold start), they are first compiled in ``jobs``
    worker processes (``default_jobs()``; 1: none), ``PHASES`` in turn; the features then run
    here as always, which loads them (and compiles anything a worker did not leave behind).
    """
    from reference_impl._jitcache import purge_stale_cache
    dropped = purge_stale_cache()          # machine code compiled against since-edited modules
    if progress and dropped:
        progress(f"  (dropped the stale cache of {', '.join(dropped)})")
    jobs = default_jobs() if jobs is None else jobs
    if jobs > 1 and 4 * len(not_cached()) > len(kernels()):
        _compile_side_by_side(jobs, progress)
    seconds = {}
    for name, run in FEATURES.items():
        t = time.perf_counter()
        run()
        seconds[name] = time.perf_counter() - t
        if progress:
            progress(f"  {name:<18} {seconds[name]:6.2f} s")
    return seconds


def kernels() -> dict[str, object]:
    """Every numba dispatcher defined in the package: ``module.name`` -> dispatcher."""
    from numba.core.registry import CPUDispatcher

    from reference_impl._jitcache import modules
    found = {}
    for name, f in modules().items():
        if name.split(".")[0] in ("__main__", "warmup", "kit") or f.stem == "__init__":
            continue
        mod = importlib.import_module(f"{__package__}.{name}")
        for attr, obj in vars(mod).items():
            if isinstance(obj, CPUDispatcher) and obj.py_func.__module__ == mod.__name__:
                found[f"{name}.{attr}"] = obj
    return found


def not_cached() -> list[str]:
    """Kernels of the package that numba's cache does not hold (no index file where numba
    looks), leaving out those marked ``inline="always"`` (compiled only inside their callers).
    Empty after ``warm()``: every kernel is reached from some feature."""
    return sorted(name for name, disp in kernels().items()
                  if disp.targetoptions.get("inline") != "always"
                  and not Path(disp._cache._cache_file._index_path).exists())


def main() -> int:
    t = time.perf_counter()
    print("warming numba's cache (each feature compiles once, then loads from the cache):", flush=True)
    warm(progress=lambda line: print(line, flush=True))
    missed = not_cached()
    print(f"done in {time.perf_counter() - t:.1f} s")
    if missed:
        print(f"error: the cache does not hold these kernels (no feature in warmup.FEATURES reaches them): "
              f"{', '.join(missed)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
