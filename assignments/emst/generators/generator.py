"""Seeded test generator for `emst` (and the point cases of `closest-pair`, `proximity-network`).

``generate(case, seed)`` returns the points (the entry function's one argument): the point kinds of the Delaunay
problems (``assignments/delaunay/generators/generator.py``: tutorial, grid, cocircular, collinear,
duplicates, scaled, ...) plus the kinds that are hard for proximity graphs:

* ``clusters``: clusters of very different sizes and spreads (``sizes``, ``spreads``);
* ``near_ties``: ``count`` pairs whose squared lengths differ by one part in 2**60, or with
  ``shape: triangles`` triangles whose two long sides differ by less than the rounding of their
  squared lengths: float lengths call them equal, exact arithmetic does not;
* ``vertical``: a vertical line (``n``) plus a few points off it, the worst case of sweeps by x;
* ``columns``: ``cols`` columns one apart, each of ``per`` points ten apart in y (integer
  coordinates, a random shift of 0..4 in y per point): the short edges join neighbouring columns,
  and ``per`` - 1 points lie between their ends in (x, y) order, so a window of a fixed size in
  sorted order misses them;

and, for every kind, ``offset`` (added to both coordinates after ``scale``, e.g. 1e9).
``solve(points)`` is the reference answer (``reference_impl``, grader side only): the EMST over
all n indices, each duplicate joined to its first copy by a zero-length edge.

    python assignments/emst/generators/generator.py '{"kind": "near_ties", "count": 3}' 7

Example:
    >>> generate({"kind": "tutorial", "shuffle": False}, 0)
    [[1.0, 1.0], [3.0, 2.0], [5.0, 1.0], [4.0, 4.0]]
    >>> solve([[1, 1], [3, 2], [5, 1], [4, 4], [1, 1]])
    [[0, 1], [0, 4], [1, 2], [1, 3]]
"""

from __future__ import annotations

import importlib.util
import json
import random
import sys
from pathlib import Path

_spec = importlib.util.spec_from_file_location(
    "_delaunay_point_cases", Path(__file__).resolve().parents[2] / "delaunay" / "generators" / "generator.py")
_points = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_points)
KINDS = _points.KINDS + ("clusters", "near_ties", "vertical", "columns")


def _points_for(case: dict, seed: int) -> list[list[float]]:
    rng = random.Random(seed)
    kind = case.get("kind")
    if kind == "clusters":  # e.g. 2000 points within 1e-6 next to 5 points spread over 1
        pts = []
        for size, spread in zip(case.get("sizes", [500, 5]), case.get("spreads", [1e-6, 1.0])):
            cx, cy = rng.random(), rng.random()
            pts += [(cx + spread * rng.random(), cy + spread * rng.random()) for _ in range(size)]
    elif kind == "near_ties" and case.get("shape") == "triangles":
        # A, B one apart and C above them: |AC|^2 - |BC|^2 = 2**-52 is below the rounding of
        # the squared lengths (about 4.25), so floats see a tie that exact arithmetic breaks
        pts = []
        for k in range(int(case.get("count", 4))):
            pts += [(0.0, 8.0 * k), (1.0, 8.0 * k), (0.5 + 2.0 ** -53, 8.0 * k + 2.0)]
    elif kind == "near_ties":  # unit pairs and pairs of squared length 1 + 2**-60 (exact in doubles)
        pts = []
        for k in range(int(case.get("count", 4))):
            x, y = 8.0 * k, 4.0 * (k % 3)
            pts += [(x, y), (x + 1.0, y + (2.0 ** -30 if k % 2 == 0 else 0.0))]
    elif kind == "vertical":
        n = int(case.get("n", 100))
        pts = [(0.0, rng.random()) for _ in range(n)] + [(rng.random(), rng.random()) for _ in range(3)]
    elif kind == "columns":
        cols, per = int(case.get("cols", 2)), int(case.get("per", 10))
        if cols < 1 or per < 1:
            raise ValueError(f"columns: cols and per must be positive, got {cols} and {per}")
        pts = [(float(c), 10.0 * k + rng.randint(0, 4)) for c in range(cols) for k in range(per)]
    else:
        return _points.generate({**case, "shuffle": False}, seed)
    return [[float(x), float(y)] for x, y in pts]


def generate(case: dict, seed: int) -> list[list[float]]:
    """Points for one case; the same ``(case, seed)`` gives the same points."""
    if case.get("kind") not in KINDS:
        raise ValueError(f"unknown case kind {case.get('kind')!r}; expected one of {', '.join(KINDS)}")
    pts = _points_for(case, seed)
    scale, offset = float(case.get("scale", 1.0)), float(case.get("offset", 0.0))
    if case.get("kind") in ("clusters", "near_ties", "vertical", "columns"):
        pts = [[x * scale, y * scale] for x, y in pts]
    if case.get("shuffle", True):
        random.Random(seed + 1).shuffle(pts)
    return [[x + offset, y + offset] for x, y in pts]


def solve(points: list[list[float]]) -> list[list[int]]:
    """A Euclidean minimum spanning tree over all n indices (duplicates by zero-length edges)."""
    import numpy as np
    from reference_impl import Delaunay, euclidean_mst

    if len(points) < 2:
        return []
    P = np.asarray(points, dtype=float)
    edges = euclidean_mst(P).tolist()
    edges += [[int(r), i] for i, r in enumerate(Delaunay(P).index_map.tolist()) if r != i]
    return sorted(edges)


if __name__ == "__main__":
    pts = generate(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(pts)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in pts))
