"""Constrained Delaunay triangulation (CDT) and triangulation of polygons with holes.

A *constrained* Delaunay triangulation of points and segments contains every
segment as a chain of edges, and among such triangulations it is the most
Delaunay one: for every edge that is not a constraint, the opposite vertices
lie outside (or on) the circumcircles of the adjacent triangles (Chew 1987).

How (Sloan's flip method, 1993, on top of the fast Delaunay kernel):

1. ``Delaunay(points)`` (exact, numba) triangulates the points.
2. Each segment a-b is inserted in turn.  Around a, find the triangle that the
   ray towards b enters (or the edge it runs along).  Walk along a-b collecting
   the edges it crosses.  Flip each crossing edge whose quadrilateral is
   strictly convex, re-queueing it while the new diagonal still crosses a-b;
   re-queue the others (some edge is always flippable).  When a-b is an edge,
   Lawson-flip the touched triangles until every non-constraint edge is
   locally Delaunay again.  (The simpler cavity method, which re-triangulates
   the two "pseudo-polygons" beside the segment, assumes every crossed
   triangle's vertices lie on the cavity boundary; a segment can cross all the
   triangles around a vertex, so the cavity can enclose a vertex and that
   assumption fails.  Flips have no such case.)
3. A segment passing exactly through a vertex is split there (a -> v, v -> b),
   so collinear overlapping segments and T-junctions need nothing special.  A
   segment that *properly* crosses an earlier one raises ``ValueError`` naming
   both (this implementation adds no Steiner points).

Every decision (which side, in-circle, along-edge) uses the exact predicates.
Segments are inserted in a canonical (coordinate) order, so the triangles do
not depend on the order the segments are given in.

``polygon_triangulation(boundary, holes)`` runs the CDT on the polygon's vertices
with its edges as constraints, checks exactly that boundary and holes are simple
and disjoint with every hole inside the boundary (a proper crossing is caught by
the insertion; a vertex on another edge by the split record; a repeated vertex by
the duplicate map; a misplaced hole by the flood fill), and keeps the triangles
reached by a flood fill from the inside of the boundary that never crosses a
constraint edge.

Run the doctests:  python -m doctest reference_impl/constrained.py

>>> cdt = ConstrainedDelaunay([(0, 0), (4, 0), (4, 4), (0, 4), (1, 2), (3, 2)], [(0, 2)])
>>> [0, 2] in cdt.constraint_edges().tolist()
True
>>> pt = polygon_triangulation([(0, 0), (3, 0), (3, 3), (0, 3)], [[(1, 1), (2, 1), (2, 2), (1, 2)]])
>>> len(pt.simplices)
8
"""
from __future__ import annotations

from typing import NamedTuple, Sequence

import numpy as np
from numba import njit
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from .delaunay import Delaunay
from .points import as_points
from .predicates import incircle_nb, orient2d, orient2d_nb, workspace

__all__ = ["ConstrainedDelaunay", "constrained_delaunay", "PolygonTriangulation",
           "polygon_triangulation", "fan_search"]

# error codes of the numba kernel
_OK, _CROSSING, _LOST = 0, 1, 2


# ----------------------------------------------------------------------------- numba kernel
@njit(cache=True, inline="always")
def _slot(tri, t, v):
    """Position (0, 1, 2) of vertex v in triangle t, -1 if absent."""
    for k in range(3):
        if tri[t, k] == v:
            return k
    return -1


@njit(cache=True, inline="always")
def _third(tri, t, u, v):
    """Position in triangle t of the vertex that is neither u nor v."""
    for k in range(3):
        x = tri[t, k]
        if x != u and x != v:
            return k
    return -1


@njit(cache=True, inline="always")
def _ahead(ax, ay, qx, qy, x, y):
    """For (x, y) on the line through a and q: does it lie on the ray from a through q?"""
    if ax != qx:
        return (x > ax) == (qx > ax) and x != ax
    return (y > ay) == (qy > ay) and y != ay


