"""Benchmark: reference_impl.Delaunay against Triangle and scipy.spatial in the same process.

    python benchmarks/bench_delaunay.py            # full table (about 2 minutes)
    python benchmarks/bench_delaunay.py --quick    # 1e3 .. 1e5 only
    python benchmarks/bench_delaunay.py --sizes 1000000 --repeat 5

Prints, for uniform random points in the unit square (1e3 .. 1e6) and for the
1000x1000 integer grid (every square cocircular): the best-of-k wall time of

* ``Delaunay(points).simplices``           (ours: exact predicates, neighbours too)
* ``triangle.triangulate({'vertices': p})`` (Shewchuk's Triangle, divide and conquer)
* ``scipy.spatial.Delaunay(p)``             (Qhull)

and the ratios ours/Triangle and ours/scipy (below 1.0 means we are faster).
Ours and Triangle run alternately (ours, Triangle, ours, ...) so that machine
noise hits both alike; scipy runs after them (once from 1e6 points on, where it
takes ~15 s).  Then, each in a fresh subprocess: peak resident memory
for 1e6 points, and the numba start-up cost (first call compiling into an empty
cache, then a second process loading the cache).
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
    cells = [f"{label:<22}", f"{ours:8.3f}", f"{tri:8.3f}", f"{sc:8.3f}" if sc else "       -",
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
    Delaunay(np.random.default_rng(0).random((1000, 2))).simplices
    print(time.perf_counter() - t)
""")


def _sub(code, *args, env=None):
    out = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True,
                         env=env, cwd=tempfile.gettempdir(), timeout=1200)
    if out.returncode != 0:
        raise RuntimeError(out.stderr)
    return float(out.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="sizes 1e3..1e5, no grid, no subprocess checks")
    ap.add_argument("--sizes", type=int, nargs="*", help="uniform sizes to run")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--no-scipy-at", type=int, default=2_000_000,
                    help="skip scipy from this size on (it takes ~15 s at 1e6)")
    args = ap.parse_args()
    sizes = args.sizes or ([1_000, 10_000, 100_000] if args.quick else [1_000, 10_000, 100_000, 1_000_000])

    _ours(np.random.default_rng(1).random((100, 2)))  # compile (or load the cache) before timing
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}, {os.cpu_count()} cpus; best of {args.repeat}")
    print(f"{'input':<22} | {'ours s':>8} | {'Triangle':>8} | {'scipy':>8} | {'/Tri':>7} | {'/scipy':>7} | {'triangles':>10}")
    print("-" * 96)
    rng = np.random.default_rng(0)
    for n in sizes:
        pts = rng.random((n, 2))
        best, count = best_times(pts, args.repeat, with_scipy=n < args.no_scipy_at)
        print(fmt_row(f"uniform {n:,}", best, count), flush=True)
    if not args.quick:
        g = np.array(np.meshgrid(np.arange(1000.0), np.arange(1000.0))).reshape(2, -1).T.copy()
        best, count = best_times(g, args.repeat, with_scipy=False)
        print(fmt_row("grid 1000x1000", best, count), flush=True)
        print("  (scipy is left out on the grid: Qhull needs joggling ('QJ') or merges facets there)")

        print("\npeak resident memory, 1e6 uniform points (MiB above the process's baseline):")
        for which in ("ours", "triangle", "scipy"):
            print(f"  {which:<9} {_sub(MEM_CODE, which, '1000000'):8.1f}")

        with tempfile.TemporaryDirectory() as cache:
            env = dict(os.environ, NUMBA_CACHE_DIR=cache, PYTHONPATH=str(ROOT))
            first = _sub(JIT_CODE, env=env)
            second = _sub(JIT_CODE, env=env)
        print(f"\nnumba start-up (import + first Delaunay of 1000 points, fresh process):")
        print(f"  empty cache (compiles): {first:6.2f} s")
        print(f"  cached (second process): {second:6.2f} s")


if __name__ == "__main__":
    main()
