"""Seeded test generator for `obstacle-clearance`: point obstacles plus a start and a goal.

The grader calls ``generate_args(case, seed) -> [points, start, goal]`` for every case of
``course.yaml`` and ``solve(points, start, goal)`` (``reference_impl.max_clearance``, grader side
only) for the answer. Point sets come from the Delaunay problems' generator (same kinds: grid,
cocircular, collinear, duplicates, scaled, ...) plus the kinds below. Print one case:

    python assignments/obstacle-clearance/generators/generator.py '{"kind": "room", "n": 24}' 3

Example:
    >>> generate_args({"kind": "points", "points": [[0, 0], [2, 0]], "start": [1, 1], "goal": [1, -1]}, 0)
    [[[0.0, 0.0], [2.0, 0.0]], [1.0, 1.0], [1.0, -1.0]]
"""
from __future__ import annotations

import importlib.util
import json
import math
import random
import sys
from pathlib import Path

_BASE = Path(__file__).resolve().parents[2] / "delaunay" / "generators" / "generator.py"
OWN_KINDS = ("room", "offset", "far_clusters", "thin")


def _base():
    spec = importlib.util.spec_from_file_location("_delaunay_generator", _BASE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def point_set(case: dict, seed: int) -> list[list[float]]:
    """The obstacles: a kind of the Delaunay generator, or ``room`` (a ring of n points with one
    wider gap, the door), ``offset`` (uniform in a square of side ``spread``, 1000, shifted by ``offset``, 1e9) or
    ``far_clusters`` (a dense cluster of n points and a sparse one of n // 50, far apart) or
    ``thin`` (uniform in a 1 x 0.01 strip: most circumcentres fall outside the hull)."""
    rng = random.Random(seed)
    kind = case.get("kind")
    n = int(case.get("n", 10))
    if kind == "room":
        door = float(case.get("door", 2.5))          # the gap is `door` times the regular spacing
        step = 2 * math.pi / (n - 1 + door)
        pts = [(math.cos(step * (k + door)), math.sin(step * (k + door))) for k in range(n)]
    elif kind == "offset":
        off, spread = float(case.get("offset", 1e9)), float(case.get("spread", 1000.0))
        pts = [(off + spread * rng.random(), off + spread * rng.random()) for _ in range(n)]
    elif kind == "far_clusters":
        pts = [(rng.gauss(0, 1e-3), rng.gauss(0, 1e-3)) for _ in range(n)]
        pts += [(100 + rng.gauss(0, 10), rng.gauss(0, 10)) for _ in range(max(3, n // 50))]
    elif kind == "thin":
        pts = [(rng.random(), 0.01 * rng.random()) for _ in range(n)]
    else:
        return _base().generate(case, seed)
    scale = float(case.get("scale", 1.0))
    return [[float(x) * scale, float(y) * scale] for x, y in pts]


def _box(points: list[list[float]]) -> tuple[float, float, float, float]:
    if not points:
        return -1.0, -1.0, 1.0, 1.0
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return min(xs), min(ys), max(xs), max(ys)


def generate_args(case: dict, seed: int) -> list:
    """``[points, start, goal]``. ``start`` / ``goal`` are given in the case or drawn: ``"inside"``
    (uniform in the points' bounding box, the default), ``"outside"`` (beyond the box on the
    left / right), ``"centre"`` of the box, or ``"obstacle"`` (on a random obstacle)."""
    points = point_set(case, seed)
    rng = random.Random(seed + 1)
    x0, y0, x1, y1 = _box(points)
    w, h = x1 - x0, y1 - y0
    scale = float(case.get("scale", 1.0))

    def place(spec, side):
        if isinstance(spec, list):
            return [float(spec[0]) * scale, float(spec[1]) * scale]
        if spec == "outside":
            return [x0 - 0.5 * w - 1e-9 * scale if side == 0 else x1 + 0.5 * w + 1e-9 * scale, y0 + 0.5 * h]
        if spec == "centre":
            return [0.5 * x0 + 0.5 * x1, 0.5 * y0 + 0.5 * y1]
        if spec == "obstacle":
            return list(rng.choice(points))
        return [x0 + rng.random() * w, y0 + rng.random() * h]

    return [points, place(case.get("start", "inside"), 0), place(case.get("goal", "inside"), 1)]


def solve(points: list, start: list, goal: list) -> float:
    """The reference radius (``reference_impl.max_clearance``)."""
    from reference_impl import max_clearance

    return max_clearance(points, start, goal)


if __name__ == "__main__":
    pts, s, g = generate_args(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(pts)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in pts) + f"{s[0]!r} {s[1]!r}\n{g[0]!r} {g[1]!r}\n")