@njit(cache=True)
def fan_search(tri, nbr, vt, X, Y, a, qx, qy, w):
    """Where does the ray from vertex ``a`` towards point q leave ``a``?

    Walks the triangles around ``a`` (starting at ``vt[a]``, counter-clockwise,
    then clockwise from the start if a boundary edge is met).  Returns
    ``(t, x)``: the ray runs along edge (a, x) of triangle t when ``x >= 0``;
    it enters the interior of t when ``x == -1``; ``t == -1`` when no triangle
    around ``a`` contains the direction (a on the boundary, q pointing out).
    """
    t0 = vt[a]
    if t0 < 0:
        return -1, -1
    ax = X[a]
    ay = Y[a]
    t = t0
    ccw = True
    while True:
        k = _slot(tri, t, a)
        x = tri[t, (k + 1) % 3]
        y = tri[t, (k + 2) % 3]
        ox = orient2d_nb(ax, ay, qx, qy, X[x], Y[x], w)
        oy = orient2d_nb(ax, ay, qx, qy, X[y], Y[y], w)
        if ox == 0 and _ahead(ax, ay, qx, qy, X[x], Y[x]):
            return t, x
        if oy == 0 and _ahead(ax, ay, qx, qy, X[y], Y[y]):
            return t, y
        if ox < 0 and oy > 0:
            return t, -1
        if ccw:
            nx = nbr[t, (k + 1) % 3]          # across edge (a, y)
            if nx == t0:
                return -1, -1
            if nx >= 0:
                t = nx
                continue
            ccw = False
            t = t0
            k = _slot(tri, t, a)
        nx = nbr[t, (k + 2) % 3]              # across edge (a, x)
        if nx < 0:
            return -1, -1
        t = nx


@njit(cache=True)
def _find_edge(tri, nbr, vt, u, v):
    """A triangle t containing edge (u, v) and the slot of its third vertex; (-1, -1) if absent."""
    t0 = vt[u]
    t = t0
    ccw = True
    while True:
        k = _slot(tri, t, u)
        if tri[t, (k + 1) % 3] == v:
            return t, (k + 2) % 3
        if tri[t, (k + 2) % 3] == v:
            return t, (k + 1) % 3
        if ccw:
            nx = nbr[t, (k + 1) % 3]
            if nx == t0:
                return -1, -1
            if nx >= 0:
                t = nx
                continue
            ccw = False
            t = t0
            k = _slot(tri, t, u)
        nx = nbr[t, (k + 2) % 3]
        if nx < 0:
            return -1, -1
        t = nx


@njit(cache=True)
def _flip(tri, nbr, cid, vt, t, k):
    """Flip the edge opposite slot k of t.  t = (p, u, v), o = (q, v, u) become (p, u, q), (q, v, p)."""
    o = nbr[t, k]
    p = tri[t, k]
    u = tri[t, (k + 1) % 3]
    v = tri[t, (k + 2) % 3]
    ko = _third(tri, o, u, v)
    q = tri[o, ko]
    na, ca = nbr[t, (k + 1) % 3], cid[t, (k + 1) % 3]      # across (v, p)
    nb, cb = nbr[t, (k + 2) % 3], cid[t, (k + 2) % 3]      # across (p, u)
    nc, cc = nbr[o, (ko + 1) % 3], cid[o, (ko + 1) % 3]    # across (u, q)
    nd, cd = nbr[o, (ko + 2) % 3], cid[o, (ko + 2) % 3]    # across (q, v)
    tri[t, 0], tri[t, 1], tri[t, 2] = p, u, q
    nbr[t, 0], nbr[t, 1], nbr[t, 2] = nc, o, nb
    cid[t, 0], cid[t, 1], cid[t, 2] = cc, -1, cb
    tri[o, 0], tri[o, 1], tri[o, 2] = q, v, p
    nbr[o, 0], nbr[o, 1], nbr[o, 2] = na, t, nd
    cid[o, 0], cid[o, 1], cid[o, 2] = ca, -1, cd
    if nc >= 0:
        nbr[nc, _third(tri, nc, u, q)] = t
    if na >= 0:
        nbr[na, _third(tri, na, v, p)] = o
    vt[p] = t
    vt[u] = t
    vt[q] = o
    vt[v] = o


