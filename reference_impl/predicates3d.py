"""Exact 3D predicates: ``orient3d`` and ``insphere`` for any finite doubles.

Sign conventions (Shewchuk's, so that his papers and code read the same):

* ``orient3d(a, b, c, d)`` is the sign of the determinant of the rows
  ``a - d``, ``b - d``, ``c - d``.  It is **+1 when d lies below the plane
  through a, b, c**, where "above" is the side from which a, b, c appear
  counter-clockwise; -1 above; 0 when the four points are coplanar.  Put
  differently: +1 when a, b, c appear *clockwise* seen from d.  Example: a, b, c
  counter-clockwise in the plane z = 0 seen from +z, d with z < 0 gives +1.
  (This is minus the right-handed volume sign det(b - a, c - a, d - a).)
  A tetrahedron (a, b, c, d) is *positively oriented* when orient3d > 0; then
  each face, listed as in ``FACES`` below, is counter-clockwise seen from outside.
* ``insphere(a, b, c, d, e)`` is **+1 when e lies strictly inside the sphere
  through a, b, c, d**, -1 outside, 0 on it, provided orient3d(a, b, c, d) > 0.
  For a negatively oriented tetrahedron the sign flips; for coplanar a, b, c, d
  the value is the sign of a degenerate determinant (e's side of the plane, or
  0 when e is coplanar too).

The answers are exact for every finite double input, by the same three stages
as the 2D predicates (``predicates.py``):

1. a floating-point filter with Shewchuk's error bounds
   (``O3D_ERRBOUND_A = (7 + 56e)e``, ``ISP_ERRBOUND_A = (16 + 224e)e``, e = 2**-53),
   used only when the coordinate differences are below 2**200 (orient3d) or
   2**150 (insphere), so nothing can overflow, and the permanent is above
   2**-600 (2**-450), with an extra absolute term of 2**-850 (2**-600) in the
   bound that covers every rounding error an underflowing product can add;
2. otherwise the exact determinant with expansion arithmetic (``expansion.py``)
   after scaling every coordinate of the call by one power of two; differences
   that are exact (grids, nearby floats) keep the expansions one component long,
   so ties stay cheap;
3. if a call mixes magnitudes more than 2**250 (orient3d) or 2**140 (insphere)
   apart, so that expansion components could underflow, Python integers decide
   (a numba ``objmode`` block; rare).

``*_nb`` functions are for numba-compiled callers and take a scratch array
from ``workspace3d()``; ``orient3d``/``insphere`` take points; the ``*_batch``
functions take (k, 3) arrays.  ``exact_coordinates_3d``, ``orient3d_exact`` and
``insphere_exact`` are the plain integer versions (for checkers).

>>> orient3d((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1))
1
>>> insphere((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1), (0.1, 0.1, -0.1))
1
>>> insphere((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1), (1, 1, -1))   # a cube corner: cospherical
0
"""
from __future__ import annotations

import math
from typing import Iterable, Sequence

import numba
import numpy as np
from numba import njit

from .expansion import EPSILON, add, diff, mul, negate
from .points import as_points

__all__ = ["orient3d", "insphere", "orient3d_batch", "insphere_batch", "orient3d_nb",
           "insphere_nb", "workspace3d", "exact_coordinates_3d", "orient3d_exact",
           "insphere_exact", "FACES", "O3D_ERRBOUND_A", "ISP_ERRBOUND_A"]

O3D_ERRBOUND_A = (7.0 + 56.0 * EPSILON) * EPSILON
ISP_ERRBOUND_A = (16.0 + 224.0 * EPSILON) * EPSILON

#: FACES[k] lists the face opposite vertex k of a positively oriented tetrahedron
#: (v0, v1, v2, v3) so that it is counter-clockwise seen from outside: (face, v_k)
#: is an even permutation of (v0, v1, v2, v3).
FACES = ((1, 3, 2), (0, 2, 3), (0, 3, 1), (0, 1, 2))

