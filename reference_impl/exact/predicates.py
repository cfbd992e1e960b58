"""Exact geometric predicates: orientation and in-circle tests for any finite doubles.

``orient2d(a, b, c)`` is +1 when a, b, c turn counter-clockwise, -1 clockwise,
0 when collinear.  ``incircle(a, b, c, d)`` is +1 when d lies strictly inside
the circle through a, b, c (given counter-clockwise), -1 outside, 0 on it.
The answers are *exact*: no epsilon, no scale dependence.

How (the adaptive scheme of Shewchuk, "Adaptive precision floating-point
arithmetic and fast robust geometric predicates", 1997):

1. A floating-point filter evaluates the determinant once and compares it with
   a proven error bound; almost every call ends here.  The bound assumes no
   underflow or overflow, so the filter only answers when the magnitudes are in
   a safe range (this is what makes 1e-300 and 1e300 inputs right).
2. If the coordinate differences are exact small integers (integer grids, where
   almost every test is a tie), the plain determinant is computed without any
   rounding, so its sign is exact: ties stay cheap.
3. If the differences, as integers at one power-of-two scale, fit 60 bits (float grids
   such as ``linspace`` or 0.1 spacing, rectangles at float positions: ties whose
   differences are not exact doubles), the sign is computed with int64 digits
   (``fixed.py``, about 0.1 us instead of 1-3 us).
4. Otherwise the determinant is recomputed exactly with expansion arithmetic
   (``expansion.py``) after scaling all coordinates by one power of two
   (``scaling.pow2_scale``, which does not change the sign).  When the input differences are exact the
   expansions stay one or two components long.
5. If the coordinates of one call span more than 2**150 in magnitude (so that
   expansion components could underflow), the sign is computed with Python
   integers instead (``verify.exact_sign`` in a numba ``objmode`` block).  This is the
   rare path.

``*_nb`` functions take a scratch array from ``workspace()`` and are meant for
numba-compiled callers; the plain functions accept pairs and are for Python.

>>> orient2d((0, 0), (1, 0), (0, 1))
1
>>> incircle((0, 0), (1, 0), (0, 1), (1, 1))   # cocircular
0
>>> orient2d((0.5, 0.5000000000000001), (12, 12), (24, 24))   # naive arithmetic says 0
1
"""
from __future__ import annotations

import math

import numba
import numpy as np
from numba import njit

from reference_impl.exact.expansion import (EPSILON, accumulate, add, certain_sign, compress, diff,
                                            mul, negate, scale, sign, sign_of, two_diff)
from reference_impl.exact.coldcall import cold
from reference_impl.exact.fixed import NO_ANSWER, SCRATCH, incircle_of_parts, orient_of_parts
from reference_impl.exact.scaling import pow2_scale
from reference_impl.exact.verify import exact_sign
from reference_impl.validate import as_xy

__all__ = ["orient2d", "incircle", "orient2d_nb", "incircle_nb", "workspace", "WORKSPACE_SIZE"]

CCW_ERRBOUND_A = (3.0 + 16.0 * EPSILON) * EPSILON
ICC_ERRBOUND_A = (10.0 + 96.0 * EPSILON) * EPSILON

# Filter safety ranges (see module docstring, step 1).
_O_LO, _O_HI = 2.0 ** -900, 2.0 ** 1000   # orient: |detleft| + |detright|
_I_DMAX = 2.0 ** 150                       # incircle: largest |difference|
_I_LO = 2.0 ** -600                        # incircle: permanent
_EXACT_MIN = 2.0 ** -150                   # exact stage: smallest scaled non-zero coordinate
_O_INT = 2.0 ** 25                         # integer stage bounds on |differences|
_I_INT = 2.0 ** 11

WORKSPACE_SIZE = 8192
# Layout of the incircle scratch (offsets into the workspace).  Sizes are the
# worst-case lengths: differences 2, squares and 2x2 products 8, lifts and
# cofactors 16, lift*cofactor 512, sums of those up to 1536.
_D = 0          # 12 slots: six 2-component differences
_S1, _S2 = 16, 32                   # 16 each
_LIFT, _COF = 64, 96                # 32 each
_T1, _T2 = 128, 640                 # 512 each: mul scratch
_TERM = 1152                        # 512
_ACC, _ACC2 = 1664, 3328            # 1536 each
_V = 4864                           # 8: scaled coordinates
_L = 4872                           # 6: lengths of the differences (stored as floats)
_SB = 4896                          # 448: the "exact differences" stage (_incircle_of_differences)
_B_LO, _B_HI = 2.0 ** -150, 2.0 ** 150   # its safe range for |differences| (_safe)
_FX = 5344                          # SCRATCH: the fixed-point stage (fixed.py), as int64