@njit(cache=True)
def _legalize(tri, nbr, cid, vt, X, Y, w, stack, top):
    """Lawson flips until every non-constraint edge in ``stack[:top]`` (vertex pairs) is locally Delaunay."""
    while top > 0:
        top -= 1
        u = stack[top, 0]
        v = stack[top, 1]
        t, k = _find_edge(tri, nbr, vt, u, v)
        if t < 0 or cid[t, k] >= 0 or nbr[t, k] < 0:
            continue
        o = nbr[t, k]
        q = tri[o, _third(tri, o, u, v)]
        a, b, c = tri[t, 0], tri[t, 1], tri[t, 2]
        if incircle_nb(X[a], Y[a], X[b], Y[b], X[c], Y[c], X[q], Y[q], w) > 0:
            p = tri[t, k]
            _flip(tri, nbr, cid, vt, t, k)
            if top + 4 > stack.shape[0]:
                bigger = np.empty((2 * stack.shape[0], 2), np.int64)
                bigger[:top] = stack[:top]
                stack = bigger
            stack[top, 0], stack[top, 1] = p, u
            stack[top + 1, 0], stack[top + 1, 1] = u, q
            stack[top + 2, 0], stack[top + 2, 1] = q, v
            stack[top + 3, 0], stack[top + 3, 1] = v, p
            top += 4


@njit(cache=True)
def _insert_segment(s, a, b, tri, nbr, cid, vt, X, Y, w, through, err, queue, touched, stack):
    """Insert constraint segment number s from vertex a to vertex b.  False on error (see err).

    Sloan's method: collect the edges crossed by the segment, flip each one whose
    quadrilateral is strictly convex (re-queueing it if the new diagonal still
    crosses), re-queue the others; then Lawson-flip the touched region back to
    constrained Delaunay.  The walk stops at the first vertex lying exactly on
    the segment, which splits it.
    """
    while a != b:
        bx = X[b]
        by = Y[b]
        t, x = fan_search(tri, nbr, vt, X, Y, a, bx, by, w)
        if t < 0:
            err[0] = _LOST
            return False
        if x >= 0:                                   # the segment runs along edge (a, x)
            k = _third(tri, t, a, x)
            if cid[t, k] < 0:
                cid[t, k] = s
                o = nbr[t, k]
                if o >= 0:
                    cid[o, _third(tri, o, a, x)] = s
            if x != b and through[s] < 0:
                through[s] = x
            a = x
            continue
        # --- walk from a towards b, collecting the crossed edges
        ax = X[a]
        ay = Y[a]
        k = _slot(tri, t, a)
        right = tri[t, (k + 1) % 3]
        left = tri[t, (k + 2) % 3]
        kc = k                                       # slot (in t) opposite the crossed edge
        nq = 0
        touched[0] = t
        nt = 1
        while True:
            if cid[t, kc] >= 0:
                err[0] = _CROSSING
                err[2] = cid[t, kc]
                err[3] = right
                err[4] = left
                return False
            queue[nq, 0] = right
            queue[nq, 1] = left
            nq += 1
            t = nbr[t, kc]
            touched[nt] = t
            nt += 1
            wv = tri[t, _third(tri, t, right, left)]
            o = 0 if wv == b else orient2d_nb(ax, ay, bx, by, X[wv], Y[wv], w)
            if o == 0:                               # reached b, or a vertex on the segment
                break
            if o > 0:
                kc = _slot(tri, t, left)             # next crossed edge (right, wv)
                left = wv
            else:
                kc = _slot(tri, t, right)            # next crossed edge (wv, left)
                right = wv
        e = wv
        if e != b and through[s] < 0:
            through[s] = e
        ex = X[e]
        ey = Y[e]
        # --- Sloan: flip the crossing edges away (queue[head:] circularly, nq edges in it)
        head = 0
        stall = 0
        cap = queue.shape[0]
        while nq > 0:
            u = queue[head, 0]
            v = queue[head, 1]
            head = (head + 1) % cap
            nq -= 1
            t, k = _find_edge(tri, nbr, vt, u, v)
            o = nbr[t, k]
            p = tri[t, k]
            q = tri[o, _third(tri, o, u, v)]
            su = orient2d_nb(X[p], Y[p], X[q], Y[q], X[u], Y[u], w)
            sv = orient2d_nb(X[p], Y[p], X[q], Y[q], X[v], Y[v], w)
            if su * sv < 0:                          # strictly convex quadrilateral: flip
                _flip(tri, nbr, cid, vt, t, k)
                stall = 0
                op = 0 if (p == a or p == e) else orient2d_nb(ax, ay, ex, ey, X[p], Y[p], w)
                oq = 0 if (q == a or q == e) else orient2d_nb(ax, ay, ex, ey, X[q], Y[q], w)
                if op * oq < 0:
                    tail = (head + nq) % cap
                    queue[tail, 0] = p
                    queue[tail, 1] = q
                    nq += 1
            else:
                tail = (head + nq) % cap
                queue[tail, 0] = u
                queue[tail, 1] = v
                nq += 1
                stall += 1
                if stall > nq:                       # no flippable edge: cannot happen (Sloan 1993)
                    err[0] = _LOST
                    return False
        t, k = _find_edge(tri, nbr, vt, a, e)
        if t < 0:
            err[0] = _LOST
            return False
        cid[t, k] = s
        o = nbr[t, k]
        cid[o, _third(tri, o, a, e)] = s
        # --- restore the constrained Delaunay property in the touched triangles
        top = 0
        for i in range(nt):
            t = touched[i]
            for k in range(3):
                stack[top, 0] = tri[t, (k + 1) % 3]
                stack[top, 1] = tri[t, (k + 2) % 3]
                top += 1
        _legalize(tri, nbr, cid, vt, X, Y, w, stack, top)
        a = e
    return True


