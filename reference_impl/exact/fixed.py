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
3. carries are propagated (``normalise``) until every digit but the top one is in
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

__all__ = ["BITS", "SCRATCH", "NO_ANSWER", "orient_fixed", "incircle_fixed", "orient_of_parts",
           "incircle_of_parts", "load_rows", "mul_add", "normalise", "digits_sign", "clear"]

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
def _split(b):
    """For the double with IEEE-754 bits b (an int64, see ``_bits``), v == m * 2**k exactly:
    returns (m, k, low, top) with m a signed integer of at most 53 bits and 2**low, 2**top the
    lowest and highest set bits of |v| (low = _NONE for zero; for infinity, low = -_NONE and
    top = _NONE, so that the caller's span check fails)."""
    ex = (b >> 52) & 0x7FF
    m = b & ((1 << 52) - 1)
    if ex == 0x7FF:                             # an overflowed difference (inputs near 1e308):
        return 0, 0, -_NONE, _NONE              # a span no call fits, so "no answer"
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
def mul_add(iw, a, la, b, lb, out, sgn):
    """iw[out + i + j] += sgn * iw[a + i] * iw[b + j] (i < la, j < lb): the coefficients of a
    product of two digit strings, added in place (the caller bounds their sums)."""
    for i in range(la):
        x = sgn * iw[a + i]
        if x != 0:
            for j in range(lb):
                iw[out + i + j] += x * iw[b + j]


@njit(cache=True, inline="always")
def normalise(iw, at, n):
    """Propagate carries through iw[at:at+n] so that all but the last digit are in
    [0, 2**BITS); the last takes the final carry (it must not overflow: callers size n)."""
    carry = 0
    for i in range(n - 1):
        v = iw[at + i] + carry
        iw[at + i] = v & _MASK
        carry = v >> BITS
    iw[at + n - 1] += carry


@njit(cache=True, inline="always")
def digits_sign(iw, at, n):
    """Sign of a normalised number iw[at:at+n] (see ``normalise``)."""
    top = iw[at + n - 1]
    if top != 0:
        return 1 if top > 0 else -1
    for i in range(n - 1):
        if iw[at + i] != 0:
            return 1
    return 0


@njit(cache=True, inline="always")
def clear(iw, at, n):
    """iw[at:at+n] = 0."""
    for i in range(n):
        iw[at + i] = 0


@njit(cache=True, inline="always")
def _fold(bh, bl, e, top):
    """(lowest, highest) set bit so far, updated with one exact difference hi + lo (bits)."""
    _, _, lo, tp = _split(bh)
    _, _, lw, _ = _split(bl)
    return min(e, lo, lw), max(top, tp)          # (|lo| is below |hi|)


@njit(cache=True, inline="always")
def _verdict(e, top):
    """After folding every difference: 0 when all are zero, ``NO_ANSWER`` when they do not fit
    60 bits at one scale, 1 when the digits can be written (``_put``)."""
    if e == _NONE:
        return 0
    return NO_ANSWER if top - e > _SPAN else 1


@njit(cache=True, inline="always")
def _put(bh, bl, e, iw, at):
    """iw[at:at+3] = the digits of the exact difference hi + lo (given as bits) at scale 2**e."""
    mh, kh, _, _ = _split(bh)
    ml, kl, _, _ = _split(bl)
    _digits(mh, kh, ml, kl, e, iw, at)


@njit(cache=True, inline="always")
def _load(parts, iw):
    """The 2D predicates' loader: the digits of each exact difference ``h + l`` of ``parts`` (a
    tuple of ``(h, l)`` pairs, as ``two_diff`` returns them) at ``iw[_DIG + 3 i]``.  Returns
    ``_verdict``'s answer (1: written).  (A tuple the compiler unrolls is faster here than
    ``load_rows``'s loop over an array: 155 vs 175 ns per tie.)"""
    e = _NONE
    top = -_NONE
    for h, l in parts:
        e, top = _fold(_bits(h), _bits(l), e, top)
    r = _verdict(e, top)
    if r == 1:
        at = _DIG
        for h, l in parts:
            _put(_bits(h), _bits(l), e, iw, at)
            at += 3
    return r


