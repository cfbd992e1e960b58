"""Public input families that show floating-point and finite-bound mistakes: small inputs at every scale.

The lattice configurations of :mod:`grader.problems.smallcases` are small integers near the
origin: no rounding error, overflow or underflow ever shows on them. The families here are the same
kind of small inputs (at most 10 points; polygon vertices for ``navmesh``; operations for
``dynamic-network``), transformed so that a solution with plain double predicates, an epsilon, or
a finite super-triangle meets its limits, while each input stays exact:

* **scaled** by powers of two (``2**1000``, ``2**-1000``, ``2**40``, ``2**-40``): every coordinate
  stays exactly representable, but squares and determinants overflow to ``inf`` or underflow to 0;
* **shifted** far from the origin (by ``2**30``, ``1e9``, ``1e15``; exact for the small halves
  and integers used here): differences lose no bits, products of coordinates do;
* **one unit in the last place** (``math.nextafter``) off a degenerate configuration: four
  cocircular points or three collinear ones, one coordinate nudged up or down, at the origin and
  far from it, so that inside/outside or left/right is decided by exact arithmetic alone;
* **nearly flat** hull triangles (a point ``1e-12`` off a segment) and points beyond ``1e5`` and
  ``1e6`` (a finite super-triangle no longer contains them);
* for ``navmesh``, rooms whose shortest path must not cut through a hole between two of its own
  corners (the segment touches the hole only at its ends).

Every family is public code (no hidden data, no hidden seed) and deterministic given its seed:
``families(problem, seed, bases)`` lists the special inputs first, then the transforms of a few
small lattice configurations and of ``bases`` (the caller's random small cases). Inputs are
generator cases, like :func:`grader.problems.smallcases.cases_for`'s; a case the problem's input
validators refuse is skipped by whoever judges it (the counterexample search validates each).

Run: ``python -m grader.problems.families PROBLEM`` prints the cases, one a line.

Example:
    >>> cases = families("delaunay", seed=1)
    >>> len(cases) > 50, all(len(c["points"]) <= 10 for c in cases)
    (True, True)
    >>> scaled({"kind": "points", "points": [[1, 2]]}, 2.0 ** -1000)["points"] == [[2.0 ** -1000, 2.0 ** -999]]
    True
"""
from __future__ import annotations

import math
import random
import sys
from typing import Callable, Iterable, Sequence

from . import smallcases

__all__ = ["families", "transformed", "scaled", "shifted", "SCALES", "SHIFTS", "MAX_SIZE", "interleave"]

MAX_SIZE = 10
"""No family case is larger than this (points; polygon vertices; operations)."""
SCALES = (2.0 ** 1000, 2.0 ** -1000, 2.0 ** 40, 2.0 ** -40)
"""Exact scale factors: powers of two, so the small lattices stay exact at 1e+301 and 1e-301."""
SHIFTS = (2.0 ** 30, 1e9, 1e15)
"""Offsets far from the origin; exact for coordinates that are multiples of 1/8 below 2**50."""
SCALES_ONLY = ("voronoi",)
"""Problems with scaled lattices only (no shifts, no special cases): voronoi's checker merges cell
vertices closer than a tolerance relative to the largest coordinate, so a box a few units wide at
1e15, or 1e-12 tall and 4 wide, has cells of one or two vertices even for a right answer."""
NEAR, FAR = 1e-12, (1e5, 1e6)
POINT_PROBLEMS = ("delaunay", "bowyer-watson-timed", "emst", "proximity-network", "closest-pair",
                  "largest-empty-circle", "edge-flip", "voronoi", "obstacle-clearance")

Coord = Callable[[Sequence[float]], list]


def transformed(case: dict, f: Coord) -> dict:
    """``case`` with ``f`` applied to every coordinate tuple it holds (points, box corners, start
    and goal, polygon rings, the positions of ``join`` operations); other keys unchanged."""
    out = dict(case)
    for key in ("points", "boundary"):
        if isinstance(case.get(key), list):
            out[key] = [f(p) for p in case[key]]
    for key in ("start", "goal"):
        if isinstance(case.get(key), list):
            out[key] = f(case[key])
    if isinstance(case.get("holes"), list):
        out["holes"] = [[f(p) for p in h] for h in case["holes"]]
    if isinstance(case.get("box"), list) and len(case["box"]) == 4:
        lo, hi = f(case["box"][:2]), f(case["box"][2:])
        out["box"] = [lo[0], lo[1], hi[0], hi[1]]
    if isinstance(case.get("operations"), list):
        out["operations"] = [["join", *f(op[1:3])] if op and op[0] == "join" else op for op in case["operations"]]
    return out


