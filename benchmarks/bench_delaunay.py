"""Benchmark: reference_impl.Delaunay against Triangle and scipy.spatial in the same process.

    python benchmarks/bench_delaunay.py            # full table (about 17 minutes)
    python benchmarks/bench_delaunay.py --quick    # 1e2 .. 1e5 uniform only, no start-up checks
    python benchmarks/bench_delaunay.py --sizes 1000000 10000000 --repeat 3

Prints, for uniform random points in the unit square (1e2 .. 1e7 by default), 300
Gaussian clusters (sigma 1e-3), the integer grid (every square cocircular), the same grid
made with ``linspace`` in the unit square (cocircular too, but the coordinate differences are
not exact doubles: the predicates' fixed-point stage) and nearly collinear points (a line with
1e-9 noise), the best-of-k wall time of

* ``Delaunay(points).simplices``           (ours: exact predicates, neighbours too)
* ``triangle.triangulate({'vertices': p})`` (Shewchuk's Triangle, divide and conquer)
* ``scipy.spatial.Delaunay(p)``             (Qhull; uniform inputs below 2e6 only)

and the ratios ours/Triangle and ours/scipy (below 1.0 means we are faster).
Ours and Triangle run alternately (ours, Triangle, ours, ...) so that machine
noise hits both alike; scipy runs after them (once from 1e6 points on, where it
takes ~15 s; not at all from 2e6 on).  From 1e7 points on each runs once.  Then, each in
a fresh subprocess: peak resident memory for 1e6 and 1e7 points, and the numba start-up cost: a cold compile of every kernel
(``python -m reference_impl warm`` into an empty cache), then, in a new process after that
warm-up, the import (numpy, numba, reference_impl) and the first ``Delaunay`` of 1000 points.
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def _ours(p):
    from reference_impl import Delaunay
    return len(Delaunay(p).simplices)


def _triangle(p):
    import triangle
    return len(triangle.triangulate({"vertices": p})["triangles"])


def _scipy(p):
    import scipy.spatial
    return len(scipy.spatial.Delaunay(p).simplices)


def best_times(points, repeat, with_scipy=True):
    """Best of ``repeat`` alternating runs of ours and Triangle; scipy (slow) runs
    ``repeat`` times below 1e6 points and once from 1e6 on."""
    runners = [("ours", _ours), ("triangle", _triangle)]
    best = {name: float("inf") for name, _ in runners}
    count = {}
    for _ in range(repeat):
        for name, fn in runners:
            t = time.perf_counter()
            count[name] = fn(points)
            best[name] = min(best[name], time.perf_counter() - t)
    if with_scipy:
        best["scipy"] = float("inf")
        for _ in range(repeat if len(points) < 1_000_000 else 1):
            t = time.perf_counter()
            count["scipy"] = _scipy(points)
            best["scipy"] = min(best["scipy"], time.perf_counter() - t)
    return best, count


def fmt_row(label, best, count):
    ours, tri = best["ours"], best["triangle"]
    sc = best.get("scipy")
    ms = lambda t: f"{1e3 * t:9.3f}"  # noqa: E731
    cells = [f"{label:<22}", ms(ours), ms(tri), ms(sc) if sc else "        -",
             f"{ours / tri:7.2f}", f"{ours / sc:7.3f}" if sc else "      -", f"{count['ours']:>10,}"]
    return " | ".join(cells)


MEM_CODE = textwrap.dedent("""
    import sys, numpy as np
    def status(key):
        for line in open("/proc/self/status"):
            if line.startswith(key):
                return int(line.split()[1])          # kB
    which, n = sys.argv[1], int(sys.argv[2])
    p = np.random.default_rng(0).random((n, 2))
    if which == "ours":
        from reference_impl import Delaunay; Delaunay(p[:100]).simplices
    elif which == "triangle":
        import triangle
    else:
        import scipy.spatial
    with open("/proc/self/clear_refs", "w") as f:
        f.write("5")                                 # reset the peak (VmHWM) to the current RSS
    base = status("VmRSS")
    if which == "ours":
        s = Delaunay(p).simplices
    elif which == "triangle":
        s = triangle.triangulate({"vertices": p})["triangles"]
    else:
        s = scipy.spatial.Delaunay(p).simplices
    print((status("VmHWM") - base) / 1024)
""")

JIT_CODE = textwrap.dedent("""
    import time
    t = time.perf_counter()
    import numpy as np
    from reference_impl import Delaunay
    t1 = time.perf_counter()
    Delaunay(np.random.default_rng(0).random((1000, 2))).simplices
    print(t1 - t, time.perf_counter() - t1)
