"""Navigation mesh: a polygon with holes, triangulated, and Euclidean shortest paths in it.

The free space is the closed region inside ``boundary`` and outside the open
holes: a path may run along walls and touch hole corners.  ``NavMesh`` builds
it once (``polygon_triangulation``, below); each
``shortest_path(start, goal)`` query then returns the polyline
``[start, corner, ..., goal]`` of *optimal* length, or ``None`` when start or
goal is not in the free space.  ``shortest_path(boundary, holes, start, goal)``
does both in one call (the library behind the course's ``navmesh`` problem).

The mesh: ``polygon_triangulation(boundary, holes)`` runs the constrained
Delaunay triangulation (``constrained.py``) on the polygon's vertices with its
edges as constraints.  That also checks, exactly, that boundary and holes are
simple and disjoint with every hole inside the boundary: a proper crossing is
caught by the segment insertion, a vertex on another edge by the record of
split segments, a repeated vertex by the duplicate map, a misplaced hole by the
flood fill.  The triangles kept are those a flood fill reaches from the inside
of the boundary without crossing a constraint edge.

How a query works, and why the answer is optimal:

1. *Locate* start and goal in the triangles (exact orientation tests).  Same
   triangle: the segment is the answer (a triangle is convex).
2. *Channel and funnel* (the game-industry navmesh method): A* over the
   triangle adjacency (cost between edge midpoints) gives a channel of
   triangles; the funnel algorithm ("simple stupid funnel", with exact
   ``orient2d`` for every funnel test) pulls the string through it.  The
   result is a valid path, so its length U is an upper bound.  It is optimal
   when there are no holes (the channel is then unique), but with holes the
   cheapest channel in the triangle graph need not hold the shortest path.
3. *Certify* with A* on the visibility graph.  A shortest path in a polygonal
   domain is a polyline whose inner corners are *reflex* vertices (free angle
   over 180 degrees), and each of its segments is *tangent* at those corners
   (both wall edges at the corner lie on one side of the segment's line).  So
   the nodes are start, goal and the reflex vertices; an edge u-v is kept
   only if it is tangent at its corner ends and the closed segment lies in the
   free space.  That test walks the segment through the triangulation and
   fails exactly when it crosses a wall edge or leaves the free space at a
   vertex (exact predicates; touching walls is allowed).  A* with the
   straight-line distance to the goal (a consistent heuristic) returns a
   shortest path of this graph, which is a shortest path in the free space.
   Visibility is only tested for nodes that A* expands, and not at all for a
   candidate whose g + h exceeds U (it cannot lie on a path shorter than the
   funnel's), which is what keeps queries fast.

Lengths are summed in floating point; every decision about geometry is exact.

Run the doctests:  python -m doctest reference_impl/structures/navmesh.py

>>> room = [(0, 0), (10, 0), (10, 10), (0, 10)]
>>> pillar = [(4, 4), (6, 4), (6, 6), (4, 6)]
>>> shortest_path(room, [pillar], (2, 5.5), (8, 5.5))
[(2.0, 5.5), (4.0, 6.0), (6.0, 6.0), (8.0, 5.5)]
>>> shortest_path(room, [pillar], (2, 6), (8, 6))           # grazing the wall is allowed
[(2.0, 6.0), (8.0, 6.0)]
>>> shortest_path(room, [pillar], (5, 5), (8, 5)) is None     # start inside the pillar
True
"""
from __future__ import annotations

import heapq
import math
from typing import NamedTuple, Sequence

import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from reference_impl.structures.constrained import _ahead, _fmt, _run_cdt, _slot, _third, fan_search, orient_many
from reference_impl.mesh.delaunay import Delaunay
from reference_impl.validate import as_point, as_ring
from reference_impl.exact.predicates import orient2d, orient2d_nb, workspace

__all__ = ["NavMesh", "shortest_path", "funnel", "PolygonTriangulation", "polygon_triangulation"]

Point = tuple[float, float]


