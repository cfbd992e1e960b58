"""Proximity graphs from the Delaunay triangulation: EMST, closest pair, Gabriel graph, RNG.

    python -c "from reference_impl.structures.proximity import euclidean_mst; print(euclidean_mst([(0,0),(1,0),(0,2)]))"

Every one of these graphs is a subgraph of the Delaunay graph, in a chain:

    EMST  ⊆  relative neighbourhood graph  ⊆  Gabriel graph  ⊆  Delaunay graph

so each is computed from the Delaunay edges (``reference_impl.Delaunay``) in
O(n log n), and the closest pair is the shortest Delaunay edge.

Exactness.  Every decision compares squared distances or signs of dot
products of differences of the input doubles.  A floating-point filter with a
proven error bound decides almost every case; when it cannot (ties on grids and
circles, near-ties), the value is recomputed exactly with expansion arithmetic
(``expansion.py``), or with Python integers when the coordinates of one test
span more than 2**150 in magnitude.  Sorting edges by length works the same
way: float keys with error intervals, and only the runs of overlapping
intervals are merge-sorted again with the exact comparison.  No epsilon anywhere.

Every function takes the points or a ``Delaunay`` of them (whose mesh it then
uses: no re-triangulation; points removed from it are left out).

Conventions (as in the rest of ``reference_impl``): edges are (k, 2) int arrays
with i < j in each row and rows sorted; duplicated points are merged, so only
the representative of a duplicate group (its smallest index, ``Delaunay.index_map``)
appears in an edge; all-collinear input gives the chain of consecutive points.
Ties (equal lengths) are broken by the coordinates of the endpoints, never by
their indices, so the results do not depend on the input order.

>>> pts = [(0, 0), (4, 0), (0, 3), (5, 5), (4, 1)]
>>> euclidean_mst(pts).tolist()
[[0, 1], [0, 2], [1, 4], [3, 4]]
>>> closest_pair(pts)
Pair(i=1, j=4)
>>> gabriel_graph([(0, 0), (2, 0), (1, 1), (1, -3)]).tolist()   # (1, 1) sits on the circle on 0-1
[[0, 2], [0, 3], [1, 2], [1, 3]]
"""
from __future__ import annotations

import math
from fractions import Fraction
from typing import NamedTuple

import numba
import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from reference_impl.mesh.delaunay import Delaunay, as_delaunay
from reference_impl.mesh.topology import each_edge_once, find_root, union_roots, vertex_adjacency
from reference_impl.exact.expansion import EPSILON, add, diff, mul, negate, two_diff, two_product, two_sum

__all__ = ["Pair", "euclidean_mst", "closest_pair", "gabriel_graph", "relative_neighborhood_graph"]

# ----------------------------------------------------------------------------- exact kernels
# Filter constants.  The value of a*b + c*d - e*f - g*h, each factor a difference
# of two doubles, is computed with relative error at most about 5 eps per unit
# of the permanent |ab| + |cd| + |ef| + |gh|; 8 eps leaves a margin.  The filter
# is only trusted where nothing can overflow or underflow.
_BOUND = 8.0 * EPSILON
_F_LO = 2.0 ** -900        # smallest permanent for the filter (underflow errors are then negligible)
_F_DMAX = 2.0 ** 500       # largest |difference| for the filter (no overflow in products)
_EXACT_MIN = 2.0 ** -150   # exact stage: smallest scaled non-zero coordinate
_SCRATCH = 128


@njit(cache=True)
def _scratch():
    return np.empty(_SCRATCH, dtype=np.float64)


def _products_python(v) -> int:
    """Exact sign of (v0-v1)(v2-v3) + (v4-v5)(v6-v7) - (v8-v9)(v10-v11) - (v12-v13)(v14-v15)."""
    f = [Fraction(float(x)) for x in v]
    val = ((f[0] - f[1]) * (f[2] - f[3]) + (f[4] - f[5]) * (f[6] - f[7])
           - (f[8] - f[9]) * (f[10] - f[11]) - (f[12] - f[13]) * (f[14] - f[15]))
    return (val > 0) - (val < 0)