# filter safety ranges (module docstring, stage 1)
_O_DMAX, _O_PLO, _O_ABS = 2.0 ** 200, 2.0 ** -600, 2.0 ** -850
_I_DMAX, _I_PLO, _I_ABS = 2.0 ** 150, 2.0 ** -450, 2.0 ** -600
# exact stage: smallest non-zero coordinate after scaling the largest into [0.5, 1).
# Degree-k products of multiples of 2**-(L+52) stay multiples of 2**-(k(L+52)) >= 2**-1074.
_O_EXACT_MIN, _I_EXACT_MIN = 2.0 ** -250, 2.0 ** -140

# workspace layout (offsets); sizes are worst-case expansion lengths with
# two-component differences: 2x2 minors 16, 3x3 minors 192, lifts 24,
# lift * minor 9216, sum of four such terms 36864.
_V = 0             # 15 scaled coordinates
_LEN = 16          # 12 lengths of differences, 6 of 2x2 minors, 4 of 3x3 minors, 4 of lifts
_D = 48            # 12 differences, 2 slots each
_M2 = 72           # six 2x2 minors, 16 each
_M3 = 168          # four 3x3 minors, 192 each
_LIFT = 936        # four lifts, 24 each
_P1, _P2, _P3 = 1032, 1224, 1416     # 192 each: partial products
_Q = 1608          # 384: partial sum
_TERM = 1992       # 9216
_T1 = 11208        # 9216: mul scratch
_T2 = 20424        # 9216
_ACC = 29640       # 36864
_ACC2 = 66504      # 36864
WORKSPACE3D_SIZE = 103368


def workspace3d() -> np.ndarray:
    """A scratch array for ``orient3d_nb`` / ``insphere_nb`` (one per thread of work).

    >>> workspace3d().shape
    (103368,)
    """
    return np.empty(WORKSPACE3D_SIZE, dtype=np.float64)


# --------------------------------------------------------------------- exact integer versions
def exact_coordinates_3d(points: Iterable[Sequence[float]]) -> list[tuple[int, int, int]]:
    """The points as integer triples, all scaled by one common power of two.

    Orientation and in-sphere signs are invariant under a common positive scaling,
    so the integer versions give the exact answers for the doubles.

    >>> exact_coordinates_3d([(0.5, 1.0, 2.0), (0.25, -2.0, 0.0)])
    [(2, 4, 8), (1, -8, 0)]
    """
    ratios = []
    for p in points:
        q = [float(v) for v in p]
        if len(q) != 3 or not all(math.isfinite(v) for v in q):
            raise ValueError(f"point {tuple(p)!r} is not three finite numbers")
        ratios.append([v.as_integer_ratio() for v in q])
    den = 1
    for r in ratios:
        for _, d in r:
            den = max(den, d)   # denominators are powers of two: the max is a common multiple
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def _det3(a, b, c) -> int:
    return (a[2] * (b[0] * c[1] - c[0] * b[1]) + b[2] * (c[0] * a[1] - a[0] * c[1])
            + c[2] * (a[0] * b[1] - b[0] * a[1]))


def orient3d_exact(a, b, c, d) -> int:
    """orient3d on integer (or Fraction) coordinates: sign of det(a - d, b - d, c - d).

    >>> orient3d_exact((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1))
    1
    """
    r = [tuple(p[i] - d[i] for i in range(3)) for p in (a, b, c)]
    v = _det3(*r)
    return (v > 0) - (v < 0)


def insphere_exact(a, b, c, d, e) -> int:
    """insphere on integer (or Fraction) coordinates (+1: e inside, for orient3d(a,b,c,d) > 0).

    >>> insphere_exact((0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, -2), (1, 1, -1))
    1
    """
    r = [tuple(p[i] - e[i] for i in range(3)) for p in (a, b, c, d)]
    lift = [x * x + y * y + z * z for x, y, z in r]
    ra, rb, rc, rd = r
    v = (lift[3] * _det3(ra, rb, rc) - lift[2] * _det3(rd, ra, rb)
         + lift[1] * _det3(rc, rd, ra) - lift[0] * _det3(rb, rc, rd))
    return (v > 0) - (v < 0)