@njit(cache=True)
def insert_segments(tri, nbr, cid, vt, X, Y, seg, through, err, w):
    """Insert every segment ``seg[s] = (a, b)`` (vertex ids) into the triangulation in place.

    ``cid[t, k]`` receives the segment id of constraint edges; ``through[s]`` the
    first vertex found strictly inside segment s (or stays -1).  Returns False
    and fills ``err = [code, s, other segment, u, v]`` when segment s properly
    crosses the constraint edge (u, v) of segment ``other``.  ``w`` is a
    ``workspace()`` scratch array for the predicates.
    """
    cap = tri.shape[0] + 3
    queue = np.empty((cap, 2), np.int64)       # crossing edges (at most one per triangle)
    touched = np.empty(cap, np.int64)
    stack = np.empty((3 * cap + 16, 2), np.int64)
    for s in range(seg.shape[0]):
        if not _insert_segment(s, seg[s, 0], seg[s, 1], tri, nbr, cid, vt, X, Y, w, through, err,
                               queue, touched, stack):
            err[1] = s
            return False
    return True



# ----------------------------------------------------------------------------- python API
def _as_segments(segments, n: int) -> np.ndarray:
    """Validate segments: an (k, 2) array of integer point indices in 0..n-1."""
    if isinstance(segments, (str, bytes)):
        raise ValueError(f"segments must be (k, 2) point indices, got text {segments[:40]!r}")
    try:
        raw = np.asarray(segments)
    except (ValueError, TypeError) as exc:
        raise ValueError(f"segments must be a (k, 2) array of point indices: {exc}") from None
    if raw.size == 0:
        return np.zeros((0, 2), dtype=np.int64)
    if raw.ndim != 2 or raw.shape[1] != 2:
        raise ValueError(f"segments must have shape (k, 2), got {raw.shape}")
    if raw.dtype.kind == "O" and all(isinstance(v, (int, np.integer)) and not isinstance(v, bool)
                                     for v in raw.ravel()):
        raw = raw.astype(np.int64)
    if raw.dtype.kind not in "iu":
        raise ValueError(f"segments must contain integer point indices, got dtype {raw.dtype}")
    seg = raw.astype(np.int64)
    bad = np.flatnonzero(((seg < 0) | (seg >= n)).any(axis=1))
    if len(bad):
        raise ValueError(f"segments[{bad[0]}] = {seg[bad[0]].tolist()} has an index outside 0..{n - 1}")
    return seg


