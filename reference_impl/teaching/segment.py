"""How constrained Delaunay inserts one segment: remove the crossed triangles, retriangulate the
two cavities (lesson 13).

Run the examples:  python -m pytest reference_impl/teaching/segment.py

``insert_segment(points, triangles, a, b)`` takes a triangulation (for example the Delaunay
one) and the segment from vertex a to vertex b, and returns every stage:

1. walk from a along the segment and collect the triangles it crosses (in order);
2. delete them: this leaves two polygons, one on each side of the segment, each with the
   segment as one of its edges (the vertices left of a->b, and those right of it);
3. triangulate each polygon with the segment as an edge: pick the polygon vertex c whose
   circle through a, b, c contains no other polygon vertex, make (a, b, c), then do the same for
   the two smaller polygons cut off by a-c and c-b (each now with that edge as its base).

This is the textbook cavity method (Anglada 1997; Shewchuk's lecture notes on constrained
Delaunay).  Every test is exact (``orient2d``, ``incircle``).  Assumptions: the segment passes
through no other vertex (a vertex on it would split it into two segments) and crosses no other
constrained edge; then, starting from the Delaunay triangulation, the result is the constrained
Delaunay triangulation of the points and that one segment.

>>> pts = [(0, 0), (2, -1), (4, 0), (2.5, 1), (2, 3), (1.5, 1.2)]
>>> from reference_impl.teaching.bowyer_watson import bowyer_watson
>>> ins = insert_segment(pts, bowyer_watson(pts), 1, 4)      # from (2, -1) up to (2, 3)
>>> ins.crossed, ins.left, ins.right, ins.new
([(1, 3, 5), (3, 4, 5)], [5], [3], [(1, 4, 5), (1, 3, 4)])
>>> sorted(ins.triangles.tolist())
[[0, 1, 5], [0, 5, 4], [1, 2, 3], [1, 3, 4], [1, 4, 5], [2, 4, 3]]
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from reference_impl.exact.predicates import incircle, orient2d
from reference_impl.validate import as_points

__all__ = ["insert_segment", "SegmentInsertion"]

Tri = tuple[int, int, int]


@dataclass(frozen=True)
class SegmentInsertion:
    """The stages of one segment insertion (vertex indices; triangles counter-clockwise).

    ``crossed``: the triangles the segment crosses, from a to b; ``left`` / ``right``: the
    cavity vertices left / right of a->b, in order from a to b; ``new``: the triangles made,
    the left cavity's first (each with the polygon it closed); ``triangles``: the result.
    """

    a: int
    b: int
    before: np.ndarray
    crossed: list[Tri]
    left: list[int]
    right: list[int]
    new: list[Tri]
    triangles: np.ndarray


def _canon(t) -> Tri:
    a, b, c = (int(v) for v in t)
    if a < b and a < c:
        return (a, b, c)
    return (b, c, a) if b < c else (c, a, b)


def _dedupe(chain: list[int]) -> list[int]:
    out: list[int] = []
    for v in chain:
        if not out or out[-1] != v:
            out.append(v)
    return out


def _fill(xy, x: int, y: int, chain: list[int], out: list[Tri]) -> None:
    """Triangulate the polygon x -> y -> reversed(chain) -> x (chain left of x->y, listed from x's end)."""
    if not chain:
        return
    c = 0
    for k in range(1, len(chain)):
        if incircle(xy[x], xy[y], xy[chain[c]], xy[chain[k]]) > 0:
            c = k                          # chain[k] is inside: the circle through it is smaller on this side
    out.append((x, y, chain[c]))
    _fill(xy, x, chain[c], chain[:c], out)
    _fill(xy, chain[c], y, chain[c + 1:], out)


def insert_segment(points, triangles, a: int, b: int) -> SegmentInsertion:
    """Insert the segment a-b into a triangulation; every stage recorded (see the module text).

    Raises ``ValueError`` if a or b is not a vertex, a == b, or the segment
    passes through another vertex.  A segment that is already an edge crosses
    nothing and changes nothing.

    >>> ins = insert_segment([(0, 0), (1, 0), (0, 1)], [(0, 1, 2)], 0, 1)
    >>> ins.crossed, ins.new
    ([], [])
    """
    P = as_points(points)
    xy = [tuple(p) for p in P.tolist()]
    T = [_canon(t) for t in np.asarray(triangles, dtype=np.int64).reshape(-1, 3).tolist()]
    before = np.array(T, dtype=np.int64).reshape(-1, 3)
    a, b = int(a), int(b)
    if a == b:
        raise ValueError(f"segment {a}-{b} has zero length")
    apex: dict[tuple[int, int], int] = {}
    for u, v, w in T:
        apex[(u, v)], apex[(v, w)], apex[(w, u)] = w, u, v
    used = {v for t in T for v in t}
    for v in (a, b):
        if v not in used:
            raise ValueError(f"point {v} is not a vertex of the triangulation")
    if (a, b) in apex or (b, a) in apex:
        return SegmentInsertion(a, b, before, [], [], [], [], before)
    pa, pb = xy[a], xy[b]
    # 1. the triangle at a that the segment leaves through: (a, r, l) with r right of a->b, l left
    start = None
    for (u, v), w in apex.items():
        if u == a:                         # triangle (a, v, w)
            sv, sw = orient2d(pa, pb, xy[v]), orient2d(pa, pb, xy[w])
            if sv == 0 and _ahead(pa, pb, xy[v]) or sw == 0 and _ahead(pa, pb, xy[w]):
                raise ValueError(f"segment {a}-{b} passes through a vertex")
            if sv < 0 < sw:
                start = (v, w)
                break
    if start is None:
        raise ValueError(f"segment {a}-{b} leaves the triangulation (is it inside the convex hull?)")
    r, l = start
    crossed = [_canon((a, r, l))]
    left, right = [l], [r]
    while True:
        w = apex.get((l, r))               # the triangle across edge r-l: (l, r, w)
        if w is None:
            raise ValueError(f"segment {a}-{b} leaves the triangulation (is it inside the convex hull?)")
        crossed.append(_canon((l, r, w)))
        if w == b:
            break
        side = orient2d(pa, pb, xy[w])
        if side == 0:
            raise ValueError(f"segment {a}-{b} passes through vertex {w}")
        if side > 0:
            l = w
            left.append(w)
        else:
            r = w
            right.append(w)
    left, right = _dedupe(left), _dedupe(right)
    new: list[Tri] = []
    _fill(xy, a, b, left, new)
    _fill(xy, b, a, right[::-1], new)
    gone = set(crossed)
    result = [t for t in T if t not in gone] + [_canon(t) for t in new]
    for t in new:
        if orient2d(xy[t[0]], xy[t[1]], xy[t[2]]) <= 0:
            raise RuntimeError(f"internal error: new triangle {t} is not counter-clockwise")
    return SegmentInsertion(a, b, before, crossed, left, right, [_canon(t) for t in new],
                            np.array(result, dtype=np.int64).reshape(-1, 3))


def _ahead(pa, pb, v) -> bool:
    """For v on the line ab: is v strictly between a and b?"""
    return min(pa[0], pb[0]) < v[0] < max(pa[0], pb[0]) or min(pa[1], pb[1]) < v[1] < max(pa[1], pb[1])
