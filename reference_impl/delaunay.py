"""Delaunay: the fast, robust 2D Delaunay triangulation (numba-compiled Bowyer-Watson).

    python -c "from reference_impl import Delaunay; print(Delaunay([(0,0),(1,0),(0,1),(1,1)]).simplices)"

The data model is scipy's and Delaunator's: ``points`` (n, 2) float64,
``simplices`` (m, 3) point indices counter-clockwise, ``neighbors`` (m, 3) with
``neighbors[t, k]`` the triangle opposite vertex k (-1 on the hull), ``hull``
the hull vertices counter-clockwise.  The kernel is in ``_mesh.py``; the
insertion order in ``ordering.py``; the exact predicates in ``predicates.py``.

Input rules: duplicates are merged (``index_map[i]`` is the index that point i
was merged into: the smallest index with the same coordinates); all-collinear
input gives no triangles, and ``edges()`` is then the sorted chain; fewer than
three distinct points is not an error; NaN, infinity, a wrong shape or text
raise ``ValueError``.  The result is the same set of triangles whatever the
input order, degenerate inputs included.

>>> d = Delaunay([(0, 0), (2, 0), (0, 2), (2, 2), (1, 1)])
>>> len(d.simplices), sorted(d.hull.tolist())
(4, [0, 1, 2, 3])
>>> int(d.find_simplex((0.5, 1.0))) >= 0, int(d.find_simplex((5.0, 5.0)))
(True, -1)
"""
from __future__ import annotations

import numpy as np

from . import _mesh
from .ordering import insertion_order
from .points import as_point, as_points
from .predicates import workspace

__all__ = ["Delaunay"]

_ITYPE = np.int32  # mesh arrays: half the memory traffic of int64


