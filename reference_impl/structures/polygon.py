"""Polygons with holes, triangulated: the free space of the navigation mesh.

``polygon_triangulation(boundary, holes)`` runs the constrained Delaunay
triangulation (``constrained.constrain_delaunay``) on the polygon's vertices
with its edges as constraints, and keeps the triangles inside.  That also
checks, exactly, that boundary and holes are simple and disjoint with every
hole inside the boundary: a proper crossing is caught by the segment
insertion, a vertex on another edge by the record of split segments, a
repeated vertex by the duplicate map, a misplaced hole by the flood fill.  The
triangles kept are those a flood fill reaches from the inside of the boundary
without crossing a constraint edge.  ``navmesh.NavMesh`` answers shortest-path
queries on the result.

Run the doctests:  python -m pytest reference_impl/structures/polygon.py

>>> pt = polygon_triangulation([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (1, 3), (3, 3), (3, 1)]])
>>> len(pt.simplices), [r.tolist() for r in pt.rings]
(8, [[0, 1, 2, 3], [4, 5, 6, 7]])
"""
from __future__ import annotations

from typing import NamedTuple, Sequence

import numpy as np
from numpy.typing import ArrayLike

from numba import njit

from reference_impl.exact.predicates import orient2d, orient2d_nb, workspace
from reference_impl.mesh.delaunay import Delaunay
from reference_impl.structures.constrained import constrain_delaunay, format_point
from reference_impl.validate import as_rings

__all__ = ["PolygonTriangulation", "polygon_triangulation"]


class PolygonTriangulation(NamedTuple):
    """Triangles of a polygon with holes.

    ``points``: the vertices, boundary first then each hole (input order, closing
    duplicates removed); ``simplices`` (m, 3) counter-clockwise; ``neighbors``
    (m, 3), -1 across the boundary and hole edges; ``rings``: vertex indices of
    the boundary (counter-clockwise) then of each hole (clockwise), so the free
    space is always on the left of a ring edge.
    """
    points: np.ndarray
    simplices: np.ndarray
    neighbors: np.ndarray
    rings: tuple


def _winding(p, ring_pts: np.ndarray) -> int:
    """Exact winding number of ring_pts around p (p not on the ring)."""
    wn = 0
    for a, b in zip(ring_pts, np.roll(ring_pts, -1, axis=0)):
        if a[1] <= p[1] < b[1] and orient2d(a, b, p) > 0:
            wn += 1
        elif b[1] <= p[1] < a[1] and orient2d(a, b, p) < 0:
            wn -= 1
    return wn


@njit(cache=True)
def _ring_turns(pts, offset, w):
    """Exact orientation of each ring (+1 counter-clockwise), read at its lexicographically
    smallest vertex, which is a convex corner.  Ring r is vertices ``offset[r]:offset[r + 1]``."""
    out = np.empty(offset.shape[0] - 1, np.int64)
    for r in range(offset.shape[0] - 1):
        lo, hi = offset[r], offset[r + 1]
        v = lo
        for i in range(lo + 1, hi):
            if pts[i, 0] < pts[v, 0] or (pts[i, 0] == pts[v, 0] and pts[i, 1] < pts[v, 1]):
                v = i
        p = v - 1 if v > lo else hi - 1
        q = v + 1 if v + 1 < hi else lo
        out[r] = orient2d_nb(pts[p, 0], pts[p, 1], pts[v, 0], pts[v, 1], pts[q, 0], pts[q, 1], w)
    return out


@njit(cache=True)
def _free_space(tri, nbr, cid, offset, turns):
    """The triangles of the free space, by a flood fill that never crosses a constraint edge.

    The rings (ring r: vertices ``offset[r]:offset[r + 1]``, the boundary first; ``turns``:
    their orientations, ``_ring_turns``) are normalised, the boundary counter-clockwise and
    the holes clockwise, so the free space is
    left of every ring edge u -> ``succ[u]``.  The fill starts from the triangles left of
    the boundary edges.  Returns ``along`` (the vertices, each ring in its normalised
    order), ``bad`` (the first hole, counted from 1, with an edge whose left side is not
    free space: it is outside the boundary, or inside or around another hole; 0 if none),
    and the free triangles compacted: their vertices and neighbours (-1 across a
    constraint edge)."""
    nrings = offset.shape[0] - 1
    n = offset[nrings]
    succ = np.empty(n, np.int64)
    along = np.empty(n, np.int64)
    for r in range(nrings):
        lo, hi = offset[r], offset[r + 1]
        flipped = (turns[r] > 0) != (r == 0)
        for i in range(lo, hi):
            if flipped:
                succ[i] = i - 1 if i > lo else hi - 1
                along[i] = lo + hi - 1 - i
            else:
                succ[i] = i + 1 if i + 1 < hi else lo
                along[i] = i
    m = tri.shape[0]
    left = np.full(n, -1, np.int64)                 # the triangle left of u -> succ[u]
    for t in range(m):
        for k in range(3):
            u = tri[t, k + 1 if k < 2 else 0]
            if succ[u] == tri[t, k + 2 if k < 1 else k - 1]:
                left[u] = t
    free = np.zeros(m, np.bool_)
    stack = np.empty(m, np.int64)
    top = 0
    for u in range(offset[1]):
        t = left[u]
        if t >= 0 and not free[t]:
            free[t] = True
            stack[top] = t
            top += 1
    while top > 0:
        top -= 1
        t = stack[top]
        for k in range(3):
            o = nbr[t, k]
            if o >= 0 and cid[t, k] < 0 and not free[o]:
                free[o] = True
                stack[top] = o
                top += 1
    bad = 0
    r = 1
    for u in range(offset[1], n):                  # every hole edge must have free space on its left
        while u >= offset[r + 1]:
            r += 1
        if left[u] < 0 or not free[left[u]]:
            bad = r
            break
    new = np.full(m, -1, np.int64)
    count = 0
    for t in range(m):
        if free[t]:
            new[t] = count
            count += 1
    simp = np.empty((count, 3), np.int64)
    nbrs = np.empty((count, 3), np.int64)
    for t in range(m):
        r = new[t]
        if r >= 0:
            for k in range(3):
                simp[r, k] = tri[t, k]
                nbrs[r, k] = -1 if cid[t, k] >= 0 or nbr[t, k] < 0 else new[nbr[t, k]]
    return along, bad, simp, nbrs