def scaled(case: dict, factor: float) -> dict:
    """``case`` with every coordinate multiplied by ``factor`` (``ValueError`` unless positive)."""
    if not (isinstance(factor, (int, float)) and math.isfinite(factor) and factor > 0):
        raise ValueError(f"scale factor must be a positive finite number, got {factor!r}")
    return transformed(case, lambda p: [float(c) * factor for c in p])


def shifted(case: dict, offset: float) -> dict:
    """``case`` with ``offset`` added to every coordinate (``ValueError`` unless finite)."""
    if not (isinstance(offset, (int, float)) and math.isfinite(offset)):
        raise ValueError(f"offset must be a finite number, got {offset!r}")
    return transformed(case, lambda p: [float(c) + offset for c in p])


def size_of(case: dict) -> int:
    """Points, else polygon vertices, else operations of a case."""
    if isinstance(case.get("operations"), list):
        return len(case["operations"])
    if isinstance(case.get("boundary"), list):
        return len(case["boundary"]) + sum(len(h) for h in case.get("holes") or [])
    return len(case.get("points") or [])


def _nudged(points: list[list[float]], k: int, axis: int, up: bool) -> list[list[float]]:
    out = [list(map(float, p)) for p in points]
    out[k][axis] = math.nextafter(out[k][axis], math.inf if up else -math.inf)
    return out


def _special_2d() -> list[list[list[float]]]:
    """Point lists: nearly flat hull triangles, points beyond 1e5 and 1e6, then one-ulp nudges of
    cocircular and collinear configurations (near the origin and far from it)."""
    square = [[0, 0], [2, 0], [2, 2], [0, 2]]
    kite = [[0, 0], [2, 0], [2, 2], [0, 2], [1, 3]]
    line = [[0, 0], [1, 1], [2, 2], [0, 2]]
    out: list[list[list[float]]] = [[list(map(float, p)) for p in kite]]
    for eps in (NEAR, -NEAR, 1e-9):
        out.append([[0.0, 0.0], [1.0, eps], [2.0, 0.0], [1.0, 1.0]])
        out.append([[0.0, 0.0], [2.0, 0.0], [1.0, eps]])
    for far in FAR:
        out.append([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [2 * far, 2 * far]])
        out.append([[-far, -far], [far, -far], [0.0, far], [0.0, 0.0], [1.0, 1.0]])
        out.append([[0.0, 0.0], [far, 1.0], [-far, 1.0], [0.0, -far]])
    for offset in (0.0, 2.0 ** 30, 1e9):
        for base, movers in ((square, (2, 3)), (line, (1,))):
            moved = [[c + offset for c in p] for p in base]
            for k in movers:
                for axis in (0, 1):
                    for up in (True, False):
                        out.append(_nudged(moved, k, axis, up))
    return out


def _special_3d() -> list[list[list[float]]]:
    """3D: one-ulp nudges of a cube's corners (cospherical), a nearly flat tetrahedron, far points."""
    cube = [[x, y, z] for x in (0, 2) for y in (0, 2) for z in (0, 2)]
    out = []
    for offset in (0.0, 2.0 ** 30):
        moved = [[c + offset for c in p] for p in cube]
        for k in (0, 7):
            for axis in range(3):
                for up in (True, False):
                    out.append(_nudged(moved, k, axis, up))
    out.append([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [1.0, 1.0, NEAR], [1.0, 1.0, 1.0]])
    for far in FAR:
        out.append([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [far, far, far]])
    return out


def _points_case(problem: str, pts: list, k: int) -> dict:
    """A generator case of a point problem around the point list ``pts`` (box, start/goal as the
    problem needs: derived from the points' bounding box, so they scale with them)."""
    case: dict = {"kind": "points", "points": pts, "shuffle": False}
    if problem == "edge-flip":
        case["start"] = "sweep"
    elif problem in ("voronoi", "obstacle-clearance"):
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
        if problem == "voronoi":
            case["box"] = [x0, y0, x1, y1] if (x0 < x1 and y0 < y1 and k % 2) else \
                [x0 - (x1 - x0 or 1), y0 - (y1 - y0 or 1), x1 + (x1 - x0 or 1), y1 + (y1 - y0 or 1)]
        else:
            case["start"], case["goal"] = [x0, (y0 + y1) / 2], [x1, (y0 + y1) / 2]
    return case


