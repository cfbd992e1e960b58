"""Finding the first bad triangle: the tutorial's optimisation ideas counted against the walk (lesson 13).

Run the examples:  python -m pytest reference_impl/teaching/locate.py

Every Bowyer-Watson insertion starts by finding one *bad* triangle (one whose circumcircle
strictly contains the new point p); the others are then found through neighbours.  This module
counts, for one triangulation and one new point, how many triangles each strategy *tests*
(an in-circle test each) before it holds a bad one.  Counts, not times: they do not depend on
the machine.

* ``scan``: the tutorial's loop over the triangle list, stopped at the first bad triangle (the
  tutorial's code does not stop: it tests every triangle, ``len(triangles)`` tests);
* ``walk``: from a starting triangle, step across the edge that has p on its far side
  (the course's ``locate="walk"``);
* ``KDTree``, ``QuadTree``, ``HashGrid``: find the inserted vertex nearest to p, then test the
  triangles around it.  One of them is always bad: p's nearest vertex q becomes p's Delaunay
  neighbour (the nearest-neighbour graph is part of the Delaunay graph), so a triangle at q is
  destroyed.  Their own work is counted separately (tree nodes or grid cells visited);
* ``BVH``: a bounding-volume hierarchy over the triangles' circumcircle boxes; only
  triangles whose box contains p are tested;
* circumcircle caching and a GPU change the cost of a test, not which triangles are tested:
  a cache of centres and radii speeds each of the scan's tests (with an exact test for the
  close calls), and a GPU runs all ``len(triangles)`` tests in parallel.

Assumptions: p lies inside the convex hull of the triangulation (so some real triangle contains
it) and the triangulation is Delaunay (then the walk cannot cycle).

>>> pts = np.array([(0, 0), (1, 0), (1, 1), (0, 1), (0.4, 0.6)])
>>> tris = np.array([(0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)])
>>> m = TriMesh(pts, tris)
>>> m.scan((0.2, 0.1)), m.walk((0.2, 0.1), start=2)
(1, 2)
>>> KDTree(pts).nearest((0.2, 0.1))[0]
0
"""
from __future__ import annotations

import math

import numpy as np

from reference_impl.exact.predicates import incircle, orient2d
from reference_impl.validate import as_points

__all__ = ["TriMesh", "KDTree", "QuadTree", "HashGrid", "BVH"]