@njit(cache=True)
def _products_exact(v, w):
    """Exact sign of the expression of ``_products_python`` (v: 16 doubles, overwritten).

    All values are scaled by one power of two (the sign does not change) so that
    expansion arithmetic can neither overflow nor underflow; if the values span
    too many binades for that, Python integers decide.
    """
    m = 0.0
    for x in v:
        m = max(m, abs(x))
    if m == 0.0:
        return 0
    k = -math.frexp(m)[1]
    lo = math.ldexp(_EXACT_MIN, -k)
    for x in v:
        if x != 0.0 and abs(x) < lo:
            with numba.objmode(s="int64"):
                s = _products_python(v)
            return s
    for i in range(16):
        v[i] = math.ldexp(v[i], k)
    d1, d2, prod, t1, t2 = w[0:2], w[2:4], w[8:16], w[16:24], w[24:32]
    acc, acc2 = w[32:64], w[64:96]
    acc[0] = 0.0
    nacc = 1
    for term in range(4):          # acc += +-(v[o] - v[o+1]) * (v[o+2] - v[o+3])
        o = 4 * term
        n1 = diff(v[o], v[o + 1], d1)
        n2 = diff(v[o + 2], v[o + 3], d2)
        np_ = mul(d1, n1, d2, n2, prod, t1, t2)
        if term >= 2:
            negate(prod, np_)
        nacc = add(acc, nacc, prod, np_, acc2)
        acc[:nacc] = acc2[:nacc]
    top = acc[nacc - 1]
    return 1 if top > 0.0 else (-1 if top < 0.0 else 0)


@njit(cache=True, inline="always")
def _clean_diff(a, b):
    """a - b is computed exactly and its products cannot underflow or overflow."""
    x, e = two_diff(a, b)
    return e == 0.0 and (x == 0.0 or 2.0 ** -450 <= abs(x) < 2.0 ** 500)


@njit(cache=True)
def _sign_if_exact(x1, x2, y1, y2, x3, x4, y3, y4):
    """Sign of x1 x2 + y1 y2 - x3 x4 - y3 y4 if no operation rounds (ties on grids), else 2."""
    p1, e1 = two_product(x1, x2)
    p2, e2 = two_product(y1, y2)
    p3, e3 = two_product(x3, x4)
    p4, e4 = two_product(y3, y4)
    s1, f1 = two_sum(p1, p2)
    s2, f2 = two_sum(p3, p4)
    d, f3 = two_diff(s1, s2)
    if e1 == 0.0 and e2 == 0.0 and e3 == 0.0 and e4 == 0.0 and f1 == 0.0 and f2 == 0.0 and f3 == 0.0:
        return 1 if d > 0.0 else (-1 if d < 0.0 else 0)
    return 2


@njit(cache=True)
def sq_dist_cmp(ax, ay, bx, by, cx, cy, dx, dy, w):
    """Exact sign of |a - b|^2 - |c - d|^2 (``w`` is scratch from ``_scratch()``)."""
    x1 = ax - bx
    y1 = ay - by
    x2 = cx - dx
    y2 = cy - dy
    s1 = x1 * x1 + y1 * y1
    s2 = x2 * x2 + y2 * y2
    det = s1 - s2
    perm = s1 + s2
    if perm > _F_LO and max(abs(x1), abs(y1), abs(x2), abs(y2)) < _F_DMAX:
        err = _BOUND * perm
        if det > err:
            return 1
        if -det > err:
            return -1
    if _clean_diff(ax, bx) and _clean_diff(ay, by) and _clean_diff(cx, dx) and _clean_diff(cy, dy):
        s = _sign_if_exact(x1, x1, y1, y1, x2, x2, y2, y2)
        if s != 2:
            return s
    v = w[_SCRATCH - 16:]
    v[0] = ax; v[1] = bx; v[2] = ax; v[3] = bx
    v[4] = ay; v[5] = by; v[6] = ay; v[7] = by
    v[8] = cx; v[9] = dx; v[10] = cx; v[11] = dx
    v[12] = cy; v[13] = dy; v[14] = cy; v[15] = dy
    return _products_exact(v, w)


