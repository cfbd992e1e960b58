"""Exact checkers: is this a valid Delaunay triangulation of these points?

The judge uses these to accept *any* valid answer (cocircular ties make the
Delaunay triangulation non-unique), and the tests use them as an oracle that
shares no code with the predicates it checks: every decision here is made with
Python integers, after scaling all coordinates by one common power of two.

Run the doctest:  python -m doctest reference_impl/verify.py

>>> pts = [(0, 0), (1, 0), (0, 1), (1, 1)]
>>> check_delaunay(pts, [(0, 1, 3), (0, 3, 2)])
(True, 'ok')
>>> check_delaunay(pts, [(0, 3, 1), (0, 3, 2)])[0]   # clockwise triangle
False

Why the checks below are enough (a short proof, so that nobody has to trust
a long list of ad-hoc tests):

1. every triangle is strictly counter-clockwise (positive area), and
2. the triangles' boundaries add up, as a chain of directed edges, to exactly
   the convex-hull cycle (collinear hull points included).

Then for every point y not on an edge, the number of triangles covering y equals
the winding number of the hull cycle around y (1 inside, 0 outside), because
each triangle covers y with sign +1.  So the triangles tile the hull with no
overlap; and a point of the set lying inside a triangle or an edge would force
an overlap.  With 3. every distinct point used as a vertex, the triangles form a
triangulation of the points; and 4. every interior edge locally Delaunay makes
it (globally) Delaunay (Delaunay's lemma).
"""
from __future__ import annotations

from typing import Iterable, Sequence

import math
import operator

__all__ = ["exact_coordinates", "orient_exact", "incircle_exact", "convex_hull_exact",
           "check_delaunay", "check_triangulation_size", "brute_force_empty_circles"]


def exact_coordinates(points: Iterable[Sequence[float]]) -> list[tuple[int, int]]:
    """Return the points as integer pairs, all scaled by one common power of two.

    Signs of orientation and in-circle determinants are invariant under a common
    positive scaling, so the integer versions give the exact answers.

    >>> exact_coordinates([(0.5, 1.0), (0.25, -2.0)])
    [(2, 4), (1, -8)]
    """
    ratios = []
    for p in points:
        x, y = float(p[0]), float(p[1])
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"point {tuple(p)!r} is not finite")
        ratios.append((x.as_integer_ratio(), y.as_integer_ratio()))
    den = 1
    for (_, dx), (_, dy) in ratios:
        den = max(den, dx, dy)  # denominators are powers of two: the max is a common multiple
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def orient_exact(a: tuple[int, int], b: tuple[int, int], c: tuple[int, int]) -> int:
    """Sign of twice the signed area of (a, b, c): +1 counter-clockwise, 0 collinear.

    >>> orient_exact((0, 0), (1, 0), (0, 1))
    1
    """
    d = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])
    return (d > 0) - (d < 0)


def incircle_exact(a, b, c, d) -> int:
    """+1 if d is strictly inside the circle through CCW a, b, c; 0 on it; -1 outside.

    >>> incircle_exact((0, 0), (2, 0), (0, 2), (1, 1))
    1
    """
    adx, ady = a[0] - d[0], a[1] - d[1]
    bdx, bdy = b[0] - d[0], b[1] - d[1]
    cdx, cdy = c[0] - d[0], c[1] - d[1]
    det = ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
           + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
           + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))
    return (det > 0) - (det < 0)


def convex_hull_exact(P: list[tuple[int, int]], keep_collinear: bool = True) -> list[int]:
    """Indices of the convex hull of integer points, counter-clockwise (Andrew's chain).

    Duplicated coordinates appear once (the smallest index).  With
    ``keep_collinear`` the points lying on hull edges are included.

    >>> convex_hull_exact([(0, 0), (2, 0), (1, 0), (0, 2), (1, 1)])
    [0, 2, 1, 4, 3]
    """
    first: dict[tuple[int, int], int] = {}
    for i, p in enumerate(P):
        first.setdefault(p, i)
    order = sorted(first.values(), key=lambda i: P[i])
    if len(order) <= 2:
        return order

    def chain(seq):
        out: list[int] = []
        for i in seq:
            while len(out) >= 2:
                s = orient_exact(P[out[-2]], P[out[-1]], P[i])
                if s < 0 or (s == 0 and not keep_collinear):
                    out.pop()
                else:
                    break
            out.append(i)
        return out

    lower, upper = chain(order), chain(order[::-1])
    if all(orient_exact(P[order[0]], P[order[-1]], P[i]) == 0 for i in order):
        return order  # all collinear: the "hull" is the sorted chain
    return lower[:-1] + upper[:-1]


def _rows(triangles) -> list[list]:
    """Triangles as a list of rows (numpy arrays, lists or tuples), without importing numpy."""
    rows = triangles.tolist() if hasattr(triangles, "tolist") else list(triangles)
    return [list(t) for t in rows]


