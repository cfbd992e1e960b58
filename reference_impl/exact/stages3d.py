"""The exact stages of the 3D predicates (``predicates3d.py``), for calls the filter cannot decide.

Not meant to be used directly: ``orient3d_nb`` and ``insphere_nb`` in
``predicates3d`` call ``orient3d_exact_stage`` / ``insphere_exact_stage`` here when
their floating-point filter is inconclusive.  The stages, cheapest first:

(a) if all coordinate differences are exact and small multiples of one power
    of two (grids, integer data: |d| < 2**16 units for orient3d, 2**9 for
    insphere), the float formula has no rounding at all (every intermediate is
    an integer below 2**53 units) and decides;
(a') if the exact differences, as integers at one power-of-two scale, fit 60 bits
    (float grids: ``linspace``, 0.1 spacing), the determinant is computed in int64
    digits (``fixed.py``) and decides;
(-) if the call mixes magnitudes more than 2**250 (orient3d) or 2**140
    (insphere) apart, so that expansion components could underflow, Python
    integers decide (a numba ``objmode`` block; rare); otherwise every
    coordinate is scaled by one power of two (max in [0.5, 1)) and
(b) the determinant of the *rounded* differences is computed exactly with
    expansion arithmetic (``expansion.py``) and decides unless it lies within
    Shewchuk's second bound (``O3D_ERRBOUND_B``, ``ISP_ERRBOUND_B`` times the
    permanent) of zero;
(c) else that value plus the first-order effect of the rounding tails, in
    floating point, decides unless it is within ``*_ERRBOUND_C * permanent +
    RESULT_ERRBOUND * |stage b|`` of zero.  The bounds are derived as for
    Shewchuk's stage C: with |tail| <= e |difference|, the terms of order two
    and more in the tails are below 10.01 e^2 permanent (degree 5), the float
    evaluation of the first-order part errs by at most about 16 e * 5 e
    permanent; the constants taken, 128 e^2 (insphere) and 64 e^2 (orient3d),
    have a margin over both (Shewchuk's own are 71 e^2 and 26 e^2);
(d) else the exact determinant of the exact differences.

Expansions are compressed (Shewchuk's ``compress``) as they grow, so they stay a
few components long.  Workspace sizes still allow the uncompressed worst case.

The integer versions (``exact_coordinates_3d``, ``orient3d_exact``,
``insphere_exact``) live in ``verify.py`` (stdlib only, so judges' checkers can use
them without numba); they are also this module's Python fallback.

>>> w = np.empty(WORKSPACE3D_SIZE)
>>> orient3d_exact_stage(0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 2.0, 3.0, 0.0, w)
0
"""
from __future__ import annotations

import math

import numba
import numpy as np
from numba import njit

from reference_impl.exact.expansion import (EPSILON, accumulate, add, compress, diff, mul, negate,
                                            sign, sign_of, two_diff)
from reference_impl.exact.fixed import NO_ANSWER, clear, digits_sign, load_rows, mul_add, normalise
from reference_impl.exact.scaling import pow2_scale
from reference_impl.exact.verify import (exact_coordinates_3d, exact_sign, insphere_exact,  # noqa: F401 (re-exported)
                                         orient3d_exact)

O3D_ERRBOUND_B = (3.0 + 28.0 * EPSILON) * EPSILON
O3D_ERRBOUND_C = 64.0 * EPSILON * EPSILON
ISP_ERRBOUND_B = (5.0 + 72.0 * EPSILON) * EPSILON
ISP_ERRBOUND_C = 128.0 * EPSILON * EPSILON
RESULT_ERRBOUND = 4.0 * EPSILON

_O_EXACT_MIN, _I_EXACT_MIN = 2.0 ** -250, 2.0 ** -140
_C_PLO = 2.0 ** -900             # stage (c) only where no product can underflow

