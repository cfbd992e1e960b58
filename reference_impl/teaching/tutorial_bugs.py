"""The original Bowyer-Watson tutorial's code (the one this course corrects), reproduced on
purpose: an exhibit of what goes wrong.

Run the examples:  python -m pytest reference_impl/teaching/tutorial_bugs.py

Do not use this code to triangulate anything; use ``bowyer_watson`` (the
teaching version) or ``Delaunay`` (the fast one).  ``naive_bowyer_watson``
does what the tutorial's code does, written anew, mistakes included.  The
mistakes are numbered as in lesson 04 and lesson 12:

1. triangles are never oriented, yet the in-circle determinant is read as
   "inside" when positive, which is only true for counter-clockwise triangles;
2. the cavity boundary keeps *one* copy of an edge shared by two bad
   triangles (it should drop both), so the new triangles overlap;
3. the super-triangle is fixed at +-1e5: (a) a point outside it (the tutorial's
   own test at 1e6) can lie in no circumcircle at all and is silently skipped;
   (b) at the end, every triangle touching the super-triangle is dropped, which
   also drops real hull triangles whose circumcircle contains a super vertex;
4. the in-circle test is ``np.linalg.det(...) > 0`` in floating point: ties and
   near-ties (cocircular points, grids) get a sign from rounding noise (and its
   remedy, an area epsilon, depends on the scale).

Each failure is shown below on a concrete input (``EXHIBITS``) and confirmed by
the exact checker ``verify.check_delaunay``; the course's tests repeat these
checks and show that ``bowyer_watson`` gets every one of them right.

>>> from reference_impl.exact.verify import check_delaunay
>>> def check(name, **kw):
...     pts = EXHIBITS[name]
...     return check_delaunay(pts, naive_bowyer_watson(pts, **kw))
>>> check("overlap")            # mistake 2: three points, the edge shared by two bad triangles is kept
(False, 'the directed edge 0->1 is used by 2 triangles: triangles overlap')
>>> check("clockwise")          # mistake 1 (with 2)
(False, 'triangle 1 = (1, 2, 3) is clockwise; triangles must be counter-clockwise')
>>> check("zero-area")
(False, 'triangle 3 = (2, 1, 3) is degenerate (zero area); triangles must be counter-clockwise')
>>> naive_bowyer_watson(EXHIBITS["large"]).tolist()   # mistake 3a, the tutorial's 1e6 test: no triangle
[]
>>> naive_bowyer_watson(EXHIBITS["hull-lost"]).tolist()   # mistake 3b: (0, 1, 2) is missing, a dent
[[0, 1, 3], [1, 2, 3]]
>>> print(check("hull-lost")[1])
edge 0-1 has a triangle on one side only but is not a convex hull edge (a hole, a gap or an overlap)

``fix`` switches single corrections on, to see which mistake causes what:
``"orientation"`` (orient every new triangle with the exact ``orient2d``),
``"predicate"`` (exact ``incircle`` instead of the determinant) and
``"boundary"`` (drop shared edges).

>>> check("overlap", fix=["boundary"])
(True, 'ok')
>>> check("clockwise", fix=["boundary"]), check("zero-area", fix=["boundary"])
((True, 'ok'), (True, 'ok'))

The orientation mistake bites together with the boundary one: a kept shared
edge can have the new point on its right, which makes a clockwise triangle,
whose in-circle sign is then backwards for every later point.  With a correct
boundary, every new triangle is counter-clockwise by construction (the course's
version still checks it with ``orient2d``), as long as the super-triangle is: the
tutorial's happens to be listed counter-clockwise, so on its own the mistake is
latent.  List the same corners clockwise and every in-circle answer is backwards
from the first point on (no point is ever inserted); orienting every triangle, the
super-triangle included, cures it:

>>> cw = SUPER_TRIANGLE[::-1]
>>> naive_bowyer_watson(EXHIBITS["clockwise"], fix=["predicate", "boundary"], super_triangle=cw).tolist()
[]
>>> check("clockwise", fix=ALL_FIXES, super_triangle=cw)
(True, 'ok')

Rounding noise in the determinant is the remaining mistake (4): on the 12 integer
points of x^2 + y^2 = 25 every in-circle test is an exact tie, which ``np.linalg.det``
decides by noise.  Which insertion orders break depends on the machine's BLAS, so
ten shuffles are tried; the exact predicate gets all of them right:

>>> import random
>>> orders = [random.Random(s).sample(RING_25, 12) for s in range(10)]
>>> any(not check_delaunay(q, naive_bowyer_watson(q, fix=["orientation", "boundary"]))[0] for q in orders)
True
>>> all(check_delaunay(q, naive_bowyer_watson(q, fix=ALL_FIXES))[0] for q in orders)
True

With all three fixes, what is left is the finite super-triangle, and it still
fails (mistake 3, both halves): only the vertex at infinity of ``bowyer_watson``
cures those.

>>> naive_bowyer_watson(EXHIBITS["large"], fix=ALL_FIXES).tolist()
[]
>>> check("hull-lost", fix=ALL_FIXES)[0]
False

Why is (0, 1, 2) lost?  It is a flat triangle, so its circumcircle is huge
(radius 500000) and contains the super vertex (-1e5, -1e5): with the super
vertices present, (0, 1, 2) is not Delaunay, so it never appears.  Note that
with *no* fix the order [(0, 0), (2, 0), (1, 1e-6), (1, 1)] happens to come out
right: two mistakes cancel, which is how such bugs survive in tutorials.

>>> lucky = [(0, 0), (2, 0), (1, 1e-6), (1, 1)]
>>> check_delaunay(lucky, naive_bowyer_watson(lucky))
(True, 'ok')
>>> check_delaunay(lucky, naive_bowyer_watson(lucky, fix=ALL_FIXES))[0]
False
"""
from __future__ import annotations