class _Kernel(NamedTuple):
    tri: np.ndarray
    nbr: np.ndarray
    cid: np.ndarray          # input segment index of each constraint edge, -1 elsewhere
    through: np.ndarray      # per input segment: a vertex strictly inside it, or -1
    error: tuple | None      # (segment, other segment, u, v) for a proper crossing


def _run_cdt(d: Delaunay, segments: np.ndarray) -> _Kernel:
    """Insert ``segments`` (input indices) into the Delaunay triangulation ``d``."""
    pts = d.points
    n = len(pts)
    rep = d.index_map
    tri = np.ascontiguousarray(d.simplices, dtype=np.int64).copy()
    nbr = np.ascontiguousarray(d.neighbors, dtype=np.int64).copy()
    cid = np.full(tri.shape, -1, dtype=np.int64)
    through = np.full(len(segments), -1, dtype=np.int64)
    if len(tri) == 0 or len(segments) == 0:
        return _Kernel(tri, nbr, cid, through, None)
    seg = rep[segments]
    # canonical order: each segment from its lexicographically smaller end, sorted by coordinates
    a, b = seg[:, 0], seg[:, 1]
    swap = (pts[a, 0] > pts[b, 0]) | ((pts[a, 0] == pts[b, 0]) & (pts[a, 1] > pts[b, 1]))
    seg = np.where(swap[:, None], seg[:, ::-1], seg)
    order = np.lexsort((pts[seg[:, 1], 1], pts[seg[:, 1], 0], pts[seg[:, 0], 1], pts[seg[:, 0], 0]))
    vt = np.full(n, -1, dtype=np.int64)
    vt[tri.ravel()] = np.repeat(np.arange(len(tri)), 3)
    err = np.zeros(5, dtype=np.int64)
    sub_through = np.full(len(seg), -1, dtype=np.int64)
    ok = insert_segments(tri, nbr, cid, vt, pts[:, 0].copy(), pts[:, 1].copy(),
                         np.ascontiguousarray(seg[order]), sub_through, err, workspace())
    mask = cid >= 0
    cid[mask] = order[cid[mask]]                      # back to input segment numbers
    through[order] = sub_through
    if not ok:
        if err[0] != _CROSSING:
            raise RuntimeError("constrained Delaunay: lost the segment walk (please report this input)")
        return _Kernel(tri, nbr, cid, through,
                       (int(order[err[1]]), int(order[err[2]]), int(err[3]), int(err[4])))
    return _Kernel(tri, nbr, cid, through, None)


def _fmt(p) -> str:
    return f"({float(p[0]):g}, {float(p[1]):g})"


