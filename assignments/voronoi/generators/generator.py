"""Seeded test generator for `voronoi`: sites plus a box that contains them.

The grader calls ``generate_args(case, seed) -> [points, bbox]`` for every case of ``course.yaml``
and ``solve(points, bbox)`` (``reference_impl.voronoi``, grader side only) for the answer. Point
sets are those of the obstacle-clearance generator (the Delaunay kinds plus ``room``, ``offset``,
``far_clusters``, ``thin``). The box (``box`` in the case): ``margin`` (the points' bounding box
grown by ``margin`` times its size, 0.1 by default), ``tight`` (the bounding box itself: sites on
the box's sides and corners) or a given ``[xmin, ymin, xmax, ymax]``. Print one case:

    python assignments/voronoi/generators/generator.py '{"kind": "grid", "w": 3, "h": 3, "box": "tight"}' 3

Example:
    >>> generate_args({"kind": "points", "points": [[0, 0], [2, 0]], "box": [-1, -1, 3, 1]}, 0)
    [[[0.0, 0.0], [2.0, 0.0]], [-1.0, -1.0, 3.0, 1.0]]
"""
from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

_POINT_SETS = Path(__file__).resolve().parents[2] / "obstacle-clearance" / "generators" / "generator.py"


def generate_args(case: dict, seed: int) -> list:
    """``[points, bbox]`` for one case."""
    spec = importlib.util.spec_from_file_location("_clearance_generator", _POINT_SETS)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    points = module.point_set(case, seed)
    box = case.get("box", "margin")
    scale = float(case.get("scale", 1.0))
    if isinstance(box, list):
        return [points, [float(v) * scale for v in box]]
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    x0, y0, x1, y1 = min(xs), min(ys), max(xs), max(ys)
    size = max(x1 - x0, y1 - y0) or max(abs(x0), abs(y0), scale)
    m = 0.0 if box == "tight" else float(case.get("margin", 0.1)) * size
    mx = m if x1 > x0 else max(m, 0.1 * size)         # a flat set still needs a box with area
    my = m if y1 > y0 else max(m, 0.1 * size)
    return [points, [x0 - mx, y0 - my, x1 + mx, y1 + my]]


def solve(points: list, bbox: list) -> list:
    """One counter-clockwise polygon per point (``reference_impl.voronoi``)."""
    from reference_impl import voronoi

    return [c.tolist() for c in voronoi(points, bbox)]


if __name__ == "__main__":
    pts, box = generate_args(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(pts)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in pts) + " ".join(map(repr, box)) + "\n")