import itertools  # noqa: F401 (the doctests use it)
from typing import Iterable, Sequence

import numpy as np

from reference_impl.validate import as_points
from reference_impl.exact.predicates import incircle, orient2d

__all__ = ["naive_bowyer_watson", "RING_25", "tutorial_det", "det_in_circumcircle", "tutorial_boundary",
           "epsilon_says_degenerate", "SUPER_TRIANGLE", "ALL_FIXES", "EXHIBITS"]

Point = tuple[float, float]
CoordTriangle = tuple[Point, Point, Point]

RING_25: tuple[Point, ...] = tuple((float(x), float(y)) for x in range(-5, 6) for y in range(-5, 6)
                                  if x * x + y * y == 25)
"""The 12 integer points on the circle x^2 + y^2 = 25: every four of them are cocircular."""

SUPER_TRIANGLE: CoordTriangle = ((-1e5, -1e5), (1e5, -1e5), (0.0, 1e5))
"""The tutorial's fixed super-triangle."""

ALL_FIXES = ("orientation", "predicate", "boundary")

EXHIBITS: dict[str, tuple[Point, ...]] = {
    "overlap": ((7.0, 4.0), (8.0, 9.0), (2.0, 4.0)),
    "square": ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)),
    "clockwise": ((0.0, 0.0), (4.0, 0.0), (1.0, 2.0), (3.0, 1.0)),
    "zero-area": ((0.0, 1.0), (1.0, 0.0), (0.0, 0.0), (3.0, 0.0)),
    "cocircular": ((-4.0, -3.0), (-5.0, 0.0), (5.0, 0.0), (0.0, 5.0), (3.0, -4.0)),
    "large": ((1e6, 1e6), (2e6, 3e6), (4e6, 1e6)),
    "hull-lost": ((0.0, 0.0), (1.0, 1e-6), (2.0, 0.0), (1.0, 1.0)),
}
"""Inputs on which the tutorial's algorithm fails (all valid, all with a unique Delaunay
triangulation except "square" and "cocircular", which have cocircular ties)."""


