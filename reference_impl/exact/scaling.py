"""Scaling by powers of two: the one way every module rescales coordinates without rounding.

Multiplying a double by a power of two changes only its exponent, so (as long as
nothing overflows or falls into the subnormal range) it is exact, and the sign of
every determinant, and the order of every distance, stays the same.  The exact
predicates scale their inputs so that the largest magnitude lies in [0.5, 1)
before building expansions; the structures scale whole point sets before their
float formulas, and scale the answers back.

- ``pow2_scale(v, min_scaled)`` (numba, in place): scale a float64 array so that
  its largest magnitude lies in [0.5, 1); it refuses (returns False, ``v``
  unchanged) when a non-zero value would fall below ``min_scaled``.
- ``pow2_exponent(*arrays)`` (numpy): the exponent ``e`` with
  ``max|a| * 2**-e`` in [0.5, 1) over all the arrays (0 for all zeros); per row
  with ``axis=1``; ``keep_normal=True`` lowers a positive ``e`` so that the
  smallest non-zero magnitude stays a normal double after scaling by ``2**-e``.
  Scale with ``np.ldexp(a, -e)`` and back with ``np.ldexp(a, e)``.

>>> import numpy as np
>>> v = np.array([3.0, -0.375, 0.0])
>>> pow2_scale(v, 2.0 ** -150), v.tolist()
(True, [0.75, -0.09375, 0.0])
>>> pow2_exponent(np.array([[3.0, 1e-300]]), np.array([-5.0]))
3
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["pow2_scale", "pow2_exponent"]


@njit(cache=True)
def pow2_scale(v, min_scaled):
    """Scale v in place by 2**k so that max|v| is in [0.5, 1) (no change for all zeros).

    Returns False, and scales nothing, if a non-zero value would then be below
    ``min_scaled`` (the caller takes an exact Python path instead).  The scaling is
    exact: every scaled non-zero value is at least ``min_scaled`` (a normal double).
    """
    m = 0.0
    for x in v:
        m = max(m, abs(x))
    if m == 0.0:
        return True
    _, e = math.frexp(m)
    lo = math.ldexp(min_scaled, e)   # the threshold in unscaled units
    for x in v:
        if x != 0.0 and abs(x) < lo:
            return False
    k = -e
    while k != 0:                    # at most two exact steps of at most 2**1000
        step = max(-1000, min(1000, k))
        f = math.ldexp(1.0, step)
        for i in range(v.shape[0]):
            v[i] *= f
        k -= step
    return True


def pow2_exponent(*arrays: np.ndarray, axis: int | None = None, keep_normal: bool = False):
    """The exponent e with max|a| * 2**-e in [0.5, 1) over ``arrays`` (0 when all are zero).

    With ``axis=1`` (arrays of the same number of rows) an int array: one exponent per
    row.  With ``keep_normal`` a positive e is lowered so that the smallest non-zero
    magnitude, scaled by 2**-e, is still a normal double (then the scaling is exact).

    >>> pow2_exponent(np.array([0.0, 0.0]))
    0
    >>> pow2_exponent(np.array([[1.0, 2.0], [0.25, 0.0]]), axis=1).tolist()
    [2, -1]
    >>> pow2_exponent(np.array([2.0 ** 1000, 2.0 ** -1000]), keep_normal=True)
    22
    """
    if axis is not None:
        rows = [np.abs(np.asarray(a, dtype=np.float64)).max(axis=axis) for a in arrays]
        return np.frexp(np.maximum.reduce(rows))[1]
    absolute = [np.abs(np.asarray(a, dtype=np.float64)) for a in arrays]
    m = max((float(a.max()) for a in absolute if a.size), default=0.0)
    if m == 0.0:
        return 0
    e = math.frexp(m)[1]
    if keep_normal and e > 0:
        emin = min(math.frexp(float(a[a > 0].min()))[1] for a in absolute if (a > 0).any())
        e = min(e, max(0, 1021 + emin))
    return e