def workspace() -> np.ndarray:
    """A scratch array for the ``*_nb`` predicates (one per thread of work)."""
    return np.empty(WORKSPACE_SIZE, dtype=np.float64)


# --------------------------------------------------------------------- orient2d
@njit(cache=True)
def _small_integer(d, limit):
    """True when d is an integer with |d| < limit (then products of such stay exact)."""
    return abs(d) < limit and d == math.floor(d)


@njit(cache=True)
def _safe(d):
    """0, or a magnitude whose fourth power and its rounding errors stay normal doubles."""
    return d == 0.0 or _B_LO < abs(d) < _B_HI


@njit(cache=True)
def _cross(a, b, c, d, w, at):
    """w[at:at+4] = a*d - b*c exactly (two products, one expansion sum); returns the length."""
    w[at + 4] = a
    w[at + 5] = b
    n1 = scale(w[at + 4:at + 5], 1, d, w[at + 6:at + 8])
    n2 = scale(w[at + 5:at + 6], 1, -c, w[at + 8:at + 10])
    return add(w[at + 6:at + 6 + n1], n1, w[at + 8:at + 8 + n2], n2, w[at:at + 4])


@njit(cache=True)
def _lifted(x, y, cross, n, w, at):
    """w[at:at+32] = (x^2 + y^2) * cross exactly, as x*(x*cross) + y*(y*cross); the length."""
    nx = scale(cross, n, x, w[at + 32:at + 40])
    nxx = scale(w[at + 32:at + 32 + nx], nx, x, w[at + 40:at + 56])
    ny = scale(cross, n, y, w[at + 56:at + 64])
    nyy = scale(w[at + 56:at + 56 + ny], ny, y, w[at + 64:at + 80])
    return add(w[at + 40:at + 40 + nxx], nxx, w[at + 64:at + 64 + nyy], nyy, w[at:at + 32])


@njit(cache=True, _nrt=False)
def _incircle_of_differences(adx, ady, bdx, bdy, cdx, cdy, w):
    """Exact sign of the in-circle determinant of exact differences (all ``_safe``)."""
    b = _SB
    nbc = _cross(bdx, cdx, bdy, cdy, w, b)           # bdx*cdy - cdx*bdy
    nca = _cross(cdx, adx, cdy, ady, w, b + 16)      # cdx*ady - adx*cdy
    nab = _cross(adx, bdx, ady, bdy, w, b + 32)      # adx*bdy - bdx*ady
    na = _lifted(adx, ady, w[b:b + nbc], nbc, w, b + 48)
    nb = _lifted(bdx, bdy, w[b + 16:b + 16 + nca], nca, w, b + 128)
    nc = _lifted(cdx, cdy, w[b + 32:b + 32 + nab], nab, w, b + 208)
    nab2 = add(w[b + 48:b + 48 + na], na, w[b + 128:b + 128 + nb], nb, w[b + 288:b + 352])
    n = add(w[b + 288:b + 288 + nab2], nab2, w[b + 208:b + 208 + nc], nc, w[b + 352:b + 448])
    return sign_of(w[b + 352:b + 448], n)


# The exact stages slice their workspace and may box it for the Python fallback, so they keep
# numba's reference counting even when a caller is compiled without it (``mesh/kernel.build``):
# ``_nrt=True`` is set explicitly because numba otherwise inherits the caller's setting.
@njit(cache=True, _nrt=True)
def _orient_exact(ax, ay, bx, by, cx, cy, w):
    # Stage "grid line": three points on one vertical or one horizontal line (a grid's rows
    # and columns) are collinear, whatever their coordinates.
    if (ax == bx and bx == cx) or (ay == by and by == cy):
        return 0
    # Stage "integer": when the differences are exact small integers (integer grids), the
    # plain determinant has no rounding error at all (products < 2**52, sum < 2**53).
    acx, t1 = two_diff(ax, cx)
    bcy, t2 = two_diff(by, cy)
    acy, t3 = two_diff(ay, cy)
    bcx, t4 = two_diff(bx, cx)
    if (t1 == 0.0 and t2 == 0.0 and t3 == 0.0 and t4 == 0.0
            and _small_integer(acx, _O_INT) and _small_integer(bcy, _O_INT)
            and _small_integer(acy, _O_INT) and _small_integer(bcx, _O_INT)):
        return sign(acx * bcy - acy * bcx)
    s = orient_of_parts(((acx, t1), (acy, t3), (bcx, t4), (bcy, t2)), w[_FX:_FX + SCRATCH].view(np.int64))
    if s != NO_ANSWER:                     # stage "fixed point"
        return s
    v = w[_V:_V + 6]
    v[0] = ax; v[1] = ay; v[2] = bx; v[3] = by; v[4] = cx; v[5] = cy
    if not pow2_scale(v, _EXACT_MIN):      # magnitudes too far apart: Python integers
        with numba.objmode(s="int64"):
            s = exact_sign(v, 2)
        return s
    acx = w[0:2]; bcy = w[2:4]; acy = w[4:6]; bcx = w[6:8]
    n1 = diff(v[0], v[4], acx)
    n2 = diff(v[3], v[5], bcy)
    n3 = diff(v[1], v[5], acy)
    n4 = diff(v[2], v[4], bcx)
    p = w[16:32]; q = w[32:48]; t1 = w[48:64]; t2 = w[64:80]; h = w[80:112]
    np_ = mul(acx, n1, bcy, n2, p, t1, t2)
    nq = mul(acy, n3, bcx, n4, q, t1, t2)
    negate(q, nq)
    return sign_of(h, add(p, np_, q, nq, h))