def tutorial_det(triangle: Sequence[Point], p: Point) -> float:
    """The tutorial's in-circle determinant: ``np.linalg.det`` of the lifted 3x3 matrix.

    Positive means "p inside" only for a counter-clockwise triangle.  For four
    points exactly on one circle the true value is 0, but LAPACK's rounded
    elimination often returns a tiny non-zero number whose sign is noise (which
    ties come out non-zero depends on the machine's BLAS kernels).  Of the 495
    quadruples of the 12 integer points on x^2 + y^2 = 25, some always do:

    >>> quads = list(itertools.combinations(RING_25, 4))
    >>> len(RING_25), len(quads), any(tutorial_det(q[:3], q[3]) != 0 for q in quads)
    (12, 495, True)
    >>> all(incircle(*q) == 0 for q in quads)      # the exact predicate: every one a tie
    True
    """
    (ax, ay), (bx, by), (cx, cy) = triangle
    dx, dy = p
    rows = [[ux - dx, uy - dy, (ux - dx) ** 2 + (uy - dy) ** 2]
            for ux, uy in ((ax, ay), (bx, by), (cx, cy))]
    return float(np.linalg.det(np.array(rows, dtype=float)))


def det_in_circumcircle(triangle: Sequence[Point], p: Point) -> bool:
    """The tutorial's in-circle test: ``tutorial_det(triangle, p) > 0``.

    Mistake 1: for a clockwise triangle the sign flips, so a point at the
    centre of the circle is reported outside:

    >>> det_in_circumcircle([(0, 0), (2, 0), (0, 2)], (1, 1))     # counter-clockwise
    True
    >>> det_in_circumcircle([(0, 0), (0, 2), (2, 0)], (1, 1))     # same triangle, clockwise
    False

    Mistake 4: an exact tie (four points on one circle) is decided by rounding
    noise (see ``tutorial_det``), where the exact ``incircle`` says 0.
    """
    return tutorial_det(triangle, p) > 0


def tutorial_boundary(bad: Iterable[Sequence]) -> list[tuple]:
    """The tutorial's cavity boundary: an edge is added unless its reverse is already there.

    Mistake 2: two bad triangles sharing an edge list it as a->b and b->a; the
    first copy is kept, so an edge *inside* the cavity survives and the new
    triangles built on it overlap.  The correct boundary drops both copies
    (``bowyer_watson.cavity_boundary``):

    >>> tutorial_boundary([(0, 1, 2), (2, 1, 3)])      # 1->2 is inside the cavity, yet kept
    [(0, 1), (1, 2), (2, 0), (1, 3), (3, 2)]
    """
    boundary: list[tuple] = []
    for tri in bad:
        for k in range(3):
            edge = (tri[k], tri[(k + 1) % 3])
            if edge[::-1] not in boundary:
                boundary.append(edge)
    return boundary


def _exact_boundary(bad: list[CoordTriangle]) -> list[tuple[Point, Point]]:
    edges = [(t[k], t[(k + 1) % 3]) for t in bad for k in range(3)]
    present = set(edges)
    return [e for e in edges if (e[1], e[0]) not in present]