def _orient_python(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz) -> int:
    return orient3d_exact(*exact_coordinates_3d([(ax, ay, az), (bx, by, bz), (cx, cy, cz),
                                                 (dx, dy, dz)]))


def _insphere_python(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez) -> int:
    return insphere_exact(*exact_coordinates_3d([(ax, ay, az), (bx, by, bz), (cx, cy, cz),
                                                 (dx, dy, dz), (ex, ey, ez)]))


# --------------------------------------------------------------------- exact expansion stage
@njit(cache=True)
def _scale3(v, lo_scaled):
    """k with max|v| * 2**k in [0.5, 1); False if a non-zero |v| * 2**k < lo_scaled."""
    m = 0.0
    for x in v:
        m = max(m, abs(x))
    if m == 0.0:
        return 0, True
    _, e = math.frexp(m)
    lo = math.ldexp(lo_scaled, e)   # the threshold in unscaled units
    for x in v:
        if x != 0.0 and abs(x) < lo:
            return -e, False
    for i in range(v.shape[0]):
        v[i] = math.ldexp(v[i], -e)
    return -e, True


@njit(cache=True)
def _minor2(w, i, j, out):
    """out = x_i * y_j - x_j * y_i from the differences of rows i and j; returns the length."""
    ln = w[_LEN:_LEN + 12]
    xi = w[_D + 6 * i:_D + 6 * i + 2]
    yi = w[_D + 6 * i + 2:_D + 6 * i + 4]
    xj = w[_D + 6 * j:_D + 6 * j + 2]
    yj = w[_D + 6 * j + 2:_D + 6 * j + 4]
    p = w[_P1:_P1 + 8]
    q = w[_P2:_P2 + 8]
    t1 = w[_T1:_T1 + 8]
    t2 = w[_T2:_T2 + 8]
    n1 = mul(xi, int(ln[3 * i]), yj, int(ln[3 * j + 1]), p, t1, t2)
    n2 = mul(xj, int(ln[3 * j]), yi, int(ln[3 * i + 1]), q, t1, t2)
    negate(q, n2)
    return add(p, n1, q, n2, out)


@njit(cache=True)
def _zm(w, row, m, nm, sgn, out):
    """out = sgn * z_row * m for an expansion m (at most 16 long); returns the length."""
    z = w[_D + 6 * row + 4:_D + 6 * row + 6]
    nz = int(w[_LEN + 3 * row + 2])
    n = mul(m, nm, z, nz, out, w[_T1:_T1 + 64], w[_T2:_T2 + 64])
    if sgn < 0:
        negate(out, n)
    return n


@njit(cache=True)
def _minor3(w, i, mi, ni, si, j, mj, nj, sj, k, mk, nk, sk, out):
    """out = z_i*(si*mi) + z_j*(sj*mj) + z_k*(sk*mk): a 3x3 minor; returns the length."""
    p1 = w[_P1:_P1 + 64]
    p2 = w[_P2:_P2 + 64]
    p3 = w[_P3:_P3 + 64]
    q = w[_Q:_Q + 128]
    n1 = _zm(w, i, mi, ni, si, p1)
    n2 = _zm(w, j, mj, nj, sj, p2)
    n3 = _zm(w, k, mk, nk, sk, p3)
    nq = add(p1, n1, p2, n2, q)
    return add(q, nq, p3, n3, out)


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
def _orient3d_exact(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, w):
    v = w[_V:_V + 12]
    v[0] = ax; v[1] = ay; v[2] = az; v[3] = bx; v[4] = by; v[5] = bz
    v[6] = cx; v[7] = cy; v[8] = cz; v[9] = dx; v[10] = dy; v[11] = dz
    _, ok = _scale3(v, _O_EXACT_MIN)
    if not ok:
        with numba.objmode(s="int64"):
            s = _orient_python(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz)
        return s
    _diffs(w, 3)
    m_bc = w[_M2:_M2 + 16]
    m_ca = w[_M2 + 16:_M2 + 32]
    m_ab = w[_M2 + 32:_M2 + 48]
    n_bc = _minor2(w, 1, 2, m_bc)
    n_ca = _minor2(w, 2, 0, m_ca)
    n_ab = _minor2(w, 0, 1, m_ab)
    out = w[_M3:_M3 + 192]
    n = _minor3(w, 0, m_bc, n_bc, 1, 1, m_ca, n_ca, 1, 2, m_ab, n_ab, 1, out)
    top = out[n - 1]
    return 1 if top > 0.0 else (-1 if top < 0.0 else 0)


