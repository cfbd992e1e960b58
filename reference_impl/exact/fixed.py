"""Exact orientation and in-circle signs in fixed point: the coordinate differences as integers.

    python -m pytest reference_impl/exact/fixed.py      # its examples (as reference_impl.exact.fixed)

The stage of ``predicates.py`` for ties whose coordinate differences are *not* exact doubles:
a grid spaced 0.1 or made with ``linspace``, squares placed at float positions.  There almost
every in-circle test of neighbouring points is an exact tie, the filter cannot decide, and the
expansion arithmetic (``expansion.py``) takes a few microseconds per call.  Here instead:

1. each difference p - q is computed exactly as two doubles ``hi + lo`` (``two_diff``); every
   such double is a multiple of ``2**e``, where ``e`` is the lowest set bit over all of them,
   so ``D = (hi + lo) / 2**e`` is an integer; when every ``|hi| < 2**(e + 59)``, so that
   ``|D| < 2**60``, it is computed in an int64 from the bits of hi and lo (no libm call);
   otherwise the caller falls back to expansions (the differences of that call span more than
   about 60 binary orders: a coordinate at 1e-17 beside one at 0.1, say);
2. each D is split into three digits of ``BITS = 21`` bits (two in ``[0, 2**21)``, the top one
   signed), and the determinant is computed digit-wise: a product of two digits is below
   ``2**42``, so the sums of a few dozen of them stay far below ``2**63``, and no operation can
   overflow;
3. carries are propagated (``_normalise``) until every digit but the top one is in
   ``[0, 2**21)``; then the sign of the number is the sign of its top digit, or + when that is
   zero and any digit is not (measured: about 0.1 us a call, against 1-3 us for expansions).

Scaling every difference by the same ``2**-e`` multiplies the orientation determinant by
``2**-2e`` and the in-circle determinant by ``2**-4e``: positive factors, so the signs are
those of the input.  No function allocates; ``iw`` is an int64 scratch of ``SCRATCH`` entries.

>>> import numpy as np
>>> iw = np.empty(SCRATCH, dtype=np.int64)
>>> incircle_fixed(0.1, 0.1, 0.3, 0.1, 0.3, 0.3, 0.1, 0.3, iw)    # a square: cocircular
0
>>> orient_fixed(0.1, 0.2, 0.2, 0.4, 0.3, 0.6, iw)   # y = 2x holds exactly for these doubles
0
>>> orient_fixed(0.0, 0.3, 0.1, 0.2, 0.2, 0.1, iw)   # x + y = 0.3, but 0.1 + 0.2 != 0.3 here
-1
"""
from __future__ import annotations

from llvmlite import ir
from numba import njit, types
from numba.extending import intrinsic

from reference_impl.exact.expansion import two_diff

__all__ = ["BITS", "SCRATCH", "NO_ANSWER", "orient_fixed", "incircle_fixed"]

BITS = 21
_MASK = (1 << BITS) - 1
_SPAN = 58               # |D| < 2**(_SPAN + 1) * (1 + 2**-52) < 2**60: three digits, top one < 2**18
NO_ANSWER = 2            # what the functions return when the differences do not fit
_NONE = 1 << 20          # "no set bit" (a zero double)

# Layout of the int64 scratch ``iw``.
_DIG = 0                 # 18: six differences, three digits each (x of point j at 6j, y at 6j+3)
_P = 18                  # 6: a product of two differences (five coefficients and a carry)
_LIFT = 24               # 6: x^2 + y^2 (< 2**123), normalised
_COF = 30                # 6: a 2x2 cofactor (|.| < 2**123), normalised
_ACC = 36                # 12: the sum of the three terms (11 coefficients and a carry)
SCRATCH = 48


@intrinsic
def _bits(typingctx, x):
    """The IEEE-754 bits of a float64 as an int64 (a bit cast: no libm call, no rounding)."""
    if x != types.float64:
        return None

    def codegen(context, builder, signature, args):
        return builder.bitcast(args[0], ir.IntType(64))
    return types.int64(types.float64), codegen