# workspace layout (offsets); sizes are worst-case expansion lengths with
# two-component differences: 2x2 minors 16, 3x3 minors 192, lifts 24,
# lift * minor 9216, sum of four such terms 36864.
_V = 0             # 15 scaled coordinates
_LEN = 16          # lengths: 12 differences, 6 2x2 minors at 12, 4 3x3 minors at 18, 4 lifts at 22
_I = 48            # 12 differences as small integers (stage 0)
_D = 64            # 12 differences, 2 slots each
_M2 = 88           # six 2x2 minors, 16 each
_M3 = 184          # four 3x3 minors, 192 each
_LIFT = 952        # four lifts, 24 each
_P1, _P2, _P3 = 1048, 1240, 1432     # 192 each: partial products
_Q = 1624          # 384: partial sum
_TERM = 2008       # 9216
_T1 = 11224        # 9216: mul scratch
_T2 = 20440        # 9216
_ACC = 29656       # 36864
_ACC2 = 66520      # 36864
_H, _TL = 103384, 103396             # 12 rounded differences and their 12 tails (stage c)
_FX, _FSIZE = 103408, 130          # the fixed-point stage, viewed as int64 (offsets below)
WORKSPACE3D_SIZE = _FX + _FSIZE
_FD, _FM2, _FM3, _FL, _FA = 0, 36, 72, 108, 114   # digits: 12 differences x 3, six 2x2 minors
#   x 6, four 3x3 minors x 9, a lift x 6, the sum x 16 (bounds: see _fixed_point)


# --------------------------------------------------------------------- floating-point formulas
@njit(cache=True)
def _minus(px, py, pz, qx, qy, qz):
    """p - q in floating point."""
    return px - qx, py - qy, pz - qz


@njit(cache=True)
def _minor(x1, y1, x2, y2):
    """x1*y2 - x2*y1 in floating point, and its permanent |x1*y2| + |x2*y1|."""
    p = x1 * y2
    q = x2 * y1
    return p - q, abs(p) + abs(q)


@njit(cache=True)
def _det3(adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz):
    """The 3x3 determinant of the rows a, b, c and its permanent, in floating point."""
    bc, bc_p = _minor(bdx, bdy, cdx, cdy)
    ca, ca_p = _minor(cdx, cdy, adx, ady)
    ab, ab_p = _minor(adx, ady, bdx, bdy)
    det = adz * bc + bdz * ca + cdz * ab
    perm = bc_p * abs(adz) + ca_p * abs(bdz) + ab_p * abs(cdz)
    return det, perm


@njit(cache=True)
def orient3d_det_perm(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz):
    """orient3d's determinant, its permanent and the largest |difference| (all in floating
    point), from the four points (pass d = 0 for differences already taken)."""
    adx, ady, adz = _minus(ax, ay, az, dx, dy, dz)
    bdx, bdy, bdz = _minus(bx, by, bz, dx, dy, dz)
    cdx, cdy, cdz = _minus(cx, cy, cz, dx, dy, dz)
    det, perm = _det3(adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz)
    dmax = max(abs(adx), abs(bdx), abs(cdx), abs(ady), abs(bdy), abs(cdy),
               abs(adz), abs(bdz), abs(cdz))
    return det, perm, dmax


