"""Float filters for many predicates at once (numpy): each sign where a proven error bound decides it,
0 where it does not (the caller decides those exactly, in integers).

The exact checkers (``verify.check_delaunay`` and ``verify.check_delaunay_3d`` with ``bulk=``this
module) use it to decide most of an answer's orientation and in-circle / in-sphere tests in a few
array operations; the problem checkers name it in ``LIBRARY`` like ``verify``. Without numpy
(an exported Kattis validator on a machine without it) ``AVAILABLE`` is False and the checkers
use ``verify``'s one-at-a-time filters instead.

The bounds are Shewchuk's (1997) for his evaluation order, used here in that order, times two (a
margin); they hold when no operation underflows or overflows, which the callers ensure by using them
only on "tame" coordinates (``verify._tame``: every coordinate 0 or of magnitude in [2^-150, 2^150]).

Run the doctests: ``python -m pytest --doctest-modules reference_impl/exact/bulk.py``

>>> import numpy as np
>>> z, o = np.zeros(2), np.ones(2)
>>> orient2d(z, z, o, z, z, np.array([1.0, -1.0])).tolist()
[1, -1]
"""
try:
    import numpy as np
except ImportError:  # pragma: no cover - an exported validator without numpy
    np = None

AVAILABLE = np is not None

_EPS = 2.0 ** -53
CCW_BOUND = 2 * (3.0 + 16.0 * _EPS) * _EPS
ICC_BOUND = 2 * (10.0 + 96.0 * _EPS) * _EPS
O3D_BOUND = 2 * (7.0 + 56.0 * _EPS) * _EPS
ISP_BOUND = 2 * (16.0 + 224.0 * _EPS) * _EPS


def _signs(det, bound):
    """+1 / -1 where |det| exceeds the bound, 0 elsewhere (int8)."""
    out = np.zeros(det.shape, dtype=np.int8)
    out[det > bound] = 1
    out[-det > bound] = -1
    return out


def orient2d(ax, ay, bx, by, cx, cy):
    """Signs of orient2d(a, b, c) (+1 counter-clockwise), 0 where the filter cannot tell.

    >>> orient2d(*[np.array([v]) for v in (0.0, 0.0, 1.0, 1.0, 2.0, 2.0)]).tolist()
    [0]
    """
    left = (ax - cx) * (by - cy)
    right = (ay - cy) * (bx - cx)
    return _signs(left - right, CCW_BOUND * (np.abs(left) + np.abs(right)))


def incircle(ax, ay, bx, by, cx, cy, dx, dy):
    """Signs of incircle(a, b, c, d) (+1: d inside the circle of counter-clockwise a, b, c), 0: undecided.

    >>> incircle(*[np.array([v]) for v in (0.0, 0.0, 2.0, 0.0, 0.0, 2.0, 1.0, 1.0)]).tolist()
    [1]
    """
    adx, ady, bdx, bdy, cdx, cdy = ax - dx, ay - dy, bx - dx, by - dy, cx - dx, cy - dy
    bdxcdy, cdxbdy = bdx * cdy, cdx * bdy
    cdxady, adxcdy = cdx * ady, adx * cdy
    adxbdy, bdxady = adx * bdy, bdx * ady
    alift, blift, clift = adx * adx + ady * ady, bdx * bdx + bdy * bdy, cdx * cdx + cdy * cdy
    det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady)
    permanent = ((np.abs(bdxcdy) + np.abs(cdxbdy)) * alift + (np.abs(cdxady) + np.abs(adxcdy)) * blift
                 + (np.abs(adxbdy) + np.abs(bdxady)) * clift)
    return _signs(det, ICC_BOUND * permanent)


def orient3d(a, b, c, d):
    """Signs of orient3d(a, b, c, d) for (k, 3) arrays of points (the sign of det(a-d, b-d, c-d)).

    >>> orient3d(*[np.array([p], dtype=float) for p in ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1))]).tolist()
    [1]
    """
    adx, ady, adz = (a - d).T
    bdx, bdy, bdz = (b - d).T
    cdx, cdy, cdz = (c - d).T
    bdxcdy, cdxbdy = bdx * cdy, cdx * bdy
    cdxady, adxcdy = cdx * ady, adx * cdy
    adxbdy, bdxady = adx * bdy, bdx * ady
    det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady)
    permanent = ((np.abs(bdxcdy) + np.abs(cdxbdy)) * np.abs(adz) + (np.abs(cdxady) + np.abs(adxcdy)) * np.abs(bdz)
                 + (np.abs(adxbdy) + np.abs(bdxady)) * np.abs(cdz))
    return _signs(det, O3D_BOUND * permanent)


def insphere(a, b, c, d, e):
    """Signs of insphere(a, b, c, d, e) for (k, 3) arrays (+1: e inside, when orient3d(a, b, c, d) > 0).

    >>> pts = ((0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, -2), (1, 1, -1))
    >>> insphere(*[np.array([p], dtype=float) for p in pts]).tolist()
    [1]
    """
    aex, aey, aez = (a - e).T
    bex, bey, bez = (b - e).T
    cex, cey, cez = (c - e).T
    dex, dey, dez = (d - e).T
    aexbey, bexaey = aex * bey, bex * aey
    bexcey, cexbey = bex * cey, cex * bey
    cexdey, dexcey = cex * dey, dex * cey
    dexaey, aexdey = dex * aey, aex * dey
    aexcey, cexaey = aex * cey, cex * aey
    bexdey, dexbey = bex * dey, dex * bey
    ab, bc, cd, da = aexbey - bexaey, bexcey - cexbey, cexdey - dexcey, dexaey - aexdey
    ac, bd = aexcey - cexaey, bexdey - dexbey
    abc = aez * bc - bez * ac + cez * ab
    bcd = bez * cd - cez * bd + dez * bc
    cda = cez * da + dez * ac + aez * cd
    dab = dez * ab + aez * bd + bez * da
    alift = aex * aex + aey * aey + aez * aez
    blift = bex * bex + bey * bey + bez * bez
    clift = cex * cex + cey * cey + cez * cez
    dlift = dex * dex + dey * dey + dez * dez
    det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd)
    A = np.abs
    az, bz, cz, dz = A(aez), A(bez), A(cez), A(dez)
    p_ab, p_bc, p_cd, p_da = A(aexbey) + A(bexaey), A(bexcey) + A(cexbey), A(cexdey) + A(dexcey), A(dexaey) + A(aexdey)
    p_ac, p_bd = A(aexcey) + A(cexaey), A(bexdey) + A(dexbey)
    permanent = ((p_cd * bz + p_bd * cz + p_bc * dz) * alift
                 + (p_da * cz + p_ac * dz + p_cd * az) * blift
                 + (p_ab * dz + p_bd * az + p_da * bz) * clift
                 + (p_bc * az + p_ac * bz + p_ab * cz) * dlift)
    return _signs(det, ISP_BOUND * permanent)