class TriMesh:
    """A triangulation with neighbours, and the in-circle test counted.

    ``triangles`` (m, 3) counter-clockwise.  ``neighbors[t, k]`` is the triangle across
    the edge opposite vertex k (-1 outside the hull); ``around[v]`` lists v's triangles.

    >>> m = TriMesh([(0, 0), (1, 0), (1, 1), (0, 1)], [(0, 1, 2), (0, 2, 3)])
    >>> m.neighbors.tolist(), m.around[0]
    ([[-1, 1, -1], [-1, -1, 0]], [0, 1])
    >>> m.bad_mask((0.9, 0.1)).tolist(), m.containing((0.1, 0.9))
    ([True, True], (1, 2))
    >>> m.around_vertex(1, (0.9, 0.1))
    1
    """

    def __init__(self, points, triangles) -> None:
        self.P = as_points(points)
        self.xy = [tuple(p) for p in self.P.tolist()]
        self.T = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
        where = {}
        for t, (a, b, c) in enumerate(self.T.tolist()):
            where[(a, b)], where[(b, c)], where[(c, a)] = t, t, t
        self.neighbors = np.full(self.T.shape, -1, dtype=np.int64)
        self.around: list[list[int]] = [[] for _ in range(len(self.P))]
        for t, tri in enumerate(self.T.tolist()):
            for k in range(3):
                u, v = tri[(k + 1) % 3], tri[(k + 2) % 3]
                self.neighbors[t, k] = where.get((v, u), -1)
                self.around[tri[k]].append(t)

    def is_bad(self, t: int, p) -> bool:
        """Does triangle t's circumcircle strictly contain p (exact)?"""
        a, b, c = self.T[t]
        return incircle(self.xy[a], self.xy[b], self.xy[c], tuple(p)) > 0

    def bad_mask(self, p) -> np.ndarray:
        """Every triangle's in-circle answer for p at once: a float determinant, and the exact
        test wherever the float one is within a (generous) error bound of zero."""
        A = self.P[self.T] - np.asarray(p, dtype=float)
        lift = (A ** 2).sum(axis=2)
        x, y = A[..., 0], A[..., 1]
        det = (x[:, 0] * (y[:, 1] * lift[:, 2] - y[:, 2] * lift[:, 1])
               - x[:, 1] * (y[:, 0] * lift[:, 2] - y[:, 2] * lift[:, 0])
               + x[:, 2] * (y[:, 0] * lift[:, 1] - y[:, 1] * lift[:, 0]))
        ax, ay = np.abs(x), np.abs(y)
        perm = (ax[:, 0] * (ay[:, 1] * lift[:, 2] + ay[:, 2] * lift[:, 1])
                + ax[:, 1] * (ay[:, 0] * lift[:, 2] + ay[:, 2] * lift[:, 0])
                + ax[:, 2] * (ay[:, 0] * lift[:, 1] + ay[:, 1] * lift[:, 0]))
        bad = det > 0
        for t in np.flatnonzero(np.abs(det) <= 1e-12 * perm):
            bad[t] = self.is_bad(int(t), p)
        return bad

    def scan(self, p) -> int:
        """Triangles the tutorial's loop tests before its first bad one (that one included)."""
        hits = np.flatnonzero(self.bad_mask(p))
        if hits.size == 0:
            raise ValueError(f"no triangle is bad for {tuple(p)}: is it a duplicate of a vertex?")
        return int(hits[0]) + 1

    def _step(self, t: int, p: tuple) -> int | None:
        """The neighbour across the first edge of ``t`` that has p strictly on its outer side, or None
        when p is in ``t`` (the visibility walk's step)."""
        tri = self.T[t]
        for k in range(3):
            u, v = tri[(k + 1) % 3], tri[(k + 2) % 3]
            if orient2d(self.xy[u], self.xy[v], p) < 0:
                nxt = int(self.neighbors[t, k])
                if nxt < 0:
                    raise ValueError(f"{p} is outside the convex hull of the triangulation")
                return nxt
        return None

    def containing(self, p, start: int = 0) -> tuple[int, int]:
        """(triangle containing p, triangles visited), by the visibility walk from ``start``."""
        t, visited = start, 1
        p = tuple(p)
        while (nxt := self._step(t, p)) is not None:
            t, visited = nxt, visited + 1
        return t, visited

    def walk(self, p, start: int = 0) -> int:
        """Triangles the walk from ``start`` tests until it stands on a bad one.

        Each triangle on the way is tested; the triangle that contains p is
        always bad, so the walk stops there at the latest.
        """
        t, visited = start, 1
        p = tuple(p)
        while not self.is_bad(t, p):
            nxt = self._step(t, p)
            if nxt is None:
                raise RuntimeError("internal error: the triangle containing p is not bad")
            t, visited = nxt, visited + 1
        return visited

    def around_vertex(self, q: int, p) -> int:
        """Triangles tested around vertex q (in its list) until a bad one for p."""
        for k, t in enumerate(self.around[q], start=1):
            if self.is_bad(t, p):
                return k
        raise ValueError(f"no triangle around vertex {q} is bad for {tuple(p)}: q is not p's nearest vertex")


# ----------------------------------------------------------------------------- nearest vertex structures
def _d2(P: np.ndarray, i: int, p) -> float:
    return (P[i, 0] - p[0]) ** 2 + (P[i, 1] - p[1]) ** 2