class ConstrainedDelaunay:
    """Constrained Delaunay triangulation of points and segments (exact, no Steiner points).

    ``points``: (n, 2) coordinates; ``segments``: (k, 2) indices into points.
    Attributes, in the data model of ``Delaunay``: ``points``, ``simplices`` (m, 3)
    counter-clockwise, ``neighbors`` (m, 3) (-1 on the hull), ``constrained`` (m, 3)
    bool (edge opposite vertex k is part of a segment), ``index_map`` (duplicates
    merged to the smallest index, as in ``Delaunay``).  The triangles cover the
    convex hull of the points.  A segment through a vertex is split there; two
    segments crossing properly raise ``ValueError``; a zero-length segment is
    ignored.  All-collinear input gives no triangles.

    >>> cdt = ConstrainedDelaunay([(0, 0), (2, -1), (4, 0), (2, 1), (2, 3)], [(1, 4)])
    >>> sorted(map(sorted, cdt.simplices.tolist()))
    [[0, 1, 3], [0, 3, 4], [1, 2, 3], [2, 3, 4]]
    >>> ConstrainedDelaunay([(0, 0), (2, 2), (0, 2), (2, 0)], [(0, 1), (2, 3)])
    Traceback (most recent call last):
    ...
    ValueError: segments[1] = (0, 2)-(2, 0) properly crosses segments[0] = (0, 0)-(2, 2)
    """

    def __init__(self, points, segments=()) -> None:
        self._delaunay = Delaunay(points)
        self._segments = _as_segments(segments, len(self._delaunay.points))
        k = _run_cdt(self._delaunay, self._segments)
        if k.error is not None:
            s, o = k.error[:2]
            raise ValueError(f"segments[{s}] = {self._describe(s)} properly crosses "
                             f"segments[{o}] = {self._describe(o)}")
        self._k = k

    def _describe(self, s: int) -> str:
        a, b = self._segments[s]
        return f"{_fmt(self.points[a])}-{_fmt(self.points[b])}"

    @property
    def points(self) -> np.ndarray:
        """The input points, (n, 2) float64."""
        return self._delaunay.points

    @property
    def segments(self) -> np.ndarray:
        """The input segments, (k, 2) point indices."""
        return self._segments

    @property
    def simplices(self) -> np.ndarray:
        """(m, 3) point indices of the triangles, counter-clockwise."""
        return self._k.tri

    @property
    def neighbors(self) -> np.ndarray:
        """(m, 3): triangle opposite vertex k (-1 on the convex hull)."""
        return self._k.nbr

    @property
    def constrained(self) -> np.ndarray:
        """(m, 3) bool: the edge opposite vertex k lies on an input segment."""
        return self._k.cid >= 0

    @property
    def index_map(self) -> np.ndarray:
        """``index_map[i]``: the index point i was merged into (i unless a duplicate)."""
        return self._delaunay.index_map

    def edges(self) -> np.ndarray:
        """Unique undirected edges (k, 2) with i < j, sorted.

        >>> ConstrainedDelaunay([(0, 0), (1, 0), (0, 1)]).edges().tolist()
        [[0, 1], [0, 2], [1, 2]]
        """
        return _unique_edges(self.simplices, np.ones(self.simplices.shape, bool))

    def constraint_edges(self) -> np.ndarray:
        """Unique sorted edges (k, 2) that lie on input segments (segments split at vertices).

        >>> ConstrainedDelaunay([(0, 0), (1, 0), (2, 0), (1, 1)], [(0, 2)]).constraint_edges().tolist()
        [[0, 1], [1, 2]]
        """
        return _unique_edges(self.simplices, self.constrained)

    def __repr__(self) -> str:
        return (f"ConstrainedDelaunay(n={len(self.points)}, segments={len(self._segments)}, "
                f"triangles={len(self.simplices)})")


def _unique_edges(tri: np.ndarray, mask: np.ndarray) -> np.ndarray:
    e = np.concatenate([tri[:, [1, 2]][mask[:, 0]], tri[:, [2, 0]][mask[:, 1]], tri[:, [0, 1]][mask[:, 2]]])
    if len(e) == 0:
        return np.zeros((0, 2), dtype=np.int64)
    return np.unique(np.sort(e, axis=1), axis=0)


def constrained_delaunay(points, segments) -> np.ndarray:
    """Triangles (m, 3), counter-clockwise, of the constrained Delaunay triangulation.

    Shorthand for ``ConstrainedDelaunay(points, segments).simplices`` (no point is
    added, so the input points are the output points).

    >>> constrained_delaunay([(0, 0), (1, 0), (0, 1)], [(0, 1)]).tolist()
    [[0, 1, 2]]
    """
    return ConstrainedDelaunay(points, segments).simplices


# ----------------------------------------------------------------------------- polygons
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


def _clean_ring(ring, name: str) -> np.ndarray:
    """Validated (k, 2) ring without repeated consecutive vertices or a closing copy of the first."""
    pts = as_points(ring, name=name)
    if len(pts):
        keep = np.any(pts != np.roll(pts, 1, axis=0), axis=1)
        keep[0] = True
        pts = pts[keep]
        if len(pts) > 1 and np.array_equal(pts[0], pts[-1]):
            pts = pts[:-1]
    if len(pts) < 3:
        raise ValueError(f"{name} needs at least 3 distinct vertices, got {len(pts)}")
    return pts