@njit(cache=True)
def dot_sign(px, py, qx, qy, rx, ry, w):
    """Exact sign of (p - r) . (q - r): negative iff r is strictly inside the circle on diameter pq."""
    x1 = px - rx
    y1 = py - ry
    x2 = qx - rx
    y2 = qy - ry
    a = x1 * x2
    b = y1 * y2
    det = a + b
    perm = abs(a) + abs(b)
    if perm > _F_LO and max(abs(x1), abs(y1), abs(x2), abs(y2)) < _F_DMAX:
        err = _BOUND * perm
        if det > err:
            return 1
        if -det > err:
            return -1
    if _clean_diff(px, rx) and _clean_diff(py, ry) and _clean_diff(qx, rx) and _clean_diff(qy, ry):
        s = _sign_if_exact(x1, x2, y1, y2, 0.0, 0.0, 0.0, 0.0)
        if s != 2:
            return s
    v = w[_SCRATCH - 16:]
    v[0] = px; v[1] = rx; v[2] = qx; v[3] = rx
    v[4] = py; v[5] = ry; v[6] = qy; v[7] = ry
    for i in range(8, 16):
        v[i] = 0.0
    return _products_exact(v, w)


# ----------------------------------------------------------------------------- Delaunay edges
class _Graph:
    """The Delaunay edges of a point set, with the apex of each adjacent triangle."""

    def __init__(self, points) -> None:
        d = as_delaunay(points)            # a given Delaunay is used as it is
        self.P = d.points
        self.index_map = d.index_map
        s = np.asarray(d.simplices, dtype=np.int64)
        if len(s) == 0:  # collinear or fewer than 3 distinct points: the sorted chain
            chain = np.asarray(d.hull, dtype=np.int64)
            u, v = chain[:-1], chain[1:]
            a1 = a2 = np.full(len(u), -1, dtype=np.int64)
        else:
            nb = np.asarray(d.neighbors, dtype=np.int64)
            t, k = each_edge_once(nb)
            u, v = s[t, (k + 1) % 3], s[t, (k + 2) % 3]
            o = nb[t, k]
            a1 = s[t, k]
            a2 = np.where(o >= 0, s[np.maximum(o, 0)].sum(axis=1) - u - v, -1)
        self.u, self.v = np.minimum(u, v), np.maximum(u, v)
        self.a1, self.a2 = a1, a2

    def adjacency(self) -> tuple[np.ndarray, np.ndarray]:
        """CSR (indptr, indices) of the Delaunay graph."""
        return vertex_adjacency(self.u, self.v, len(self.P))