@njit(cache=True)
def insphere_det_perm(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez):
    """insphere's determinant, its permanent and the largest |difference| (Shewchuk's
    formulas, in floating point) from the five points (e = 0 for differences already taken)."""
    aex, aey, aez = _minus(ax, ay, az, ex, ey, ez)
    bex, bey, bez = _minus(bx, by, bz, ex, ey, ez)
    cex, cey, cez = _minus(cx, cy, cz, ex, ey, ez)
    dex, dey, dez = _minus(dx, dy, dz, ex, ey, ez)
    ab, ab_p = _minor(aex, aey, bex, bey)
    bc, bc_p = _minor(bex, bey, cex, cey)
    cd, cd_p = _minor(cex, cey, dex, dey)
    da, da_p = _minor(dex, dey, aex, aey)
    ac, ac_p = _minor(aex, aey, cex, cey)
    bd, bd_p = _minor(bex, bey, dex, dey)
    abc = aez * bc - bez * ac + cez * ab
    bcd = bez * cd - cez * bd + dez * bc
    cda = cez * da + dez * ac + aez * cd
    dab = dez * ab + aez * bd + bez * da
    alift = aex * aex + aey * aey + aez * aez
    blift = bex * bex + bey * bey + bez * bez
    clift = cex * cex + cey * cey + cez * cez
    dlift = dex * dex + dey * dey + dez * dez
    det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd)
    az_, bz_, cz_, dz_ = abs(aez), abs(bez), abs(cez), abs(dez)
    perm = ((cd_p * bz_ + bd_p * cz_ + bc_p * dz_) * alift + (da_p * cz_ + ac_p * dz_ + cd_p * az_) * blift
            + (ab_p * dz_ + bd_p * az_ + da_p * bz_) * clift + (bc_p * az_ + ac_p * bz_ + ab_p * cz_) * dlift)
    dmax = max(abs(aex), abs(bex), abs(cex), abs(dex), abs(aey), abs(bey), abs(cey), abs(dey),
               abs(aez), abs(bez), abs(cez), abs(dez))
    return det, perm, dmax


# --------------------------------------------------------------------- exact stages
# After the filter: (0) if every difference is exact and all are small multiples of one power
# of two, the float formula is error-free (integers below 2**53); (B) otherwise the exact
# determinant of the *rounded* differences decides unless it is within Shewchuk's
# errboundB of zero; (C) the exact determinant of the exact differences.  Expansions are
# compressed as they go, so they stay a few components long.
@njit(cache=True)
def _diffs(w, nrows):
    """Differences of rows 0..nrows-1 minus the last row, exactly, into the workspace."""
    v = w[_V:_V + 15]
    last = 3 * nrows
    for r in range(nrows):
        for c in range(3):
            s = 3 * r + c
            w[_LEN + s] = diff(v[s], v[last + c], w[_D + 2 * s:_D + 2 * s + 2])


@njit(cache=True)
def _heads(w, n):
    """Save the rounded differences and their tails at w[_H:], w[_TL:], and make the rounded
    ones the working differences; True if any difference was inexact."""
    inexact = False
    for s in range(n):
        if w[_LEN + s] == 2.0:
            w[_TL + s] = w[_D + 2 * s]
            w[_D + 2 * s] = w[_D + 2 * s + 1]
            w[_LEN + s] = 1.0
            inexact = True
        else:
            w[_TL + s] = 0.0
        w[_H + s] = w[_D + 2 * s]
    return inexact


@njit(cache=True)
def _o3_first_order(h, t):
    """The part of orient3d's determinant linear in the tails t of the differences h."""
    adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz = h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7], h[8]
    tax, tay, taz, tbx, tby, tbz, tcx, tcy, tcz = t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8]
    return ((adz * ((bdx * tcy + tbx * cdy) - (cdx * tby + tcx * bdy))
             + taz * (bdx * cdy - cdx * bdy))
            + (bdz * ((cdx * tay + tcx * ady) - (adx * tcy + tax * cdy))
               + tbz * (cdx * ady - adx * cdy))
            + (cdz * ((adx * tby + tax * bdy) - (bdx * tay + tbx * ady))
               + tcz * (adx * bdy - bdx * ady)))