def _rooms() -> list[dict]:
    """``navmesh`` rooms where the shortest path is tempted through a hole along a segment between
    two of the hole's corners (it touches the hole only at its ends); and a concave hole."""
    square = [[0, 0], [4, 0], [4, 4], [0, 4]]
    big_hole = [[1, 1], [1, 3], [3, 3], [3, 1]]
    ell_hole = [[1, 1], [1, 3], [2, 3], [2, 2], [3, 2], [3, 1]]
    out = []
    for hole in (big_hole, ell_hole):
        for start, goal in (([0.5, 0.5], [3.5, 3.5]), ([3.5, 3.5], [0.5, 0.5]), ([0.5, 3.5], [3.5, 0.5]),
                            ([1, 1], [3.5, 3.5]), ([0.5, 0.5], [3, 3])):
            out.append({"kind": "room", "boundary": square, "holes": [hole], "start": start, "goal": goal})
    return out


def _lattice_bases(problem: str, count: int) -> list[dict]:
    """``count`` lattice configurations of the problem (the larger ones, spread out)."""
    try:
        cases = smallcases.cases_for(problem)
    except ValueError:
        return []
    cases = [c for c in cases if size_of(c) <= MAX_SIZE and (size_of(c) >= 3 or problem == "navmesh")]
    if problem == "dynamic-network":
        return []
    step = max(1, len(cases) // count)
    return cases[::-1][::step][:count]


def _network(pts: list) -> dict:
    """Operations joining ``pts`` (at most 4), querying each, failing the first, querying again."""
    pts = pts[:4]
    ops: list = [["join", float(x), float(y)] for x, y in pts]
    ops += [["neighbors", i] for i in range(len(pts))] + [["fail", 0]] + [["neighbors", i] for i in range(1, len(pts))]
    return {"kind": "ops", "operations": ops[:MAX_SIZE]}


def families(problem: str, seed: int = 1, bases: Iterable[dict] = ()) -> list[dict]:
    """The family cases of ``problem`` (at most :data:`MAX_SIZE` elements each): every scale and
    shift of two lattice configurations first, then the special ones (nearly flat, far out, one-ulp
    nudges) in turn with the scales and shifts of more lattice configurations and of ``bases``
    (cases of the problem, e.g. random small ones), each base's transforms in an order shuffled by
    ``seed``. Deterministic. An empty list for a problem not known here (a course's own)."""
    rng = random.Random(seed)
    if problem == "delaunay-3d":
        special = [{"kind": "points", "points": p, "shuffle": False} for p in _special_3d()]
    elif problem == "navmesh":
        special = _rooms()
    elif problem == "dynamic-network":
        special = [_network(p) for p in _special_2d()]
    elif problem in POINT_PROBLEMS:
        special = [_points_case(problem, p, k) for k, p in enumerate(_special_2d())]
    else:
        return []
    if problem in SCALES_ONLY:
        special = []
    if problem == "dynamic-network":
        base_list = [_network(p) for p in smallcases.point_lists(max_n=4) if len(p) >= 3][::7]
    else:
        base_list = _lattice_bases(problem, 12)
    base_list += [b for b in bases if size_of(b) <= MAX_SIZE]
    moved = []
    for b in base_list:
        variants = [scaled(b, s) for s in SCALES] + [shifted(b, o) for o in SHIFTS if problem not in SCALES_ONLY]
        rng.shuffle(variants)
        moved.append(variants)
    head = [v for vs in moved[:2] for v in vs]             # every transform of two configurations first
    rest = [v for k in range(len(SCALES) + len(SHIFTS)) for vs in moved[2:] for v in vs[k:k + 1]]
    return [c for c in head + interleave(special, rest) if size_of(c) <= MAX_SIZE]


def interleave(*lists: Sequence) -> list:
    """One element of each list in turn, until all are used up.

    >>> interleave([1, 2, 3], ["a"])
    [1, 'a', 2, 3]
    """
    out, k = [], 0
    while any(k < len(seq) for seq in lists):
        out += [seq[k] for seq in lists if k < len(seq)]
        k += 1
    return out


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: python -m grader.problems.families PROBLEM")
    for c in families(sys.argv[1]):
        print(c)