@njit(cache=True)
def load_rows(v, nrows, dim, iw, at, tmp):
    """The 3D stages' loader (``stages3d``): the digits of each exact difference
    ``v[dim r + c] - v[dim nrows + c]`` (point r < nrows minus the last point, coordinate
    c < dim) at ``iw[at + 3 (dim r + c)]``; ``iw[tmp:]`` holds the bits of the differences' hi
    and lo meanwhile (2 dim nrows slots).  Returns ``_verdict``'s answer (1: written)."""
    n = dim * nrows
    e = _NONE
    top = -_NONE
    for r in range(nrows):
        for c in range(dim):
            s = dim * r + c
            h, l = two_diff(v[s], v[n + c])
            iw[tmp + 2 * s] = _bits(h)
            iw[tmp + 2 * s + 1] = _bits(l)
            e, top = _fold(iw[tmp + 2 * s], iw[tmp + 2 * s + 1], e, top)
    r = _verdict(e, top)
    if r == 1:
        for s in range(n):
            _put(iw[tmp + 2 * s], iw[tmp + 2 * s + 1], e, iw, at + 3 * s)
    return r


@njit(cache=True)
def orient_of_parts(parts, iw):
    """``orient_fixed`` of the differences ``parts = (acx, acy, bcx, bcy)``, each an exact
    ``(hi, lo)`` pair (``predicates`` computes them for its earlier stages)."""
    r = _load(parts, iw)
    if r != 1:
        return r
    clear(iw, _P, 6)
    mul_add(iw, _DIG, 3, _DIG + 9, 3, _P, 1)     # acx * bcy
    mul_add(iw, _DIG + 3, 3, _DIG + 6, 3, _P, -1)    # - acy * bcx
    normalise(iw, _P, 6)
    return digits_sign(iw, _P, 6)


@njit(cache=True)
def incircle_of_parts(parts, iw):
    """``incircle_fixed`` of the differences ``parts = (adx, ady, bdx, bdy, cdx, cdy)`` (p - d
    for p = a, b, c), each an exact ``(hi, lo)`` pair."""
    r = _load(parts, iw)
    if r != 1:
        return r
    clear(iw, _ACC, 12)
    for r in range(3):
        i = 6 * r                                # point r: x digits at i, y digits at i + 3
        j = 6 * ((r + 1) % 3)
        k = 6 * ((r + 2) % 3)
        clear(iw, _LIFT, 6)
        mul_add(iw, i, 3, i, 3, _LIFT, 1)        # x^2 + y^2
        mul_add(iw, i + 3, 3, i + 3, 3, _LIFT, 1)
        normalise(iw, _LIFT, 6)
        clear(iw, _COF, 6)
        mul_add(iw, j, 3, k + 3, 3, _COF, 1)     # jx * ky - kx * jy
        mul_add(iw, k, 3, j + 3, 3, _COF, -1)
        normalise(iw, _COF, 6)
        mul_add(iw, _LIFT, 6, _COF, 6, _ACC, 1)  # acc += lift * cof: each coefficient gets at
                                                 # most 6 products below 2**42 from each term
    normalise(iw, _ACC, 12)
    return digits_sign(iw, _ACC, 12)


@njit(cache=True)
def orient_fixed(ax, ay, bx, by, cx, cy, iw):
    """Exact sign of orient2d(a, b, c), or ``NO_ANSWER`` when the differences do not fit."""
    return orient_of_parts((two_diff(ax, cx), two_diff(ay, cy), two_diff(bx, cx), two_diff(by, cy)), iw)


@njit(cache=True)
def incircle_fixed(ax, ay, bx, by, cx, cy, dx, dy, iw):
    """Exact sign of incircle(a, b, c, d), or ``NO_ANSWER`` when the differences do not fit."""
    return incircle_of_parts((two_diff(ax, dx), two_diff(ay, dy), two_diff(bx, dx), two_diff(by, dy),
                              two_diff(cx, dx), two_diff(cy, dy)), iw)