@njit(cache=True)
def _isp_first_order(h, t):
    """The part of insphere's determinant linear in the tails t of the differences h."""
    ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz = (h[0], h[1], h[2], h[3], h[4], h[5],
                                                      h[6], h[7], h[8], h[9], h[10], h[11])
    tax, tay, taz, tbx, tby, tbz, tcx, tcy, tcz, tdx, tdy, tdz = (t[0], t[1], t[2], t[3], t[4],
                                                                  t[5], t[6], t[7], t[8], t[9],
                                                                  t[10], t[11])
    ab = ax * by - bx * ay
    bc = bx * cy - cx * by
    cd = cx * dy - dx * cy
    da = dx * ay - ax * dy
    ac = ax * cy - cx * ay
    bd = bx * dy - dx * by
    eab = (ax * tby + tax * by) - (bx * tay + tbx * ay)
    ebc = (bx * tcy + tbx * cy) - (cx * tby + tcx * by)
    ecd = (cx * tdy + tcx * dy) - (dx * tcy + tdx * cy)
    eda = (dx * tay + tdx * ay) - (ax * tdy + tax * dy)
    eac = (ax * tcy + tax * cy) - (cx * tay + tcx * ay)
    ebd = (bx * tdy + tbx * dy) - (dx * tby + tdx * by)
    abc = az * bc - bz * ac + cz * ab
    bcd = bz * cd - cz * bd + dz * bc
    cda = cz * da + dz * ac + az * cd
    dab = dz * ab + az * bd + bz * da
    eabc = (az * ebc - bz * eac + cz * eab) + (taz * bc - tbz * ac + tcz * ab)
    ebcd = (bz * ecd - cz * ebd + dz * ebc) + (tbz * cd - tcz * bd + tdz * bc)
    ecda = (cz * eda + dz * eac + az * ecd) + (tcz * da + tdz * ac + taz * cd)
    edab = (dz * eab + az * ebd + bz * eda) + (tdz * ab + taz * bd + tbz * da)
    alift = ax * ax + ay * ay + az * az
    blift = bx * bx + by * by + bz * bz
    clift = cx * cx + cy * cy + cz * cz
    dlift = dx * dx + dy * dy + dz * dz
    ea = 2.0 * (ax * tax + ay * tay + az * taz)
    eb = 2.0 * (bx * tbx + by * tby + bz * tbz)
    ec = 2.0 * (cx * tcx + cy * tcy + cz * tcz)
    ed = 2.0 * (dx * tdx + dy * tdy + dz * tdz)
    return (((dlift * eabc + ed * abc) - (clift * edab + ec * dab))
            + ((blift * ecda + eb * cda) - (alift * ebcd + ea * bcd)))


@njit(cache=True)
def _small_ints(w, nrows, bits):
    """Stage (a): if the differences of rows 0..nrows-1 minus the last row (coordinates in
    w[_V:]) are exact and multiples of one power of two, each below 2**bits in units of
    it, store them in those units at w[_I:] and return True."""
    last = 3 * nrows
    m = 0.0
    for s in range(last):
        x, y = two_diff(w[_V + s], w[_V + last + s % 3])
        if y != 0.0:
            return False
        w[_I + s] = x
        m = max(m, abs(x))
    if m == 0.0:
        return True
    _, e = math.frexp(m)
    q = bits - e
    if q > 1000 or q < -1000:
        return False
    f = math.ldexp(1.0, q)
    for s in range(last):
        d = w[_I + s]
        t = d * f
        if t != math.floor(t) or (t == 0.0 and d != 0.0):
            return False
        w[_I + s] = t
    return True


# Minor tables (rows a=0, b=1, c=2, d=3 of the differences).  Indices come from these
# arrays rather than from literals in the code, so numba compiles one version of each
# helper instead of one per literal combination.
# 2x2 minors x_i*y_j - x_j*y_i: (i, j, slot); rows 0-5 for insphere, 6-8 for orient3d
_PAIRS = np.array([[0, 1, 0], [1, 2, 1], [2, 3, 2], [3, 0, 3], [0, 2, 4], [1, 3, 5],
                   [1, 2, 0], [2, 0, 1], [0, 1, 2]], dtype=np.int64)
# 3x3 minors sum of sign * z_row * minor2[slot]: three (row, slot, sign) triples
_TRIPLES = np.array([[0, 1, 1, 1, 4, -1, 2, 0, 1],    # abc = az*bc - bz*ac + cz*ab
                     [1, 2, 1, 2, 5, -1, 3, 1, 1],    # bcd = bz*cd - cz*bd + dz*bc
                     [2, 3, 1, 3, 4, 1, 0, 2, 1],     # cda = cz*da + dz*ac + az*cd
                     [3, 0, 1, 0, 5, 1, 1, 3, 1],     # dab = dz*ab + az*bd + bz*da
                     [0, 0, 1, 1, 1, 1, 2, 2, 1]],    # orient3d: az*bc + bz*ca + cz*ab
                    dtype=np.int64)