def check_delaunay(points, triangles) -> tuple[bool, str]:
    """Check exactly that ``triangles`` is a Delaunay triangulation of ``points``.

    ``points`` is (n, 2) finite floats; ``triangles`` is (m, 3) point indices in
    counter-clockwise order.  Any index of a duplicated point may be used.
    All-collinear input (or fewer than 3 distinct points) has exactly one valid
    answer: no triangles.  Returns ``(ok, message)``; the message names the
    first problem found.
    """
    P = exact_coordinates(points)
    n = len(P)
    tris = _rows(triangles)
    canon: dict[tuple[int, int], int] = {}
    for i, p in enumerate(P):
        canon.setdefault(p, i)
    rep = [canon[p] for p in P]
    T: list[tuple[int, int, int]] = []
    for k, t in enumerate(tris):
        try:
            ids = [operator.index(v) for v in t]
        except TypeError:
            return False, f"triangle {k} has non-integer vertex indices {list(t)!r}"
        if len(ids) != 3:
            return False, f"triangle {k} = {ids} does not have exactly 3 vertices"
        if any(v < 0 or v >= n for v in ids):
            return False, f"triangle {k} = {ids} has an index outside 0..{n - 1}"
        T.append((rep[ids[0]], rep[ids[1]], rep[ids[2]]))

    hull = convex_hull_exact(P, keep_collinear=True)
    distinct = sorted(set(rep))
    flat = len(distinct) < 3 or all(orient_exact(P[hull[0]], P[hull[-1]], P[i]) == 0 for i in distinct)
    if flat:
        if T:
            return False, "the points are all collinear (or fewer than 3 distinct): no triangle is possible"
        return True, "ok"

    # 1. positive orientation
    for k, (a, b, c) in enumerate(T):
        s = orient_exact(P[a], P[b], P[c])
        if s <= 0:
            what = "degenerate (zero area)" if s == 0 else "clockwise"
            return False, f"triangle {k} = {tuple(tris[k])} is {what}; triangles must be counter-clockwise"
    # 2. boundary chain equals the hull cycle
    count: dict[tuple[int, int], int] = {}
    for a, b, c in T:
        for u, v in ((a, b), (b, c), (c, a)):
            count[(u, v)] = count.get((u, v), 0) + 1
    for (u, v), m in count.items():
        if m > 1:
            return False, f"the directed edge {u}->{v} is used by {m} triangles: triangles overlap"
    hull_edges = {(hull[i], hull[(i + 1) % len(hull)]) for i in range(len(hull))}
    for (u, v) in count:
        if (v, u) not in count and (u, v) not in hull_edges:
            return False, (f"edge {u}-{v} has a triangle on one side only but is not a convex hull edge "
                           "(a hole, a gap or an overlap)")
    for e in hull_edges:
        if e not in count:
            return False, f"convex hull edge {e[0]}-{e[1]} is not covered by any triangle"
        if (e[1], e[0]) in count:
            return False, f"a triangle lies outside the convex hull across edge {e[0]}-{e[1]}"
    # 3. every distinct point is a vertex
    used = {v for t in T for v in t}
    missing = [i for i in distinct if i not in used]
    if missing:
        return False, f"point {missing[0]} {tuple(points[missing[0]])} is not a vertex of any triangle"
    # 4. local Delaunay on every interior edge
    opposite = {}
    for a, b, c in T:
        opposite[(a, b)] = c
        opposite[(b, c)] = a
        opposite[(c, a)] = b
    for (u, v), w in opposite.items():
        x = opposite.get((v, u))
        if x is not None and u < v and incircle_exact(P[u], P[v], P[w], P[x]) > 0:
            return False, (f"edge {u}-{v} is not Delaunay: point {x} is strictly inside the "
                           f"circumcircle of triangle ({u}, {v}, {w})")
    return True, "ok"


def check_triangulation_size(n_distinct: int, n_hull: int, n_triangles: int) -> bool:
    """Euler's count for a triangulation of n points with h on the hull: 2n - 2 - h.

    >>> check_triangulation_size(4, 4, 2)
    True
    """
    return n_triangles == 2 * n_distinct - 2 - n_hull


def brute_force_empty_circles(points, triangles) -> tuple[bool, str]:
    """O(n m) check that no point is strictly inside any triangle's circumcircle.

    Slow but independent of any edge structure; meant for small test inputs.
    """
    P = exact_coordinates(points)
    for k, (a, b, c) in enumerate(_rows(triangles)):
        for i, p in enumerate(P):
            if incircle_exact(P[a], P[b], P[c], p) > 0:
                return False, f"point {i} is inside the circumcircle of triangle {k}"
    return True, "ok"
