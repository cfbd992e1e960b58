"""Seeded test generator for `delaunay-3d`: point sets in space.

The grader calls ``generate(case, seed)`` for every case in ``course.yaml`` and ``solve(points)``
for the reference answer (``reference_impl.delaunay_3d``, in the grader's process only). Print one
case in the input format by hand:

    python assignments/delaunay-3d/generators/generator.py '{"kind": "grid", "a": 2, "b": 2, "c": 2}' 7

Example:
    >>> generate({"kind": "points", "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "shuffle": False}, 0)
    [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
"""

from __future__ import annotations

import json
import math
import random
import sys

KINDS = ("points", "uniform", "ball", "clustered", "grid", "lattice-sphere", "sphere", "coplanar",
         "layers", "collinear", "duplicates", "moment-curve")


def generate(case: dict, seed: int) -> list[list[float]]:
    """Points (a list of ``[x, y, z]`` floats) for one case; the same ``(case, seed)`` gives the same points."""
    rng = random.Random(seed)
    kind = case.get("kind")
    if kind not in KINDS:
        raise ValueError(f"delaunay-3d generator: unknown case kind {kind!r}; expected one of {', '.join(KINDS)}")
    n = int(case.get("n", 10))
    if kind == "points":
        pts = [tuple(p) for p in case["points"]]
    elif kind == "uniform":
        pts = [(rng.random(), rng.random(), rng.random()) for _ in range(n)]
    elif kind == "ball":
        pts = []
        while len(pts) < n:
            p = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
            if sum(v * v for v in p) <= 1:
                pts.append(p)
    elif kind == "clustered":  # a few dense clusters of very different sizes in a sparse cloud
        pts = [(rng.random(), rng.random(), rng.random()) for _ in range(n // 4)]
        for size, spread in ((n // 2, 1e-4), (n // 8, 1e-2), (n - n // 4 - n // 2 - n // 8, 1e-7)):
            c = (rng.random(), rng.random(), rng.random())
            pts += [tuple(c[i] + rng.gauss(0, spread) for i in range(3)) for _ in range(size)]
    elif kind == "grid":  # every cube of the grid is cospherical: the answer is far from unique
        a, b, c = int(case.get("a", 3)), int(case.get("b", case.get("a", 3))), int(case.get("c", case.get("a", 3)))
        pts = [(i, j, k) for i in range(a) for j in range(b) for k in range(c)]
    elif kind == "lattice-sphere":  # integer points exactly on x^2 + y^2 + z^2 = r2 (+ the centre)
        r2 = int(case.get("r2", 27))
        r = math.isqrt(r2)
        pts = [(x, y, z) for x in range(-r, r + 1) for y in range(-r, r + 1) for z in range(-r, r + 1)
               if x * x + y * y + z * z == r2]
        if case.get("centre"):
            pts.append((0, 0, 0))
    elif kind == "sphere":  # nearly cospherical floats: rounding decides each in-sphere test
        pts = []
        for _ in range(n):
            v = [rng.gauss(0, 1) for _ in range(3)]
            norm = math.sqrt(sum(x * x for x in v))
            pts.append(tuple(x / norm for x in v))
    elif kind == "coplanar":  # no tetrahedron exists
        pts = [(rng.random(), rng.random(), 0.0) for _ in range(n)]
        pts = [(x, y, x + 2 * y) for x, y, _ in pts] if case.get("tilted") else pts
    elif kind == "layers":  # several planes of random points: many coplanar quadruples
        k = int(case.get("k", 3))
        pts = [(rng.random(), rng.random(), float(z)) for z in range(k) for _ in range(n)]
    elif kind == "collinear":
        pts = [(t, 2 * t + 1, 3 * t - 2) for t in range(n)]
    elif kind == "duplicates":  # a small integer grid, every point repeated
        base = [(rng.randint(0, 3), rng.randint(0, 3), rng.randint(0, 3)) for _ in range(n)]
        pts = base + [rng.choice(base) for _ in range(int(case.get("repeats", n)))]
    else:  # moment curve (t, t^2, t^3): a quadratic number of tetrahedra
        pts = [(t, t * t, t ** 3) for t in range(-(n // 2), n - n // 2)]
    scale = float(case.get("scale", 1.0))
    offset = float(case.get("offset", 0.0))
    if case.get("shuffle", True):
        rng.shuffle(pts)
    return [[float(v) * scale + offset for v in p] for p in pts]


def solve(points: list[list[float]]) -> list[list[int]]:
    """A valid answer from the reference library (positively oriented tetrahedra)."""
    import numpy as np
    from reference_impl import delaunay_3d

    if len(points) < 4:
        return []
    return np.asarray(delaunay_3d(np.asarray(points, dtype=float).reshape(-1, 3))).tolist()


if __name__ == "__main__":
    pts = generate(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(pts)}\n" + "".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in pts))