@njit(cache=True)
def _minor2(w, q):
    """The 2x2 minor of row q of _PAIRS into its slot at w[_M2:], compressed."""
    i, j, slot = _PAIRS[q, 0], _PAIRS[q, 1], _PAIRS[q, 2]
    ln = w[_LEN:_LEN + 18]
    xi = w[_D + 6 * i:_D + 6 * i + 2]
    yi = w[_D + 6 * i + 2:_D + 6 * i + 4]
    xj = w[_D + 6 * j:_D + 6 * j + 2]
    yj = w[_D + 6 * j + 2:_D + 6 * j + 4]
    p = w[_P1:_P1 + 8]
    r = w[_P2:_P2 + 8]
    t1 = w[_T1:_T1 + 8]
    t2 = w[_T2:_T2 + 8]
    out = w[_M2 + 16 * slot:_M2 + 16 * slot + 16]
    n1 = mul(xi, int(ln[3 * i]), yj, int(ln[3 * j + 1]), p, t1, t2)
    n2 = mul(xj, int(ln[3 * j]), yi, int(ln[3 * i + 1]), r, t1, t2)
    negate(r, n2)
    ln[12 + slot] = compress(out, add(p, n1, r, n2, out))


@njit(cache=True)
def _zm(w, row, slot, sgn, out):
    """out = sgn * z_row * minor2[slot]; returns the length."""
    z = w[_D + 6 * row + 4:_D + 6 * row + 6]
    nz = int(w[_LEN + 3 * row + 2])
    m = w[_M2 + 16 * slot:_M2 + 16 * slot + 16]
    nm = int(w[_LEN + 12 + slot])
    n = mul(m, nm, z, nz, out, w[_T1:_T1 + 64], w[_T2:_T2 + 64])
    if sgn < 0:
        negate(out, n)
    return n


@njit(cache=True)
def _minor3(w, r, out):
    """The 3x3 minor of row r of _TRIPLES into out, compressed; returns the length."""
    t = _TRIPLES[r]
    p1 = w[_P1:_P1 + 64]
    p2 = w[_P2:_P2 + 64]
    p3 = w[_P3:_P3 + 64]
    q = w[_Q:_Q + 128]
    n1 = _zm(w, t[0], t[1], t[2], p1)
    n2 = _zm(w, t[3], t[4], t[5], p2)
    n3 = _zm(w, t[6], t[7], t[8], p3)
    nq = add(p1, n1, p2, n2, q)
    return compress(out, add(q, nq, p3, n3, out))


@njit(cache=True)
def _sign_estimate(e, n):
    est = 0.0
    for i in range(n):
        est += e[i]
    return sign_of(e, n), est


@njit(cache=True)
def _orient_expansion(w):
    """orient3d's determinant, exactly, from the differences in the workspace."""
    for q in range(6, 9):
        _minor2(w, q)
    out = w[_M3:_M3 + 192]
    n = 0
    for r in range(4, 5):        # (a loop index: not a literal, see _PAIRS)
        n = _minor3(w, r, out)
    return _sign_estimate(out, n)


