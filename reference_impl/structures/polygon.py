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

Run the doctests:  python -m doctest reference_impl/structures/polygon.py

>>> pt = polygon_triangulation([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (1, 3), (3, 3), (3, 1)]])
>>> len(pt.simplices), [r.tolist() for r in pt.rings]
(8, [[0, 1, 2, 3], [4, 5, 6, 7]])
"""
from __future__ import annotations

from typing import NamedTuple, Sequence

import numpy as np
from numpy.typing import ArrayLike

from reference_impl.exact.predicates import orient2d, workspace
from reference_impl.mesh.delaunay import Delaunay
from reference_impl.mesh.topology import triangles_left_of
from reference_impl.structures.constrained import constrain_delaunay, format_point, orient_many
from reference_impl.validate import as_ring

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
    names = ["boundary"] + [f"hole {h}" for h in range(len(holes))]
    rings = [as_ring(boundary, "boundary")] + [as_ring(h, f"holes[{i}]") for i, h in enumerate(holes)]
    sizes = np.array([len(r) for r in rings])
    offset = np.concatenate([[0], np.cumsum(sizes)])
    pts = np.vstack(rings)
    ring_of = np.repeat(np.arange(len(rings)), sizes)
    local = np.arange(len(pts)) - offset[ring_of]
    nxt = np.arange(len(pts)) + 1
    nxt[offset[1:] - 1] = offset[:-1]
    seg = np.stack([np.arange(len(pts)), nxt], axis=1)

    def vname(i):
        return f"{names[ring_of[i]]} vertex {local[i]} {format_point(pts[i])}"

    def ename(s):
        return f"{names[ring_of[s]]} edge {local[s]} {format_point(pts[s])}-{format_point(pts[nxt[s]])}"

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
    # orientation from the lexicographically smallest vertex (a convex corner): boundary CCW, holes CW
    prv = np.arange(len(pts)) - 1
    prv[offset[:-1]] = offset[1:] - 1
    lowest = np.lexsort((pts[:, 1], pts[:, 0], ring_of))[offset[:-1]]
    ccw = orient_many(pts[:, 0].copy(), pts[:, 1].copy(), prv[lowest], lowest, nxt[lowest], workspace()) > 0
    flip = ccw != (np.arange(len(rings)) == 0)
    succ = np.where(flip[ring_of], prv, nxt)              # next vertex along the normalised ring
    ring_idx = [np.arange(offset[r + 1] - 1, offset[r] - 1, -1) if flip[r] else np.arange(offset[r], offset[r + 1])
                for r in range(len(rings))]
    # flood fill from the inside of the boundary, never crossing a constraint edge
    tri, nbr, cid = k.tri, k.nbr, k.cid
    m, n = len(tri), len(pts)
    # the triangle left of each normalised ring edge u -> succ[u]: boundary edges, then hole edges
    starts = np.concatenate([ring_idx[0], np.arange(offset[1], n)])
    left = triangles_left_of(tri, n, starts, succ[starts])
    t_idx, k_idx = np.nonzero((nbr >= 0) & (cid < 0))
    from scipy.sparse import coo_matrix          # (imported here: scipy.sparse takes 0.2-0.4 s to import)
    from scipy.sparse.csgraph import connected_components

    graph = coo_matrix((np.ones(len(t_idx)), (t_idx, nbr[t_idx, k_idx])), shape=(m, m))
    _, label = connected_components(graph, directed=False)
    seeds = left[:len(ring_idx[0])]
    free = np.isin(label, label[seeds])
    if len(rings) > 1:
        side, owner = left[len(ring_idx[0]):], ring_of[offset[1]:]
        bad = np.flatnonzero((side < 0) | ~free[side])
        if len(bad):
            h = int(owner[bad[0]])
            p = rings[h][0]
            if _winding(p, rings[0]) == 0:
                raise ValueError(f"{names[h]} lies outside the boundary")
            inside = [g for g in range(1, len(rings)) if g != h and _winding(p, rings[g]) != 0]
            where = f"inside hole {inside[0] - 1}" if inside else "around another hole"
            raise ValueError(f"{names[h]} lies {where}; holes must be disjoint")
    new = np.full(m + 1, -1, dtype=np.int64)
    new[np.flatnonzero(free)] = np.arange(int(free.sum()))
    nb = np.where(cid[free] >= 0, -1, new[nbr[free]])
    return PolygonTriangulation(pts, tri[free].copy(), nb, tuple(ring_idx))
