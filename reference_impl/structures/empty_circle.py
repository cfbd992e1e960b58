"""Largest empty circle: the widest circle, centred in the convex hull, with no point inside.

Use it from Python::

    from reference_impl.structures.empty_circle import largest_empty_circle
    cx, cy, r = largest_empty_circle(points)

or run the examples: ``python -m pytest --doctest-modules reference_impl/structures/empty_circle.py``.

>>> largest_empty_circle([(0, 0), (4, 0), (4, 4), (0, 4)])
Circle(x=2.0, y=2.0, r=2.8284271247461903)

Why these candidates (Toussaint 1983).  Let d(x) be the distance from x to the
nearest point and H the convex hull.  Inside the Voronoi cell of a point p,
d(x) = |x - p| is a convex function, so its maximum over the convex polygon
cell(p) ∩ H is at a vertex of that polygon.  Those vertices are

1. Voronoi vertices inside H: the circumcentres of Delaunay triangles,
   with r = the circumradius (the circumcircle is empty);
2. points where a Voronoi edge crosses the hull boundary;
3. hull vertices, where r = 0 (never the best when there is a triangle).

Candidates 2 are found by walking along each hull edge u -> v through the
Voronoi cells it crosses: start in the cell of u; from the cell of s, the edge
leaves through the bisector of s and the Delaunay neighbour q that it meets
first (smallest parameter t, among the q with (v - u).(q - s) > 0); record that
crossing and continue in the cell of q, until the cell of v.  Each Voronoi edge
crosses the boundary of the convex hull at most twice, so all walks together
take O(n) steps.

Exactness.  The walk's decisions (the sign of (v - u).(q - s), and which of two
bisectors is crossed first) are made exactly: a floating-point filter with a
proven error bound, and Python integers when it cannot decide.  The sign makes
the projection of the current site on the edge strictly increase, so the walk
always ends.  Which circumcentres lie in H is decided by exact orientation tests
on the computed centres (a binary search in the hull polygon).  The centres and radii themselves are floating-point
values (a few ulps of the coordinates, more for nearly flat triangles); they are
computed after scaling all points by one power of two, so 1e-300 and 1e300
inputs behave like 1.  Among equally large candidates the one with the
smallest (x, y) is returned, and every computation starts from the points in a
canonical order, so the answer does not depend on the input order.

Degenerate input: one distinct point gives ``(x, y, 0.0)``; collinear points
(two included) have a segment as hull, and the answer is the midpoint of the
longest gap between consecutive points, with half its length as radius.  An
empty input raises ``ValueError`` (there is no hull to put a centre in).
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numba
import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from reference_impl.mesh.delaunay import Delaunay, as_delaunay
from reference_impl.exact.expansion import EPSILON
from reference_impl.structures.hull import convex_hull
from reference_impl.exact.predicates import orient2d_nb, workspace
from reference_impl.exact.scaling import pow2_exponent
from reference_impl.structures.voronoi import circumcentres, delaunay_adjacency

__all__ = ["Circle", "largest_empty_circle"]


# --------------------------------------------------------------------- exact walk decisions
def _dot_sign_exact(ux, uy, vx, vy, sx, sy, qx, qy) -> int:
    from reference_impl.exact.verify import exact_coordinates
    (ux, uy), (vx, vy), (sx, sy), (qx, qy) = exact_coordinates([(ux, uy), (vx, vy), (sx, sy), (qx, qy)])
    d = (vx - ux) * (qx - sx) + (vy - uy) * (qy - sy)
    return (d > 0) - (d < 0)


def _first_crossing_exact(ux, uy, vx, vy, sx, sy, ax, ay, bx, by) -> int:
    from reference_impl.exact.verify import exact_coordinates
    (ux, uy), (vx, vy), (sx, sy), (ax, ay), (bx, by) = exact_coordinates(
        [(ux, uy), (vx, vy), (sx, sy), (ax, ay), (bx, by)])
    s2 = (sx - ux) ** 2 + (sy - uy) ** 2
    na = (ax - ux) ** 2 + (ay - uy) ** 2 - s2
    nb = (bx - ux) ** 2 + (by - uy) ** 2 - s2
    da = (vx - ux) * (ax - sx) + (vy - uy) * (ay - sy)
    db = (vx - ux) * (bx - sx) + (vy - uy) * (by - sy)
    val = na * db - nb * da
    return (val > 0) - (val < 0)


_SAFE_LO = 2.0 ** -900   # below this, underflow could hide in the float filter


@njit(cache=True)
def _dot_sign(ux, uy, vx, vy, sx, sy, qx, qy):
    """Exact sign of (v - u) . (q - s)."""
    dx = vx - ux
    dy = vy - uy
    t1 = dx * (qx - sx)
    t2 = dy * (qy - sy)
    d = t1 + t2
    mag = abs(t1) + abs(t2)
    if mag > _SAFE_LO and abs(d) > 8.0 * EPSILON * mag:
        return 1 if d > 0.0 else -1
    if mag == 0.0:
        return 0
    with numba.objmode(r="int64"):
        r = _dot_sign_exact(ux, uy, vx, vy, sx, sy, qx, qy)
    return r


@njit(cache=True)
def _crossing_terms(ux, uy, vx, vy, sx, sy, qx, qy):
    """N, |N|-bound, D, |D|-bound with t = N / (2 D) the parameter where the walk along
    u -> v meets the bisector of s and q (N = |q - u|^2 - |s - u|^2, D = (v - u).(q - s))."""
    ax = sx - ux
    ay = sy - uy
    bx = qx - ux
    by = qy - uy
    ex = qx - sx
    ey = qy - sy
    dx = vx - ux
    dy = vy - uy
    num = ex * (bx + ax) + ey * (by + ay)
    mnum = abs(ex) * (abs(bx) + abs(ax)) + abs(ey) * (abs(by) + abs(ay))
    den = dx * ex + dy * ey
    mden = abs(dx * ex) + abs(dy * ey)
    return num, mnum, den, mden


@njit(cache=True)
def _first_crossing(ux, uy, vx, vy, sx, sy, ax, ay, bx, by):
    """Exact sign of t_a - t_b: which bisector (of s with a, or of s with b) the walk
    along u -> v meets first.  Both (v - u).(a - s) and (v - u).(b - s) must be > 0."""
    na, mna, da, mda = _crossing_terms(ux, uy, vx, vy, sx, sy, ax, ay)
    nb, mnb, db, mdb = _crossing_terms(ux, uy, vx, vy, sx, sy, bx, by)
    val = na * db - nb * da
    bound = mna * mdb + mnb * mda
    if bound > _SAFE_LO and abs(val) > 32.0 * EPSILON * bound:
        return 1 if val > 0.0 else -1
    with numba.objmode(r="int64"):
        r = _first_crossing_exact(ux, uy, vx, vy, sx, sy, ax, ay, bx, by)
    return r


@njit(cache=True)
def _boundary_candidates(X, Y, hull, ptr, nbr, cx, cy, cr):
    """Walk every hull edge through the Voronoi cells it crosses; record each crossing
    (centre and radius) in cx, cy, cr; return how many."""
    h = hull.shape[0]
    n = X.shape[0]
    k = 0
    for i in range(h):
        u = hull[i]
        v = hull[(i + 1) % h]
        ux, uy, vx, vy = X[u], Y[u], X[v], Y[v]
        s = u
        steps = 0
        while s != v:
            best = -1
            for j in range(ptr[s], ptr[s + 1]):
                q = nbr[j]
                if _dot_sign(ux, uy, vx, vy, X[s], Y[s], X[q], Y[q]) <= 0:
                    continue
                if best < 0 or _first_crossing(ux, uy, vx, vy, X[s], Y[s],
                                               X[q], Y[q], X[best], Y[best]) < 0:
                    best = q
            steps += 1
            if best < 0 or steps > n or k >= cx.shape[0]:
                raise RuntimeError("largest_empty_circle: hull walk lost its way (internal error)")
            num, _, den, _ = _crossing_terms(ux, uy, vx, vy, X[s], Y[s], X[best], Y[best])
            t = min(max(num / (2.0 * den), 0.0), 1.0)
            x = ux + t * (vx - ux)
            y = uy + t * (vy - uy)
            cx[k] = x
            cy[k] = y
            cr[k] = min(math.hypot(x - X[s], y - Y[s]), math.hypot(x - X[best], y - Y[best]))
            k += 1
            s = best
    return k


@njit(cache=True)
def _in_hull(V, X, Y, qx, qy, todo, w):
    """For each query i with todo[i], is (qx[i], qy[i]) in the closed convex polygon with
    vertex indices V (strictly convex, counter-clockwise)?  Binary search over the fan
    from V[0], exact orientations: O(log h) per query."""
    h = V.shape[0]
    res = np.zeros(qx.shape[0], dtype=np.bool_)
    x0, y0 = X[V[0]], Y[V[0]]
    for i in range(qx.shape[0]):
        if not todo[i]:
            continue
        px, py = qx[i], qy[i]
        if orient2d_nb(x0, y0, X[V[1]], Y[V[1]], px, py, w) < 0:
            continue
        if orient2d_nb(x0, y0, X[V[h - 1]], Y[V[h - 1]], px, py, w) > 0:
            continue
        lo, hi = 1, h - 2            # the last k with q on or left of V0 -> Vk
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if orient2d_nb(x0, y0, X[V[mid]], Y[V[mid]], px, py, w) >= 0:
                lo = mid
            else:
                hi = mid - 1
        res[i] = orient2d_nb(X[V[lo]], Y[V[lo]], X[V[lo + 1]], Y[V[lo + 1]], px, py, w) >= 0
    return res


# --------------------------------------------------------------------- candidates
def _circumcircles(simp: np.ndarray, X: np.ndarray, Y: np.ndarray):
    """Circumcentre and radius (the distance to the nearest of its three vertices) of
    every triangle."""
    px, py = circumcentres(simp, X, Y)
    with np.errstate(over="ignore", invalid="ignore"):
        r = np.min(np.hypot(px[:, None] - X[simp], py[:, None] - Y[simp]), axis=1)
    return px, py, r


def _best(cx: np.ndarray, cy: np.ndarray, r: np.ndarray) -> int:
    """Index of the largest radius; ties go to the smallest (x, y)."""
    top = np.flatnonzero(r == r.max())
    return int(top[np.lexsort((cy[top], cx[top]))[0]])


def _collinear_answer(chain: np.ndarray, X: np.ndarray, Y: np.ndarray) -> tuple[float, float, float]:
    """Midpoint and half-length of the longest gap of a sorted collinear chain (scaled)."""
    if len(chain) == 1:
        return float(X[chain[0]]), float(Y[chain[0]]), 0.0
    xs, ys = X[chain], Y[chain]
    along = xs if xs[-1] != xs[0] else ys             # gaps are proportional to this coordinate
    lo, hi = along[:-1], along[1:]
    gap = hi - lo                                     # gap + err == hi - lo exactly (two_diff)
    hv = hi - gap
    err = (hi - (gap + hv)) + (hv - lo)
    # the longest gap exactly: largest float gap, then largest error term; the first on ties
    i = int(np.argmax(np.where(gap == gap.max(), err, -np.inf)))
    ax, ay, bx, by = xs[i], ys[i], xs[i + 1], ys[i + 1]
    return float(0.5 * ax + 0.5 * bx), float(0.5 * ay + 0.5 * by), float(0.5 * math.hypot(bx - ax, by - ay))


class Circle(NamedTuple):
    """Centre and radius (a tuple: ``cx, cy, r = circle`` and ``circle == (x, y, r)`` work)."""

    x: float
    y: float
    r: float


def largest_empty_circle(points: ArrayLike | Delaunay) -> Circle:
    """``Circle(x, y, r)``: centre and radius of a largest circle with no point strictly
    inside, whose centre lies in the convex hull of ``points``.

    ``points``: the (n, 2) points, or a ``Delaunay`` of them (its mesh is used as it is:
    no re-triangulation; removed points are left out).  One distinct point gives radius
    0; collinear points give the midpoint of the longest gap.  Raises ``ValueError`` for
    empty or malformed input.

    >>> largest_empty_circle([(0, 0), (2, 0), (1, 1)])       # right angle: centre on the hull
    Circle(x=1.0, y=0.0, r=1.0)
    >>> largest_empty_circle([(0, 0), (1, 0), (4, 0)]) == (2.5, 0.0, 1.5)   # collinear: the longest gap
    True
    >>> tuple(largest_empty_circle([(3, 4)]))
    (3.0, 4.0, 0.0)
    """
    d = as_delaunay(points)
    pts = d.points
    if not d.live.any():
        raise ValueError("points is empty: the largest empty circle needs at least one point")
    k = pow2_exponent(pts)
    X = np.ldexp(pts[:, 0], -k)
    Y = np.ldexp(pts[:, 1], -k)
    simp = d.simplices
    if len(simp) == 0:
        cx, cy, r = _collinear_answer(d.hull, X, Y)
        return Circle(float(np.ldexp(cx, k)), float(np.ldexp(cy, k)), float(np.ldexp(r, k)))
    ptr, nbr = delaunay_adjacency(d)
    bcap = 6 * len(pts) + 16
    bx, by, br = np.empty(bcap), np.empty(bcap), np.empty(bcap)
    nb = _boundary_candidates(X, Y, d.hull.astype(np.int64), ptr, nbr, bx, by, br)
    px, py, pr = _circumcircles(simp, X, Y)
    ok = np.isfinite(px) & np.isfinite(py) & np.isfinite(pr)
    ok = _in_hull(convex_hull(d), X, Y, px, py, ok, workspace())
    cx = np.concatenate([bx[:nb], px[ok]])
    cy = np.concatenate([by[:nb], py[ok]])
    cr = np.concatenate([br[:nb], pr[ok]])
    i = _best(cx, cy, cr)
    return Circle(float(np.ldexp(cx[i], k)), float(np.ldexp(cy[i], k)), float(np.ldexp(cr[i], k)))
