"""Seeded test generator for `navmesh`: rooms (a boundary polygon with polygonal holes) and a start
and a goal point.

``generate_args(case, seed)`` returns the entry function's four arguments
``[boundary, holes, start, goal]``. Case kinds:

* ``room``: everything given in the case (``boundary``, ``holes``, ``start``, ``goal``), e.g. the
  hand-made degenerate rooms: paths along walls, holes touching the straight line at a vertex,
  collinear wall vertices, start or goal on a wall or outside;
* ``cells``: a ``boundary`` (``rect``, ``circle`` or ``star`` with ``boundary_n`` vertices) around
  a ``cells`` x ``cells`` grid with one random convex hole (3 to ``max_sides`` corners) strictly
  inside each cell; start and goal are random grid corners (always in the gaps between holes).

For every kind, ``scale_exp`` multiplies all coordinates by ``2**scale_exp`` (exact: a power of
two) and then ``offset`` is added (e.g. 1e9, exact for the integer rooms).
``solve(boundary, holes, start, goal)`` is ``shortest_path`` below (the problem's adapter on
``reference_impl.NavMesh``; grader side only).

    python assignments/navmesh/generators/generator.py '{"kind": "cells", "cells": 2}' 7

Example:
    >>> generate_args({"kind": "room", "boundary": [[0, 0], [4, 0], [4, 4], [0, 4]], "holes": [],
    ...                "start": [1, 1], "goal": [3, 1], "offset": 10}, 0)[2:]
    [[11.0, 11.0], [13.0, 11.0]]
    >>> solve([[0, 0], [4, 0], [4, 4], [0, 4]], [], [1, 1], [3, 2])
    [[1.0, 1.0], [3.0, 2.0]]
"""
from __future__ import annotations

import json
import math
import random
import sys

KINDS = ("room", "cells")


def _cells(case: dict, rng: random.Random):
    k = int(case.get("cells", 3))
    size = float(case.get("size", 100.0))
    shape, nb = case.get("boundary", "rect"), int(case.get("boundary_n", 64))
    if shape == "rect":
        half = size * k / 2
        boundary = [[-half - size, -half - size], [half + size, -half - size],
                    [half + size, half + size], [-half - size, half + size]]
    elif shape in ("circle", "star"):
        radius = size * k * 1.2
        boundary = []
        for i in range(nb):
            r = radius * (0.9 if shape == "star" and i % 2 else 1.0)
            a = 2 * math.pi * i / nb
            boundary.append([r * math.cos(a), r * math.sin(a)])
    else:
        raise ValueError(f"navmesh generator: unknown boundary {shape!r} (rect, circle, star)")
    lo = -size * k / 2
    holes = []
    for i in range(k):
        for j in range(k):
            cx, cy = lo + size * (i + 0.5), lo + size * (j + 0.5)
            m = rng.randint(3, int(case.get("max_sides", 6)))
            angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(m))
            r = size * rng.uniform(0.25, 0.45)
            holes.append([[cx + r * math.cos(a), cy + r * math.sin(a)] for a in angles])

    def corner():
        return [lo + size * rng.randint(0, k), lo + size * rng.randint(0, k)]

    start, goal = corner(), corner()
    if case.get("start_outside"):
        start = [4.0 * size * k, 0.0]
    return boundary, holes, start, goal


def generate_args(case: dict, seed: int) -> list:
    """``[boundary, holes, start, goal]`` for one case; the same ``(case, seed)`` gives the same room."""
    kind = case.get("kind")
    if kind == "room":
        boundary, holes, start, goal = case["boundary"], case.get("holes", []), case["start"], case["goal"]
    elif kind == "cells":
        boundary, holes, start, goal = _cells(case, random.Random(seed))
    else:
        raise ValueError(f"navmesh generator: unknown case kind {kind!r}; expected one of {', '.join(KINDS)}")
    scale = 2.0 ** int(case.get("scale_exp", 0))
    offset = float(case.get("offset", 0.0))

    def fix(p):
        return [float(p[0]) * scale + offset, float(p[1]) * scale + offset]

    return [[fix(p) for p in boundary], [[fix(p) for p in h] for h in holes], fix(start), fix(goal)]


def shortest_path(boundary, holes, start, goal) -> list[tuple[float, float]] | None:
    """The problem's adapter: the Euclidean shortest path ``[start, ..., goal]`` (tuples) inside
    ``boundary`` outside ``holes``, or None when start or goal is outside the free space
    (``reference_impl.NavMesh(boundary, holes).shortest_path(start, goal)``; grader side only).

    >>> shortest_path([(0, 0), (4, 0), (4, 4), (0, 4)], [], (1, 1), (3, 2))
    [(1.0, 1.0), (3.0, 2.0)]
    """
    from reference_impl import NavMesh

    return NavMesh(boundary, holes).shortest_path(start, goal)


def solve(boundary, holes, start, goal) -> list[list[float]] | None:
    """The shortest path ``[start, ..., goal]`` (``shortest_path`` above, as lists), or None."""
    path = shortest_path(boundary, holes, start, goal)
    return None if path is None else [[float(x), float(y)] for x, y in path]


def write_input(args: list) -> str:
    """The text format: boundary (n, n lines), holes (h, then m and m lines each), start, goal."""
    boundary, holes, start, goal = args

    def ring(pts):
        return f"{len(pts)}\n" + "".join(f"{float(x)!r} {float(y)!r}\n" for x, y in pts)

    return (ring(boundary) + f"{len(holes)}\n" + "".join(ring(h) for h in holes)
            + f"{float(start[0])!r} {float(start[1])!r}\n{float(goal[0])!r} {float(goal[1])!r}\n")


if __name__ == "__main__":
    sys.stdout.write(write_input(generate_args(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)))
