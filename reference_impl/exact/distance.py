"""Exact distance comparisons, and the exact sort of edges by length (the proximity graphs' arithmetic).

- ``sq_dist_cmp(ax, ay, bx, by, cx, cy, dx, dy, w)``: the exact sign of |a - b|^2 - |c - d|^2;
- ``dot_sign(px, py, qx, qy, rx, ry, w)``: the exact sign of (p - r) . (q - r) (negative
  iff r is strictly inside the circle on diameter pq);
- ``length_order(P, u, v)``: a permutation of the edges (u[i], v[i]) of the points P by
  exact length, equal lengths ordered by the endpoints' coordinates.

The two predicates are numba functions for compiled callers; ``w`` is a ``scratch()``
array.  Both are one expression, a sum of two products of differences minus two
more, decided the same way as ``predicates.py``: a floating-point filter with a
proven error bound, then an error-free float evaluation when no operation rounds
(ties on grids), then expansion arithmetic (``expansion.py``) after scaling by a power
of two (``scaling.pow2_scale``), or Python fractions when the coordinates of one
test span more than 2**150.  The length sort uses float keys with error intervals
and sorts only the runs of overlapping intervals again, exactly.  No epsilon.

>>> w = scratch()
>>> sq_dist_cmp(0.0, 0.0, 3.0, 4.0, 1.0, 1.0, 6.0, 1.0, w)     # |(3, 4)| = 5 = |(5, 0)|
0
>>> dot_sign(0.0, 0.0, 2.0, 0.0, 1.0, 0.5, w)                  # (1, 0.5) inside the circle on 0-2
-1
>>> P = np.array([[0.0, 0.0], [3.0, 0.0], [0.0, 1.0]])
>>> length_order(P, np.array([0, 0, 1]), np.array([1, 2, 2])).tolist()     # lengths 3, 1, sqrt(10)
[1, 0, 2]
"""
from __future__ import annotations

from fractions import Fraction

import numba
import numpy as np
from numba import njit

from reference_impl.exact.expansion import (EPSILON, accumulate, add, certain_sign, diff, mul, negate,
                                            sign, sign_of, two_diff, two_product, two_sum)
from reference_impl.exact.scaling import pow2_exponent, pow2_scale
from reference_impl.exact.sorting import merge_sort

__all__ = ["sq_dist_cmp", "dot_sign", "length_order", "scratch", "SCRATCH_SIZE"]

# Filter constants.  The value of a*b + c*d - e*f - g*h, each factor a difference
# of two doubles, is computed with relative error at most about 5 eps per unit
# of the permanent |ab| + |cd| + |ef| + |gh|; 8 eps leaves a margin.  The filter
# is only trusted where nothing can overflow or underflow.
_BOUND = 8.0 * EPSILON
_F_LO = 2.0 ** -900        # smallest permanent for the filter (underflow errors are then negligible)
_F_DMAX = 2.0 ** 500       # largest |difference| for the filter (no overflow in products)
_EXACT_MIN = 2.0 ** -150   # exact stage: smallest scaled non-zero coordinate
SCRATCH_SIZE = 128
# scratch layout: expansions at [0, 96), the 8 differences at [96, 104), the 16 values at [112, 128)
_DIFFS, _VALUES = 96, SCRATCH_SIZE - 16