@njit(cache=True)
def orient3d_nb(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, w):
    """Exact orient3d sign (see the module docstring); ``w`` is a ``workspace3d()`` array."""
    adx = ax - dx
    bdx = bx - dx
    cdx = cx - dx
    ady = ay - dy
    bdy = by - dy
    cdy = cy - dy
    adz = az - dz
    bdz = bz - dz
    cdz = cz - dz
    bdxcdy = bdx * cdy
    cdxbdy = cdx * bdy
    cdxady = cdx * ady
    adxcdy = adx * cdy
    adxbdy = adx * bdy
    bdxady = bdx * ady
    det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady)
    permanent = ((abs(bdxcdy) + abs(cdxbdy)) * abs(adz) + (abs(cdxady) + abs(adxcdy)) * abs(bdz)
                 + (abs(adxbdy) + abs(bdxady)) * abs(cdz))
    dmax = max(abs(adx), abs(bdx), abs(cdx), abs(ady), abs(bdy), abs(cdy),
               abs(adz), abs(bdz), abs(cdz))
    if dmax < _O_DMAX and permanent > _O_PLO:
        errbound = O3D_ERRBOUND_A * permanent + _O_ABS
        if det > errbound:
            return 1
        if -det > errbound:
            return -1
    return _orient3d_exact(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, w)


@njit(cache=True)
def _insphere_exact(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez, w):
    v = w[_V:_V + 15]
    v[0] = ax; v[1] = ay; v[2] = az; v[3] = bx; v[4] = by; v[5] = bz
    v[6] = cx; v[7] = cy; v[8] = cz; v[9] = dx; v[10] = dy; v[11] = dz
    v[12] = ex; v[13] = ey; v[14] = ez
    _, ok = _scale3(v, _I_EXACT_MIN)
    if not ok:
        with numba.objmode(s="int64"):
            s = _insphere_python(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez)
        return s
    _diffs(w, 4)
    ln = w[_LEN:_LEN + 26]
    # 2x2 minors (x, y columns) of the rows a=0, b=1, c=2, d=3
    ab = w[_M2:_M2 + 16]
    bc = w[_M2 + 16:_M2 + 32]
    cd = w[_M2 + 32:_M2 + 48]
    da = w[_M2 + 48:_M2 + 64]
    ac = w[_M2 + 64:_M2 + 80]
    bd = w[_M2 + 80:_M2 + 96]
    nab = _minor2(w, 0, 1, ab)
    nbc = _minor2(w, 1, 2, bc)
    ncd = _minor2(w, 2, 3, cd)
    nda = _minor2(w, 3, 0, da)
    nac = _minor2(w, 0, 2, ac)
    nbd = _minor2(w, 1, 3, bd)
    # 3x3 minors: abc = az*bc - bz*ac + cz*ab, bcd = bz*cd - cz*bd + dz*bc,
    #             cda = cz*da + dz*ac + az*cd, dab = dz*ab + az*bd + bz*da
    m_abc = w[_M3:_M3 + 192]
    m_bcd = w[_M3 + 192:_M3 + 384]
    m_cda = w[_M3 + 384:_M3 + 576]
    m_dab = w[_M3 + 576:_M3 + 768]
    ln[18] = _minor3(w, 0, bc, nbc, 1, 1, ac, nac, -1, 2, ab, nab, 1, m_abc)
    ln[19] = _minor3(w, 1, cd, ncd, 1, 2, bd, nbd, -1, 3, bc, nbc, 1, m_bcd)
    ln[20] = _minor3(w, 2, da, nda, 1, 3, ac, nac, 1, 0, cd, ncd, 1, m_cda)
    ln[21] = _minor3(w, 3, ab, nab, 1, 0, bd, nbd, 1, 1, da, nda, 1, m_dab)
    # lifts |row|^2
    sq = w[_P1:_P1 + 8]
    s2 = w[_P2:_P2 + 16]
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
        ln[22 + r] = n
    # det = dlift*abc - clift*dab + blift*cda - alift*bcd
    term = w[_TERM:_TERM + 9216]
    t1 = w[_T1:_T1 + 9216]
    t2 = w[_T2:_T2 + 9216]
    acc = w[_ACC:_ACC + 36864]
    acc2 = w[_ACC2:_ACC2 + 36864]
    nacc = 0
    for step in range(4):
        if step == 0:
            r, m, sgn = 3, m_abc, 1
            nm = int(ln[18])
        elif step == 1:
            r, m, sgn = 2, m_dab, -1
            nm = int(ln[21])
        elif step == 2:
            r, m, sgn = 1, m_cda, 1
            nm = int(ln[20])
        else:
            r, m, sgn = 0, m_bcd, -1
            nm = int(ln[19])
        lift = w[_LIFT + 24 * r:_LIFT + 24 * r + 24]
        nt = mul(m, nm, lift, int(ln[22 + r]), term, t1, t2)
        if sgn < 0:
            negate(term, nt)
        if nacc == 0:
            for q in range(nt):
                acc[q] = term[q]
            nacc = nt
        else:
            k = add(acc, nacc, term, nt, acc2)
            for q in range(k):
                acc[q] = acc2[q]
            nacc = k
    top = acc[nacc - 1]
    return 1 if top > 0.0 else (-1 if top < 0.0 else 0)