_orient_exact_cold = cold(_orient_exact, 7)   # (coldcall.py: keeps the filter's path free of refcounting)


@njit(cache=True, inline="always")
def orient2d_nb(ax, ay, bx, by, cx, cy, w):
    """Exact orientation sign of (a, b, c); ``w`` is a ``workspace()`` array."""
    acx, acy = ax - cx, ay - cy
    bcx, bcy = bx - cx, by - cy
    detleft = acx * bcy
    detright = acy * bcx
    det = detleft - detright
    detsum = abs(detleft) + abs(detright)
    s = certain_sign(det, detsum, detsum, _O_HI, _O_LO, CCW_ERRBOUND_A, 0.0)
    if s != 0:
        return s
    return _orient_exact_cold(ax, ay, bx, by, cx, cy, w)


# --------------------------------------------------------------------- incircle
@njit(cache=True, inline="always")
def _two_values(a, b, c, d):
    """Whether a, b, c, d take at most two distinct values."""
    o = b if b != a else (c if c != a else d)
    return (b == a or b == o) and (c == a or c == o) and (d == a or d == o)


@njit(cache=True, _nrt=True)
def _incircle_exact(ax, ay, bx, by, cx, cy, dx, dy, w):
    # Stage "grid cell": four points with at most two x values and two y values are the
    # corners of an axis-parallel rectangle, which are cocircular, or two of them coincide;
    # either way the determinant is exactly 0.  (Every tie of a grid, in a few comparisons
    # whatever the coordinates: a linspace grid's ties otherwise need the fixed-point stage.)
    if _two_values(ax, bx, cx, dx) and _two_values(ay, by, cy, dy):
        return 0
    # Stage "integer" (see _orient_exact): |differences| < 2**12 keeps every term of the
    # determinant below 2**50 and the sum below 2**53, so the plain formula is exact.
    adx, t1 = two_diff(ax, dx)
    ady, t2 = two_diff(ay, dy)
    bdx, t3 = two_diff(bx, dx)
    bdy, t4 = two_diff(by, dy)
    cdx, t5 = two_diff(cx, dx)
    cdy, t6 = two_diff(cy, dy)
    exact = t1 == 0.0 and t2 == 0.0 and t3 == 0.0 and t4 == 0.0 and t5 == 0.0 and t6 == 0.0
    if exact:
        if (_small_integer(adx, _I_INT) and _small_integer(ady, _I_INT)
                and _small_integer(bdx, _I_INT) and _small_integer(bdy, _I_INT)
                and _small_integer(cdx, _I_INT) and _small_integer(cdy, _I_INT)):
            return sign((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
                        + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
                        + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))
    # Stage "fixed point" (fixed.py): the differences as integers at one power-of-two scale
    # (float grids, float rectangles; anything whose differences span at most ~60 bits)
    s = incircle_of_parts(((adx, t1), (ady, t2), (bdx, t3), (bdy, t4), (cdx, t5), (cdy, t6)),
                          w[_FX:_FX + SCRATCH].view(np.int64))
    if s != NO_ANSWER:
        return s
    if exact:
        # Stage "exact differences" (Shewchuk's stage B when its tails are zero): the
        # determinant of the six exact differences, with expansions no longer than 96.
        if (_safe(adx) and _safe(ady) and _safe(bdx) and _safe(bdy) and _safe(cdx)
                and _safe(cdy)):
            return _incircle_of_differences(adx, ady, bdx, bdy, cdx, cdy, w)
    v = w[_V:_V + 8]
    v[0] = ax; v[1] = ay; v[2] = bx; v[3] = by; v[4] = cx; v[5] = cy; v[6] = dx; v[7] = dy
    if not pow2_scale(v, _EXACT_MIN):
        with numba.objmode(s="int64"):
            s = exact_sign(v, 2)
        return s
    # differences p - d for p = a, b, c; slot j holds x (j even) or y (j odd) of point j // 2
    dlen = w[_L:_L + 6]
    for j in range(6):
        dlen[j] = diff(v[j], v[6 + (j % 2)], w[_D + 2 * j:_D + 2 * j + 2])
    t1 = w[_T1:_T1 + 512]
    t2 = w[_T2:_T2 + 512]
    s1 = w[_S1:_S1 + 16]; s2 = w[_S2:_S2 + 16]
    lift = w[_LIFT:_LIFT + 32]; cof = w[_COF:_COF + 32]
    term = w[_TERM:_TERM + 512]
    acc = w[_ACC:_ACC + 1536]
    acc2 = w[_ACC2:_ACC2 + 1536]
    nacc = 0
    for r in range(3):
        i = r
        j = (r + 1) % 3
        kk = (r + 2) % 3
        ix = w[_D + 4 * i:_D + 4 * i + 2]; nix = int(dlen[2 * i])
        iy = w[_D + 4 * i + 2:_D + 4 * i + 4]; niy = int(dlen[2 * i + 1])
        jx = w[_D + 4 * j:_D + 4 * j + 2]; njx = int(dlen[2 * j])
        jy = w[_D + 4 * j + 2:_D + 4 * j + 4]; njy = int(dlen[2 * j + 1])
        kx = w[_D + 4 * kk:_D + 4 * kk + 2]; nkx = int(dlen[2 * kk])
        ky = w[_D + 4 * kk + 2:_D + 4 * kk + 4]; nky = int(dlen[2 * kk + 1])
        # lift = ix^2 + iy^2
        n1 = mul(ix, nix, ix, nix, s1, t1, t2)
        n2 = mul(iy, niy, iy, niy, s2, t1, t2)
        nl = add(s1, n1, s2, n2, lift)
        # cofactor = jx*ky - kx*jy
        n1 = mul(jx, njx, ky, nky, s1, t1, t2)
        n2 = mul(kx, nkx, jy, njy, s2, t1, t2)
        negate(s2, n2)
        nc = add(s1, n1, s2, n2, cof)
        # compressed first, the factors are a few components long (their values need about
        # 110 bits), so the product costs a handful of two-products instead of up to 16 x 16
        nl = compress(lift, nl)
        nc = compress(cof, nc)
        nt = mul(lift, nl, cof, nc, term, t1, t2)
        nacc = accumulate(acc, nacc, term, nt, acc2, True)
    return sign_of(acc, nacc)


