"""A headless tour of the course's library: ``python -m reference_impl demo``.

``python -m reference_impl warm`` compiles every numba kernel into the cache (see warmup.py).

It prints what a person would see in the first lessons (the tutorial's example,
the failures the course fixes, the speed of the fast version next to scipy) and
writes a picture to ``build/demo.png``; then it judges an accepted and a wrong
submission with the contest judge, as an instructor would.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np


def demo(out_dir: str = "build") -> None:
    from reference_impl import Delaunay, orient2d
    from reference_impl.exact.verify import check_delaunay

    print("Delaunay course: a headless tour\n")
    four = [(1, 1), (3, 2), (5, 1), (4, 4)]
    t0 = time.perf_counter()
    d = Delaunay(four)
    print(f"1. The tutorial's four points {four}")
    print(f"   triangles (counter-clockwise, point indices): {d.simplices.tolist()}")
    print(f"   convex hull: {d.hull.tolist()}   (first call compiles the numba kernel: {time.perf_counter() - t0:.1f} s)")
    try:
        from reference_impl.teaching.bowyer_watson import dry_run
        print("\n" + "\n".join("   " + line for line in dry_run(four).splitlines()))
    except ImportError:
        pass

    print("\n2. What plain floating point gets wrong, and the exact predicates get right")
    a, b, c = (0.5, 0.5000000000000001), (12.0, 12.0), (24.0, 24.0)
    naive = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])
    print(f"   orientation of {a}, {b}, {c}: naive determinant {naive}, exact sign {orient2d(a, b, c)}")
    big = [(1e6, 1e6), (2e6, 3e6), (4e6, 1e6)]
    print(f"   the tutorial's large-coordinate test {big}: {Delaunay(big).simplices.tolist()} "
          "(a fixed +-1e5 super-triangle loses it)")
    grid = np.array([(i, j) for i in range(30) for j in range(30)], float)
    ok, _ = check_delaunay(grid, Delaunay(grid).simplices)
    print(f"   a 30x30 integer grid (every square cocircular): valid Delaunay = {ok}")

    print("\n3. Speed (same process, uniform random points)")
    import scipy.spatial
    rng = np.random.default_rng(0)
    for n in (10_000, 100_000, 1_000_000):
        pts = rng.random((n, 2))
        t = time.perf_counter()
        m = len(Delaunay(pts).simplices)
        ours = time.perf_counter() - t
        line = f"   n={n:>9,}: Delaunay {ours:6.3f} s ({m:,} triangles)"
        if n <= 100_000:
            t = time.perf_counter()
            scipy.spatial.Delaunay(pts)
            line += f", scipy.spatial {time.perf_counter() - t:6.3f} s"
        print(line)

    out = Path(out_dir)
    out.mkdir(exist_ok=True)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    pts = rng.random((200, 2))
    d = Delaunay(pts)
    fig, ax = plt.subplots(figsize=(5, 5))
    ax.triplot(pts[:, 0], pts[:, 1], d.simplices, lw=0.7, color="0.3")
    ax.plot(*pts[d.hull].T, color="tab:red", lw=1.5)
    ax.plot(*pts[d.hull[[-1, 0]]].T, color="tab:red", lw=1.5)
    ax.scatter(pts[:, 0], pts[:, 1], s=6, zorder=3)
    ax.set_aspect("equal")
    ax.set_title("Delaunay triangulation of 200 random points")
    fig.savefig(out / "demo.png", dpi=100, bbox_inches="tight")
    print(f"\n4. Picture written to {out / 'demo.png'}")

    root = Path(__file__).resolve().parent.parent
    solutions = root / "solutions" / "delaunay"
    if solutions.is_dir():
        import subprocess
        print("\n5. The judge (python -m grader judge delaunay FILE), sandboxed, on the solutions here:")
        for name in ("accepted_walk.py", "wrong_tutorial.py"):
            if not (solutions / name).is_file():  # the student edition ships the wrong one only
                continue
            run = subprocess.run([sys.executable, "-m", "grader", "judge", "delaunay", str(solutions / name)],
                                 capture_output=True, text=True, cwd=root, timeout=600)
            summary = [line for line in run.stdout.splitlines() if line.startswith("delaunay:")]
            print(f"   {name}: {summary[0] if summary else run.stderr.strip()[-300:]}")


def main(argv: list[str]) -> int:
    if argv[:1] in ([], ["demo"]):
        demo()
        return 0
    if argv[:1] == ["warm"]:
        from reference_impl.warmup import main as warm_main
        return warm_main()
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