@njit(cache=True)
def insphere_nb(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez, w):
    """Exact insphere sign (see the module docstring); ``w`` is a ``workspace3d()`` array."""
    aex = ax - ex
    bex = bx - ex
    cex = cx - ex
    dex = dx - ex
    aey = ay - ey
    bey = by - ey
    cey = cy - ey
    dey = dy - ey
    aez = az - ez
    bez = bz - ez
    cez = cz - ez
    dez = dz - ez
    aexbey = aex * bey
    bexaey = bex * aey
    ab = aexbey - bexaey
    bexcey = bex * cey
    cexbey = cex * bey
    bc = bexcey - cexbey
    cexdey = cex * dey
    dexcey = dex * cey
    cd = cexdey - dexcey
    dexaey = dex * aey
    aexdey = aex * dey
    da = dexaey - aexdey
    aexcey = aex * cey
    cexaey = cex * aey
    ac = aexcey - cexaey
    bexdey = bex * dey
    dexbey = dex * bey
    bd = bexdey - dexbey
    abc = aez * bc - bez * ac + cez * ab
    bcd = bez * cd - cez * bd + dez * bc
    cda = cez * da + dez * ac + aez * cd
    dab = dez * ab + aez * bd + bez * da
    alift = aex * aex + aey * aey + aez * aez
    blift = bex * bex + bey * bey + bez * bez
    clift = cex * cex + cey * cey + cez * cez
    dlift = dex * dex + dey * dey + dez * dez
    det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd)
    aezp = abs(aez)
    bezp = abs(bez)
    cezp = abs(cez)
    dezp = abs(dez)
    ab_p = abs(aexbey) + abs(bexaey)
    bc_p = abs(bexcey) + abs(cexbey)
    cd_p = abs(cexdey) + abs(dexcey)
    da_p = abs(dexaey) + abs(aexdey)
    ac_p = abs(aexcey) + abs(cexaey)
    bd_p = abs(bexdey) + abs(dexbey)
    permanent = ((cd_p * bezp + bd_p * cezp + bc_p * dezp) * alift
                 + (da_p * cezp + ac_p * dezp + cd_p * aezp) * blift
                 + (ab_p * dezp + bd_p * aezp + da_p * bezp) * clift
                 + (bc_p * aezp + ac_p * bezp + ab_p * cezp) * dlift)
    dmax = max(abs(aex), abs(bex), abs(cex), abs(dex), abs(aey), abs(bey), abs(cey), abs(dey),
               aezp, bezp, cezp, dezp)
    if dmax < _I_DMAX and permanent > _I_PLO:
        errbound = ISP_ERRBOUND_A * permanent + _I_ABS
        if det > errbound:
            return 1
        if -det > errbound:
            return -1
    return _insphere_exact(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez, w)


