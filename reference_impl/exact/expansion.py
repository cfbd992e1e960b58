"""Floating-point expansion arithmetic (Shewchuk 1997), compiled with numba.

An *expansion* is a list of doubles, ordered by increasing magnitude and
non-overlapping, whose exact sum is the number it represents.  Sums and
products of expansions are computed exactly with error-free transformations
(`two_sum`, `two_product`), so the sign of a polynomial in the input doubles
can be decided exactly.  The predicates in ``predicates.py`` use these only
when their fast floating-point filter cannot decide.

Conventions (the invariants every function here keeps):

* an expansion is ``(e, elen)``: the first ``elen`` entries of array ``e``;
* zero components are eliminated, but an expansion always has ``elen >= 1``
  (zero is ``[0.0]``), so the most significant component ``e[elen - 1]``
  carries the sign of the whole value;
* no function allocates: callers pass output (and scratch) slices.

Never compile this with ``fastmath``: re-association destroys the error terms.

Example (run ``python -m pytest reference_impl/exact/expansion.py``; a plain ``python -m doctest`` on the
file would cache compiled code under the module name "expansion"):

>>> import numpy as np
>>> h = np.empty(4)
>>> two_sum(1.0, 1e-30)
(1.0, 1e-30)
>>> n = add(np.array([1e-30, 1.0]), 2, np.array([-1.0]), 1, h)
>>> h[:n].tolist(), sign_of(h, n)
([1e-30], 1)
"""
from __future__ import annotations

from numba import njit

SPLITTER = 134217729.0  # 2**27 + 1, splits a double into two 26-bit halves
EPSILON = 2.0 ** -53     # half an ulp of 1.0 (round-to-nearest unit roundoff)

__all__ = ["SPLITTER", "EPSILON", "two_sum", "two_diff", "two_product", "diff", "add",
           "scale", "mul", "negate", "compress", "accumulate", "sign", "sign_of", "certain_sign"]


@njit(cache=True)
def two_sum(a, b):
    """x + y == a + b exactly, with x = fl(a + b)."""
    x = a + b
    bv = x - a
    av = x - bv
    return x, (a - av) + (b - bv)


@njit(cache=True)
def two_diff(a, b):
    """x + y == a - b exactly, with x = fl(a - b)."""
    x = a - b
    bv = a - x
    av = x + bv
    return x, (a - av) + (bv - b)


@njit(cache=True)
def _split(a):
    c = SPLITTER * a
    big = c - a
    hi = c - big
    return hi, a - hi


@njit(cache=True)
def two_product(a, b):
    """x + y == a * b exactly, with x = fl(a * b) (Dekker's product)."""
    x = a * b
    ahi, alo = _split(a)
    bhi, blo = _split(b)
    err = x - ahi * bhi
    err -= alo * bhi
    err -= ahi * blo
    return x, alo * blo - err


@njit(cache=True)
def _keep(h, hi, x):
    """Append the component x at h[hi] unless it is zero; return the new length."""
    if x != 0.0:
        h[hi] = x
        return hi + 1
    return hi


@njit(cache=True)
def _close(h, hi, q):
    """Append the last (most significant) component q, kept even when zero if h is empty."""
    if q != 0.0 or hi == 0:
        h[hi] = q
        hi += 1
    return hi


@njit(cache=True)
def diff(a, b, h):
    """Write the exact difference a - b into h as an expansion; return its length."""
    x, y = two_diff(a, b)
    if y != 0.0:
        h[0] = y
        h[1] = x
        return 2
    h[0] = x
    return 1


@njit(cache=True)
def add(e, elen, f, flen, h):
    """h = e + f exactly (Shewchuk's fast_expansion_sum_zeroelim); return len(h)."""
    ei = 0
    fi = 0
    enow = e[0]
    fnow = f[0]
    if (fnow > enow) == (fnow > -enow):
        q = enow
        ei += 1
    else:
        q = fnow
        fi += 1
    hi = 0
    while ei < elen or fi < flen:
        # take the smaller-magnitude remaining component next
        if fi >= flen or (ei < elen and ((f[fi] > e[ei]) == (f[fi] > -e[ei]))):
            nxt = e[ei]
            ei += 1
        else:
            nxt = f[fi]
            fi += 1
        q, hh = two_sum(q, nxt)
        hi = _keep(h, hi, hh)
    return _close(h, hi, q)


@njit(cache=True)
def scale(e, elen, b, h):
    """h = e * b exactly for a double b (scale_expansion_zeroelim); return len(h)."""
    q, hh = two_product(e[0], b)
    hi = _keep(h, 0, hh)
    for i in range(1, elen):
        p1, p0 = two_product(e[i], b)
        s, hh = two_sum(q, p0)
        hi = _keep(h, hi, hh)
        # p1 dominates s, so a fast two-sum is exact here
        q = p1 + s
        hi = _keep(h, hi, s - (q - p1))
    return _close(h, hi, q)


@njit(cache=True)
def mul(e, elen, f, flen, h, t1, t2):
    """h = e * f exactly; t1 and t2 are scratch of the same size as h (2*elen*flen)."""
    n = scale(e, elen, f[0], h)
    for j in range(1, flen):
        m = scale(e, elen, f[j], t1)
        k = add(h, n, t1, m, t2)
        for i in range(k):
            h[i] = t2[i]
        n = k
    return n


@njit(cache=True)
def negate(e, elen):
    """Negate an expansion in place."""
    for i in range(elen):
        e[i] = -e[i]


@njit(cache=True)
def compress(e, n):
    """Shewchuk's compress, in place: the same value as a shorter expansion; returns its length."""
    bottom = n - 1
    q = e[bottom]
    for i in range(n - 2, -1, -1):
        enow = e[i]
        qnew = q + enow
        small = enow - (qnew - q)
        if small != 0.0:
            e[bottom] = qnew
            bottom -= 1
            q = small
        else:
            q = qnew
    top = 0
    for i in range(bottom + 1, n):
        hnow = e[i]
        qnew = hnow + q
        small = q - (qnew - hnow)
        if small != 0.0:
            e[top] = small
            top += 1
        q = qnew
    e[top] = q
    return top + 1


@njit(cache=True)
def accumulate(acc, nacc, term, nt, scratch, squeeze):
    """acc += term in place (``nacc == 0``: acc = term); ``scratch`` holds the sum first.

    With ``squeeze`` the sum is compressed.  Returns the new length of acc.
    """
    if nacc == 0:
        for q in range(nt):
            acc[q] = term[q]
        return nt
    n = add(acc, nacc, term, nt, scratch)
    if squeeze:
        n = compress(scratch, n)
    for q in range(n):
        acc[q] = scratch[q]
    return n


@njit(cache=True)
def sign(x):
    """The sign of a double: 1, -1 or 0."""
    return 1 if x > 0.0 else (-1 if x < 0.0 else 0)


@njit(cache=True)
def sign_of(e, n):
    """The sign of the expansion e[:n]: the sign of its most significant component."""
    return sign(e[n - 1])


@njit(cache=True, inline="always")
def certain_sign(det, perm, dmax, dmax_limit, perm_lo, bound, abs_bound):
    """A floating-point filter: the sign of det when |det| exceeds ``bound * perm + abs_bound``
    (trusted only where ``dmax < dmax_limit`` and ``perm > perm_lo``), else 0 (undecided)."""
    if dmax < dmax_limit and perm > perm_lo:
        errbound = bound * perm + abs_bound
        if det > errbound:
            return 1
        if -det > errbound:
            return -1
    return 0