def _sorted_edges(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    e = np.stack([np.minimum(u, v), np.maximum(u, v)], axis=1).astype(np.int64)
    return e[np.lexsort((e[:, 1], e[:, 0]))] if len(e) else e.reshape(0, 2)


# ----------------------------------------------------------------------------- exact length order
@njit(cache=True)
def _length_keys(X, Y, u, v, key, err):
    """key = fl(|pu - pv|^2) on power-of-two-scaled coordinates; err = 0 when provably exact."""
    tiny = 2.0 ** -400
    for i in range(len(u)):
        dx, ex = two_diff(X[u[i]], X[v[i]])
        dy, ey = two_diff(Y[u[i]], Y[v[i]])
        sx, fx = two_product(dx, dx)
        sy, fy = two_product(dy, dy)
        s, fs = two_sum(sx, sy)
        key[i] = s
        exact = (ex == 0.0 and ey == 0.0 and fx == 0.0 and fy == 0.0 and fs == 0.0
                 and (dx == 0.0 or abs(dx) >= tiny) and (dy == 0.0 or abs(dy) >= tiny))
        err[i] = 0.0 if exact else 8.0 * EPSILON * s + 2.0 ** -1000


@njit(cache=True)
def _length_expansions(X, Y, u, v, rows, E, L):
    """E[i, :L[i]] = exact expansion of |pu - pv|^2 for each edge i in ``rows``.

    Exact only if no product underflows: the caller guarantees every non-zero
    coordinate is at least 2**-450 in magnitude (and every one below 1).
    """
    d1, d2 = np.empty(2), np.empty(2)
    s1, s2, t1, t2 = np.empty(8), np.empty(8), np.empty(8), np.empty(8)
    for i in rows:
        n1 = diff(X[u[i]], X[v[i]], d1)
        n2 = diff(Y[u[i]], Y[v[i]], d2)
        m1 = mul(d1, n1, d1, n1, s1, t1, t2)
        m2 = mul(d2, n2, d2, n2, s2, t1, t2)
        L[i] = add(s1, m1, s2, m2, E[i])


@njit(cache=True)
def _expansion_cmp(E, L, i, j, w):
    """Exact sign of E[i] - E[j] (two expansions)."""
    nj = L[j]
    neg = w[0:16]
    for k in range(nj):
        neg[k] = -E[j, k]
    nh = add(E[i], L[i], neg, nj, w[16:48])
    top = w[16 + nh - 1]
    return 1 if top > 0.0 else (-1 if top < 0.0 else 0)


@njit(cache=True, inline="always")
def _length_cmp(X, Y, u, v, key, err, E, L, i, j, w):
    """Exact sign of |edge i|^2 - |edge j|^2: exact float keys compare directly; otherwise
    the precomputed expansions E when there are any, else ``sq_dist_cmp``."""
    if err[i] == 0.0 and err[j] == 0.0:
        return 1 if key[i] > key[j] else (-1 if key[i] < key[j] else 0)
    if len(L):
        return _expansion_cmp(E, L, i, j, w)
    return sq_dist_cmp(X[u[i]], Y[u[i]], X[v[i]], Y[v[i]], X[u[j]], Y[u[j]], X[v[j]], Y[v[j]], w)


@njit(cache=True)
def _merge_sort(seg, buf, X, Y, u, v, key, err, E, L, w):
    """Stable bottom-up merge sort of the edge ids in ``seg`` by exact length."""
    n = len(seg)
    width = 1
    while width < n:
        for lo in range(0, n - width, 2 * width):
            mid = lo + width
            hi = min(lo + 2 * width, n)
            a, b, k = lo, mid, 0
            while a < mid and b < hi:
                if _length_cmp(X, Y, u, v, key, err, E, L, seg[b], seg[a], w) < 0:
                    buf[k] = seg[b]
                    b += 1
                else:
                    buf[k] = seg[a]
                    a += 1
                k += 1
            buf[k:k + mid - a] = seg[a:mid]
            k += mid - a
            buf[k:k + hi - b] = seg[b:hi]
            k += hi - b
            seg[lo:hi] = buf[:k]
        width *= 2


@njit(cache=True)
def _sort_runs(X, Y, u, v, key, err, E, L, order, starts, ends):
    """Merge-sort each run order[starts[r]:ends[r]] by exact length; return, per position,
    whether the edge there is exactly as long as the one before it in the same run."""
    w = _scratch()
    buf = np.empty(max(1, np.max(ends - starts)), dtype=order.dtype)
    same = np.zeros(len(order), dtype=np.bool_)
    for r in range(len(starts)):
        _merge_sort(order[starts[r]:ends[r]], buf, X, Y, u, v, key, err, E, L, w)
        for i in range(starts[r] + 1, ends[r]):
            same[i] = _length_cmp(X, Y, u, v, key, err, E, L, order[i - 1], order[i], w) == 0
    return same


def _difference_classes(P: np.ndarray, u: np.ndarray, v: np.ndarray) -> np.ndarray | None:
    """Rows (|dx|, |dy|), larger first, each difference exact as hi + lo: equal rows, equal lengths.

    None if a difference overflows (then no grouping is done)."""
    a, b = P[u], P[v]
    hi = a - b
    bv = a - hi
    lo = (a - (hi + bv)) + (bv - b)            # two_diff: a - b == hi + lo exactly
    sign = np.where(hi < 0, -1.0, 1.0)
    hi, lo = hi * sign, lo * sign
    swap = (hi[:, 0] < hi[:, 1]) | ((hi[:, 0] == hi[:, 1]) & (lo[:, 0] < lo[:, 1]))
    C = np.where(swap[:, None], np.c_[hi[:, 1], lo[:, 1], hi[:, 0], lo[:, 0]],
                 np.c_[hi[:, 0], lo[:, 0], hi[:, 1], lo[:, 1]])
    return C if np.isfinite(C).all() else None


def _length_order(P: np.ndarray, u: np.ndarray, v: np.ndarray, first_only: bool = False) -> np.ndarray:
    """Permutation of the edges (u, v) by exact length; equal lengths ordered by coordinates.

    1. Float keys with error intervals (zero when provably exact) sort almost
       everything; only runs of overlapping intervals can be out of order.
    2. In those runs, edges with the same exact difference vector (up to sign
       and swap) have equal lengths: one representative per such group is sorted
       exactly (``_sort_runs``), then equal representatives are merged.
    3. Each run is laid out by (exact length rank, endpoint coordinates).
    With ``first_only`` only the first position is guaranteed.
    """
    m = len(u)
    if m == 0:
        return np.zeros(0, dtype=np.int64)
    key = np.zeros(m)
    err = np.full(m, np.inf)     # if scaling would lose bits: every decision to the exact sort
    top = float(np.max(np.abs(P)))
    e = math.frexp(top)[1] if top > 0 else 0
    S = np.ldexp(P, -e)          # a power of two: the order of lengths is unchanged
    lossless = bool(np.array_equal(np.ldexp(S, e), P))
    if lossless:
        _length_keys(S[:, 0].copy(), S[:, 1].copy(), u, v, key, err)
    order = np.argsort(key, kind="stable")
    lo_k = (key - err)[order]
    hi_k = (key + err)[order]
    certain = np.maximum.accumulate(hi_k)[:-1] < np.minimum.accumulate(lo_k[::-1])[::-1][1:]
    run_of = np.cumsum(np.r_[True, certain]) - 1                  # run of each position
    multi = np.bincount(run_of) > 1
    if first_only:
        multi[1:] = False
    if not multi.any():
        return order
    pos = np.flatnonzero(multi[run_of])
    rows, rid = order[pos], run_of[pos]
    # 2. groups of equal difference vectors inside each run
    C = _difference_classes(P, u[rows], v[rows])
    if C is None:
        C = np.c_[rows, rows, rows, rows].astype(float)
    g = np.lexsort((C[:, 3], C[:, 2], C[:, 1], C[:, 0], rid))
    rows, rid, C = rows[g], rid[g], C[g]
    first = np.r_[True, (rid[1:] != rid[:-1]) | np.any(C[1:] != C[:-1], axis=1)]
    group_of = np.cumsum(first) - 1
    reps, rep_run = rows[first], rid[first]
    group_of_rep = np.zeros(m, dtype=np.int64)
    group_of_rep[reps] = np.arange(len(reps))
    starts = np.flatnonzero(np.r_[True, rep_run[1:] != rep_run[:-1]])
    ends = np.r_[starts[1:], len(reps)]
    Sr = np.abs(S[np.concatenate([u[reps], v[reps]])])
    E, L = np.empty((0, 16)), np.zeros(0, dtype=np.int64)
    if lossless and not np.any((Sr > 0) & (Sr < 2.0 ** -450)):
        E, L = np.empty((m, 16)), np.zeros(m, dtype=np.int64)
        _length_expansions(S[:, 0].copy(), S[:, 1].copy(), u, v, reps, E, L)
    # (without E, coordinates span too many binades: sq_dist_cmp rescales each test)
    same = _sort_runs(P[:, 0].copy(), P[:, 1].copy(), u, v, key, err, E, L, reps, starts, ends)
    rank = np.empty(len(reps), dtype=np.int64)
    rank[group_of_rep[reps]] = np.cumsum(~same)
    # 3. by rank, then by the endpoints in lexicographic (x, y) order: a geometric tie-break
    pu, pv = P[u[rows]], P[v[rows]]
    swap = (pu[:, 0] > pv[:, 0]) | ((pu[:, 0] == pv[:, 0]) & (pu[:, 1] > pv[:, 1]))
    lo_pt, hi_pt = np.where(swap[:, None], pv, pu), np.where(swap[:, None], pu, pv)
    order[pos] = rows[np.lexsort((hi_pt[:, 1], hi_pt[:, 0], lo_pt[:, 1], lo_pt[:, 0],
                                  rank[group_of]))]
    return order


# ----------------------------------------------------------------------------- MST
@njit(cache=True)
def _kruskal(n, u, v, order, target):
    parent = np.arange(n)
    size = np.ones(n, dtype=np.int64)
    out = np.empty((target, 2), dtype=np.int64)
    k = 0
    for idx in order:
        if k == target:
            break
        a = find_root(parent, u[idx])
        b = find_root(parent, v[idx])
        if a == b:
            continue
        union_roots(parent, size, a, b)
        out[k, 0] = u[idx]
        out[k, 1] = v[idx]
        k += 1
    return out[:k]


def euclidean_mst(points: ArrayLike | Delaunay) -> np.ndarray:
    """Edges of a Euclidean minimum spanning tree, (n_distinct - 1, 2), i < j, rows sorted.

    Kruskal over the Delaunay edges with an exact length order, so the total
    length is optimal even among near-ties; equal lengths are broken by the
    endpoints' coordinates, so the tree is the same for any input order.
    Duplicates are merged: the tree spans the distinct points, and a duplicate
    index (``Delaunay(points).index_map[i] != i``) appears in no edge.
    Collinear input gives the chain; fewer than 2 distinct points give no edge.

    >>> euclidean_mst([(0, 0), (1, 0), (2, 0), (1, 0)]).tolist()
    [[0, 1], [1, 2]]
    """
    g = _Graph(points)
    n_distinct = int(np.count_nonzero(g.index_map == np.arange(len(g.P))))
    if n_distinct < 2:
        return np.zeros((0, 2), dtype=np.int64)
    order = _length_order(g.P, g.u, g.v)
    tree = _kruskal(len(g.P), g.u, g.v, order, n_distinct - 1)
    return _sorted_edges(tree[:, 0], tree[:, 1])


class Pair(NamedTuple):
    """Two point indices (a tuple: ``i, j = pair`` and ``pair == (i, j)`` work)."""

    i: int
    j: int


def closest_pair(points: ArrayLike | Delaunay) -> Pair:
    """A pair ``Pair(i, j)``, i < j, of points at minimum distance (exact).

    If some points coincide the distance is 0, and the answer is the two smallest
    indices of the duplicated location with the smallest (x, y).  Otherwise it is
    the shortest Delaunay edge; among equally short ones, the one whose endpoints
    come first in (x, y) order.  Fewer than 2 points raise ``ValueError``.

    >>> closest_pair([(0, 0), (5, 5), (1, 1), (5, 6)])
    Pair(i=1, j=3)
    >>> closest_pair([(3, 3), (1, 1), (3, 3), (1, 1)])
    Pair(i=1, j=3)
    """
    d = as_delaunay(points)
    P = d.points
    n_live = int(np.count_nonzero(d.live))
    if n_live < 2:
        raise ValueError(f"closest_pair needs at least 2 points, got {n_live}")
    g = _Graph(d)
    rep = g.index_map
    dup = np.flatnonzero((rep != np.arange(len(P))) & (rep >= 0))    # removed points: rep -1
    if len(dup):
        groups = np.unique(rep[dup])
        first = groups[np.lexsort((P[groups, 1], P[groups, 0]))[0]]
        return Pair(int(first), int(np.min(dup[rep[dup] == first])))
    i = _length_order(P, g.u, g.v, first_only=True)[0]
    return Pair(int(g.u[i]), int(g.v[i]))


# ----------------------------------------------------------------------------- Gabriel and RNG
@njit(cache=True)
def _gabriel_mask(X, Y, u, v, a1, a2):
    w = _scratch()
    keep = np.ones(len(u), dtype=np.bool_)
    for i in range(len(u)):
        p, q = u[i], v[i]
        for r in (a1[i], a2[i]):
            if r >= 0 and dot_sign(X[p], Y[p], X[q], Y[q], X[r], Y[r], w) <= 0:
                keep[i] = False
    return keep


def gabriel_graph(points: ArrayLike | Delaunay) -> np.ndarray:
    """Edges (k, 2), i < j, rows sorted, of the Gabriel graph.

    p and q are joined when the *closed* disc with diameter pq contains no other
    point, that is (r - p) . (r - q) > 0 for every other point r (exact).  This
    is the standard definition; it makes the graph unique and a subgraph of every
    Delaunay triangulation (with "strictly inside" instead, both diagonals of a
    square would qualify and cross).  A Delaunay edge passes iff the apexes of its
    one or two triangles are outside that disc (any point in the disc would lie
    in an empty circumcircle otherwise).  Collinear input gives the chain;
    duplicates are merged (only representatives appear).

    >>> gabriel_graph([(0, 0), (1, 0), (1, 1), (0, 1)]).tolist()   # the square's diagonals fail
    [[0, 1], [0, 3], [1, 2], [2, 3]]
    """
    g = _Graph(points)
    keep = _gabriel_mask(g.P[:, 0].copy(), g.P[:, 1].copy(), g.u, g.v, g.a1, g.a2)
    return _sorted_edges(g.u[keep], g.v[keep])


@njit(cache=True, inline="always")
def _in_lune(X, Y, r, p, q, w):
    """max(|rp|, |rq|) < |pq| exactly."""
    return (sq_dist_cmp(X[r], Y[r], X[p], Y[p], X[p], Y[p], X[q], Y[q], w) < 0
            and sq_dist_cmp(X[r], Y[r], X[q], Y[q], X[p], Y[p], X[q], Y[q], w) < 0)


@njit(cache=True, inline="always")
def _disc_step(X, Y, indptr, indices, stack, st, seen, stamp, c, o, w):
    """One step of the search of the open disc centred c with radius |co|.

    ``st`` = [stack top, next adjacency slot, end of adjacency].  A step either
    takes the next vertex off the stack or looks at one neighbour.  Returns
    1 if a point of the lune of co was met, -1 if the disc is exhausted, else 0.
    """
    if st[1] == st[2]:
        if st[0] == 0:
            return -1
        st[0] -= 1
        x = stack[st[0]]
        st[1] = indptr[x]
        st[2] = indptr[x + 1]
        return 0
    y = indices[st[1]]
    st[1] += 1
    if seen[y] != stamp:
        seen[y] = stamp
        if sq_dist_cmp(X[y], Y[y], X[c], Y[c], X[c], Y[c], X[o], Y[o], w) < 0:
            if sq_dist_cmp(X[y], Y[y], X[o], Y[o], X[c], Y[c], X[o], Y[o], w) < 0:
                return 1
            stack[st[0]] = y
            st[0] += 1
    return 0


@njit(cache=True)
def _rng_mask(X, Y, u, v, a1, a2, indptr, indices):
    """For each candidate edge pq: is the open lune of pq empty?

    The points of S inside the open disc D(p, |pq|) induce a connected subgraph of
    any Delaunay triangulation containing p (every such t has a Delaunay
    neighbour strictly closer to p: the one whose Voronoi cell the segment from t
    to p enters first), so a search from p that only enters that disc meets every
    point of the lune.  The searches from p and from q advance one neighbour at a
    time in turns, and the first one to run out proves the lune empty.
    """
    w = _scratch()
    n = len(X)
    keep = np.ones(len(u), dtype=np.bool_)
    seen_p = np.full(n, -1, dtype=np.int64)
    seen_q = np.full(n, -1, dtype=np.int64)
    stack_p = np.empty(n, dtype=np.int64)
    stack_q = np.empty(n, dtype=np.int64)
    st_p = np.zeros(3, dtype=np.int64)
    st_q = np.zeros(3, dtype=np.int64)
    for i in range(len(u)):
        p, q = u[i], v[i]
        if (a1[i] >= 0 and _in_lune(X, Y, a1[i], p, q, w)) or \
                (a2[i] >= 0 and _in_lune(X, Y, a2[i], p, q, w)):
            keep[i] = False
            continue
        seen_p[p] = seen_p[q] = i      # q is on the boundary of p's disc, not inside: skip
        seen_q[q] = seen_q[p] = i      # the exact (tie) evaluation of |pq| against itself
        stack_p[0], stack_q[0] = p, q
        st_p[0], st_p[1], st_p[2] = 1, 0, 0       # one vertex (p) on the stack, no neighbour pending
        st_q[0], st_q[1], st_q[2] = 1, 0, 0
        while True:
            r = _disc_step(X, Y, indptr, indices, stack_p, st_p, seen_p, i, p, q, w)
            if r == 0:
                r = _disc_step(X, Y, indptr, indices, stack_q, st_q, seen_q, i, q, p, w)
            if r != 0:
                keep[i] = r < 0
                break
    return keep


def relative_neighborhood_graph(points: ArrayLike | Delaunay) -> np.ndarray:
    """Edges (k, 2), i < j, rows sorted, of the relative neighbourhood graph (RNG).

    p and q are joined when no point r is closer to both than they are to each
    other: no r with max(|rp|, |rq|) < |pq| (the open lune is empty; exact).
    It lies between the EMST and the Gabriel graph, so only Gabriel edges are
    candidates.  Collinear input gives the chain; duplicates are merged.

    >>> relative_neighborhood_graph([(0, 0), (2, 0), (1, 1)]).tolist()   # (1, 1) is in the lune of 0-1
    [[0, 2], [1, 2]]
    """
    g = _Graph(points)
    X, Y = g.P[:, 0].copy(), g.P[:, 1].copy()
    gab = _gabriel_mask(X, Y, g.u, g.v, g.a1, g.a2)
    indptr, indices = g.adjacency()
    keep = _rng_mask(X, Y, g.u[gab], g.v[gab], g.a1[gab], g.a2[gab], indptr, indices)
    return _sorted_edges(g.u[gab][keep], g.v[gab][keep])