# --------------------------------------------------------------------- batch and python API
@njit(cache=True)
def _orient3d_many(a, b, c, d, w):
    out = np.empty(a.shape[0], dtype=np.int8)
    for i in range(a.shape[0]):
        out[i] = orient3d_nb(a[i, 0], a[i, 1], a[i, 2], b[i, 0], b[i, 1], b[i, 2],
                             c[i, 0], c[i, 1], c[i, 2], d[i, 0], d[i, 1], d[i, 2], w)
    return out


@njit(cache=True)
def _insphere_many(a, b, c, d, e, w):
    out = np.empty(a.shape[0], dtype=np.int8)
    for i in range(a.shape[0]):
        out[i] = insphere_nb(a[i, 0], a[i, 1], a[i, 2], b[i, 0], b[i, 1], b[i, 2],
                             c[i, 0], c[i, 1], c[i, 2], d[i, 0], d[i, 1], d[i, 2],
                             e[i, 0], e[i, 1], e[i, 2], w)
    return out


_PY_WORK = workspace3d()


def _rows(arrays, names) -> list[np.ndarray]:
    out = [as_points(np.atleast_2d(x) if np.ndim(x) == 1 else x, name=nm, dim=3)
           for x, nm in zip(arrays, names)]
    k = len(out[0])
    for x, nm in zip(out, names):
        if len(x) != k:
            raise ValueError(f"{nm} has {len(x)} points but {names[0]} has {k}")
    return out


def orient3d_batch(a, b, c, d) -> np.ndarray:
    """orient3d row by row for (k, 3) arrays; returns an int8 array of signs.

    >>> orient3d_batch([[0, 0, 0]], [[1, 0, 0]], [[0, 1, 0]], [[0, 0, 1]]).tolist()
    [-1]
    """
    return _orient3d_many(*_rows((a, b, c, d), ("a", "b", "c", "d")), _PY_WORK)


def insphere_batch(a, b, c, d, e) -> np.ndarray:
    """insphere row by row for (k, 3) arrays; returns an int8 array of signs.

    >>> insphere_batch([[0, 0, 0]], [[1, 0, 0]], [[0, 1, 0]], [[0, 0, -1]], [[5, 5, 5]]).tolist()
    [-1]
    """
    return _insphere_many(*_rows((a, b, c, d, e), ("a", "b", "c", "d", "e")), _PY_WORK)


def _xyz(p, name) -> tuple[float, float, float]:
    if isinstance(p, (str, bytes)) or np.ndim(p) != 1:
        raise ValueError(f"{name} must be three numbers, got {p!r}")
    q = as_points([p], name=name, dim=3)[0]
    return float(q[0]), float(q[1]), float(q[2])


def orient3d(a, b, c, d) -> int:
    """Exact orientation: +1 if d is below the plane of a, b, c (a, b, c counter-clockwise
    seen from above), -1 above, 0 coplanar.

    >>> orient3d((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1))
    -1
    >>> orient3d((0, 0, 0), (1, 0, 0), (0, 1, 0), (5, 7, 0))
    0
    """
    return int(orient3d_nb(*_xyz(a, "a"), *_xyz(b, "b"), *_xyz(c, "c"), *_xyz(d, "d"), _PY_WORK))


def insphere(a, b, c, d, e) -> int:
    """Exact in-sphere test: +1 if e is strictly inside the sphere through a, b, c, d
    (given with orient3d(a, b, c, d) > 0), -1 outside, 0 on the sphere.

    >>> insphere((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1), (0.5, 0.5, -0.5))
    1
    """
    return int(insphere_nb(*_xyz(a, "a"), *_xyz(b, "b"), *_xyz(c, "c"), *_xyz(d, "d"),
                           *_xyz(e, "e"), _PY_WORK))