def _closer(P: np.ndarray, ids, p, best: list) -> None:
    """Update ``best = [squared distance, index]`` with the points ``ids`` of a leaf."""
    for i in ids:
        d = _d2(P, i, p)
        if d < best[0]:
            best[:] = [d, i]


class KDTree:
    """A 2D kd-tree over points (split at the median, alternating x and y, leaves of up to 4).

    ``nearest(p)`` -> (index, nodes visited).

    >>> KDTree([(0, 0), (5, 5), (1, 1)]).nearest((4, 4))
    (1, 1)
    """

    LEAF = 4

    def __init__(self, points) -> None:
        self.P = as_points(points)
        self.root = self._build(np.arange(len(self.P)), 0)

    def _build(self, idx: np.ndarray, depth: int):
        if len(idx) <= self.LEAF:
            return ("leaf", idx.tolist())
        axis = depth % 2
        idx = idx[np.argsort(self.P[idx, axis], kind="stable")]
        mid = len(idx) // 2
        return ("split", axis, float(self.P[idx[mid], axis]),
                self._build(idx[:mid], depth + 1), self._build(idx[mid:], depth + 1))

    def nearest(self, p) -> tuple[int, int]:
        best = [math.inf, -1]
        visited = 0

        def visit(node) -> None:
            nonlocal visited
            visited += 1
            if node[0] == "leaf":
                _closer(self.P, node[1], p, best)
                return
            _, axis, cut, lo, hi = node
            near, far = (lo, hi) if p[axis] < cut else (hi, lo)
            visit(near)
            if (p[axis] - cut) ** 2 < best[0]:
                visit(far)

        visit(self.root)
        return int(best[1]), visited


class QuadTree:
    """A point-region quadtree over points (square cells split in four, up to 4 points per leaf).

    ``nearest(p)`` -> (index, nodes visited).

    >>> QuadTree([(0, 0), (5, 5), (1, 1)]).nearest((4, 4))[0]
    1
    """

    LEAF = 4

    def __init__(self, points) -> None:
        self.P = as_points(points)
        lo, hi = self.P.min(axis=0), self.P.max(axis=0)
        side = float(max(hi - lo)) or 1.0
        self.root = self._build(np.arange(len(self.P)), float(lo[0]), float(lo[1]), side, 0)

    def _build(self, idx: np.ndarray, x: float, y: float, side: float, depth: int):
        if len(idx) <= self.LEAF or depth > 40:
            return ("leaf", x, y, side, idx.tolist())
        h = side / 2
        right = self.P[idx, 0] >= x + h
        top = self.P[idx, 1] >= y + h
        kids = [self._build(idx[(right == r) & (top == u)], x + r * h, y + u * h, h, depth + 1)
                for r in (0, 1) for u in (0, 1)]
        return ("split", x, y, side, kids)

    def nearest(self, p) -> tuple[int, int]:
        best = [math.inf, -1]
        visited = 0

        def box_d2(node) -> float:
            _, x, y, side = node[:4]
            dx = max(x - p[0], 0.0, p[0] - x - side)
            dy = max(y - p[1], 0.0, p[1] - y - side)
            return dx * dx + dy * dy

        def visit(node) -> None:
            nonlocal visited
            visited += 1
            if node[0] == "leaf":
                _closer(self.P, node[4], p, best)
                return
            for kid in sorted(node[4], key=box_d2):
                if box_d2(kid) < best[0]:
                    visit(kid)

        visit(self.root)
        return int(best[1]), visited