@njit(cache=True, inline="always")
def _exponent_of_power(t):
    """log2(t) for an int64 power of two t (its conversion to float64 is exact)."""
    return ((_bits(float(t)) >> 52) & 0x7FF) - 1023


@njit(cache=True, inline="always")
def _split(v):
    """v == m * 2**k exactly: returns (m, k, low, top) with m a signed integer of at most 53
    bits and 2**low, 2**top the lowest and highest set bits of |v| (low = _NONE for zero)."""
    b = _bits(v)
    ex = (b >> 52) & 0x7FF
    m = b & ((1 << 52) - 1)
    if ex == 0:                                 # zero or subnormal
        if m == 0:
            return 0, 0, _NONE, -_NONE
        k = -1074
        top = k
        while (m >> (top - k + 1)) != 0:        # (subnormals: rare, a short loop)
            top += 1
    else:
        m |= 1 << 52
        k = ex - 1075
        top = k + 52
    low = k + _exponent_of_power(m & -m)
    if b < 0:
        m = -m
    return m, k, low, top


@njit(cache=True, inline="always")
def _shifted(m, s):
    """m * 2**s for s >= 0, or m / 2**-s (exact: the callers' m has that many trailing zeros)."""
    return m << s if s >= 0 else m >> -s


@njit(cache=True, inline="always")
def _digits(mh, kh, ml, kl, e, iw, at):
    """iw[at:at+3] = the three digits of D = (mh 2**kh + ml 2**kl) / 2**e (|D| < 2**60)."""
    d = _shifted(mh, kh - e) + _shifted(ml, kl - e)
    iw[at] = d & _MASK
    d >>= BITS                                  # arithmetic shift: floor division
    iw[at + 1] = d & _MASK
    iw[at + 2] = d >> BITS


@njit(cache=True, inline="always")
def _product(iw, a, b, out, sgn):
    """iw[out:out+5] += sgn * (digits at a) * (digits at b), coefficient by coefficient."""
    for i in range(3):
        x = sgn * iw[a + i]
        for j in range(3):
            iw[out + i + j] += x * iw[b + j]


@njit(cache=True, inline="always")
def _normalise(iw, at, n):
    """Propagate carries through iw[at:at+n] so that all but the last digit are in
    [0, 2**BITS); the last takes the final carry (it must not overflow: callers size n)."""
    carry = 0
    for i in range(n - 1):
        v = iw[at + i] + carry
        iw[at + i] = v & _MASK
        carry = v >> BITS
    iw[at + n - 1] += carry


@njit(cache=True, inline="always")
def _sign(iw, at, n):
    """Sign of a normalised number iw[at:at+n] (see ``_normalise``)."""
    top = iw[at + n - 1]
    if top != 0:
        return 1 if top > 0 else -1
    for i in range(n - 1):
        if iw[at + i] != 0:
            return 1
    return 0


@njit(cache=True, inline="always")
def _clear(iw, at, n):
    for i in range(n):
        iw[at + i] = 0


@njit(cache=True)
def orient_fixed(ax, ay, bx, by, cx, cy, iw):
    """Exact sign of orient2d(a, b, c), or ``NO_ANSWER`` when the differences do not fit."""
    h0, l0 = two_diff(ax, cx)
    h1, l1 = two_diff(ay, cy)
    h2, l2 = two_diff(bx, cx)
    h3, l3 = two_diff(by, cy)
    m0, k0, lo0, tp0 = _split(h0)
    m1, k1, lo1, tp1 = _split(h1)
    m2, k2, lo2, tp2 = _split(h2)
    m3, k3, lo3, tp3 = _split(h3)
    n0, j0, lw0, _ = _split(l0)
    n1, j1, lw1, _ = _split(l1)
    n2, j2, lw2, _ = _split(l2)
    n3, j3, lw3, _ = _split(l3)
    e = min(lo0, lo1, lo2, lo3, lw0, lw1, lw2, lw3)
    if e == _NONE:
        return 0
    if max(tp0, tp1, tp2, tp3) - e > _SPAN:
        return NO_ANSWER
    _digits(m0, k0, n0, j0, e, iw, _DIG)        # acx
    _digits(m1, k1, n1, j1, e, iw, _DIG + 3)    # acy
    _digits(m2, k2, n2, j2, e, iw, _DIG + 6)    # bcx
    _digits(m3, k3, n3, j3, e, iw, _DIG + 9)    # bcy
    _clear(iw, _P, 6)
    _product(iw, _DIG, _DIG + 9, _P, 1)          # acx * bcy
    _product(iw, _DIG + 3, _DIG + 6, _P, -1)     # - acy * bcx
    _normalise(iw, _P, 6)
    return _sign(iw, _P, 6)