""")


def _sub(code, *args, env=None):
    # an empty private folder as the working directory: `python -c` imports from it first (the
    # shared /tmp would let any account put a numpy.py there)
    with tempfile.TemporaryDirectory(prefix="bench-cwd-") as cwd:
        out = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True,
                             env=env, cwd=cwd, timeout=1200)
    if out.returncode != 0:
        raise RuntimeError(out.stderr)
    return [float(v) for v in out.stdout.strip().splitlines()[-1].split()]


def inputs(n: int, rng) -> dict[str, np.ndarray]:
    """The input kinds of the table, about n points each (the grid is the nearest square)."""
    centres = rng.random((300, 2))
    k = int(round(n ** 0.5))
    return {
        "uniform": rng.random((n, 2)),
        "clusters": centres[rng.integers(0, 300, n)] + rng.normal(0, 1e-3, (n, 2)),
        "grid": np.array(np.meshgrid(np.arange(float(k)), np.arange(float(k)))).reshape(2, -1).T.copy(),
        "float grid": np.array(np.meshgrid(np.linspace(0, 1, k), np.linspace(0, 1, k))).reshape(2, -1).T.copy(),
        "near-line": np.column_stack([t := rng.random(n), 0.5 * t + rng.normal(0, 1e-9, n)]),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="uniform 1e2..1e5 only, no start-up checks")
    ap.add_argument("--sizes", type=int, nargs="*", help="sizes to run")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--kinds", nargs="*", default=None, help="input kinds (default: all; --quick: uniform)")
    ap.add_argument("--no-startup", action="store_true", help="leave out memory and numba start-up")
    ap.add_argument("--no-scipy-at", type=int, default=2_000_000,
                    help="skip scipy from this size on (it takes ~15 s at 1e6)")
    args = ap.parse_args()
    sizes = args.sizes or ([100, 1_000, 10_000, 100_000] if args.quick
                           else [100, 1_000, 10_000, 100_000, 1_000_000, 10_000_000])
    kinds = args.kinds or (["uniform"] if args.quick else ["uniform", "clusters", "grid", "float grid", "near-line"])

    _ours(np.random.default_rng(1).random((100, 2)))  # compile (or load the cache) before timing
    best_times(np.random.default_rng(2).random((1000, 2)), 200)   # then warm both sides alike (the
    # first row ran cold otherwise: the CPU clock and caches settle in the first second of calls)
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}, {os.cpu_count()} cpus; best of {args.repeat}")
    print(f"{'input':<22} | {'ours ms':>9} | {'Triangle':>9} | {'scipy':>9} | {'/Tri':>7} | {'/scipy':>7} | {'triangles':>10}")
    print("-" * 96)
    for kind in kinds:
        for n in sizes:
            pts = inputs(n, np.random.default_rng(n))[kind]
            repeat = args.repeat if n < 1_000_000 else min(args.repeat, 3 if n < 10_000_000 else 1)
            repeat = repeat * 20 if n <= 1_000 else repeat          # tiny inputs: more runs, less noise
            best, count = best_times(pts, repeat, with_scipy=kind == "uniform" and n < args.no_scipy_at)
            print(fmt_row(f"{kind} {len(pts):,}", best, count), flush=True)
    if not args.quick:
        print("  (scipy runs on uniform input only: Qhull needs joggling ('QJ') or merges facets on the others)")
    if not (args.quick or args.no_startup):
        print("\npeak resident memory, uniform points (MiB above the process's baseline):")
        for n in (1_000_000, 10_000_000):
            cells = [f"{which} {_sub(MEM_CODE, which, str(n))[0]:8.1f}"
                     for which in ("ours", "triangle") + (("scipy",) if n < args.no_scipy_at else ())]
            print(f"  {n:>10,}: " + "   ".join(cells))

        with tempfile.TemporaryDirectory() as cache:
            env = dict(os.environ, NUMBA_CACHE_DIR=cache, PYTHONPATH=str(ROOT))
            t = time.perf_counter()
            warm = subprocess.run([sys.executable, "-m", "reference_impl", "warm"], env=env, cwd=cache,  # private, empty
                                  capture_output=True, text=True, timeout=3600)
            cold = time.perf_counter() - t
            if warm.returncode != 0:
                raise RuntimeError(warm.stderr)
            imports, first = _sub(JIT_CODE, env=env)
        print("\nnumba start-up:")
        print(f"  cold compile of every kernel (python -m reference_impl warm, empty cache): {cold:6.1f} s")
        print("\n".join("    " + line.strip() for line in warm.stdout.splitlines()[1:-1]))
        print(f"  after the warm-up, a new process: import {imports:5.2f} s, then the first Delaunay of "
              f"1000 points {first:5.2f} s")


if __name__ == "__main__":
    main()