def naive_bowyer_watson(points, *, fix: Iterable[str] = (), log: list | None = None,
                        super_triangle: CoordTriangle = SUPER_TRIANGLE) -> np.ndarray:
    """The tutorial's algorithm (with its mistakes) as (m, 3) indices into ``points``.

    Triangles are returned in the vertex order the algorithm built them (it
    never orients them); a vertex is the first input index with its coordinates.
    ``fix``: any of ``"orientation"``, ``"predicate"``, ``"boundary"`` (see the
    module docstring).  ``log``: a list; one line per inserted point is appended
    (its bad triangles, the boundary kept, the triangles made; super-triangle
    corners are S0, S1, S2), to compare with a correct run's step log.
    ``super_triangle``: its three corners, in the order the algorithm starts from (the
    tutorial's, counter-clockwise, by default); the ``"orientation"`` fix orients it too.

    Three input points that form a perfectly ordinary triangle are enough for
    the overlap (mistake 2): the second point's cavity has two triangles, and
    the edge between them is kept.

    >>> from reference_impl.exact.verify import check_delaunay
    >>> pts = [(7, 4), (8, 9), (2, 4)]
    >>> naive_bowyer_watson(pts).tolist()                # the same triangle twice
    [[0, 1, 2], [0, 1, 2]]
    >>> check_delaunay(pts, naive_bowyer_watson(pts))[1]
    'the directed edge 0->1 is used by 2 triangles: triangles overlap'
    >>> check_delaunay(pts, naive_bowyer_watson(pts, fix=["boundary"]))
    (True, 'ok')
    >>> steps = []; _ = naive_bowyer_watson(pts, log=steps); print(steps[1])
    point 1: 2 bad (S1, S2, 0), (S2, S0, 0); boundary of 5 edges S1->S2, S2->0, 0->S1, S2->S0, S0->0; 5 new
    """
    fixes = set(fix)
    unknown = fixes - set(ALL_FIXES)
    if unknown:
        raise ValueError(f"unknown fix {sorted(unknown)[0]!r}; choose from {list(ALL_FIXES)}")
    coords: list[Point] = [(x, y) for x, y in as_points(points).tolist()]

    def contains(t: CoordTriangle, p: Point) -> bool:
        if "predicate" in fixes:
            return incircle(t[0], t[1], t[2], p) > 0
        return det_in_circumcircle(t, p)

    def make(a: Point, b: Point, c: Point) -> CoordTriangle:
        if "orientation" in fixes and orient2d(a, b, c) < 0:
            return (b, a, c)
        return (a, b, c)

    first_index: dict[Point, int] = {}
    for i, p in enumerate(coords):
        first_index.setdefault(p, i)

    corners = tuple((float(x), float(y)) for x, y in super_triangle)

    def name(v: Point) -> str:
        return f"S{corners.index(v)}" if v in corners else str(first_index[v])

    triangulation: list[CoordTriangle] = [make(*corners)]
    for i, p in enumerate(coords):
        bad = [t for t in triangulation if contains(t, p)]
        boundary = _exact_boundary(bad) if "boundary" in fixes else tutorial_boundary(bad)
        if log is not None:
            log.append(f"point {i}: {len(bad)} bad " + ", ".join("(" + ", ".join(map(name, t)) + ")" for t in bad)
                       + f"; boundary of {len(boundary)} edges "
                       + ", ".join(f"{name(a)}->{name(b)}" for a, b in boundary) + f"; {len(boundary)} new")
        for t in bad:
            triangulation.remove(t)
        for a, b in boundary:
            triangulation.append(make(a, b, p))
    kept = [t for t in triangulation if not any(v in corners for v in t)]
    return np.array([[first_index[v] for v in t] for t in kept], dtype=np.int64).reshape(-1, 3)


def epsilon_says_degenerate(a: Point, b: Point, c: Point, eps: float = 1e-9) -> bool:
    """The tutorial's remedy for "near-zero area" triangles: area below ``eps`` means degenerate.

    Mistake 4 again: thresholds depend on the scale.  The tutorial's own example is a valid
    triangle (exactly counter-clockwise or clockwise, never collinear), yet a
    1e-9 area threshold throws it away; the same shape scaled by 1e6 passes:

    >>> epsilon_says_degenerate((0, 0), (0, 1e-6), (2e-6, 0)), orient2d((0, 0), (0, 1e-6), (2e-6, 0))
    (True, -1)
    >>> epsilon_says_degenerate((0, 0), (0, 1.0), (2.0, 0))
    False
    """
    area = 0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
    return area < eps