@njit(cache=True)
def _insphere_expansion(w):
    """insphere's determinant, exactly, from the differences in the workspace."""
    ln = w[_LEN:_LEN + 26]
    for q in range(6):           # 2x2 minors ab, bc, cd, da, ac, bd (x, y columns)
        _minor2(w, q)
    for r in range(4):           # 3x3 minors abc, bcd, cda, dab
        ln[18 + r] = _minor3(w, r, w[_M3 + 192 * r:_M3 + 192 * r + 192])
    # lifts |row|^2
    sq = w[_P1:_P1 + 8]
    s2 = w[_P2:_P2 + 24]
    for r in range(4):
        lift = w[_LIFT + 24 * r:_LIFT + 24 * r + 24]
        n = 0
        for c in range(3):
            x = w[_D + 6 * r + 2 * c:_D + 6 * r + 2 * c + 2]
            nx = int(ln[3 * r + c])
            nsq = mul(x, nx, x, nx, sq, w[_T1:_T1 + 8], w[_T2:_T2 + 8])
            if c == 0:
                for q in range(nsq):
                    lift[q] = sq[q]
                n = nsq
            else:
                for q in range(n):
                    s2[q] = lift[q]
                n = add(s2, n, sq, nsq, lift)
        ln[22 + r] = compress(lift, n)
    # det = dlift*abc - clift*dab + blift*cda - alift*bcd
    term = w[_TERM:_TERM + 9216]
    t1 = w[_T1:_T1 + 9216]
    t2 = w[_T2:_T2 + 9216]
    acc = w[_ACC:_ACC + 36864]
    acc2 = w[_ACC2:_ACC2 + 36864]
    nacc = 0
    for step in range(4):
        r = 3 - step
        m = w[_M3 + 192 * (0, 3, 2, 1)[step]:_M3 + 192 * (0, 3, 2, 1)[step] + 192]
        nm = int(ln[(18, 21, 20, 19)[step]])
        lift = w[_LIFT + 24 * r:_LIFT + 24 * r + 24]
        nt = compress(term, mul(m, nm, lift, int(ln[22 + r]), term, t1, t2))
        if step % 2 == 1:
            negate(term, nt)
        nacc = accumulate(acc, nacc, term, nt, acc2, True)
    return _sign_estimate(acc, nacc)


@njit(cache=True)
def _fixed_point(w, nrows):
    """Stage (a'): the determinant in fixed point (``fixed.py``) when the differences, as
    integers at one power-of-two scale, fit 60 bits (float grids: ``linspace``, 0.1 spacing);
    ``NO_ANSWER`` otherwise.  Same minors and signs as the expansions below: 2x2 minors
    (< 2**121, 6 digits), 3x3 minors (< 2**183, 9 digits), lifts (< 2**122, 6 digits), and
    for insphere dlift*abc - clift*dab + blift*cda - alift*bcd (< 2**307, 16 digits; each of
    its coefficients gets at most 24 products of two 21-bit digits)."""
    iw = w[_FX:_FX + _FSIZE].view(np.int64)
    r = load_rows(w[_V:_V + 3 * nrows + 3], nrows, 3, iw, _FD, _FM3)   # row i: x, y, z at 9i, +3, +6
    if r != 1:
        return r
    q0, nq = (0, 6) if nrows == 4 else (6, 3)
    for q in range(q0, q0 + nq):                 # x_i y_j - x_j y_i
        i, j, at = _PAIRS[q, 0], _PAIRS[q, 1], _FM2 + 6 * _PAIRS[q, 2]
        clear(iw, at, 6)
        mul_add(iw, _FD + 9 * i, 3, _FD + 9 * j + 3, 3, at, 1)
        mul_add(iw, _FD + 9 * j, 3, _FD + 9 * i + 3, 3, at, -1)
        normalise(iw, at, 6)
    t0, nm = (0, 4) if nrows == 4 else (4, 1)
    for m in range(nm):                          # sum of sign * z_row * minor2[slot]
        at = _FM3 + 9 * m
        clear(iw, at, 9)
        for u in range(3):
            row, slot, sg = _TRIPLES[t0 + m, 3 * u], _TRIPLES[t0 + m, 3 * u + 1], _TRIPLES[t0 + m, 3 * u + 2]
            mul_add(iw, _FD + 9 * row + 6, 3, _FM2 + 6 * slot, 6, at, sg)
        normalise(iw, at, 9)
    if nrows == 3:
        return digits_sign(iw, _FM3, 9)
    clear(iw, _FA, 16)
    for step in range(4):
        r = 3 - step
        clear(iw, _FL, 6)
        for c in range(3):                       # lift of row r
            mul_add(iw, _FD + 9 * r + 3 * c, 3, _FD + 9 * r + 3 * c, 3, _FL, 1)
        normalise(iw, _FL, 6)
        m = (0, 3, 2, 1)[step]
        mul_add(iw, _FL, 6, _FM3 + 9 * m, 9, _FA, 1 if step % 2 == 0 else -1)
    normalise(iw, _FA, 16)
    return digits_sign(iw, _FA, 16)


