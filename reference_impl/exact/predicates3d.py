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
2. otherwise the exact stages in ``stages3d.py``: an error-free float
   evaluation when the differences are exact small multiples of one power of
   two (grids: cheap ties), then Shewchuk-style stages B and C on the rounded
   differences (exact expansion arithmetic from ``expansion.py``, compressed),
   then the exact determinant with expansions after scaling by a power of two;
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

import numpy as np
from numba import njit

from reference_impl.exact.expansion import EPSILON, certain_sign
from reference_impl.exact.coldcall import cold
from reference_impl.exact.stages3d import (WORKSPACE3D_SIZE, exact_coordinates_3d, insphere_det_perm,
                                           insphere_exact, insphere_exact_stage, orient3d_det_perm,
                                           orient3d_exact, orient3d_exact_stage)
from reference_impl.validate import as_point_rows, as_xyz

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


def workspace3d() -> np.ndarray:
    """A scratch array for ``orient3d_nb`` / ``insphere_nb`` (one per thread of work).

    >>> workspace3d().shape
    (103538,)
    """
    return np.empty(WORKSPACE3D_SIZE, dtype=np.float64)


# the exact stages through coldcall.cold: no reference counting on the filters' path
_orient3d_exact_cold = cold(orient3d_exact_stage, 13)
_insphere_exact_cold = cold(insphere_exact_stage, 16)


@njit(cache=True)
def orient3d_nb(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, w):
    """Exact orient3d sign (see the module docstring); ``w`` is a ``workspace3d()`` array."""
    det, permanent, dmax = orient3d_det_perm(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz)
    s = certain_sign(det, permanent, dmax, _O_DMAX, _O_PLO, O3D_ERRBOUND_A, _O_ABS)
    if s != 0:
        return s
    return _orient3d_exact_cold(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, w)


@njit(cache=True)
def insphere_nb(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez, w):
    """Exact insphere sign (see the module docstring); ``w`` is a ``workspace3d()`` array."""
    det, permanent, dmax = insphere_det_perm(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz,
                                             ex, ey, ez)
    s = certain_sign(det, permanent, dmax, _I_DMAX, _I_PLO, ISP_ERRBOUND_A, _I_ABS)
    if s != 0:
        return s
    return _insphere_exact_cold(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez, w)


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


def orient3d_batch(a, b, c, d) -> np.ndarray:
    """orient3d row by row for (k, 3) arrays; returns an int8 array of signs.

    >>> orient3d_batch([[0, 0, 0]], [[1, 0, 0]], [[0, 1, 0]], [[0, 0, 1]]).tolist()
    [-1]
    """
    return _orient3d_many(*as_point_rows((a, b, c, d), ("a", "b", "c", "d")), _PY_WORK)


def insphere_batch(a, b, c, d, e) -> np.ndarray:
    """insphere row by row for (k, 3) arrays; returns an int8 array of signs.

    >>> insphere_batch([[0, 0, 0]], [[1, 0, 0]], [[0, 1, 0]], [[0, 0, -1]], [[5, 5, 5]]).tolist()
    [-1]
    """
    return _insphere_many(*as_point_rows((a, b, c, d, e), ("a", "b", "c", "d", "e")), _PY_WORK)


def orient3d(a, b, c, d) -> int:
    """Exact orientation: +1 if d is below the plane of a, b, c (a, b, c counter-clockwise
    seen from above), -1 above, 0 coplanar.

    >>> orient3d((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1))
    -1
    >>> orient3d((0, 0, 0), (1, 0, 0), (0, 1, 0), (5, 7, 0))
    0
    """
    return int(orient3d_nb(*as_xyz(a, "a"), *as_xyz(b, "b"), *as_xyz(c, "c"), *as_xyz(d, "d"), _PY_WORK))


def insphere(a, b, c, d, e) -> int:
    """Exact in-sphere test: +1 if e is strictly inside the sphere through a, b, c, d
    (given with orient3d(a, b, c, d) > 0), -1 outside, 0 on the sphere.

    >>> insphere((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1), (0.5, 0.5, -0.5))
    1
    """
    return int(insphere_nb(*as_xyz(a, "a"), *as_xyz(b, "b"), *as_xyz(c, "c"), *as_xyz(d, "d"),
                           *as_xyz(e, "e"), _PY_WORK))