@njit(cache=True)
def incircle_fixed(ax, ay, bx, by, cx, cy, dx, dy, iw):
    """Exact sign of incircle(a, b, c, d), or ``NO_ANSWER`` when the differences do not fit."""
    # the differences p - d for p = a, b, c (x and y), exactly as hi + lo, hi = m 2**k
    h0, l0 = two_diff(ax, dx)
    h1, l1 = two_diff(ay, dy)
    h2, l2 = two_diff(bx, dx)
    h3, l3 = two_diff(by, dy)
    h4, l4 = two_diff(cx, dx)
    h5, l5 = two_diff(cy, dy)
    m0, k0, lo0, tp0 = _split(h0)
    m1, k1, lo1, tp1 = _split(h1)
    m2, k2, lo2, tp2 = _split(h2)
    m3, k3, lo3, tp3 = _split(h3)
    m4, k4, lo4, tp4 = _split(h4)
    m5, k5, lo5, tp5 = _split(h5)
    n0, j0, lw0, _ = _split(l0)
    n1, j1, lw1, _ = _split(l1)
    n2, j2, lw2, _ = _split(l2)
    n3, j3, lw3, _ = _split(l3)
    n4, j4, lw4, _ = _split(l4)
    n5, j5, lw5, _ = _split(l5)
    e = min(lo0, lo1, lo2, lo3, lo4, lo5, lw0, lw1, lw2, lw3, lw4, lw5)
    if e == _NONE:
        return 0
    if max(tp0, tp1, tp2, tp3, tp4, tp5) - e > _SPAN:
        return NO_ANSWER
    _digits(m0, k0, n0, j0, e, iw, _DIG)
    _digits(m1, k1, n1, j1, e, iw, _DIG + 3)
    _digits(m2, k2, n2, j2, e, iw, _DIG + 6)
    _digits(m3, k3, n3, j3, e, iw, _DIG + 9)
    _digits(m4, k4, n4, j4, e, iw, _DIG + 12)
    _digits(m5, k5, n5, j5, e, iw, _DIG + 15)
    _clear(iw, _ACC, 12)
    for r in range(3):
        i = 6 * r                                # point r: x digits at i, y digits at i + 3
        j = 6 * ((r + 1) % 3)
        k = 6 * ((r + 2) % 3)
        _clear(iw, _LIFT, 6)
        _product(iw, i, i, _LIFT, 1)             # x^2 + y^2
        _product(iw, i + 3, i + 3, _LIFT, 1)
        _normalise(iw, _LIFT, 6)
        _clear(iw, _COF, 6)
        _product(iw, j, k + 3, _COF, 1)          # jx * ky - kx * jy
        _product(iw, k, j + 3, _COF, -1)
        _normalise(iw, _COF, 6)
        for a in range(6):                       # acc += lift * cof: each coefficient gets at
            x = iw[_LIFT + a]                    # most 6 products below 2**42 from each term
            if x != 0:
                for b in range(6):
                    iw[_ACC + a + b] += x * iw[_COF + b]
    _normalise(iw, _ACC, 12)
    return _sign(iw, _ACC, 12)