# ----------------------------------------------------------------------------- the free space
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
    key = (tri[:, [1, 2, 0]] * n + tri[:, [2, 0, 1]]).ravel()      # directed edge opposite slot k
    order = np.argsort(key)
    sorted_key = key[order]

    def left_triangles(u):
        """Triangle left of each normalised ring edge u -> succ[u] (-1 if none), and the ring of u."""
        v = succ[u]
        pos = np.minimum(np.searchsorted(sorted_key, u * n + v), len(key) - 1)
        return np.where(sorted_key[pos] == u * n + v, order[pos] // 3, -1), ring_of[u]

    t_idx, k_idx = np.nonzero((nbr >= 0) & (cid < 0))
    from scipy.sparse import coo_matrix          # (imported here: scipy.sparse takes 0.2-0.4 s to import)
    from scipy.sparse.csgraph import connected_components

    graph = coo_matrix((np.ones(len(t_idx)), (t_idx, nbr[t_idx, k_idx])), shape=(m, m))
    _, label = connected_components(graph, directed=False)
    seeds, _ = left_triangles(ring_idx[0])
    free = np.isin(label, label[seeds])
    if len(rings) > 1:
        side, owner = left_triangles(np.arange(offset[1], len(pts)))
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


# ----------------------------------------------------------------------------- numba kernels
@njit(cache=True, inline="always")
def _contains(tri, t, X, Y, px, py, w):
    """Does the closed triangle t contain p (exact)?"""
    for k in range(3):
        a = tri[t, k]
        b = tri[t, (k + 1) % 3]
        if orient2d_nb(X[a], Y[a], X[b], Y[b], px, py, w) < 0:
            return False
    return True


@njit(cache=True)
def _locate(tri, X, Y, px, py, w):
    """First triangle whose closure contains p, -1 if none (exact; O(m))."""
    for t in range(tri.shape[0]):
        if _contains(tri, t, X, Y, px, py, w):
            return t
    return -1


@njit(cache=True, inline="always")
def _reached(px, py, qx, qy, x, y):
    """For (x, y) on the ray from p through q: is q at or before (x, y)?"""
    if px != qx:
        return qx <= x if qx > px else qx >= x
    return qy <= y if qy > py else qy >= y


@njit(cache=True)
def _visible(tri, nbr, vt, X, Y, pv, pt, px, py, qx, qy, qv, w):
    """Does the closed segment p-q lie in the closed free space?

    p is vertex ``pv`` (``pv >= 0``) or a point of the closed free triangle
    ``pt``; q is vertex ``qv`` (or -1: any point).  Walks along p-q through
    triangle interiors (crossing an edge with no free triangle behind it
    fails) and through vertices met exactly (where ``fan_search`` must find a
    free triangle or edge in the direction of q).  Every test is an exact
    orientation along the fixed line p-q.
    """
    if px == qx and py == qy:
        return True
    v = pv
    t = pt
    right = -1
    left = -1
    if v < 0:
        if _contains(tri, t, X, Y, qx, qy, w):
            return True
        for k in range(3):
            x = tri[t, k]
            if orient2d_nb(px, py, qx, qy, X[x], Y[x], w) == 0 and _ahead(px, py, qx, qy, X[x], Y[x]):
                v = x                                  # the segment leaves t through vertex x
                break
        if v < 0:
            for k in range(3):
                a = tri[t, (k + 1) % 3]
                b = tri[t, (k + 2) % 3]
                if (orient2d_nb(px, py, qx, qy, X[a], Y[a], w) < 0
                        and orient2d_nb(px, py, qx, qy, X[b], Y[b], w) > 0):
                    right = a                          # leaves t through edge (a, b)
                    left = b
                    t = nbr[t, k]
                    break
            if right < 0 or t < 0:
                return False
    while True:
        if v >= 0:                                     # at vertex v, on the segment
            if v == qv or (X[v] == qx and Y[v] == qy):
                return True
            t, x = fan_search(tri, nbr, vt, X, Y, v, qx, qy, qv, w)
            if t < 0:
                return False                           # the direction leaves the free space here
            if x >= 0:                                 # along the edge (v, x)
                if _reached(X[v], Y[v], qx, qy, X[x], Y[x]):
                    return True
                v = x
                continue
            k = _slot(tri, t, v)
            right = tri[t, (k + 1) % 3]
            left = tri[t, (k + 2) % 3]
            if orient2d_nb(X[right], Y[right], X[left], Y[left], qx, qy, w) >= 0:
                return True
            t = nbr[t, k]
            if t < 0:
                return False
            v = -1
        # inside triangle t, entered through the edge (left, right)
        wv = tri[t, _third(tri, t, right, left)]
        s = orient2d_nb(px, py, qx, qy, X[wv], Y[wv], w)
        if s == 0:
            if _reached(px, py, qx, qy, X[wv], Y[wv]):
                return True
            v = wv
        elif s > 0:                                    # leave through (right, wv)
            if orient2d_nb(X[right], Y[right], X[wv], Y[wv], qx, qy, w) >= 0:
                return True
            t = nbr[t, _slot(tri, t, left)]
            left = wv
        else:                                          # leave through (wv, left)
            if orient2d_nb(X[wv], Y[wv], X[left], Y[left], qx, qy, w) >= 0:
                return True
            t = nbr[t, _slot(tri, t, right)]
            right = wv
        if v < 0 and t < 0:
            return False


@njit(cache=True, inline="always")
def _tangent(X, Y, prv, nxt, v, px, py, w):
    """The line through p and corner v has both wall edges at v on one (closed) side."""
    a = orient2d_nb(px, py, X[v], Y[v], X[prv[v]], Y[prv[v]], w)
    b = orient2d_nb(px, py, X[v], Y[v], X[nxt[v]], Y[nxt[v]], w)
    return a * b >= 0


@njit(cache=True)
def _astar(tri, nbr, vt, X, Y, prv, nxt, reflex, sv, st, sx, sy, gx, gy, limit, w):
    """A* over start, goal and the reflex vertices with lazily tested visibility.

    Returns the reflex vertices of a shortest path in order (empty for a direct
    segment), or ``[-1]`` when no path of length <= ``limit`` exists.
    """
    r = reflex.shape[0]
    S = r
    G = r + 1
    nx = np.empty(r + 2)
    ny = np.empty(r + 2)
    for i in range(r):
        nx[i] = X[reflex[i]]
        ny[i] = Y[reflex[i]]
    nx[S], ny[S], nx[G], ny[G] = sx, sy, gx, gy
    g = np.full(r + 2, np.inf)
    parent = np.full(r + 2, -1, np.int64)
    closed = np.zeros(r + 2, np.bool_)
    g[S] = 0.0
    heap = [(math.hypot(gx - sx, gy - sy), S)]
    while len(heap) > 0:
        _, u = heapq.heappop(heap)
        if closed[u]:
            continue
        closed[u] = True
        if u == G:
            break
        ux, uy = nx[u], ny[u]
        pv = sv if u == S else reflex[u]
        pt = st if u == S else -1
        d = g[u] + math.hypot(gx - ux, gy - uy)
        if (d < g[G] and d <= limit and (u == S or _tangent(X, Y, prv, nxt, pv, gx, gy, w))
                and _visible(tri, nbr, vt, X, Y, pv, pt, ux, uy, gx, gy, -1, w)):
            g[G] = d
            parent[G] = u
            heapq.heappush(heap, (d, G))
        for i in range(r):
            if closed[i]:
                continue
            d = g[u] + math.hypot(nx[i] - ux, ny[i] - uy)
            h = math.hypot(gx - nx[i], gy - ny[i])
            if d >= g[i] or d + h > limit:
                continue
            vi = reflex[i]
            if not _tangent(X, Y, prv, nxt, vi, ux, uy, w):
                continue
            if u != S and not _tangent(X, Y, prv, nxt, pv, nx[i], ny[i], w):
                continue
            if _visible(tri, nbr, vt, X, Y, pv, pt, ux, uy, nx[i], ny[i], vi, w):
                g[i] = d
                parent[i] = u
                heapq.heappush(heap, (d + h, i))
    if parent[G] < 0:
        return np.full(1, -1, np.int64)
    path = []
    u = parent[G]
    while u != S:
        path.append(reflex[u])
        u = parent[u]
    out = np.empty(len(path), np.int64)
    for i in range(len(path)):
        out[i] = path[len(path) - 1 - i]
    return out


# ----------------------------------------------------------------------------- funnel
def funnel(start: Point, goal: Point, portals: Sequence[tuple[Point, Point]]) -> list[Point]:
    """String pulling through a channel ("simple stupid funnel", exact orientation tests).

    ``portals`` are the edges crossed in order, each as ``(left, right)`` seen
    walking from start to goal.  Returns the taut path ``[start, ..., goal]``
    inside the channel: the funnel (apex, left ray, right ray) narrows portal by
    portal; when one side would cross the other, the crossed side's point is a
    corner of the path and becomes the new apex.  A side whose point is the
    apex itself (a portal ending at the apex) constrains nothing.

    >>> funnel((0, 0), (4, 0), [((1, 1), (1, -1)), ((3, 3), (3, 0.5))])
    [(0, 0), (3, 0.5), (4, 0)]
    """
    gates = [(start, start)] + list(portals) + [(goal, goal)]
    path = [start]
    apex = left = right = start
    apex_i = left_i = right_i = 0
    i = 1
    while i < len(gates):
        new_left, new_right = gates[i]
        if orient2d(apex, right, new_right) >= 0:               # the right side narrows
            if apex in (right, left) or orient2d(apex, left, new_right) < 0:
                right, right_i = new_right, i
            else:                                               # crosses the left side: corner
                path.append(left)
                apex, apex_i = left, left_i
                right, right_i = apex, apex_i
                i = apex_i + 1
                continue
        if orient2d(apex, left, new_left) <= 0:                 # the left side narrows
            if apex in (left, right) or orient2d(apex, right, new_left) > 0:
                left, left_i = new_left, i
            else:                                               # crosses the right side: corner
                path.append(right)
                apex, apex_i = right, right_i
                left, left_i = apex, apex_i
                i = apex_i + 1
                continue
        i += 1
    if path[-1] != goal:
        path.append(goal)
    return path


# ----------------------------------------------------------------------------- the mesh
class NavMesh:
    """A triangulated free space (polygon minus holes) answering shortest-path queries.

    Attributes: ``points`` (n, 2), ``triangles`` (m, 3) counter-clockwise,
    ``neighbors`` (m, 3) (-1 across walls), ``reflex`` (indices of the reflex
    corners).  Methods: ``locate(p)``, ``is_visible(p, q)``,
    ``channel_path(start, goal)``, ``shortest_path(start, goal)``.

    >>> nav = NavMesh([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])   # a notch in the top edge
    >>> nav.shortest_path((0.5, 3), (3.5, 3))
    [(0.5, 3.0), (2.0, 1.0), (3.5, 3.0)]
    >>> nav.reflex.tolist(), nav.locate((2, 3))
    ([3], -1)
    """

    def __init__(self, boundary: ArrayLike, holes: Sequence[ArrayLike] | None = ()) -> None:
        mesh = polygon_triangulation(boundary, holes)
        self.points = mesh.points
        self.triangles = mesh.simplices
        self.neighbors = mesh.neighbors
        n = len(self.points)
        self._prv, self._nxt = np.empty(n, dtype=np.int64), np.empty(n, dtype=np.int64)
        for ring in mesh.rings:
            self._nxt[ring] = np.roll(ring, -1)
            self._prv[ring] = np.roll(ring, 1)
        self._X = np.ascontiguousarray(self.points[:, 0])
        self._Y = np.ascontiguousarray(self.points[:, 1])
        self._w = workspace()
        # reflex: the free space (left of every ring edge) turns right there, an angle over 180 degrees
        turn = orient_many(self._X, self._Y, self._prv, np.arange(n), self._nxt, self._w)
        self.reflex = np.flatnonzero(turn < 0)
        self._vt = np.full(n, -1, dtype=np.int64)
        self._vt[self.triangles.ravel()] = np.repeat(np.arange(len(self.triangles)), 3)
        self._vertex_at = {tuple(p): i for i, p in enumerate(self.points.tolist())}

    def locate(self, p: ArrayLike) -> int:
        """Index of a triangle whose closure contains p, or -1 outside the free space.

        >>> nav = NavMesh([(0, 0), (4, 0), (0, 4)])
        >>> nav.locate((1, 1)), nav.locate((4, 0)), nav.locate((3, 3))
        (0, 0, -1)
        """
        q = as_point(p, name="p")
        return int(_locate(self.triangles, self._X, self._Y, q[0], q[1], self._w))

    def _anchor(self, q: np.ndarray) -> tuple[int, int]:
        """(vertex index or -1, containing triangle or -1) of a point."""
        return self._vertex_at.get((q[0], q[1]), -1), self.locate(q)

    def is_visible(self, p: ArrayLike, q: ArrayLike) -> bool:
        """Does the closed segment p-q lie in the free space (walls may be touched)?

        >>> NavMesh([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)]).is_visible((1, 3), (3, 3))
        False
        """
        a, b = as_point(p, name="p"), as_point(q, name="q")
        pv, pt = self._anchor(a)
        if pt < 0 or self.locate(b) < 0:
            return False
        return bool(_visible(self.triangles, self.neighbors, self._vt, self._X, self._Y, pv, pt,
                             a[0], a[1], b[0], b[1], self._anchor(b)[0], self._w))

    def channel_path(self, start: ArrayLike, goal: ArrayLike) -> list[Point] | None:
        """The funnel path through the A* channel of triangles (fast; optimal without holes).

        With holes the channel found can go around a hole on the wrong side, so
        this is only an upper bound there; ``shortest_path`` is always optimal.

        >>> NavMesh([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)]).channel_path((0.5, 3), (3.5, 3))
        [(0.5, 3.0), (2.0, 1.0), (3.5, 3.0)]
        """
        s, g = as_point(start, name="start"), as_point(goal, name="goal")
        ts, tg = self.locate(s), self.locate(g)
        if ts < 0 or tg < 0:
            return None
        return self._funnel_path(tuple(s.tolist()), tuple(g.tolist()), ts, tg)

    def _channel(self, ts: int, tg: int, s: Point, g: Point) -> list[int]:
        """A* over the triangle adjacency; a triangle is entered at its entry edge's midpoint."""
        P, T, N = self.points, self.triangles, self.neighbors
        best = {ts: 0.0}
        parent = {ts: -1}
        at = {ts: s}
        heap = [(math.dist(s, g), ts)]
        while heap:
            f, t = heapq.heappop(heap)
            if t == tg:
                break
            if f > best[t] + math.dist(at[t], g):
                continue                                  # stale entry
            for k in range(3):
                o = int(N[t, k])
                if o < 0:
                    continue
                mid = tuple(((P[T[t, (k + 1) % 3]] + P[T[t, (k + 2) % 3]]) / 2).tolist())
                d = best[t] + math.dist(at[t], mid)
                if d < best.get(o, math.inf):
                    best[o], parent[o], at[o] = d, t, mid
                    heapq.heappush(heap, (d + math.dist(mid, g), o))
        chain = [tg]
        while chain[-1] != ts:
            chain.append(parent[chain[-1]])
        return chain[::-1]

    def _funnel_path(self, s: Point, g: Point, ts: int, tg: int) -> list[Point]:
        chain = self._channel(ts, tg, s, g)
        portals = []
        for t, o in zip(chain, chain[1:]):
            k = int(np.flatnonzero(self.neighbors[t] == o)[0])
            right = self.points[self.triangles[t, (k + 1) % 3]]
            left = self.points[self.triangles[t, (k + 2) % 3]]
            portals.append((tuple(left.tolist()), tuple(right.tolist())))
        return funnel(s, g, portals)

    def shortest_path(self, start: ArrayLike, goal: ArrayLike) -> list[Point] | None:
        """Shortest path ``[start, corner, ..., goal]`` in the free space, or None.

        None when start or goal lies outside the closed free space (outside the
        boundary or strictly inside a hole).  ``start == goal`` gives ``[start]``.

        >>> NavMesh([(0, 0), (3, 0), (3, 3), (0, 3)]).shortest_path((1, 1), (1, 1))
        [(1.0, 1.0)]
        """
        s, g = as_point(start, name="start"), as_point(goal, name="goal")
        sv, ts = self._anchor(s)
        tg = self.locate(g)
        if ts < 0 or tg < 0:
            return None
        sp, gp = (float(s[0]), float(s[1])), (float(g[0]), float(g[1]))
        if sp == gp:
            return [sp]
        if ts == tg:
            return [sp, gp]
        quick = self._funnel_path(sp, gp, ts, tg)
        upper = sum(math.dist(a, b) for a, b in zip(quick, quick[1:]))
        for limit in (upper * (1 + 1e-9) + 1e-300, math.inf):   # the bound only prunes
            corners = _astar(self.triangles, self.neighbors, self._vt, self._X, self._Y, self._prv,
                             self._nxt, self.reflex, sv, ts, sp[0], sp[1], gp[0], gp[1], limit, self._w)
            if len(corners) == 0 or corners[0] >= 0:
                return [sp] + [tuple(p) for p in self.points[corners].tolist()] + [gp]
        raise RuntimeError("navmesh: no path found between two points of the free space (please report)")

    def __repr__(self) -> str:
        return f"NavMesh(vertices={len(self.points)}, triangles={len(self.triangles)}, reflex={len(self.reflex)})"


def shortest_path(boundary: ArrayLike, holes: Sequence[ArrayLike] | None, start: ArrayLike,
                  goal: ArrayLike) -> list[Point] | None:
    """Euclidean shortest path from start to goal inside a polygon with holes (as in problem ``navmesh``).

    ``boundary``: a simple polygon; ``holes``: simple polygons strictly inside it,
    disjoint (any orientation; invalid polygons raise ``ValueError``).  The
    free space is closed: walls may be touched.  Returns ``[start, ..., goal]``
    with corners at polygon vertices, or ``None`` when start or goal is outside
    the free space.  See ``NavMesh`` to answer many queries on one polygon.

    >>> shortest_path([(0, 0), (4, 0), (4, 4), (0, 4)], [], (1, 1), (3, 2))
    [(1.0, 1.0), (3.0, 2.0)]
    """
    return NavMesh(boundary, holes).shortest_path(start, goal)
