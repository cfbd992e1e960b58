"""Seeded test generator for the Delaunay problems (`delaunay`, `bowyer-watson-timed`).

The grader calls ``generate(case, seed)`` for every case listed in the problem's ``course.yaml``
and ``solve(points)`` for the expected answer (computed by ``reference_impl``, in the grader's
process only). Run it by hand to print one case in the problem's input format:

    python assignments/delaunay/generators/generator.py '{"kind": "grid", "w": 3, "h": 3}' 7

Example:
    >>> generate({"kind": "tutorial"}, 0)
    [[1.0, 1.0], [3.0, 2.0], [5.0, 1.0], [4.0, 4.0]]
"""

from __future__ import annotations

import json
import math
import random
import sys

KINDS = ("tutorial", "points", "uniform", "clustered", "grid", "cocircular", "circle", "collinear",
         "duplicates", "scaled")


def generate(case: dict, seed: int) -> list[list[float]]:
    """Points (a list of ``[x, y]`` floats) for one case; the same ``(case, seed)`` gives the same points."""
    rng = random.Random(seed)
    kind = case.get("kind")
    if kind not in KINDS:
        raise ValueError(f"unknown case kind {kind!r}; expected one of {', '.join(KINDS)}")
    n = int(case.get("n", 10))
    if kind == "tutorial":  # the tutorial's dry run
        pts = [(1, 1), (3, 2), (5, 1), (4, 4)]
    elif kind == "points":
        pts = [tuple(p) for p in case["points"]]
    elif kind == "uniform":
        pts = [(rng.random(), rng.random()) for _ in range(n)]
    elif kind == "clustered":
        centres = [(rng.random(), rng.random()) for _ in range(max(1, n // 200))]
        pts = []
        for _ in range(n):
            cx, cy = rng.choice(centres)
            pts.append((cx + rng.gauss(0, 0.01), cy + rng.gauss(0, 0.01)))
    elif kind == "grid":  # every grid square is cocircular: the answer is not unique
        w, h = int(case.get("w", 10)), int(case.get("h", case.get("w", 10)))
        pts = [(i, j) for i in range(w) for j in range(h)]
    elif kind == "cocircular":  # integer points exactly on x^2 + y^2 = r^2
        r = int(case.get("r", 25))
        pts = [(x, y) for x in range(-r, r + 1) for y in range(-r, r + 1) if x * x + y * y == r * r]
    elif kind == "circle":  # nearly cocircular floats (rounding decides each incircle test)
        pts = [(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)) for k in range(n)]
    elif kind == "collinear":  # no triangle exists
        pts = [(k, 2 * k + 1) for k in range(n)]
    elif kind == "duplicates":  # the tutorial's duplicate test plus random repeats
        base = [(rng.randint(0, 9), rng.randint(0, 9)) for _ in range(n)]
        pts = base + [rng.choice(base) for _ in range(int(case.get("repeats", n)))]
    else:  # scaled uniform: 1e-300 and 1e300 break epsilon tests and fixed super-triangles
        pts = [(rng.random(), rng.random()) for _ in range(n)]
    scale = float(case.get("scale", 1.0))
    if case.get("shuffle", True):
        rng.shuffle(pts)
    return [[float(x) * scale, float(y) * scale] for x, y in pts]


def solve(points: list[list[float]]) -> list[list[int]]:
    """A valid answer (CCW triangles) from the reference library, for ``.ans`` files and messages."""
    import numpy as np
    from reference_impl import Delaunay

    if len(points) < 3:
        return []
    return np.asarray(Delaunay(np.asarray(points, dtype=float)).simplices).tolist()


if __name__ == "__main__":
    pts = generate(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(pts)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in pts))