class _ArgumentNames:
    """The names ``as_rings`` gives the rings in its messages (made only for a bad ring)."""

    def __getitem__(self, i: int) -> str:
        return "boundary" if i == 0 else f"holes[{i - 1}]"


def polygon_triangulation(boundary: ArrayLike, holes: Sequence[ArrayLike] | None = ()) -> PolygonTriangulation:
    """Constrained Delaunay triangulation of a polygon with holes (triangles inside only).

    ``boundary``: (k, 2) vertices of a simple polygon, either orientation (a
    closing copy of the first vertex is allowed).  ``holes``: simple polygons
    strictly inside the boundary, pairwise disjoint, not touching the boundary
    or each other.  Violations raise ``ValueError`` naming the offending edges,
    vertices or holes.  Returns a ``PolygonTriangulation``.

    >>> pt = polygon_triangulation([(0, 0), (2, 0), (2, 2), (1, 1), (0, 2)])
    >>> len(pt.simplices), pt.rings[0].tolist()
    (3, [0, 1, 2, 3, 4])
    >>> polygon_triangulation([(0, 0), (2, 0), (0, 2), (2, 2)])
    Traceback (most recent call last):
    ...
    ValueError: polygon is not simple: boundary edge 3 (2, 2)-(0, 0) crosses boundary edge 1 (2, 0)-(0, 2)
    """
    if holes is None:
        holes = ()
    if isinstance(holes, (str, bytes)):
        raise ValueError("holes must be a sequence of polygons")
    pts, sizes = as_rings([boundary, *holes], _ArgumentNames())
    nrings = len(sizes)
    offset = np.zeros(nrings + 1, dtype=np.int64)
    np.cumsum(sizes, out=offset[1:])
    n = len(pts)
    nxt = np.arange(1, n + 1)
    nxt[offset[1:] - 1] = offset[:-1]
    seg = np.stack([np.arange(n), nxt], axis=1)

    def name(r):
        return "boundary" if r == 0 else f"hole {r - 1}"

    def vname(i):
        r = int(np.searchsorted(offset, i, side="right")) - 1
        return f"{name(r)} vertex {i - offset[r]} {format_point(pts[i])}"

    def ename(s):
        r = int(np.searchsorted(offset, s, side="right")) - 1
        return f"{name(r)} edge {s - offset[r]} {format_point(pts[s])}-{format_point(pts[nxt[s]])}"

    d = Delaunay(pts)
    rep = d.index_map
    dup = np.flatnonzero(rep != np.arange(len(pts)))
    if len(dup):
        raise ValueError(f"polygon is not simple: {vname(dup[0])} repeats {vname(rep[dup[0]])}")
    if len(d.simplices) == 0:
        raise ValueError("polygon has zero area: all vertices are collinear")
    k = constrain_delaunay(d, seg)
    if k.error is not None:
        s, o = sorted(k.error[:2])
        raise ValueError(f"polygon is not simple: {ename(o)} crosses {ename(s)}")
    hit = np.flatnonzero(k.through >= 0)
    if len(hit):
        s = hit[0]
        raise ValueError(f"polygon is not simple: {vname(k.through[s])} lies on {ename(s)}")
    # orientation from the lexicographically smallest vertex (a convex corner): boundary CCW, holes CW;
    # flood fill from the inside of the boundary, never crossing a constraint edge
    along, h, simp, nb = _free_space(k.tri, k.nbr, k.cid, offset, _ring_turns(pts, offset, workspace()))
    if h:
        p = pts[offset[h]]
        if _winding(p, pts[:offset[1]]) == 0:
            raise ValueError(f"{name(h)} lies outside the boundary")
        inside = [g for g in range(1, nrings) if g != h and _winding(p, pts[offset[g]:offset[g + 1]]) != 0]
        where = f"inside hole {inside[0] - 1}" if inside else "around another hole"
        raise ValueError(f"{name(h)} lies {where}; holes must be disjoint")
    bounds = offset.tolist()                         # (slices: np.split is 5x slower on many holes)
    return PolygonTriangulation(pts, simp, nb, tuple(along[bounds[r]:bounds[r + 1]] for r in range(nrings)))
