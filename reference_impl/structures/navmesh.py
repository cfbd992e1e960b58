"""Navigation mesh: a polygon with holes, triangulated, and Euclidean shortest paths in it.

The free space is the closed region inside ``boundary`` and outside the open
holes: a path may run along walls and touch hole corners.  ``NavMesh`` builds
it once (``polygon.polygon_triangulation``: the constrained Delaunay
triangulation of the polygon, which also checks that it is simple); each
``shortest_path(start, goal)`` query then returns the polyline
``[start, corner, ..., goal]`` of *optimal* length, or ``None`` when start or
goal is not in the free space.  ``shortest_path(boundary, holes, start, goal)``
does both in one call (the library behind the course's ``navmesh`` problem).

How a query works, and why the answer is optimal:

1. *Locate* start and goal in the triangles (exact orientation tests).  Same
   triangle: the segment is the answer (a triangle is convex).
2. *Channel and funnel* (the game-industry navmesh method): A* over the
   triangle adjacency (cost between edge midpoints) gives a channel of
   triangles; the funnel algorithm (``funnel.py``, with exact ``orient2d``
   for every funnel test) pulls the string through it.  The
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

Run the doctests:  python -m pytest reference_impl/structures/navmesh.py

>>> room = [(0, 0), (10, 0), (10, 10), (0, 10)]
>>> pillar = [(4, 4), (6, 4), (6, 6), (4, 6)]
>>> nav = NavMesh(room, [pillar])
>>> nav.shortest_path((2, 5.5), (8, 5.5))
[(2.0, 5.5), (4.0, 6.0), (6.0, 6.0), (8.0, 5.5)]
>>> nav.shortest_path((2, 6), (8, 6))           # grazing the wall is allowed
[(2.0, 6.0), (8.0, 6.0)]
>>> nav.shortest_path((5, 5), (8, 5)) is None     # start inside the pillar
True
"""
from __future__ import annotations

import heapq
import math
from typing import Sequence

import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from reference_impl.exact.predicates import orient2d_nb, workspace
from reference_impl.mesh.topology import slot, third, vertex_triangles
from reference_impl.structures.constrained import fan_search, orient_many, ray_ahead
from reference_impl.structures.funnel import funnel
from reference_impl.structures.polygon import polygon_triangulation
from reference_impl.validate import as_point

__all__ = ["NavMesh", "shortest_path"]

Point = tuple[float, float]


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
            if orient2d_nb(px, py, qx, qy, X[x], Y[x], w) == 0 and ray_ahead(px, py, qx, qy, X[x], Y[x]):
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
            k = slot(tri, t, v)
            right = tri[t, (k + 1) % 3]
            left = tri[t, (k + 2) % 3]
            if orient2d_nb(X[right], Y[right], X[left], Y[left], qx, qy, w) >= 0:
                return True
            t = nbr[t, k]
            if t < 0:
                return False
            v = -1
        # inside triangle t, entered through the edge (left, right)
        wv = tri[t, third(tri, t, right, left)]
        s = orient2d_nb(px, py, qx, qy, X[wv], Y[wv], w)
        if s == 0:
            if _reached(px, py, qx, qy, X[wv], Y[wv]):
                return True
            v = wv
        elif s > 0:                                    # leave through (right, wv)
            if orient2d_nb(X[right], Y[right], X[wv], Y[wv], qx, qy, w) >= 0:
                return True
            t = nbr[t, slot(tri, t, left)]
            left = wv
        else:                                          # leave through (wv, left)
            if orient2d_nb(X[wv], Y[wv], X[left], Y[left], qx, qy, w) >= 0:
                return True
            t = nbr[t, slot(tri, t, right)]
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
        self._vt = vertex_triangles(self.triangles, n)
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
            k = slot(self.neighbors, t, o)
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
    """Deprecated alias: use ``NavMesh(boundary, holes).shortest_path(start, goal)``.

    The four-argument form is the ``navmesh`` problem's adapter, which now lives with the
    problem (``assignments/navmesh/generators/generator.py``).  This alias warns
    (``DeprecationWarning``) and returns what ``NavMesh`` returns.

    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     path = shortest_path([(0, 0), (4, 0), (4, 4), (0, 4)], [], (1, 1), (3, 2))
    >>> path, caught[0].category.__name__
    ([(1.0, 1.0), (3.0, 2.0)], 'DeprecationWarning')
    """
    import warnings

    warnings.warn("reference_impl.shortest_path(boundary, holes, start, goal) is deprecated: "
                  "use NavMesh(boundary, holes).shortest_path(start, goal)", DeprecationWarning, stacklevel=2)
    return NavMesh(boundary, holes).shortest_path(start, goal)