@njit(cache=True)
def scratch():
    """A scratch array for ``sq_dist_cmp`` and ``dot_sign`` (one per thread of work)."""
    return np.empty(SCRATCH_SIZE, dtype=np.float64)


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
    too many binades for that, Python fractions decide.
    """
    if not pow2_scale(v, _EXACT_MIN):
        with numba.objmode(s="int64"):
            s = _products_python(v)
        return s
    d1, d2, prod, t1, t2 = w[0:2], w[2:4], w[8:16], w[16:24], w[24:32]
    acc, acc2 = w[32:64], w[64:96]
    nacc = 0
    for term in range(4):          # acc += +-(v[o] - v[o+1]) * (v[o+2] - v[o+3])
        o = 4 * term
        n1 = diff(v[o], v[o + 1], d1)
        n2 = diff(v[o + 2], v[o + 3], d2)
        np_ = mul(d1, n1, d2, n2, prod, t1, t2)
        if term >= 2:
            negate(prod, np_)
        nacc = accumulate(acc, nacc, prod, np_, acc2, False)
    return sign_of(acc, nacc)


@njit(cache=True, inline="always")
def _clean_diff(a, b):
    """a - b is computed exactly and its products cannot underflow or overflow."""
    x, e = two_diff(a, b)
    return e == 0.0 and (x == 0.0 or 2.0 ** -450 <= abs(x) < 2.0 ** 500)


@njit(cache=True)
def _sign_if_exact(v, d):
    """Sign of d0 d1 + d2 d3 - d4 d5 - d6 d7, d = the differences of v, if no operation
    rounds (ties on grids), else 2."""
    for i in range(8):
        if not _clean_diff(v[2 * i], v[2 * i + 1]):
            return 2
    first = 0.0
    plus = 0.0
    for k in range(4):
        p, e = two_product(d[2 * k], d[2 * k + 1])
        s, f = two_sum(plus, p)
        if e != 0.0 or f != 0.0:
            return 2
        plus = s
        if k == 1:
            first = plus
            plus = 0.0
    det, f = two_diff(first, plus)
    return sign(det) if f == 0.0 else 2


@njit(cache=True)
def _products_slow(v, w):
    """The exact sign of the expression of ``_products_python`` for the 16 doubles v
    (overwritten) once the filter has failed: error-free floats, else expansions."""
    d = w[_DIFFS:_DIFFS + 8]
    for i in range(8):
        d[i] = v[2 * i] - v[2 * i + 1]
    s = _sign_if_exact(v, d)
    return s if s != 2 else _products_exact(v, w)


@njit(cache=True, inline="always")
def _dots_sign(ax, ay, bx, by, cx, cy, dx, dy, ex, ey, fx, fy, gx, gy, hx, hy, w):
    """Exact sign of (a - b).(c - d) - (e - f).(g - h): the float filter, then ``_products_slow``."""
    x1, y1 = ax - bx, ay - by
    x2, y2 = cx - dx, cy - dy
    x3, y3 = ex - fx, ey - fy
    x4, y4 = gx - hx, gy - hy
    p1, p2, p3, p4 = x1 * x2, y1 * y2, x3 * x4, y3 * y4
    det = (p1 + p2) - (p3 + p4)
    perm = (abs(p1) + abs(p2)) + (abs(p3) + abs(p4))
    dmax = max(abs(x1), abs(y1), abs(x2), abs(y2), abs(x3), abs(y3), abs(x4), abs(y4))
    s = certain_sign(det, perm, dmax, _F_DMAX, _F_LO, _BOUND, 0.0)
    if s != 0:
        return s
    v = w[_VALUES:]
    v[0] = ax; v[1] = bx; v[2] = cx; v[3] = dx
    v[4] = ay; v[5] = by; v[6] = cy; v[7] = dy
    v[8] = ex; v[9] = fx; v[10] = gx; v[11] = hx
    v[12] = ey; v[13] = fy; v[14] = gy; v[15] = hy
    return _products_slow(v, w)


@njit(cache=True)
def sq_dist_cmp(ax, ay, bx, by, cx, cy, dx, dy, w):
    """Exact sign of |a - b|^2 - |c - d|^2 (``w`` is scratch from ``scratch()``)."""
    return _dots_sign(ax, ay, bx, by, ax, ay, bx, by, cx, cy, dx, dy, cx, cy, dx, dy, w)


@njit(cache=True)
def dot_sign(px, py, qx, qy, rx, ry, w):
    """Exact sign of (p - r) . (q - r): negative iff r is strictly inside the circle on diameter pq."""
    return _dots_sign(px, py, rx, ry, qx, qy, rx, ry, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, w)


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
    h = w[16:48]
    return sign_of(h, add(E[i], L[i], neg, nj, h))


@njit(cache=True, inline="always")
def _length_cmp(X, Y, u, v, key, err, E, L, i, j, w):
    """Exact sign of |edge i|^2 - |edge j|^2: exact float keys compare directly; otherwise
    the precomputed expansions E when there are any, else ``sq_dist_cmp``."""
    if err[i] == 0.0 and err[j] == 0.0:
        return 1 if key[i] > key[j] else (-1 if key[i] < key[j] else 0)
    if len(L):
        return _expansion_cmp(E, L, i, j, w)
    return sq_dist_cmp(X[u[i]], Y[u[i]], X[v[i]], Y[v[i]], X[u[j]], Y[u[j]], X[v[j]], Y[v[j]], w)


@njit(cache=True, inline="always")
def _shorter(ctx, i, j):
    """``merge_sort``'s comparison: edge i is exactly shorter than edge j."""
    X, Y, u, v, key, err, E, L, w = ctx
    return _length_cmp(X, Y, u, v, key, err, E, L, i, j, w) < 0


@njit(cache=True)
def _sort_runs(X, Y, u, v, key, err, E, L, order, starts, ends):
    """Merge-sort each run order[starts[r]:ends[r]] by exact length; return, per position,
    whether the edge there is exactly as long as the one before it in the same run."""
    w = scratch()
    buf = np.empty(max(1, np.max(ends - starts)), dtype=order.dtype)
    same = np.zeros(len(order), dtype=np.bool_)
    for r in range(len(starts)):
        merge_sort(order[starts[r]:ends[r]], buf, _shorter, (X, Y, u, v, key, err, E, L, w))
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


def length_order(P: np.ndarray, u: np.ndarray, v: np.ndarray, first_only: bool = False) -> np.ndarray:
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
    e = pow2_exponent(P)
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
