"""Delaunay: the fast, robust 2D Delaunay triangulation (numba-compiled Bowyer-Watson).

    python -c "from reference_impl import Delaunay; print(Delaunay([(0,0),(1,0),(0,1),(1,1)]).simplices)"

The data model is scipy's and Delaunator's: ``points`` (n, 2) float64,
``simplices`` (m, 3) point indices counter-clockwise, ``neighbors`` (m, 3) with
``neighbors[t, k]`` the triangle opposite vertex k (-1 on the hull), ``hull``
the hull vertices counter-clockwise.  The kernel is in ``kernel.py``; the
insertion order in ``ordering.py``; the exact predicates in ``exact/predicates.py``.

Input rules: duplicates are merged (``index_map[i]`` is the index that point i
was merged into: the smallest index with the same coordinates); all-collinear
input gives no triangles, and ``edges()`` is then the sorted chain; fewer than
three distinct points is not an error; NaN, infinity, a wrong shape or text
raise ``ValueError``.  The result is the same set of triangles whatever the
input order, degenerate inputs included.

Updates: ``insert(p)`` adds a point (its index is the next row of ``points``),
``remove(i)`` deletes point i in time proportional to its number of neighbours
(Devillers' setting: delete the star, re-triangulate the hole; see ``removal.py``).
Indices never change: ``points`` keeps every row, removed ones included, and a
removed index appears in no output (``index_map[i] == -1``, ``live[i]`` False).
After updates the triangulation is Delaunay for the live points; where
cocircular ties allow several answers it may pick another valid one than a
fresh ``Delaunay(points[live])`` would.

Composition (as in d3-delaunay and scipy): the derived structures take a ``Delaunay``
and reuse its mesh, ``d.voronoi(bbox)``, ``d.euclidean_mst()``, ``d.gabriel_graph()``,
``d.largest_empty_circle()`` (and ``closest_pair(d)``, ``max_clearance(d, s, g)``, ...);
the adjacency is lazy and cached: ``vertex_neighbor_vertices`` (CSR) and
``vertex_to_simplex``.  ``as_delaunay`` is how a structure accepts either kind of input.

>>> d = Delaunay([(0, 0), (2, 0), (0, 2), (2, 2), (1, 1)])
>>> len(d.simplices), sorted(d.hull.tolist())
(4, [0, 1, 2, 3])
>>> int(d.find_simplex((0.5, 1.0))) >= 0, int(d.find_simplex((5.0, 5.0)))
(True, -1)
>>> d.remove(4); len(d.simplices), d.vertex_neighbors(0).tolist()
(2, [1, 2, 3])
"""
from __future__ import annotations

import math
import numbers

import numpy as np

from reference_impl.mesh import kernel, removal, status
from reference_impl.mesh.ordering import SMALL, insertion_order, line_order
from reference_impl.mesh.status import BUDGET, FLAT
from reference_impl.mesh.topology import unique_edges, vertex_adjacency
from reference_impl.validate import as_point, as_points, as_queries
from reference_impl.exact.predicates import orient2d_nb, workspace

__all__ = ["Delaunay", "as_delaunay", "live_points"]

_ITYPE = np.int32  # mesh arrays: half the memory traffic of int64
_NO_ORDER = np.zeros(0, dtype=np.int64)


def _grown(a: np.ndarray, size: int, fill) -> np.ndarray:
    """``a`` copied into a new array of length ``size`` (>= len(a)), the rest ``fill``."""
    out = np.empty((size,) + a.shape[1:], dtype=a.dtype)
    out[:len(a)] = a
    out[len(a):] = fill
    return out


def _plain(v) -> bool:
    """A finite Python float, or an int that converts to float exactly (fast-path check)."""
    t = type(v)
    return (t is float and math.isfinite(v)) or (t is int and -2 ** 53 <= v <= 2 ** 53)


def as_delaunay(points_or_delaunay) -> "Delaunay":
    """The given ``Delaunay`` itself, or a new one of the given points.

    The derived structures (Voronoi, proximity graphs, empty circle, clearance, hull)
    start with this, so they accept either and never triangulate a ``Delaunay`` again.

    >>> d = Delaunay([(0, 0), (1, 0), (0, 1)])
    >>> as_delaunay(d) is d, as_delaunay([(0, 0), (1, 0), (0, 1)]).simplices.shape
    (True, (1, 3))
    """
    if isinstance(points_or_delaunay, Delaunay):
        return points_or_delaunay
    return Delaunay(points_or_delaunay)