def _equal_point_roots(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """dup[i] = first index with the same coordinates as i (in sorted order), or -1."""
    dup = np.full(len(x), -1, dtype=np.int64)
    if len(x) == 0:
        return dup
    order = np.lexsort((y, x))
    same = (x[order][1:] == x[order][:-1]) & (y[order][1:] == y[order][:-1])
    start = np.maximum.accumulate(np.where(np.r_[True, ~same], np.arange(len(x)), 0))
    root = order[start]
    dup[order] = np.where(root == order, -1, root)
    return dup


class Delaunay:
    """Delaunay triangulation of 2D points (exact predicates, O(n log n) expected).

    Attributes: ``points``, ``simplices``, ``neighbors``, ``hull``, ``index_map``.
    Methods: ``find_simplex(p)``, ``insert(p)``, ``edges()``, ``vertex_neighbors(i)``.
    """

    def __init__(self, points) -> None:
        self._points = as_points(points)
        self._build()

    # ------------------------------------------------------------------ building
    def _alloc(self, nverts: int, ntris: int) -> None:
        self._cap_v = nverts
        self._cap_t = ntris
        self._P = np.empty((nverts, 2))                  # coordinates in insertion order
        self._M = np.zeros(_mesh.RECORD * ntris, dtype=_ITYPE)   # the mesh: see _mesh.py
        self._stack = np.empty(ntris, dtype=_ITYPE)
        self._bad = np.empty(ntris, dtype=_ITYPE)
        self._ba = np.empty(ntris, dtype=_ITYPE)
        self._bb = np.empty(ntris, dtype=_ITYPE)
        self._bo = np.empty(ntris, dtype=_ITYPE)
        self._start_of = np.empty(nverts + 1, dtype=_ITYPE)

    def _build(self) -> None:
        pts = self._points
        n = len(pts)
        self._order = insertion_order(pts)               # internal vertex i = input point order[i]
        self._alloc(max(n, 4), 2 * n + 8)
        self._P[:n] = pts[self._order]
        self._n = n
        self._state = np.zeros(_mesh.STATE_SIZE, dtype=np.int64)
        self._dup = np.full(max(n, 1), -1, dtype=np.int64)
        self._w = workspace()
        self._flat = n < 3 or not _mesh.build(
            self._P[:n], self._M, self._stack, self._bad,
            self._ba, self._bb, self._bo, self._start_of, self._state, self._dup, self._w)
        if self._flat:
            self._dup[:n] = _equal_point_roots(self._P[:n, 0], self._P[:n, 1])
        self._cache = {}

    def _grow(self) -> None:
        """Double the capacity, keeping the mesh (used by ``insert``)."""
        old = (self._P, self._M, self._dup)
        nt = self._state[_mesh.S_NTRI]
        self._alloc(2 * self._cap_v, 2 * self._cap_t)
        self._P[:self._n] = old[0][:self._n]
        self._M[:_mesh.RECORD * nt] = old[1][:_mesh.RECORD * nt]
        self._dup = np.concatenate([old[2], np.full(len(old[2]), -1, dtype=np.int64)])

    # ------------------------------------------------------------------ results
    def _result(self):
        if "simplices" not in self._cache:
            rep = self._representatives()
            if self._flat:
                simp = np.zeros((0, 3), dtype=np.int64)
                neig = np.zeros((0, 3), dtype=np.int64)
                hull = self._collinear_chain(rep)
                out_of = np.zeros(0, dtype=np.int64)
            else:
                nt = int(self._state[_mesh.S_NTRI])
                simp, neig, out_of = _mesh.extract(self._M, nt, rep)
                hull = _mesh.hull_cycle(self._M, nt, self._n, rep)
            self._cache.update(simplices=simp, neighbors=neig, hull=hull, out_of=out_of, rep=rep)
        return self._cache

    def _representatives(self) -> np.ndarray:
        """rep[internal vertex] = smallest input index among the points equal to it."""
        return _mesh.smallest_labels(self._order[:self._n], self._dup[:self._n])

    def _collinear_chain(self, rep: np.ndarray) -> np.ndarray:
        n = self._n
        if n == 0:
            return np.zeros(0, dtype=np.int64)
        internal = np.flatnonzero(self._dup[:n] < 0)      # distinct points
        keys = np.lexsort((self._P[internal, 1], self._P[internal, 0]))
        return rep[internal[keys]]

    @property
    def points(self) -> np.ndarray:
        """The input points, (n, 2) float64 (inserted points appended)."""
        return self._points

    @property
    def simplices(self) -> np.ndarray:
        """(m, 3) point indices of the triangles, counter-clockwise."""
        return self._result()["simplices"]

    @property
    def neighbors(self) -> np.ndarray:
        """(m, 3): ``neighbors[t, k]`` is the triangle opposite vertex k of t, -1 on the hull."""
        return self._result()["neighbors"]

    @property
    def hull(self) -> np.ndarray:
        """Convex hull vertices, counter-clockwise (collinear hull points included),
        starting at the smallest index.  For all-collinear input: the points in sorted order."""
        return self._result()["hull"]

    @property
    def index_map(self) -> np.ndarray:
        """``index_map[i]``: the index point i was merged into (i itself unless a duplicate)."""
        rep = self._result()["rep"]
        out = np.empty(self._n, dtype=np.int64)
        out[self._order[:self._n]] = rep
        return out

    def edges(self) -> np.ndarray:
        """Unique undirected edges (k, 2) with i < j, sorted; for collinear input the chain.

        >>> Delaunay([(0, 0), (1, 0), (0, 1)]).edges().tolist()
        [[0, 1], [0, 2], [1, 2]]
        """
        if self._flat:
            chain = self.hull
            e = np.stack([chain[:-1], chain[1:]], axis=1) if len(chain) > 1 else np.zeros((0, 2), np.int64)
        else:
            s = self.simplices
            e = np.concatenate([s[:, [0, 1]], s[:, [1, 2]], s[:, [2, 0]]])
        e = np.sort(e, axis=1)
        return np.unique(e, axis=0) if len(e) else e.reshape(0, 2)

    def vertex_neighbors(self, i: int) -> np.ndarray:
        """Sorted indices of the points joined to point i by a Delaunay edge."""
        e = self.edges()
        i = int(self.index_map[i])
        return np.sort(np.concatenate([e[e[:, 0] == i, 1], e[e[:, 1] == i, 0]]))

    def find_simplex(self, p):
        """Index of a triangle containing p (on an edge: any incident one), -1 outside.

        ``p`` may be one point (returns an int) or an (k, 2) array (returns an array).
        """
        q = np.asarray(p, dtype=float) if not isinstance(p, str) else p
        single = np.ndim(q) == 1
        qs = as_points([p] if single else p, name="p")
        if self._flat:
            res = np.full(len(qs), -1, dtype=np.int64)
        else:
            res = self._cache_out_of()[_mesh.find(self._M, self._P, qs,
                                                  int(self._state[_mesh.S_LAST]), self._w,
                                                  np.zeros(_mesh.STATE_SIZE, dtype=np.int64))]
            res = np.where(res >= 0, res, -1)
        return int(res[0]) if single else res

    def _cache_out_of(self) -> np.ndarray:
        out_of = self._result()["out_of"]
        return np.concatenate([out_of, [-1]])  # index -1 (outside) maps to -1

    # ------------------------------------------------------------------ updates
    def insert(self, p) -> int:
        """Insert one point; return its index (it is merged if it duplicates a point).

        >>> d = Delaunay([(0, 0), (1, 0), (0, 1)])
        >>> d.insert((1, 1)), len(d.simplices)
        (3, 2)
        """
        q = as_point(p)
        idx = self._n
        self._points = np.vstack([self._points, q[None, :]])
        if self._flat:
            self._build()
            return idx
        if self._n + 1 > self._cap_v or self._state[_mesh.S_NTRI] + 2 > self._cap_t:
            self._grow()
        self._P[idx] = q
        self._order = np.append(self._order, idx)
        self._n += 1
        if len(self._dup) < self._n:
            self._dup = np.concatenate([self._dup, np.full(len(self._dup), -1, dtype=np.int64)])
        self._dup[idx] = _mesh.insert(idx, self._P, self._M,
                                      self._stack, self._bad, self._ba, self._bb, self._bo,
                                      self._start_of, self._state, self._w)
        self._cache = {}
        return idx

    def __repr__(self) -> str:
        return f"Delaunay(n={len(self._points)}, triangles={len(self.simplices)})"
