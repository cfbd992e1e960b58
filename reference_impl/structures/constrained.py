"""Constrained Delaunay triangulation (CDT): points plus segments that must be edges.

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
   locally Delaunay again.  (Flips rather than re-triangulating the two
   "pseudo-polygons" beside the segment: a segment can cross *every* triangle
   around a vertex, and then the cavity encloses that vertex.)
3. A segment passing exactly through a vertex is split there (a -> v, v -> b),
   so collinear overlapping segments and T-junctions need nothing special.  A
   segment that *properly* crosses an earlier one raises ``ValueError`` naming
   both (this implementation adds no Steiner points).

Every decision (which side, in-circle, along-edge) uses the exact predicates.
Segments are inserted in a canonical (coordinate) order and ``Delaunay``'s
output depends only on the point set, so the triangles (cocircular ties
included) do not depend on the order of the segments or of the points.

``polygon.polygon_triangulation`` (polygons with holes) is built on this module
(``constrain_delaunay``); the mesh helpers it uses are in ``mesh/topology.py``.

Run the doctests:  python -m pytest reference_impl/structures/constrained.py

>>> cdt = ConstrainedDelaunay([(0, 0), (4, 0), (4, 4), (0, 4), (1, 2), (3, 2)], [(0, 2)])
>>> [0, 2] in cdt.constraint_edges().tolist()
True
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from reference_impl.mesh import status
from reference_impl.mesh.delaunay import Delaunay
from reference_impl.mesh.status import CROSSING, LOST, OK
from reference_impl.mesh.topology import find_edge, flip, slot, third, unique_edges, vertex_triangles
from reference_impl.validate import as_index_rows
from reference_impl.exact.predicates import incircle_nb, orient2d_nb, workspace
from reference_impl.exact.sorting import merge_sort

__all__ = ["ConstrainedDelaunay", "constrained_delaunay", "ConstrainedMesh", "constrain_delaunay",
           "fan_search", "insert_segments", "canonical_segments", "orient_many", "ray_ahead", "format_point"]



# ----------------------------------------------------------------------------- numba kernel
@njit(cache=True, inline="always")
def ray_ahead(ax, ay, qx, qy, x, y):
    """For (x, y) on the line through a and q: does it lie on the ray from a through q?"""
    if ax != qx:
        return (x > ax) == (qx > ax) and x != ax
    return (y > ay) == (qy > ay) and y != ay


@njit(cache=True, inline="always")
def fan_search(tri, nbr, vt, X, Y, a, qx, qy, qv, w):
    """Where does the ray from vertex ``a`` towards point q leave ``a``?

    Walks the triangles around ``a`` (starting at ``vt[a]``, counter-clockwise,
    then clockwise from the start if a boundary edge is met).  Returns
    ``(t, x)``: the ray runs along edge (a, x) of triangle t when ``x >= 0``;
    it enters the interior of t when ``x == -1``; ``t == -1`` when no triangle
    around ``a`` contains the direction (a on the boundary, q pointing out).
    ``qv`` is the vertex at q (-1 if none): recognised by its index, which
    spares the exact stage of the predicate a zero orientation needs.
    """
    t0 = vt[a]
    if t0 < 0:
        return -1, -1
    ax = X[a]
    ay = Y[a]
    t = t0
    ccw = True
    while True:
        k = slot(tri, t, a)
        x = tri[t, (k + 1) % 3]
        y = tri[t, (k + 2) % 3]
        if x == qv:
            return t, x
        if y == qv:
            return t, y
        ox = orient2d_nb(ax, ay, qx, qy, X[x], Y[x], w)
        oy = orient2d_nb(ax, ay, qx, qy, X[y], Y[y], w)
        if ox == 0 and ray_ahead(ax, ay, qx, qy, X[x], Y[x]):
            return t, x
        if oy == 0 and ray_ahead(ax, ay, qx, qy, X[y], Y[y]):
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
            k = slot(tri, t, a)
        nx = nbr[t, (k + 2) % 3]              # across edge (a, x)
        if nx < 0:
            return -1, -1
        t = nx


@njit(cache=True, inline="always")
def _flip(tri, nbr, cid, vt, t, k):
    """``topology.flip`` of the edge opposite slot k of t, carrying the constraint ids and ``vt``.

    t = (p, u, v), o = (q, v, u) become t = (u, q, p), o = (q, v, p); the new edge q-p is free.
    """
    o = nbr[t, k]
    ko = slot(nbr, o, t)
    ca = cid[t, (k + 1) % 3]       # across (v, p)
    cb = cid[t, (k + 2) % 3]       # across (p, u)
    cc = cid[o, (ko + 1) % 3]      # across (u, q)
    cd = cid[o, (ko + 2) % 3]      # across (q, v)
    flip(tri, nbr, t, k)
    cid[t, 0], cid[t, 1], cid[t, 2] = -1, cb, cc
    cid[o, 0], cid[o, 1], cid[o, 2] = ca, -1, cd
    vt[tri[t, 0]] = t
    vt[tri[t, 2]] = t
    vt[tri[o, 0]] = o
    vt[tri[o, 1]] = o


@njit(cache=True, inline="always")
def _push(stack, mark, top, t):
    """Push region triangle t on the legalization stack unless it is there already (``mark``
    2: in the stack, 1: in the region, not in the stack); the new top."""
    if mark[t] != 2:
        mark[t] = 2
        stack[top] = t
        top += 1
    return top


@njit(cache=True, inline="always")
def _legalize(tri, nbr, cid, vt, X, Y, w, stack, mark, top):
    """Lawson flips inside the *region* (the triangles the segment crossed, ``mark`` != 0)
    until every non-constraint edge between two region triangles is locally Delaunay.

    Only those edges need a test: the triangles the new segment does not cross stay
    constrained Delaunay, and the new triangulation is theirs plus the constrained
    Delaunay triangulation of the region with its outline fixed (Anglada 1997), which
    Lawson flips of the region's own edges reach.  Flips keep triangle ids, so the region
    stays the same set of triangles.  ``stack[:top]`` holds region triangles, each at most
    once (``mark`` 2 while in it, 1 once out).  Invariant: every region edge that may be
    illegal has a side in the stack.  A popped triangle tests an edge only when the
    triangle across is out of the stack (otherwise that one tests it later), so each edge
    is tested once unless a flip beside it pushes it again; a flip pushes both triangles
    it rewrote, which hold every edge whose two sides changed.
    """
    while top > 0:
        top -= 1
        t = stack[top]
        mark[t] = 1
        a = tri[t, 0]
        b = tri[t, 1]
        c = tri[t, 2]
        for k in range(3):
            o = nbr[t, k]
            if o < 0 or mark[o] != 1 or cid[t, k] >= 0:
                continue
            q = tri[o, slot(nbr, o, t)]
            if incircle_nb(X[a], Y[a], X[b], Y[b], X[c], Y[c], X[q], Y[q], w) > 0:
                _flip(tri, nbr, cid, vt, t, k)
                top = _push(stack, mark, top, t)
                top = _push(stack, mark, top, o)
                break
    return top


@njit(cache=True, inline="always")
def _edge_at(tri, nbr, vt, h, u, v):
    """``find_edge(u, v)``, trying triangle h first (the one that held the edge when it was
    queued: usually it still does, and the fan walk around u is skipped)."""
    if slot(tri, h, u) >= 0 and slot(tri, h, v) >= 0:
        return h, third(tri, h, u, v)
    return find_edge(tri, nbr, vt, u, v)


@njit(cache=True, inline="always")
def _insert_segment(s, a, b, tri, nbr, cid, vt, X, Y, w, through, err, queue, touched, stack, mark, side):
    """Insert constraint segment s (its input number: written to ``cid`` and ``through[s]``)
    from vertex a to vertex b.  False on error (see err).

    Sloan's method: collect the edges crossed by the segment, flip each one whose
    quadrilateral is strictly convex (re-queueing it if the new diagonal still
    crosses), re-queue the others; then Lawson-flip the touched region back to
    constrained Delaunay.  The walk stops at the first vertex lying exactly on
    the segment, which splits it.
    """
    while a != b:
        bx = X[b]
        by = Y[b]
        t, x = fan_search(tri, nbr, vt, X, Y, a, bx, by, b, w)
        if t < 0:
            err[0] = LOST
            return False
        if x >= 0:                                   # the segment runs along edge (a, x)
            k = third(tri, t, a, x)
            if cid[t, k] < 0:
                cid[t, k] = s
                o = nbr[t, k]
                if o >= 0:
                    cid[o, third(tri, o, a, x)] = s
            if x != b and through[s] < 0:
                through[s] = x
            a = x
            continue
        # --- walk from a towards b, collecting the crossed edges
        ax = X[a]
        ay = Y[a]
        k = slot(tri, t, a)
        right = tri[t, (k + 1) % 3]
        left = tri[t, (k + 2) % 3]
        kc = k                                       # slot (in t) opposite the crossed edge
        # side[v]: the side of line a-b that vertex v of the crossed region is on (-1 right,
        # +1 left, 0 on it: a and the end e), kept so that the flips below need no predicate
        side[a] = 0
        side[right] = -1
        side[left] = 1
        nq = 0
        touched[0] = t
        nt = 1
        while True:
            if cid[t, kc] >= 0:
                err[0] = CROSSING
                err[2] = cid[t, kc]
                err[3] = right
                err[4] = left
                return False
            queue[nq, 0] = right
            queue[nq, 1] = left
            queue[nq, 2] = t
            nq += 1
            t = nbr[t, kc]
            touched[nt] = t
            nt += 1
            wv = tri[t, third(tri, t, right, left)]
            o = 0 if wv == b else orient2d_nb(ax, ay, bx, by, X[wv], Y[wv], w)
            side[wv] = o
            if o == 0:                               # reached b, or a vertex on the segment
                break
            if o > 0:
                kc = slot(tri, t, left)             # next crossed edge (right, wv)
                left = wv
            else:
                kc = slot(tri, t, right)            # next crossed edge (wv, left)
                right = wv
        e = wv
        if e != b and through[s] < 0:
            through[s] = e
        # --- Sloan: flip the crossing edges away (queue[head:] circularly, nq edges in it)
        head = 0
        stall = 0
        cap = queue.shape[0]
        while nq > 0:
            u = queue[head, 0]
            v = queue[head, 1]
            h = queue[head, 2]
            head = (head + 1) % cap
            nq -= 1
            t, k = _edge_at(tri, nbr, vt, h, u, v)
            o = nbr[t, k]
            p = tri[t, k]
            q = tri[o, third(tri, o, u, v)]
            su = orient2d_nb(X[p], Y[p], X[q], Y[q], X[u], Y[u], w)
            sv = orient2d_nb(X[p], Y[p], X[q], Y[q], X[v], Y[v], w)
            if su * sv < 0:                          # strictly convex quadrilateral: flip
                _flip(tri, nbr, cid, vt, t, k)
                stall = 0
                if side[p] * side[q] < 0:             # the new diagonal still crosses a-e
                    tail = (head + nq) % cap
                    queue[tail, 0] = p
                    queue[tail, 1] = q
                    queue[tail, 2] = t
                    nq += 1
            else:
                tail = (head + nq) % cap
                queue[tail, 0] = u
                queue[tail, 1] = v
                queue[tail, 2] = t
                nq += 1
                stall += 1
                if stall > nq:                       # no flippable edge: cannot happen (Sloan 1993)
                    err[0] = LOST
                    return False
        t, k = find_edge(tri, nbr, vt, a, e)
        if t < 0:
            err[0] = LOST
            return False
        cid[t, k] = s
        o = nbr[t, k]
        cid[o, third(tri, o, a, e)] = s
        # --- restore the constrained Delaunay property in the touched triangles (flips keep
        # triangle ids, so the crossed triangles' ids are exactly the retriangulated region)
        top = 0
        for i in range(nt):
            top = _push(stack, mark, top, touched[i])
        _legalize(tri, nbr, cid, vt, X, Y, w, stack, mark, top)
        for i in range(nt):
            mark[touched[i]] = 0
        a = e
    return True


@njit(cache=True, _nrt=False)
def _insert_all(tri, nbr, cid, vt, X, Y, seg, through, err, w, ids, queue, touched, stack, mark, side):
    """``insert_segments`` on scratch arrays from the caller: ``queue`` (m + 3, 3), ``touched``
    and ``stack`` (m + 3,), ``mark`` (m,) all zero, ``side`` (n,).

    Compiled without numba's reference counting (as ``mesh/kernel.build``): the helpers are
    inlined, and each array they receive would otherwise cost an atomic incref/decref pair per
    call.  Nothing compiled in here may allocate an array; the exact stages of the predicates
    carry reference counting of their own."""
    for i in range(seg.shape[0]):
        s = ids[i]
        if not _insert_segment(s, seg[i, 0], seg[i, 1], tri, nbr, cid, vt, X, Y, w, through, err,
                               queue, touched, stack, mark, side):
            err[1] = s
            return False
    return True


@njit(cache=True)
def orient_many(X, Y, a, b, c, w):
    """Exact orientation signs of the vertex triples (a[i], b[i], c[i])."""
    out = np.empty(a.shape[0], np.int64)
    for i in range(a.shape[0]):
        out[i] = orient2d_nb(X[a[i]], Y[a[i]], X[b[i]], Y[b[i]], X[c[i]], Y[c[i]], w)
    return out


@njit(cache=True)
def insert_segments(tri, nbr, cid, vt, X, Y, seg, through, err, w, ids=None):
    """Insert every segment ``seg[i] = (a, b)`` (vertex ids) into the triangulation in place.

    Segment i is known as ``s = ids[i]`` (i without ``ids``; ``through`` and ``cid`` are
    indexed by these numbers).  ``cid[t, k]`` receives s for constraint edges;
    ``through[s]`` the first vertex found strictly inside segment s (or stays -1).  Returns
    False and fills ``err = [code, s, other segment, u, v]`` when segment s properly crosses
    the constraint edge (u, v) of segment ``other``.  ``w`` is a ``workspace()`` scratch
    array for the predicates.
    """
    if ids is None:
        ids = np.arange(seg.shape[0])
    cap = tri.shape[0] + 3
    queue = np.empty((cap, 3), np.int64)       # crossing edges (u, v, a triangle that had it)
    touched = np.empty(cap, np.int64)          # the triangles crossed by one piece of a segment
    stack = np.empty(cap, np.int64)            # legalization: each triangle at most once
    mark = np.zeros(cap, np.int8)
    side = np.zeros(X.shape[0], np.int8)       # per vertex: its side of the segment being inserted
    return _insert_all(tri, nbr, cid, vt, X, Y, seg, through, err, w, ids, queue, touched, stack, mark, side)


@njit(cache=True, inline="always")
def _before(key, p, q):  # (merge_sort's comparison)
    """Row p of ``key`` is lexicographically smaller than row q."""
    for j in range(key.shape[1]):
        if key[p, j] != key[q, j]:
            return key[p, j] < key[q, j]
    return False


@njit(cache=True)
def canonical_segments(seg, X, Y):
    """The segments in canonical order: ``(oriented, order)`` with ``oriented[i]`` input segment
    ``order[i]`` taken from its lexicographically smaller end, sorted by the coordinates
    (xa, ya, xb, yb), ties in input order (what ``np.lexsort`` gives; ``sorting.merge_sort`` here)."""
    k = seg.shape[0]
    key = np.empty((k, 4))
    ends = np.empty((k, 2), np.int64)
    for i in range(k):
        a = seg[i, 0]
        b = seg[i, 1]
        if X[a] > X[b] or (X[a] == X[b] and Y[a] > Y[b]):
            a, b = b, a
        ends[i, 0] = a
        ends[i, 1] = b
        key[i, 0] = X[a]
        key[i, 1] = Y[a]
        key[i, 2] = X[b]
        key[i, 3] = Y[b]
    order = np.arange(k)
    merge_sort(order, np.empty(k, np.int64), _before, key)
    oriented = np.empty((k, 2), np.int64)
    for i in range(k):
        oriented[i, 0] = ends[order[i], 0]
        oriented[i, 1] = ends[order[i], 1]
    return oriented, order


@njit(cache=True)
def _prepare(simp, nbrs, rep, segments, pts):
    """``constrain_delaunay``'s set-up in one call: copies of the mesh (``simp``, ``nbrs``),
    the constraint and error arrays, the coordinates as columns, the vertex -> triangle map,
    and the segments' ends mapped through ``rep`` (duplicates to their representatives) in
    canonical order (``canonical_segments``).  (``insert_segments`` is called apart: a
    compiled caller would compile its code again, predicates included, at every cold start.)"""
    k = segments.shape[0]
    seg = np.empty((k, 2), np.int64)
    for i in range(k):
        seg[i, 0] = rep[segments[i, 0]]
        seg[i, 1] = rep[segments[i, 1]]
    X = pts[:, 0].copy()
    Y = pts[:, 1].copy()
    oriented, order = canonical_segments(seg, X, Y)
    tri = simp.copy()
    err = np.zeros(5, np.int64)
    err[0] = OK
    return (tri, nbrs.copy(), np.full(simp.shape, -1, np.int64), np.full(k, -1, np.int64), err, X, Y,
            oriented, order, vertex_triangles(tri, pts.shape[0]))



# ----------------------------------------------------------------------------- python API
class ConstrainedMesh(NamedTuple):
    """The arrays of ``constrain_delaunay``: the mesh in the public layout plus the constraints."""
    tri: np.ndarray
    nbr: np.ndarray
    cid: np.ndarray          # input segment index of each constraint edge, -1 elsewhere
    through: np.ndarray      # per input segment: a vertex strictly inside it, or -1
    error: tuple | None      # (segment, other segment, u, v) for a proper crossing


def constrain_delaunay(d: Delaunay, segments: np.ndarray) -> ConstrainedMesh:
    """Insert ``segments`` ((k, 2) validated input indices) into a copy of the triangulation ``d``.

    Returns the ``ConstrainedMesh``; a proper crossing is not raised but reported
    in its ``error`` field (``ConstrainedDelaunay`` and ``polygon_triangulation``
    word the message).  The work is two compiled calls (``_prepare``, ``insert_segments``).

    >>> k = constrain_delaunay(Delaunay([(0, 0), (2, -1), (2, 1), (4, 0)]), np.array([[0, 3]]))
    >>> int((k.cid >= 0).sum()), k.error is None
    (2, True)
    """
    tri, nbr, cid, through, err, X, Y, seg, order, vt = _prepare(d.simplices, d.neighbors, d.index_map,
                                                                 segments, d.points)
    if len(tri) and len(seg):
        insert_segments(tri, nbr, cid, vt, X, Y, seg, through, err, workspace(), order)
    if err[0] == status.OK:
        return ConstrainedMesh(tri, nbr, cid, through, None)
    if status.check(err[0], "constrained Delaunay: the segment walk") != CROSSING:
        raise status.KernelError(f"constrained Delaunay: the segment walk ended with {status.NAMES[int(err[0])]}")
    return ConstrainedMesh(tri, nbr, cid, through, (int(err[1]), int(err[2]), int(err[3]), int(err[4])))


def format_point(p) -> str:
    """A point as ``(x, y)`` with ``%g`` numbers, for error messages.

    >>> format_point((1.5, 2.0))
    '(1.5, 2)'
    """
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

    def __init__(self, points: ArrayLike, segments: ArrayLike = ()) -> None:
        self._delaunay = Delaunay(points)
        self._segments = as_index_rows(segments, len(self._delaunay.points), 2, "segments")
        k = constrain_delaunay(self._delaunay, self._segments)
        if k.error is not None:
            s, o = k.error[:2]
            raise ValueError(f"segments[{s}] = {self._describe(s)} properly crosses "
                             f"segments[{o}] = {self._describe(o)}")
        self._k = k

    def _describe(self, s: int) -> str:
        a, b = self._segments[s]
        return f"{format_point(self.points[a])}-{format_point(self.points[b])}"

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
        return unique_edges(self.simplices, self.neighbors)

    def constraint_edges(self) -> np.ndarray:
        """Unique sorted edges (k, 2) that lie on input segments (segments split at vertices).

        >>> ConstrainedDelaunay([(0, 0), (1, 0), (2, 0), (1, 1)], [(0, 2)]).constraint_edges().tolist()
        [[0, 1], [1, 2]]
        """
        return unique_edges(self.simplices, self.neighbors, self.constrained)

    def __repr__(self) -> str:
        return (f"ConstrainedDelaunay(n={len(self.points)}, segments={len(self._segments)}, "
                f"triangles={len(self.simplices)})")


def constrained_delaunay(points: ArrayLike, segments: ArrayLike) -> np.ndarray:
    """Triangles (m, 3), counter-clockwise, of the constrained Delaunay triangulation.

    Shorthand for ``ConstrainedDelaunay(points, segments).simplices`` (no point is
    added, so the input points are the output points).

    >>> constrained_delaunay([(0, 0), (1, 0), (0, 1)], [(0, 1)]).tolist()
    [[0, 1, 2]]
    """
    return ConstrainedDelaunay(points, segments).simplices
