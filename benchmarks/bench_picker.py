"""Benchmark: what the kernel spends answering one dragged point in the point picker.

    python benchmarks/bench_picker.py                    # n = 30, 100, 300, 1000; 40 moves each
    python benchmarks/bench_picker.py --sizes 100 --moves 200

For each n, a ``PointPicker`` on n random points receives the same move messages the browser
sends during a drag (``kit/canvas.js``: point i to pixel (x, y)); each answer recomputes the
Delaunay triangles, redraws the lesson's matplotlib axes and turns them into the SVG scene
(``kit/scene.py``).  Printed per n: the median wall time of one whole answer and of its parts
(triangulate / draw / scene), the scene's size in JSON, and the same triangulation by
``scipy.spatial.Delaunay`` in the same process with the ratio answer/scipy (how much of an
answer is the triangulation itself).  The page's own numbers (drawing a move, the answer's
round trip) come from the browser test: ``tests/browser/test_jupyterlab.py -k drag``.

Example (2 cores, shared host)::

    n      answer ms  triangulate  draw  scene  scene KB  scipy ms  answer/scipy
    100       11.2        0.4       5.9    4.5      16       0.7        16
"""
from __future__ import annotations

import argparse
import json
import statistics
import time

import numpy as np
from scipy.spatial import Delaunay as ScipyDelaunay

from reference_impl.kit import PointPicker
from reference_impl.kit.picker import delaunay_triangles
from reference_impl.kit.scene import axes_scene


def measure(n: int, moves: int, seed: int = 0) -> dict:
    """Median milliseconds of one move answer and its parts for a picker of ``n`` random points."""
    picker = PointPicker(n=n)
    picker.load_preset("random")
    P = np.asarray(picker.view.points).reshape(-1, 2)
    i = int(np.argmin(np.hypot(P[:, 0] - 220, P[:, 1] - 200)))
    rng = np.random.default_rng(seed)
    whole, tri, draw, scene, sp = [], [], [], [], []
    x, y = P[i]
    for k in range(moves):
        x, y = x + rng.normal() * 2, y + rng.normal() * 2
        t = time.perf_counter()
        picker.handle_gesture({"kind": "move", "i": i, "x": float(x), "y": float(y), "seq": k + 1, "drag": 1,
                               "end": k == moves - 1})
        whole.append(time.perf_counter() - t)
        pts = picker.points
        t = time.perf_counter(); delaunay_triangles(pts); tri.append(time.perf_counter() - t)
        t = time.perf_counter(); picker._draw_axes(); draw.append(time.perf_counter() - t)
        t = time.perf_counter(); axes_scene(picker.canvas, pts); scene.append(time.perf_counter() - t)
        t = time.perf_counter(); ScipyDelaunay(pts); sp.append(time.perf_counter() - t)
    ms = lambda v: 1e3 * statistics.median(v)  # noqa: E731
    return {"n": n, "answer": ms(whole), "triangulate": ms(tri), "draw": ms(draw), "scene": ms(scene),
            "scene_kb": len(json.dumps(picker.view.scene)) / 1024, "scipy": ms(sp)}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[30, 100, 300, 1000])
    ap.add_argument("--moves", type=int, default=40)
    args = ap.parse_args(argv)
    if min(args.sizes) < 3 or args.moves < 1:
        raise SystemExit("--sizes must be at least 3 and --moves at least 1")
    measure(10, 3)                                           # numba and matplotlib warmed up
    print(f"{'n':>6} {'answer ms':>10} {'triangulate':>12} {'draw':>6} {'scene':>6} {'scene KB':>9} "
          f"{'scipy ms':>9} {'answer/scipy':>13}")
    for n in args.sizes:
        r = measure(n, args.moves)
        print(f"{r['n']:>6} {r['answer']:>10.1f} {r['triangulate']:>12.1f} {r['draw']:>6.1f} {r['scene']:>6.1f} "
              f"{r['scene_kb']:>9.0f} {r['scipy']:>9.1f} {r['answer'] / r['scipy']:>13.0f}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
