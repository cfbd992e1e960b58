"""Delaunay3D: the robust 3D Delaunay tetrahedralisation (numba-compiled Bowyer-Watson).

    python -c "from reference_impl.mesh.delaunay3d import delaunay_3d; print(delaunay_3d([(0,0,0),(1,0,0),(0,1,0),(0,0,1)]))"

The data model extends the 2D one: ``points`` (n, 3) float64; ``simplices``
(m, 4) point indices, every tetrahedron *positively oriented* in Shewchuk's
convention, ``orient3d(*points[s]) > 0`` (the fourth vertex lies below the
plane of the first three seen counter-clockwise from above; equivalently the
face ``FACES[k]`` opposite vertex k is counter-clockwise seen from outside);
``neighbors`` (m, 4) with ``neighbors[t, k]`` the tetrahedron across the face
opposite vertex k, -1 on the hull; ``hull_facets`` (h, 3) the convex hull's
triangles, counter-clockwise seen from outside.  The kernel is ``kernel3d.py``;
the predicates are ``predicates3d.py``.

Input rules (as in 2D): duplicates are merged (``index_map[i]`` is the smallest
index with the same coordinates, and only that index appears in the output);
all-coplanar input, and fewer than four distinct points, is not an error and
gives no tetrahedra: an empty (0, 4) array (``flat`` is then True); NaN,
infinity, a wrong shape or text raise ``ValueError``.  Coordinates from 1e-300
to 1e300 work: all decisions are exact.

Insertion order: BRIO rounds (Amenta, Choi, Rote) each sorted along a 3D
Hilbert curve; the round of a point is a hash of its coordinates and ties are
broken by coordinates, so the order, and with it the output (cospherical ties
included), depends only on the set of points, never on the order given.

Before building, all coordinates are multiplied by one power of two that brings
the largest near 1 when that is exact (it always is, unless tiny and huge values
are mixed); signs of the predicates do not change, but the fast floating-point
filter then answers for inputs at 1e-300 or 1e300 too.

>>> cube = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
>>> d = Delaunay3D(cube + [(0.5, 0.5, 0.5)])
>>> len(d.simplices), len(d.hull_facets)
(12, 12)
>>> int(d.find_simplex((0.2, 0.3, 0.4))) >= 0, int(d.find_simplex((2.0, 0.0, 0.0)))
(True, -1)
>>> delaunay_3d([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)]).shape   # coplanar: no tetrahedra
(0, 4)
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from reference_impl.mesh import kernel3d as K
from reference_impl.mesh import status
from reference_impl.mesh.ordering import mix
from reference_impl.validate import as_points, as_queries
from reference_impl.exact.predicates3d import workspace3d
from reference_impl.exact.scaling import pow2_exponent

__all__ = ["Delaunay3D", "delaunay_3d", "insertion_order_3d", "hilbert_index_3d"]

_ITYPE = np.int32
_BITS = 16          # Hilbert curve resolution per axis: 48-bit keys


# ----------------------------------------------------------------------------- insertion order
@njit(cache=True)
def hilbert_index_3d(ix: int, iy: int, iz: int, bits: int) -> int:
    """Position of the cell (ix, iy, iz) along a 3D Hilbert curve over a 2**bits grid
    (Skilling's transpose algorithm, "Programming the Hilbert curve", 2004).

    >>> [hilbert_index_3d(x, y, z, 1) for x, y, z in [(0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)]]
    [0, 1, 2, 3]
    """
    x0, x1, x2 = ix, iy, iz
    m = 1 << (bits - 1)
    q = m
    while q > 1:                       # inverse undo of excess work
        p = q - 1
        for i in range(3):
            xi = x0 if i == 0 else (x1 if i == 1 else x2)
            if xi & q:
                x0 ^= p
            else:
                t = (x0 ^ xi) & p
                x0 ^= t
                if i == 1:
                    x1 ^= t
                elif i == 2:
                    x2 ^= t
        q >>= 1
    x1 ^= x0                           # Gray encode
    x2 ^= x1
    t = 0
    q = m
    while q > 1:
        if x2 & q:
            t ^= q - 1
        q >>= 1
    x0 ^= t
    x1 ^= t
    x2 ^= t
    h = 0
    for j in range(bits - 1, -1, -1):  # interleave the transposed bits
        h = (h << 3) | (((x0 >> j) & 1) << 2) | (((x1 >> j) & 1) << 1) | ((x2 >> j) & 1)
    return h


@njit(cache=True)
def _keys3(P, bits_of, lo, inv, bits, rounds):
    n = P.shape[0]
    keys = np.empty(n, dtype=np.int64)
    top = (1 << bits) - 1
    for i in range(n):
        cx = min(top, max(0, int((P[i, 0] - lo[0]) * inv * top)))
        cy = min(top, max(0, int((P[i, 1] - lo[1]) * inv * top)))
        cz = min(top, max(0, int((P[i, 2] - lo[2]) * inv * top)))
        h = mix(bits_of[i, 0] * np.uint64(0x9E3779B97F4A7C15)
                 ^ mix(bits_of[i, 1] * np.uint64(0xC2B2AE3D27D4EB4F) ^ bits_of[i, 2]))
        tz = 0
        while tz < rounds - 1 and ((h >> np.uint64(tz)) & np.uint64(1)) == np.uint64(0):
            tz += 1
        rnd = rounds - 1 - tz
        keys[i] = ((rnd << 58) | (hilbert_index_3d(cx, cy, cz, bits) << 10)
                   | np.int64(h >> np.uint64(54)))
    return keys


def insertion_order_3d(points: np.ndarray, brio: bool = True) -> np.ndarray:
    """A permutation of ``range(len(points))`` to insert (n, 3) points in: BRIO rounds, each
    along a Hilbert curve, ties broken by coordinates (so it depends only on the point set).

    >>> sorted(insertion_order_3d(np.eye(3)).tolist())
    [0, 1, 2]
    """
    P = np.ascontiguousarray(points, dtype=np.float64)
    n = len(P)
    if n == 0:
        return np.zeros(0, dtype=np.int64)
    lo = P.min(axis=0)
    with np.errstate(over="ignore"):
        span = float((P.max(axis=0) - lo).max())
    if not math.isfinite(span):           # spans near 1e308 overflow: halve first (order only)
        return insertion_order_3d(P * 2.0 ** -8, brio)
    inv = 1.0 / span if span > 0 and math.isfinite(1.0 / span) else 0.0
    rounds = min(31, max(1, int(np.log2(n)) - 6)) if brio else 1
    keys = _keys3(P, (P + 0.0).view(np.uint64), lo, inv, _BITS, rounds)
    return np.lexsort((P[:, 2], P[:, 1], P[:, 0], keys))


# ----------------------------------------------------------------------------- the kernel driver
class Mesh:
    """Arrays and state of one ``kernel3d`` run over points already in insertion order.

    ``Mesh(coords)`` builds at once; then ``flat``, ``dup`` (per internal vertex: an
    earlier equal vertex or -1), ``state`` and ``extract()`` (tetrahedra, neighbours,
    ..., hull facets in internal numbering).
    """

    def __init__(self, coords: np.ndarray) -> None:
        n = len(coords)
        self.n = n
        k = -pow2_exponent(coords, keep_normal=True)   # exact: every non-zero value stays normal
        S = np.ldexp(coords, k) if k else coords
        self.X = np.ascontiguousarray(S[:, 0])
        self.Y = np.ascontiguousarray(S[:, 1])
        self.Z = np.ascontiguousarray(S[:, 2])
        self.state = np.zeros(K.STATE_SIZE, dtype=np.int64)
        self.dup = np.full(max(n, 1), -1, dtype=np.int64)
        self.w = workspace3d()
        self.vst = np.zeros(n + 1, dtype=_ITYPE)
        self.vhead = np.zeros(n + 1, dtype=_ITYPE)
        self._tets(7 * n + 64)
        self._cavity(1024)
        self.flat = n < 4
        while not self.flat:
            code = K.build(self.X, self.Y, self.Z, self.tet, self.nbr, self.mark, self.free,
                             self.stack, self.bad, self.bf, self.bo, self.bj, self.vst, self.vhead,
                             self.enext, self.eto, self.etet, self.eface, self.state, self.dup,
                             self.w)
            if code == status.FLAT:
                self.flat = True
            elif code == status.OK:
                break
            elif self.state[K.S_NEED] == 1:
                self._tets(2 * len(self.mark))
            else:
                self._cavity(2 * len(self.bad))
        if self.flat:
            self.dup = _flat_duplicates(coords)

    def _tets(self, cap: int) -> None:
        old = getattr(self, "tet", None)
        tet = np.full(4 * cap, K.DEAD, dtype=_ITYPE)
        nbr = np.full(4 * cap, -1, dtype=_ITYPE)
        mark = np.zeros(cap, dtype=_ITYPE)
        free = np.zeros(cap, dtype=_ITYPE)
        if old is not None:
            used = int(self.state[K.S_NTET])
            tet[:4 * used] = self.tet[:4 * used]
            nbr[:4 * used] = self.nbr[:4 * used]
            mark[:used] = self.mark[:used]
            free[:len(self.free)] = self.free
        self.tet, self.nbr, self.mark, self.free = tet, nbr, mark, free

    def _cavity(self, cap: int) -> None:
        self.stack = np.empty(cap, dtype=_ITYPE)
        self.bad = np.empty(cap, dtype=_ITYPE)
        self.bo = np.empty(cap, dtype=_ITYPE)
        self.bj = np.empty(cap, dtype=_ITYPE)
        self.bf = np.empty(3 * cap, dtype=_ITYPE)
        self.enext = np.empty(3 * cap, dtype=_ITYPE)
        self.eto = np.empty(3 * cap, dtype=_ITYPE)
        self.etet = np.empty(3 * cap, dtype=_ITYPE)
        self.eface = np.empty(3 * cap, dtype=_ITYPE)

    def extract(self):
        return K.extract(self.tet, self.nbr, int(self.state[K.S_NTET]))


def _flat_duplicates(coords: np.ndarray) -> np.ndarray:
    """dup[i] = first earlier row with the same coordinates, else -1 (for flat input)."""
    n = len(coords)
    dup = np.full(max(n, 1), -1, dtype=np.int64)
    if n:
        _, first, inverse = np.unique(coords, axis=0, return_index=True, return_inverse=True)
        root = first[inverse.reshape(-1)]
        dup[:n] = np.where(root != np.arange(n), root, -1)
    return dup


def representatives(dup: np.ndarray, order: np.ndarray) -> np.ndarray:
    """rep[internal vertex] = smallest input index among the points equal to it.

    ``dup`` as in ``Mesh.dup``; ``order[i]`` the input index of internal vertex i.

    >>> representatives(np.array([-1, -1, 0]), np.array([2, 0, 1])).tolist()
    [1, 0, 1]
    """
    n = len(order)
    root = np.where(dup[:n] >= 0, dup[:n], np.arange(n))
    rep_of_root = np.full(n, np.iinfo(np.int64).max, dtype=np.int64)
    np.minimum.at(rep_of_root, root, order)
    return rep_of_root[root]


def input_index_map(order: np.ndarray, rep: np.ndarray) -> np.ndarray:
    """``index_map`` over the input indices from the per-internal-vertex ``representatives``.

    >>> input_index_map(np.array([2, 0, 1]), np.array([1, 0, 1])).tolist()
    [0, 1, 1]
    """
    out = np.empty(len(order), dtype=np.int64)
    out[order] = rep
    return out


# ----------------------------------------------------------------------------- public API
class Delaunay3D:
    """Delaunay tetrahedralisation of 3D points (exact predicates, O(n log n) expected on
    well-spread input).

    Attributes: ``points``, ``simplices``, ``neighbors``, ``hull_facets``, ``index_map``,
    ``flat``, ``stats``.  Method: ``find_simplex(p)``.

    >>> d = Delaunay3D([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 0, 1)])
    >>> d.simplices.shape, d.index_map.tolist()
    ((1, 4), [0, 1, 2, 3, 3])
    """

    def __init__(self, points) -> None:
        self._points = as_points(points, dim=3)
        self._order = insertion_order_3d(self._points)
        self._mesh = Mesh(self._points[self._order])
        self._rep = representatives(self._mesh.dup, self._order)
        if self._mesh.flat:
            self._simp = np.zeros((0, 4), dtype=np.int64)
            self._neig = np.zeros((0, 4), dtype=np.int64)
            self._hull = np.zeros((0, 3), dtype=np.int64)
            self._out_of = np.zeros(0, dtype=np.int64)
        else:
            simp, self._neig, self._out_of, hull = self._mesh.extract()
            self._simp = self._rep[simp]
            self._hull = self._rep[hull]

    @property
    def points(self) -> np.ndarray:
        """The input points, (n, 3) float64."""
        return self._points

    @property
    def simplices(self) -> np.ndarray:
        """(m, 4) point indices of the tetrahedra, each with orient3d > 0."""
        return self._simp

    @property
    def neighbors(self) -> np.ndarray:
        """(m, 4): ``neighbors[t, k]`` is the tetrahedron across the face opposite vertex k
        of t, -1 on the hull."""
        return self._neig

    @property
    def hull_facets(self) -> np.ndarray:
        """(h, 3) convex hull triangles, counter-clockwise seen from outside (coplanar hull
        points are vertices too).  Empty for flat input."""
        return self._hull

    @property
    def flat(self) -> bool:
        """True when all points are coplanar (or fewer than 4 distinct): no tetrahedra."""
        return self._mesh.flat

    @property
    def index_map(self) -> np.ndarray:
        """``index_map[i]``: the index point i was merged into (i itself unless a duplicate)."""
        return input_index_map(self._order, self._rep)

    @property
    def stats(self) -> dict:
        """Work counters of the build: walk steps, conflict tests, cavity tetrahedra, scans."""
        s = self._mesh.state
        return {"walk_steps": int(s[K.S_STEPS]), "conflict_tests": int(s[K.S_TESTS]),
                "cavity_tets": int(s[K.S_BAD]), "fallback_scans": int(s[K.S_SCANS])}

    def find_simplex(self, p):
        """Index of a tetrahedron containing p (on a shared face: any one), -1 outside the hull.

        Shaped like the input without its last axis, as in scipy: an (..., 3) array
        gives an (...) int64 array ((k, 3) gives (k,)); one point, shape (3,), gives a
        0-d answer, returned as a Python ``int``.

        >>> Delaunay3D([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]).find_simplex([(0.1, 0.1, 0.1)])
        array([0])
        """
        qs, shape = as_queries(p, 3)
        if self.flat:
            res = np.full(len(qs), -1, dtype=np.int64)
        else:
            m = self._mesh
            # walk over the original coordinates (queries need not scale exactly)
            P = self._points[self._order]
            found = K.find(m.tet, m.nbr, np.ascontiguousarray(P[:, 0]),
                           np.ascontiguousarray(P[:, 1]), np.ascontiguousarray(P[:, 2]),
                           qs, int(m.state[K.S_LAST]), m.w, m.state.copy())
            res = np.where(found >= 0, self._out_of[np.maximum(found, 0)], -1)
        return int(res[0]) if shape == () else res.reshape(shape)

    def __repr__(self) -> str:
        return f"Delaunay3D(n={len(self._points)}, tetrahedra={len(self._simp)})"


def delaunay_3d(points) -> np.ndarray:
    """The (m, 4) tetrahedra of a Delaunay tetrahedralisation of (n, 3) points, each
    positively oriented (orient3d > 0); an empty (0, 4) array for coplanar input.

    >>> pts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    >>> t = delaunay_3d(pts)
    >>> t.tolist()
    [[0, 3, 2, 1]]
    >>> from reference_impl.exact.predicates3d import orient3d
    >>> orient3d(*(pts[i] for i in t[0]))
    1
    """
    return Delaunay3D(points).simplices
