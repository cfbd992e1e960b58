"""Convex hull of 2D points, exact: Andrew's monotone chain with exact orientation tests.

Use it from Python::

    from reference_impl.structures.hull import convex_hull
    convex_hull(points)                    # strict hull: corner points only
    convex_hull(points, collinear=True)    # also the points lying on hull edges

or run the examples: ``python -m pytest --doctest-modules reference_impl/structures/hull.py``.

>>> convex_hull([(0, 0), (2, 0), (1, 0), (2, 2), (0, 2), (1, 1)]).tolist()
[0, 1, 3, 4]
>>> convex_hull([(0, 0), (2, 0), (1, 0), (2, 2), (0, 2), (1, 1)], collinear=True).tolist()
[0, 2, 1, 3, 4]

Conventions (the same as ``Delaunay.hull`` and ``verify.convex_hull_exact``):

* the result is an int64 array of input indices, counter-clockwise, starting at
  the smallest index;
* duplicated points appear once, under their smallest index;
* every turn is decided by ``orient2d_nb`` (exact for any finite doubles), so
  points that are collinear in exact arithmetic are never taken for corners,
  and one-ulp dents are never smoothed away;
* *flat* input (fewer than three distinct points, or all of them collinear) has
  a segment or a point as its hull.  The result is then the chain sorted by
  (x, y): with ``collinear=False`` its two end points (one index for a single
  distinct point), with ``collinear=True`` every distinct point.  Empty input
  gives an empty array.

Cost: points that are certainly strictly inside the hull (inside the octagon of
the extreme points in eight directions, decided by a floating-point filter with a
proven error bound, so nothing is discarded by mistake) are dropped first
(Akl-Toussaint); the rest is sorted (O(n log n)) and scanned once by a chain
compiled with numba.
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from reference_impl.mesh.delaunay import Delaunay
from reference_impl.validate import as_points
from reference_impl.exact.predicates import CCW_ERRBOUND_A, orient2d_nb, workspace

__all__ = ["convex_hull"]


@njit(cache=True)
def _all_collinear(X, Y, w):
    """True when every point lies on the line through the first and the last point."""
    n = X.shape[0]
    for i in range(1, n - 1):
        if orient2d_nb(X[0], Y[0], X[n - 1], Y[n - 1], X[i], Y[i], w) != 0:
            return False
    return True


@njit(cache=True)
def _monotone_chain(X, Y, keep_collinear, w):
    """Hull positions (into the sorted, distinct X, Y) counter-clockwise from position 0.

    The input must be sorted by (x, y), free of duplicates and not all collinear.
    A point is popped when it makes a clockwise turn, or a straight one unless
    ``keep_collinear``.
    """
    n = X.shape[0]
    out = np.empty(2 * n, dtype=np.int64)
    k = 0
    for sweep in range(2):                      # lower chain left to right, upper right to left
        start = k
        for j in range(n):
            i = j if sweep == 0 else n - 1 - j
            while k >= start + 2:
                a = out[k - 2]
                b = out[k - 1]
                s = orient2d_nb(X[a], Y[a], X[b], Y[b], X[i], Y[i], w)
                if s < 0 or (s == 0 and not keep_collinear):
                    k -= 1
                else:
                    break
            out[k] = i
            k += 1
        k -= 1                                  # the last point starts the other chain
    return out[:k].copy()


def _extreme(pts: np.ndarray, cx: int, cy: int) -> int:
    """Index of a point maximising cx*x + cy*y (cx, cy in {-1, 0, 1}), decided exactly.

    The float sums are monotone in the exact sums, so the exact maximiser is among
    the points whose float sum is largest; those few are compared as Fractions.
    """
    with np.errstate(over="ignore"):
        s = cx * pts[:, 0] + cy * pts[:, 1]
    cand = np.flatnonzero(s == s.max())
    if len(cand) == 1 and np.isfinite(s[cand[0]]):
        return int(cand[0])
    if not np.isfinite(s.max()):
        cand = np.arange(len(pts))
    return int(max(cand, key=lambda i: cx * Fraction(pts[i, 0]) + cy * Fraction(pts[i, 1])))


def _certainly_inside(pts: np.ndarray) -> np.ndarray:
    """Mask of points strictly inside the convex hull, proven by a filtered orientation test.

    The extreme points in eight directions lie on the hull boundary, in
    counter-clockwise order; a point strictly left of every edge of their polygon
    is strictly inside the hull.  A test is trusted only when the float
    determinant exceeds Shewchuk's error bound and no underflow or overflow can
    occur; otherwise the point is kept (the exact chain decides it).
    """
    dirs = [(0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1)]
    ids = [_extreme(pts, cx, cy) for cx, cy in dirs]
    poly = []
    for i in ids:
        if not poly or (pts[i] != pts[poly[-1]]).any():
            poly.append(i)
    while len(poly) > 1 and (pts[poly[0]] == pts[poly[-1]]).all():
        poly.pop()
    inside = np.zeros(len(pts), dtype=bool)
    if len(poly) < 3:
        return inside
    inside[:] = True
    px, py = pts[:, 0], pts[:, 1]
    with np.errstate(over="ignore", invalid="ignore"):
        for a, b in zip(poly, poly[1:] + poly[:1]):
            (ax, ay), (bx, by) = pts[a], pts[b]
            left = (ax - px) * (by - py)
            right = (ay - py) * (bx - px)
            detsum = np.abs(left) + np.abs(right)
            inside &= ((left - right) > CCW_ERRBOUND_A * detsum) & (detsum > 2.0 ** -900) \
                & (detsum < 2.0 ** 1000)
    return inside


@njit(cache=True)
def _corners(X, Y, cycle, w):
    """Mask of the vertices of a closed convex cycle that are corners (not on an edge)."""
    m = len(cycle)
    keep = np.ones(m, dtype=np.bool_)
    for i in range(m):
        a, b, c = cycle[i - 1], cycle[i], cycle[(i + 1) % m]
        keep[i] = orient2d_nb(X[a], Y[a], X[b], Y[b], X[c], Y[c], w) != 0
    return keep


def _mesh_hull(d: Delaunay, collinear: bool) -> np.ndarray:
    """The hull read off a triangulation (``Delaunay.hull`` keeps the collinear points)."""
    h = np.asarray(d.hull, dtype=np.int64)
    if collinear or len(h) < 2:
        return h.copy()
    if len(d.simplices) == 0:                 # flat: the chain's two end points
        return h[[0, -1]]
    P = d.points
    h = h[_corners(np.ascontiguousarray(P[:, 0]), np.ascontiguousarray(P[:, 1]), h, workspace())]
    return np.roll(h, -int(np.argmin(h)))


def convex_hull(points: ArrayLike | Delaunay, collinear: bool = False) -> np.ndarray:
    """Indices of the convex hull of ``points``, counter-clockwise from the smallest index.

    ``points`` may be a ``Delaunay``: its hull is then read off the mesh (removed
    points are left out), with the same result as for its points.

    ``collinear=True`` also returns the points that lie on hull edges (in order
    along the edge).  Duplicates appear once (smallest index).  For flat input
    (all points collinear, or fewer than 3 distinct) the result is the chain
    sorted by (x, y): its two end points, or with ``collinear=True`` all
    distinct points.  Raises ``ValueError`` for NaN, infinity, wrong shape or text.

    >>> convex_hull([(1, 1), (0, 0), (3, 0), (0, 3)]).tolist()
    [1, 2, 3]
    >>> convex_hull([(2, 2), (0, 0), (1, 1), (0, 0)]).tolist()       # flat: sorted end points
    [1, 0]
    >>> convex_hull([(2, 2), (0, 0), (1, 1)], collinear=True).tolist()
    [1, 2, 0]
    """
    if isinstance(points, Delaunay):
        return _mesh_hull(points, collinear)
    pts = as_points(points)
    n = len(pts)
    if n == 0:
        return np.zeros(0, dtype=np.int64)
    cand = np.flatnonzero(~_certainly_inside(pts)) if n > 64 else np.arange(n)
    # sort by x, then y, then index: the first of a run of equal points has the smallest index
    order = cand[np.lexsort((cand, pts[cand, 1], pts[cand, 0]))]
    xs, ys = pts[order, 0], pts[order, 1]
    first = np.ones(len(order), dtype=bool)
    first[1:] = (xs[1:] != xs[:-1]) | (ys[1:] != ys[:-1])
    order = order[first]
    X = np.ascontiguousarray(xs[first])
    Y = np.ascontiguousarray(ys[first])
    w = workspace()
    if len(order) < 3 or _all_collinear(X, Y, w):
        chain = order if collinear else order[[0, -1]] if len(order) > 1 else order
        return chain.astype(np.int64)
    hull = order[_monotone_chain(X, Y, bool(collinear), w)].astype(np.int64)
    return np.roll(hull, -int(np.argmin(hull)))