class HashGrid:
    """A uniform grid of square cells, about ``per_cell`` points each, stored in a dict.

    ``nearest(p)`` -> (index, cells visited): rings of cells around p's cell,
    until the nearest point found is closer than any unvisited ring.

    >>> HashGrid([(0, 0), (5, 5), (1, 1)]).nearest((4, 4))[0]
    1
    """

    def __init__(self, points, per_cell: float = 1.0) -> None:
        self.P = as_points(points)
        lo, hi = self.P.min(axis=0), self.P.max(axis=0)
        area = float(np.prod(np.maximum(hi - lo, 1e-300)))
        self.h = math.sqrt(area * per_cell / len(self.P)) or 1.0
        self.lo = lo
        self.cells: dict[tuple[int, int], list[int]] = {}
        for i, (cx, cy) in enumerate(((self.P - lo) // self.h).astype(np.int64).tolist()):
            self.cells.setdefault((cx, cy), []).append(i)
        span = ((hi - lo) // self.h).astype(np.int64)
        self.rings = int(max(span)) + 1

    def nearest(self, p) -> tuple[int, int]:
        cx, cy = (int(v) for v in (np.asarray(p, dtype=float) - self.lo) // self.h)
        best, who, visited = math.inf, -1, 0
        for r in range(self.rings + 1):
            if who >= 0 and ((r - 1) * self.h) ** 2 >= best:
                break                     # every point in ring r or beyond is farther than (r - 1) h
            ring = [(cx + i, cy + j) for i in range(-r, r + 1) for j in range(-r, r + 1)
                    if max(abs(i), abs(j)) == r]
            for cell in ring:
                visited += 1
                for k in self.cells.get(cell, ()):
                    d = _d2(self.P, k, p)
                    if d < best:
                        best, who = d, k
        return int(who), visited


class BVH:
    """A bounding-volume hierarchy over the triangles' circumcircle boxes (median splits, one
    triangle per leaf).

    ``first_bad(p)`` -> (triangles tested, nodes visited): depth-first into every box that
    contains p, testing each leaf's triangle, until one is bad.

    >>> pts = [(0, 0), (1, 0), (1, 1), (0, 1)]
    >>> BVH(TriMesh(pts, [(0, 1, 2), (0, 2, 3)])).first_bad((0.9, 0.1))
    (1, 2)
    """

    def __init__(self, mesh: TriMesh) -> None:
        self.mesh = mesh
        A, B, C = (mesh.P[mesh.T[:, k]] for k in range(3))
        b, c = B - A, C - A
        d = 2 * (b[:, 0] * c[:, 1] - b[:, 1] * c[:, 0])
        bb, cc = (b ** 2).sum(axis=1), (c ** 2).sum(axis=1)
        ux = (c[:, 1] * bb - b[:, 1] * cc) / d
        uy = (b[:, 0] * cc - c[:, 0] * bb) / d
        r = np.sqrt(ux ** 2 + uy ** 2) * (1 + 1e-9)           # a little larger: boxes must not miss
        centre = A + np.c_[ux, uy]
        self.lo, self.hi = centre - r[:, None], centre + r[:, None]
        self.root = self._build(np.arange(len(mesh.T)))

    def _build(self, idx: np.ndarray):
        lo, hi = self.lo[idx].min(axis=0), self.hi[idx].max(axis=0)
        if len(idx) == 1:
            return (lo, hi, int(idx[0]))
        mid_of = (self.lo[idx] + self.hi[idx]) / 2
        axis = int(np.argmax(hi - lo))
        idx = idx[np.argsort(mid_of[:, axis], kind="stable")]
        half = len(idx) // 2
        return (lo, hi, self._build(idx[:half]), self._build(idx[half:]))

    def first_bad(self, p) -> tuple[int, int]:
        tested = visited = 0
        stack = [self.root]
        while stack:
            node = stack.pop()
            visited += 1
            lo, hi = node[0], node[1]
            if not (lo[0] <= p[0] <= hi[0] and lo[1] <= p[1] <= hi[1]):
                continue
            if len(node) == 3:
                tested += 1
                if self.mesh.is_bad(node[2], p):
                    return tested, visited
            else:
                stack.extend((node[3], node[2]))
        raise ValueError(f"no triangle is bad for {tuple(p)}")