_incircle_exact_cold = cold(_incircle_exact, 9)


@njit(cache=True, inline="always")
def incircle_nb(ax, ay, bx, by, cx, cy, dx, dy, w):
    """Exact sign of d relative to the circle through CCW a, b, c (+1 inside)."""
    adx, ady = ax - dx, ay - dy
    bdx, bdy = bx - dx, by - dy
    cdx, cdy = cx - dx, cy - dy
    bdxcdy = bdx * cdy
    cdxbdy = cdx * bdy
    alift = adx * adx + ady * ady
    cdxady = cdx * ady
    adxcdy = adx * cdy
    blift = bdx * bdx + bdy * bdy
    adxbdy = adx * bdy
    bdxady = bdx * ady
    clift = cdx * cdx + cdy * cdy
    det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady)
    permanent = ((abs(bdxcdy) + abs(cdxbdy)) * alift + (abs(cdxady) + abs(adxcdy)) * blift
                 + (abs(adxbdy) + abs(bdxady)) * clift)
    dmax = max(abs(adx), abs(ady), abs(bdx), abs(bdy), abs(cdx), abs(cdy))
    s = certain_sign(det, permanent, dmax, _I_DMAX, _I_LO, ICC_ERRBOUND_A, 0.0)
    if s != 0:
        return s
    return _incircle_exact_cold(ax, ay, bx, by, cx, cy, dx, dy, w)


# --------------------------------------------------------------------- python API
_PY_WORK = workspace()


def orient2d(a, b, c) -> int:
    """Exact orientation: +1 if a, b, c turn counter-clockwise, -1 clockwise, 0 collinear.

    >>> orient2d((0, 0), (2, 0), (1, 0))
    0
    """
    return int(orient2d_nb(*as_xy(a, "a"), *as_xy(b, "b"), *as_xy(c, "c"), _PY_WORK))


def incircle(a, b, c, d) -> int:
    """Exact in-circle test: +1 if d is strictly inside the circle through a, b, c.

    a, b, c must be counter-clockwise for the sign to mean inside (for a clockwise
    triangle the sign flips; for collinear a, b, c it is the side of the line).

    >>> incircle((0, 0), (2, 0), (0, 2), (1, 1))
    1
    """
    return int(incircle_nb(*as_xy(a, "a"), *as_xy(b, "b"), *as_xy(c, "c"), *as_xy(d, "d"),
                           _PY_WORK))
