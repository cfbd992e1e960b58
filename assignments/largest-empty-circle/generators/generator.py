"""Seeded test generator for `largest-empty-circle`.

The grader calls ``generate(case, seed) -> points`` for every case of ``course.yaml`` and
``solve(points)`` (``reference_impl.largest_empty_circle``, grader side only) for the answer.
Point sets are those of the obstacle-clearance generator (the Delaunay kinds plus ``room``,
``offset``, ``far_clusters`` and ``thin``); the input must not be all collinear. Print one case:

    python assignments/largest-empty-circle/generators/generator.py '{"kind": "thin", "n": 20}' 3

Example:
    >>> generate({"kind": "tutorial", "shuffle": False}, 0)
    [[1.0, 1.0], [3.0, 2.0], [5.0, 1.0], [4.0, 4.0]]
"""
from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

_POINT_SETS = Path(__file__).resolve().parents[2] / "obstacle-clearance" / "generators" / "generator.py"


def generate(case: dict, seed: int) -> list[list[float]]:
    """The points of one case (see the obstacle-clearance generator's ``point_set``)."""
    spec = importlib.util.spec_from_file_location("_clearance_generator", _POINT_SETS)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.point_set(case, seed)


def solve(points: list[list[float]]) -> list[float]:
    """``[x, y, r]`` from ``reference_impl.largest_empty_circle``."""
    from reference_impl import largest_empty_circle

    return list(largest_empty_circle(points))


if __name__ == "__main__":
    pts = generate(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(pts)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in pts))