def _winding(p, ring_pts: np.ndarray) -> int:
    """Exact winding number of ring_pts around p (p not on the ring)."""
    wn = 0
    for a, b in zip(ring_pts, np.roll(ring_pts, -1, axis=0)):
        if a[1] <= p[1] < b[1] and orient2d(a, b, p) > 0:
            wn += 1
        elif b[1] <= p[1] < a[1] and orient2d(a, b, p) < 0:
            wn -= 1
    return wn


def polygon_triangulation(boundary, holes: Sequence = ()) -> PolygonTriangulation:
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
    rings = [_clean_ring(boundary, "boundary")] + [_clean_ring(h, f"holes[{i}]") for i, h in enumerate(holes)]
    sizes = np.array([len(r) for r in rings])
    offset = np.concatenate([[0], np.cumsum(sizes)])
    pts = np.vstack(rings)
    ring_of = np.repeat(np.arange(len(rings)), sizes)
    local = np.arange(len(pts)) - offset[ring_of]
    nxt = np.arange(len(pts)) + 1
    nxt[offset[1:] - 1] = offset[:-1]
    seg = np.stack([np.arange(len(pts)), nxt], axis=1)

    def vname(i):
        return f"{names[ring_of[i]]} vertex {local[i]} {_fmt(pts[i])}"

    def ename(s):
        return f"{names[ring_of[s]]} edge {local[s]} {_fmt(pts[s])}-{_fmt(pts[nxt[s]])}"

    d = Delaunay(pts)
    rep = d.index_map
    dup = np.flatnonzero(rep != np.arange(len(pts)))
    if len(dup):
        raise ValueError(f"polygon is not simple: {vname(dup[0])} repeats {vname(rep[dup[0]])}")
    if len(d.simplices) == 0:
        raise ValueError("polygon has zero area: all vertices are collinear")
    k = _run_cdt(d, seg)
    if k.error is not None:
        s, o = sorted(k.error[:2])
        raise ValueError(f"polygon is not simple: {ename(o)} crosses {ename(s)}")
    hit = np.flatnonzero(k.through >= 0)
    if len(hit):
        s = hit[0]
        raise ValueError(f"polygon is not simple: {vname(k.through[s])} lies on {ename(s)}")
    # orientation from the lexicographically smallest vertex (a convex corner): boundary CCW, holes CW
    ring_idx = []
    for r in range(len(rings)):
        idx = np.arange(offset[r], offset[r + 1])
        m = int(np.lexsort((rings[r][:, 1], rings[r][:, 0]))[0])
        ccw = orient2d(rings[r][m - 1], rings[r][m], rings[r][(m + 1) % len(idx)]) > 0
        ring_idx.append(idx if ccw == (r == 0) else idx[::-1].copy())
    # flood fill from the inside of the boundary, never crossing a constraint edge
    tri, nbr, cid = k.tri, k.nbr, k.cid
    m, n = len(tri), len(pts)
    key = (tri[:, [1, 2, 0]] * n + tri[:, [2, 0, 1]]).ravel()      # directed edge opposite slot k
    order = np.argsort(key)

    def left_triangle(u, v):
        """Triangle containing the directed edge u -> v (it exists for every ring edge)."""
        pos = np.searchsorted(key[order], u * n + v)
        ok = (pos < len(key)) & (key[order][np.minimum(pos, len(key) - 1)] == u * n + v)
        return np.where(ok, order[np.minimum(pos, len(key) - 1)] // 3, -1)

    t_idx, k_idx = np.nonzero((nbr >= 0) & (cid < 0))
    graph = coo_matrix((np.ones(len(t_idx)), (t_idx, nbr[t_idx, k_idx])), shape=(m, m))
    _, label = connected_components(graph, directed=False)
    b = ring_idx[0]
    seeds = left_triangle(b, np.roll(b, -1))
    free = np.isin(label, label[seeds])
    for h in range(1, len(rings)):
        hr = ring_idx[h]
        side = left_triangle(hr, np.roll(hr, -1))
        if (side < 0).any() or not free[side].all():
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