def live_points(d: "Delaunay") -> tuple[np.ndarray, np.ndarray]:
    """``(points, indices)``: the coordinates and input indices of the points not removed.

    >>> d = Delaunay([(0, 0), (1, 0), (0, 1), (2, 2)]); d.remove(1)
    >>> live_points(d)[1].tolist()
    [0, 2, 3]
    """
    pts = d.points
    if d._nremoved == 0:
        return pts, np.arange(len(pts))
    idx = np.flatnonzero(d.live)
    return pts[idx], idx


class Delaunay:
    """Delaunay triangulation of 2D points (exact predicates, O(n log n) expected).

    Attributes: ``points``, ``simplices``, ``neighbors``, ``hull``, ``index_map``, ``live``.
    Methods: ``find_simplex(p)``, ``insert(p)``, ``remove(i)``, ``edges()``,
    ``vertex_neighbors(i)``.  Lazy, cached adjacency as in scipy: ``vertex_neighbor_vertices``,
    ``vertex_to_simplex``.  Derived structures on this mesh (no re-triangulation):
    ``voronoi(bbox)``, ``euclidean_mst()``, ``gabriel_graph()``, ``largest_empty_circle()``.

    >>> d = Delaunay([(0, 0), (1, 0), (0, 1)])
    >>> d.insert((1, 1)), d.vertex_neighbors(3).tolist()
    (3, [1, 2])
    """

    # how often ``remove`` fell back to a rebuild after a failed sanity check (never expected)
    fallbacks = 0

    def __init__(self, points) -> None:
        pts = as_points(points)
        # Input rows live in a growable buffer: ``insert`` appends in amortised O(1).
        self._pts = pts
        self._npts = len(pts)
        self._removed = np.zeros(len(pts), dtype=bool)   # per input index
        self._nremoved = 0
        self._build()

    # ------------------------------------------------------------------ building
    def _alloc_vertices(self, nverts: int) -> None:
        self._cap_v = nverts
        self._P = np.empty((nverts, 2))                  # coordinates in insertion order
        self._start_of = np.empty(nverts + 1, dtype=_ITYPE)

    def _alloc_triangles(self, ntris: int) -> None:
        self._cap_t = ntris
        self._M = np.zeros(kernel.RECORD * ntris, dtype=_ITYPE)   # the mesh: see kernel.py

    def _cavity_scratch(self) -> tuple:
        """``(stack, bad, ba, bb, bo)``: the scratch of ``insert`` and ``remove``, as long as
        the triangle capacity, made on first use (a plain build does not need them)."""
        if self._scratch is None or len(self._scratch[0]) != self._cap_t:
            self._scratch = tuple(np.empty(self._cap_t, dtype=_ITYPE) for _ in range(5))
        return self._scratch

    def _vertex_map(self) -> np.ndarray:
        """``start_of``, the vertex -> triangle map (``kernel.py``), as long as the vertex
        capacity.  A build drops its own (at 10^7 points it is 40 MB, and a plain build and
        ``simplices`` never read it); it is made again here on first use, and
        ``_ensure_dynamic`` makes it whole before anything reads it."""
        if self._start_of is None:
            self._start_of = np.empty(self._cap_v + 1, dtype=_ITYPE)
        return self._start_of

    @property
    def _w(self) -> np.ndarray:
        """The exact predicates' workspace, made on first use."""
        if self._work is None:
            self._work = workspace()
        return self._work

    def _build(self) -> None:
        """Triangulate the live input points from scratch (one compiled call, ``kernel.triangulate``)."""
        pts = self.points
        small = len(pts) - self._nremoved < SMALL     # small: the order is computed in the call,
        budget = 0                                    # and the triangles are extracted at once
        if self._nremoved:
            live = np.flatnonzero(~self._removed[:self._npts])
            order, hints = insertion_order(pts[live], with_hints=True)
            order = live[order]
        elif small:
            order, hints = _NO_ORDER, _NO_ORDER       # (the call picks the order, as below)
        else:
            order = line_order(pts)
            if len(order):                            # a thin strip: sorted order, work capped
                hints, budget = _NO_ORDER, kernel.line_budget(len(order))
            else:
                order, hints = insertion_order(pts, with_hints=True)
        built = kernel.triangulate(pts, order, hints, small and not self._nremoved, small, budget)
        if built[0] == BUDGET:                        # sorted order was too slow here: BRIO
            order, hints = insertion_order(pts, with_hints=True)
            built = kernel.triangulate(pts, order, hints, False, small, 0)
        (code, order, self._P, self._M, self._state, self._dup, simp, rep) = built
        self._flat = code == FLAT
        self._cap_v, self._cap_t = len(self._P), len(self._M) // kernel.RECORD
        self._start_of = None      # the build's vertex -> triangle map stays behind: see _vertex_map
        self._scratch = self._work = None
        n = len(order)
        # internal vertex u = input point order[u]
        self._order = order if n >= 4 else _grown(order, 4, -1)
        self._n = n
        self._dead = np.zeros(self._cap_v, dtype=bool)       # internal u was removed
        # Bookkeeping for updates, made on the first remove() / vertex_neighbors():
        # _internal (input -> internal), _label (site -> smallest live input index),
        # _copies (site -> its live internal duplicates), _free (internal ids of removed
        # points that are in no triangle: reused by insert), the vertex -> triangle map.
        self._dyn = False
        self._line = None          # flat: two distinct live internal vertices (or None)
        self._cache = {}
        if small and not self._flat:
            self._cache.update(simplices=simp, rep=rep, labels=rep)

    def _grow_vertices(self) -> None:
        """Double the room for internal vertices (used by ``insert``)."""
        old_P, old_start = self._P, self._start_of
        n, cap = self._n, 2 * self._cap_v
        self._alloc_vertices(cap)
        self._P[:n] = old_P[:n]
        if old_start is None:
            self._start_of = None
        else:
            self._start_of[:len(old_start)] = old_start  # the vertex -> triangle map
        self._order = _grown(self._order[:n], cap, -1)
        self._dup = _grown(self._dup[:n], cap, -1)
        self._dead = _grown(self._dead[:n], cap, False)
        if self._dyn and not self._flat:
            self._label = _grown(self._label[:n], cap, -1)
            self._pos = np.empty(cap + 1, dtype=np.int64)

    def _grow_triangles(self) -> None:
        """Double the room for triangles, keeping the mesh (used by ``insert``)."""
        old_M = self._M
        nt = self._state[kernel.S_NTRI]
        self._alloc_triangles(2 * self._cap_t)
        self._M[:kernel.RECORD * nt] = old_M[:kernel.RECORD * nt]

    def _append_point(self, q: np.ndarray) -> int:
        """Append an input row (amortised O(1)); return its index."""
        idx = self._npts
        if idx == len(self._pts):
            cap = max(8, 2 * idx)
            self._pts = _grown(self._pts, cap, 0.0)
            self._removed = _grown(self._removed, cap, False)
            if self._dyn:
                self._internal = _grown(self._internal, cap, -1)
        self._pts[idx] = q
        self._removed[idx] = False
        self._npts = idx + 1
        return idx

    def _ensure_dynamic(self) -> None:
        """Make the bookkeeping that ``remove`` and ``vertex_neighbors`` need (O(n), once)."""
        if self._dyn:
            return
        n = self._n
        self._internal = np.full(len(self._pts), -1, dtype=np.int64)
        self._internal[self._order[:n]] = np.arange(n)
        if not self._flat:
            cap = self._cap_v
            self._label = np.full(cap, -1, dtype=np.int64)
            self._label[:n] = kernel.smallest_labels(self._order[:n], self._dup[:n])
            self._copies = {}                              # only sites with duplicates
            for u in np.flatnonzero(self._dup[:n] >= 0).tolist():
                r = int(self._dup[u])
                self._copies.setdefault(r, [r]).append(u)
            self._pos = np.empty(cap + 1, dtype=np.int64)
            self._free = []                                # internal ids no longer in use
            removal.init_vertex_map(self._M, int(self._state[kernel.S_NTRI]), self._vertex_map())
        self._dyn = True

    # ------------------------------------------------------------------ results
    def _result(self):
        if "simplices" not in self._cache:
            if self._flat:
                self._cache.update(self._flat_result())
            else:
                n = self._n
                if self._dyn:
                    labels = self._label[:n]
                    site = np.where(self._dup[:n] < 0, np.arange(n), self._dup[:n])
                    rep = np.where(self._dead[:n], -1, labels[site])
                else:
                    rep = labels = self._representatives()
                nt = int(self._state[kernel.S_NTRI])
                simp = kernel.extract(self._M, nt, labels)
                self._cache.update(simplices=simp, rep=rep, labels=labels)
        return self._cache

    def _lazy(self, key: str) -> np.ndarray:
        """neighbors and hull are computed on first use (building needs neither)."""
        cache = self._result()
        if key not in cache:
            nt = int(self._state[kernel.S_NTRI])
            if key == "neighbors":
                cache[key] = kernel.extract_neighbors(self._M, nt, self._rows(), len(cache["simplices"]))
            else:
                cache[key] = kernel.hull_cycle(self._M, nt, self._n, cache["labels"])
        return cache[key]

    def _flat_result(self) -> dict:
        """No triangles: the distinct live points sorted (the chain along their line)."""
        n = self._n
        alive = np.flatnonzero(~self._dead[:n])
        x, y, idx = self._P[alive, 0], self._P[alive, 1], self._order[alive]
        k = np.lexsort((idx, y, x))           # along the line; equal points: smallest index first
        xs, ys = x[k], y[k]
        new = np.r_[True, (xs[1:] != xs[:-1]) | (ys[1:] != ys[:-1])] if len(k) else np.zeros(0, bool)
        chain = idx[k][new]
        rep = np.full(n, -1, dtype=np.int64)
        rep[alive[k]] = chain[np.cumsum(new) - 1]
        empty = np.zeros((0, 3), dtype=np.int64)
        return dict(simplices=empty, neighbors=empty.copy(), hull=chain,
                    rows=np.full(1, -1, dtype=np.int32), rep=rep)

    def _representatives(self) -> np.ndarray:
        """rep[internal vertex] = smallest input index among the points equal to it."""
        order, dup = self._order[:self._n], self._dup[:self._n]
        return kernel.smallest_labels(order, dup) if (dup >= 0).any() else order

    @property
    def points(self) -> np.ndarray:
        """The input points, (n, 2) float64: inserted points appended, removed ones kept."""
        return self._pts[:self._npts]

    @property
    def live(self) -> np.ndarray:
        """(n,) bool: ``live[i]`` is False once point i has been removed."""
        return ~self._removed[:self._npts]

    @property
    def simplices(self) -> np.ndarray:
        """(m, 3) point indices of the triangles, counter-clockwise."""
        return self._result()["simplices"]

    @property
    def neighbors(self) -> np.ndarray:
        """(m, 3): ``neighbors[t, k]`` is the triangle opposite vertex k of t, -1 on the hull."""
        return self._lazy("neighbors")

    @property
    def hull(self) -> np.ndarray:
        """Convex hull vertices, counter-clockwise (collinear hull points included),
        starting at the smallest index.  For all-collinear input: the points in sorted order."""
        return self._lazy("hull")

    @property
    def index_map(self) -> np.ndarray:
        """``index_map[i]``: the index point i was merged into, the smallest live index with
        the same coordinates (i itself unless a duplicate); -1 if point i was removed."""
        rep = self._result()["rep"]
        out = np.full(self._npts, -1, dtype=np.int64)
        out[self._order[:self._n]] = rep
        return out

    def edges(self) -> np.ndarray:
        """Unique undirected edges (k, 2) with i < j, sorted; for collinear input the chain.

        >>> Delaunay([(0, 0), (1, 0), (0, 1)]).edges().tolist()
        [[0, 1], [0, 2], [1, 2]]
        """
        if not self._flat:
            e = unique_edges(self.simplices, self.neighbors)     # sorted, each edge once
        else:
            chain = self.hull
            e = np.stack([chain[:-1], chain[1:]], axis=1) if len(chain) > 1 else np.zeros((0, 2), np.int64)
            e = np.sort(e, axis=1)
            e = e[np.lexsort((e[:, 1], e[:, 0]))]
        if len(e) == 0:
            return e.reshape(0, 2)
        return e[np.r_[True, (e[1:] != e[:-1]).any(axis=1)]]   # merged duplicates can repeat

    def vertex_neighbors(self, i: int, strict: bool = False) -> np.ndarray:
        """Sorted indices of the points joined to point i by a Delaunay edge.

        Each neighbouring location is named by its smallest live index (``index_map``);
        a duplicate of i is not its neighbour.  O(degree): a walk around the vertex.
        For collinear points: the one or two chain neighbours.

        With ``strict`` only the edges of the *unique* Delaunay graph count: j is a
        neighbour when some circle through i and j has every other point strictly outside
        (their Voronoi cells share an edge of positive length).  This leaves out the
        diagonals that triangulate cocircular points, so it does not depend on how ties
        were broken.

        >>> Delaunay([(0, 0), (3, 0), (1, 0), (2, 0)]).vertex_neighbors(2).tolist()
        [0, 3]
        >>> sq = Delaunay([(0, 0), (1, 0), (1, 1), (0, 1)])     # a square: one diagonal
        >>> len(sq.vertex_neighbors(0)) + len(sq.vertex_neighbors(1)), sq.vertex_neighbors(0, strict=True).tolist()
        (5, [1, 3])
        """
        i = self._check_live(i)
        if self._flat:
            chain = self.hull
            k = int(np.flatnonzero(chain == self.index_map[i])[0])
            return np.sort(chain[[j for j in (k - 1, k + 1) if 0 <= j < len(chain)]])
        self._ensure_dynamic()
        u = int(self._internal[i])
        site = u if self._dup[u] < 0 else int(self._dup[u])
        if strict:
            ring = removal.strict_link(self._M, self._P, self._start_of, site, self._w)
        else:
            ring = removal.link(self._M, self._start_of, site)
            ring = ring[ring >= 0]
        return np.sort(self._label[ring])

    def find_simplex(self, p):
        """Index of a triangle containing p (on an edge: any incident one), -1 outside.

        Shaped like the input without its last axis, as in scipy: an (..., 2) array
        of queries gives an (...) int64 array ((k, 2) gives (k,)); one point, shape
        (2,), gives a 0-d answer, returned as a Python ``int``.

        >>> d = Delaunay([(0, 0), (1, 0), (0, 1)])
        >>> d.find_simplex((0.2, 0.2)), d.find_simplex([[[0.2, 0.2], [3, 3]]]).tolist()
        (0, [[0, -1]])
        """
        qs, shape = as_queries(p, 2)
        res = np.full(len(qs), -1, dtype=np.int64)
        if not self._flat and len(qs):
            # many queries: answer them along a Hilbert curve, so each walk starts next door
            order = insertion_order(qs, brio=False) if len(qs) > 64 else np.arange(len(qs))
            found = kernel.find(self._M, self._P, qs[order], int(self._state[kernel.S_LAST]), self._w,
                               np.zeros(kernel.STATE_SIZE, dtype=np.int64))
            res[order] = self._rows()[found]
        return int(res[0]) if shape == () else res.reshape(shape)

    def _rows(self) -> np.ndarray:
        """Triangle slot -> row of ``simplices`` (-1 for ghosts, dead slots and index -1),
        made on first use: a plain build and ``simplices`` do not need it."""
        cache = self._result()
        if "rows" not in cache:
            cache["rows"] = kernel.triangle_rows(self._M, int(self._state[kernel.S_NTRI]))
        return cache["rows"]

    # ------------------------------------------------------------------ adjacency (lazy, cached)
    @property
    def vertex_neighbor_vertices(self) -> tuple[np.ndarray, np.ndarray]:
        """``(indptr, indices)``: the Delaunay graph in CSR form, as in scipy.spatial.Delaunay.

        The neighbours of point k are ``indices[indptr[k]:indptr[k + 1]]`` (sorted).
        Merged duplicates and removed points have none (their representative,
        ``index_map[k]``, has them); for collinear input the graph is the chain.
        Computed on first use and cached until the next ``insert`` or ``remove``.

        >>> indptr, indices = Delaunay([(0, 0), (1, 0), (0, 1), (0, 0)]).vertex_neighbor_vertices
        >>> indptr.tolist(), indices.tolist()
        ([0, 2, 4, 6, 6], [1, 2, 0, 2, 0, 1])
        """
        cache = self._result()
        if "vertex_neighbor_vertices" not in cache:
            e = self.edges()
            n = self._npts
            cache["vertex_neighbor_vertices"] = vertex_adjacency(e[:, 0], e[:, 1], n, rank=np.arange(n))
        return cache["vertex_neighbor_vertices"]

    @property
    def vertex_to_simplex(self) -> np.ndarray:
        """(n,) int64: some triangle having point k as a vertex, -1 if none (a merged
        duplicate, a removed point, or no triangles at all), as in scipy.spatial.Delaunay.
        Cached until the next ``insert`` or ``remove``.

        >>> Delaunay([(0, 0), (1, 0), (0, 1), (0, 0)]).vertex_to_simplex.tolist()
        [0, 0, 0, -1]
        """
        cache = self._result()
        if "vertex_to_simplex" not in cache:
            s = self.simplices
            out = np.full(self._npts, -1, dtype=np.int64)
            out[s.ravel()[::-1]] = np.repeat(np.arange(len(s)), 3)[::-1]   # the first triangle
            cache["vertex_to_simplex"] = out
        return cache["vertex_to_simplex"]

    # ------------------------------------------------------------------ derived structures
    # d3-delaunay's composition: each structure reuses this triangulation (no rebuild).
    # The imports are lazy: the structures import this module.
    def voronoi(self, bbox) -> list[np.ndarray]:
        """Voronoi cells clipped to ``bbox``: ``reference_impl.voronoi`` on this mesh.

        >>> Delaunay([(0, 0), (1, 0), (0, 1)]).voronoi((-2, -2, 2, 2))[0].tolist()
        [[-2.0, -2.0], [0.5, -2.0], [0.5, 0.5], [-2.0, 0.5]]
        """
        from reference_impl.structures.voronoi import voronoi
        return voronoi(self, bbox)

    def euclidean_mst(self) -> np.ndarray:
        """(k, 2) edges of a Euclidean minimum spanning tree: ``reference_impl.euclidean_mst``."""
        from reference_impl.structures.proximity import euclidean_mst
        return euclidean_mst(self)

    def gabriel_graph(self) -> np.ndarray:
        """(k, 2) edges of the Gabriel graph: ``reference_impl.gabriel_graph`` on this mesh.

        >>> Delaunay([(0, 0), (1, 0), (1, 1), (0, 1)]).gabriel_graph().tolist()
        [[0, 1], [0, 3], [1, 2], [2, 3]]
        """
        from reference_impl.structures.proximity import gabriel_graph
        return gabriel_graph(self)

    def largest_empty_circle(self):
        """``Circle(x, y, r)`` centred in the hull: ``reference_impl.largest_empty_circle``.

        >>> Delaunay([(0, 0), (2, 0), (1, 1)]).largest_empty_circle()
        Circle(x=1.0, y=0.0, r=1.0)
        """
        from reference_impl.structures.empty_circle import largest_empty_circle
        return largest_empty_circle(self)

    # ------------------------------------------------------------------ updates
    def insert(self, p) -> int:
        """Insert one point; return its index (it is merged if it duplicates a point).

        >>> d = Delaunay([(0, 0), (1, 0), (0, 1)])
        >>> d.insert((1, 1)), len(d.simplices)
        (3, 2)
        """
        if type(p) in (tuple, list) and len(p) == 2 and _plain(p[0]) and _plain(p[1]):
            q = np.array((p[0] + 0.0, p[1] + 0.0))       # fast path for one plain pair
        else:
            q = as_point(p)
        idx = self._append_point(q)
        self._cache = {}
        if self._flat:
            if not self._stays_flat(q):
                self._build()             # the first point off the line: triangulate
                return idx
            if self._n + 1 > self._cap_v:
                self._grow_vertices()
            u = self._n
            self._P[u] = q
            self._order[u] = idx
            self._dup[u] = -1
            self._dead[u] = False
            self._n += 1
            if self._dyn:
                self._internal[idx] = u
            return idx
        if self._state[kernel.S_NTRI] + 2 > self._cap_t:
            self._grow_triangles()
        if self._dyn and self._free:
            u = self._free.pop()          # the id of a vertex gone from the mesh
            self._internal[self._order[u]] = -1
        else:
            if self._n + 1 > self._cap_v:
                self._grow_vertices()
            u = self._n
            self._n += 1
        self._P[u] = q
        self._order[u] = idx
        self._dead[u] = False
        r = kernel.insert(u, self._P, self._M, *self._cavity_scratch(), self._vertex_map(), self._state,
                          self._w)
        self._dup[u] = r
        if self._dyn:
            self._internal[idx] = u
            if r < 0:
                # insert() keeps start_of right for the old vertices; the new one is in
                # the last triangle it made
                self._start_of[u + 1] = self._state[kernel.S_LAST]
                self._label[u] = idx
            else:
                self._copies.setdefault(int(r), [int(r)]).append(u)   # label: idx is the largest
        return idx

    def remove(self, i: int) -> None:
        """Remove point i (an index into ``points``); the triangulation stays Delaunay.

        Cost: proportional to the number of Delaunay neighbours of the point (its star is
        deleted and the hole re-triangulated, see ``removal.py``); the first call also
        makes an O(n) index.  Indices of other points do not change.  Duplicates: each
        index is a point of its own; removing one copy of a location leaves the location
        in the triangulation, now named by the smallest remaining index, and the location
        goes away with its last copy.  If the remaining points are collinear (or fewer
        than three), the triangulation becomes flat (no triangles; ``edges()`` is the
        chain) and later inserts triangulate again.  Raises ``ValueError`` for an index
        that is not an integer, out of range, or already removed.

        >>> d = Delaunay([(0, 0), (4, 0), (0, 4), (4, 4), (1, 2)])
        >>> d.remove(4); d.simplices.shape, int(d.index_map[4])
        ((2, 3), -1)
        >>> d.remove(4)
        Traceback (most recent call last):
        ...
        ValueError: point 4 was already removed
        """
        i = self._check_live(i)
        self._ensure_dynamic()
        u = int(self._internal[i])
        self._removed[i] = True
        self._nremoved += 1
        self._dead[u] = True
        self._cache = {}
        if self._flat:
            if self._line is not None and u in self._line:
                self._line = None
            return
        site = u if self._dup[u] < 0 else int(self._dup[u])
        if site != u:
            self._free.append(u)              # a duplicate is not in the mesh: reuse its id
        group = self._copies.get(site)
        if group is not None:                 # other copies of this location
            group.remove(u)
            if group:
                self._label[site] = int(self._order[group].min())
                return
            del self._copies[site]
        self._free.append(site)
        code = removal.remove(site, self._P, self._M, *self._cavity_scratch(), self._start_of, self._pos,
                              self._state, self._w)
        if code != status.OK:
            if code == status.LOST:            # a sanity check failed: the mesh is untouched
                type(self).fallbacks += 1
            self._build()                     # flat now (or, never expected, a failed check)

    def _check_live(self, i) -> int:
        if isinstance(i, (bool, np.bool_)) or not isinstance(i, numbers.Integral):
            raise ValueError(f"point index must be an integer, got {i!r}")
        i = int(i)
        if not 0 <= i < self._npts:
            raise ValueError(f"point index {i} is out of range 0..{self._npts - 1}")
        if self._removed[i]:
            raise ValueError(f"point {i} was already removed")
        return i

    def _stays_flat(self, q: np.ndarray) -> bool:
        """Flat mode: is q on the line of the live points (or are there fewer than two)?"""
        if self._line is None:
            n = self._n
            alive = np.flatnonzero(~self._dead[:n])
            if len(alive) == 0:
                return True
            P = self._P[alive]
            other = np.flatnonzero((P[:, 0] != P[0, 0]) | (P[:, 1] != P[0, 1]))
            if len(other) == 0:
                return True
            self._line = (int(alive[0]), int(alive[other[0]]))
        a, b = self._line
        P = self._P
        return orient2d_nb(P[a, 0], P[a, 1], P[b, 0], P[b, 1], q[0], q[1], self._w) == 0

    def __repr__(self) -> str:
        return f"Delaunay(n={self._npts - self._nremoved}, triangles={len(self.simplices)})"