@njit(cache=True)
def _det_perm(t, nrows):
    """The float determinant and permanent of orient3d (nrows 3) or insphere (4) from the
    differences t."""
    if nrows == 3:
        det, perm, _ = orient3d_det_perm(t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8],
                                         0.0, 0.0, 0.0)
    else:
        det, perm, _ = insphere_det_perm(t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8],
                                         t[9], t[10], t[11], 0.0, 0.0, 0.0)
    return det, perm


@njit(cache=True)
def _exact_stages(w, nrows, bits, exact_min, bound_b, bound_c):
    """Stages (a)-(d) of the module docstring for orient3d (nrows 3) or insphere (nrows 4),
    the coordinates of the nrows + 1 points at w[_V:]."""
    n = 3 * nrows
    if _small_ints(w, nrows, bits):
        det, _ = _det_perm(w[_I:_I + n], nrows)
        return sign(det)
    s = _fixed_point(w, nrows)
    if s != NO_ANSWER:
        return s
    v = w[_V:_V + n + 3]
    if not pow2_scale(v, exact_min):        # magnitudes too far apart: Python integers
        with numba.objmode(s="int64"):
            s = exact_sign(v, 3)
        return s
    _diffs(w, nrows)
    if _heads(w, n):
        sgn, est = _orient_expansion(w) if nrows == 3 else _insphere_expansion(w)
        h = w[_H:_H + n]
        _, perm = _det_perm(h, nrows)
        if abs(est) >= bound_b * perm:
            return sgn
        t = w[_TL:_TL + n]
        det = est + (_o3_first_order(h, t) if nrows == 3 else _isp_first_order(h, t))
        if perm > _C_PLO and abs(det) > bound_c * perm + RESULT_ERRBOUND * abs(est):
            return 1 if det > 0.0 else -1
        _diffs(w, nrows)
    sgn, _ = _orient_expansion(w) if nrows == 3 else _insphere_expansion(w)
    return sgn


# _nrt=True: these slice and may box their workspace, so they keep numba's reference counting
# even when called from a kernel compiled without it (``mesh/kernel3d.build``; numba would
# otherwise inherit the caller's setting).
@njit(cache=True, _nrt=True)
def orient3d_exact_stage(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, w):
    """orient3d's sign by the exact stages (after an inconclusive filter)."""
    v = w[_V:_V + 12]
    v[0] = ax; v[1] = ay; v[2] = az; v[3] = bx; v[4] = by; v[5] = bz
    v[6] = cx; v[7] = cy; v[8] = cz; v[9] = dx; v[10] = dy; v[11] = dz
    return _exact_stages(w, 3, 16, _O_EXACT_MIN, O3D_ERRBOUND_B, O3D_ERRBOUND_C)


@njit(cache=True, _nrt=True)
def insphere_exact_stage(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez, w):
    """insphere's sign by the exact stages (after an inconclusive filter)."""
    v = w[_V:_V + 15]
    v[0] = ax; v[1] = ay; v[2] = az; v[3] = bx; v[4] = by; v[5] = bz
    v[6] = cx; v[7] = cy; v[8] = cz; v[9] = dx; v[10] = dy; v[11] = dz
    v[12] = ex; v[13] = ey; v[14] = ez
    return _exact_stages(w, 4, 9, _I_EXACT_MIN, ISP_ERRBOUND_B, ISP_ERRBOUND_C)
