"""Insertion order for incremental Delaunay: BRIO rounds, each sorted along a Hilbert curve.

Inserting points in random order gives the O(n log n) expected bound but makes
every point-location walk long (about sqrt(n) steps); sorting along a
space-filling curve makes consecutive points close (about 3 steps) but loses the
randomness.  BRIO (Amenta, Choi, Rote 2003) keeps both: points are split into
rounds of doubling size at random, and each round is sorted along the curve.

The "random" round of a point is a hash of its coordinates, and ties are broken
by coordinates, so the order depends only on the *set* of points, never on the
order they were given in: that is what makes degenerate outputs (cocircular
ties) identical for any permutation of the input.

One exception: a thin strip of points (``line_order``) is inserted in plain sorted order
along it, which there does half BRIO's work; the kernel caps that work and falls back to
BRIO (``kernel.line_budget``), because sorted order can be quadratic.

>>> import numpy as np
>>> pts = np.array([[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]])
>>> sorted(insertion_order(pts).tolist())
[0, 1, 2, 3]
>>> [hilbert_index(x, y, 1) for x, y in [(0, 0), (0, 1), (1, 1), (1, 0)]]   # the curve's first "U"
[0, 1, 2, 3]
"""
from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["hilbert_index", "insertion_order", "line_order", "small_order", "walk_hints", "SMALL"]

_BITS = 16  # curve resolution per axis: a 65536 x 65536 grid


# Hilbert curve as a 4-state machine: in state s, the quadrant q = 2*xbit + ybit of the
# next level gets digit _DIG[4s + q] and the sub-square continues in state _NXT[4s + q].
# (Derived from the classic rotate-and-flip formulation; branch-free, so ~3x faster.)
_DIG = np.array([0, 1, 3, 2, 0, 3, 1, 2, 2, 1, 3, 0, 2, 3, 1, 0], dtype=np.int64)
_NXT = np.array([1, 0, 2, 0, 0, 3, 1, 1, 2, 2, 0, 3, 3, 1, 3, 2], dtype=np.int64)


def _four_levels():
    """The machine above run four levels at a time: for state s and 4-bit chunks xn, yn of the
    cell's coordinates, ``_DIG4[256 s + 16 xn + yn]`` is the next 8 bits of the index and
    ``_NXT4[...]`` the state after them (a quarter of the loop iterations)."""
    dig4 = np.empty(1024, dtype=np.int64)
    nxt4 = np.empty(1024, dtype=np.int64)
    for s0 in range(4):
        for xn in range(16):
            for yn in range(16):
                d, st = 0, s0
                for lvl in range(3, -1, -1):
                    q = (((xn >> lvl) & 1) << 1) | ((yn >> lvl) & 1)
                    d = (d << 2) | int(_DIG[4 * st + q])
                    st = int(_NXT[4 * st + q])
                dig4[256 * s0 + 16 * xn + yn] = d
                nxt4[256 * s0 + 16 * xn + yn] = st
    return dig4, nxt4


_DIG4, _NXT4 = _four_levels()


@njit(cache=True)
def hilbert_index(ix, iy, bits):
    """Position of the cell (ix, iy) along a Hilbert curve over a 2**bits grid."""
    d = 0
    s = 0
    lvl = bits - 1
    while (lvl + 1) % 4 != 0:          # single levels until a multiple of four is left
        q = (((ix >> lvl) & 1) << 1) | ((iy >> lvl) & 1)
        d = (d << 2) | _DIG[4 * s + q]
        s = _NXT[4 * s + q]
        lvl -= 1
    while lvl >= 0:                    # then four levels per table look-up
        c = 256 * s + (((ix >> (lvl - 3)) & 15) << 4) + ((iy >> (lvl - 3)) & 15)
        d = (d << 8) | _DIG4[c]
        s = _NXT4[c]
        lvl -= 4
    return d


@njit(cache=True)
def mix(h):
    """splitmix64 finaliser: a well-spread 64-bit hash of a uint64 (used by the 2D and 3D orders)."""
    h = (h ^ (h >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    h = (h ^ (h >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    return h ^ (h >> np.uint64(31))


@njit(cache=True)
def _keys(x, y, xbits, ybits, xmin, ymin, inv, bits, rounds):
    n = x.shape[0]
    keys = np.empty(n, dtype=np.int64)
    top = (1 << bits) - 1
    for i in range(n):
        fx = (x[i] - xmin) * inv
        fy = (y[i] - ymin) * inv
        ix = min(top, max(0, int(fx * top)))
        iy = min(top, max(0, int(fy * top)))
        h = mix(xbits[i] * np.uint64(0x9E3779B97F4A7C15) ^ ybits[i])
        # round r has about half the points of round r + 1: trailing zeros are geometric
        tz = 0
        while tz < rounds - 1 and ((h >> np.uint64(tz)) & np.uint64(1)) == np.uint64(0):
            tz += 1
        rnd = rounds - 1 - tz
        keys[i] = (rnd << 58) | (hilbert_index(ix, iy, bits) << 26) | np.int64(h >> np.uint64(38))
    return keys


@njit(cache=True)
def _fix_ties(order, skeys, x, y):
    # equal keys (same round, cell and hash bits): order them by coordinates.  ``skeys`` are
    # the keys in ``order`` (sorted), so finding the runs reads memory in sequence.
    n = order.shape[0]
    i = 0
    while i < n:
        j = i + 1
        while j < n and skeys[j] == skeys[i]:
            j += 1
        for a in range(i + 1, j):  # insertion sort; runs are tiny
            v = order[a]
            b = a - 1
            while b >= i and (x[order[b]] > x[v] or (x[order[b]] == x[v] and y[order[b]] > y[v])):
                order[b + 1] = order[b]
                b -= 1
            order[b + 1] = v
        i = j


@njit(cache=True)
def _order_keys(x, y, brio):
    """The sort keys of ``insertion_order`` (x, y contiguous float64, n >= 1)."""
    n = x.shape[0]
    xmin = x[0]
    xmax = x[0]
    ymin = y[0]
    ymax = y[0]
    for i in range(1, n):
        xmin = min(xmin, x[i])
        xmax = max(xmax, x[i])
        ymin = min(ymin, y[i])
        ymax = max(ymax, y[i])
    span = max(xmax - xmin, ymax - ymin)
    if span > 0 and not np.isfinite(span):  # 1e308-scale spans overflow: scale down (exactly) first
        x = x * 2.0 ** -8
        y = y * 2.0 ** -8
        xmin *= 2.0 ** -8
        ymin *= 2.0 ** -8
        span = max(xmax * 2.0 ** -8 - xmin, ymax * 2.0 ** -8 - ymin)
    inv = 0.0
    if span > 0 and np.isfinite(1.0 / span):
        inv = 1.0 / span
    rounds = 1
    if brio:
        rounds = min(31, max(1, int(np.log2(n)) - 6))
    return _keys(x, y, x.view(np.uint64), y.view(np.uint64), xmin, ymin, inv, _BITS, rounds)


@njit(cache=True)
def line_order(pts):
    """For points ``pts`` (n, 2) along a thin strip, the order along it; otherwise an empty array.

    *Thin*: the strip's width (the farthest point from the line through the lexicographically
    first and last points, along the bounding box's longer side) times the number of points
    is below its length, so the strip is narrower than the mean spacing along it.  There the
    Delaunay triangulation is nearly a chain, and inserting in sorted order puts every point
    next to the last one, beyond the end of the hull: about 6 conflict tests and 2 walk steps
    a point against BRIO's 9 and 3 on a line with 1e-9 noise, half the time.  (On a wide set
    sorted order is slow: 27 tests a point on uniform points.)  The sort is by the longer
    side's coordinate, ties by (x, y); like ``insertion_order`` it depends only on the set of
    points (the width is a maximum over the points, so it does not depend on their order
    either).  The kernel caps the work of a sorted build (``kernel.line_budget``) and starts
    again in BRIO order past the cap: on a thin but curved set, such as 4000 points on
    y = 1e-4 x^4 or y = 1e-5 exp(5 x - 5) for x in [0, 1], sorted order is quadratic (measured:
    3996 conflict tests a point).

    >>> import numpy as np
    >>> line_order(np.array([[2.0, 1.0], [0.0, 0.0], [1.0, 0.5 + 1e-9]])).tolist()
    [1, 2, 0]
    >>> line_order(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])).tolist()
    []
    """
    n = pts.shape[0]
    none = np.empty(0, np.int64)
    if n < 3:
        return none
    xmin = xmax = pts[0, 0]
    ymin = ymax = pts[0, 1]
    for i in range(1, n):
        xmin = min(xmin, pts[i, 0])
        xmax = max(xmax, pts[i, 0])
        ymin = min(ymin, pts[i, 1])
        ymax = max(ymax, pts[i, 1])
    c = 0 if xmax - xmin >= ymax - ymin else 1       # the longer side's coordinate
    a = 0
    b = 0
    for i in range(1, n):
        if pts[i, c] < pts[a, c] or (pts[i, c] == pts[a, c] and pts[i, 1 - c] < pts[a, 1 - c]):
            a = i
        if pts[i, c] > pts[b, c] or (pts[i, c] == pts[b, c] and pts[i, 1 - c] > pts[b, 1 - c]):
            b = i
    dx = pts[b, 0] - pts[a, 0]
    dy = pts[b, 1] - pts[a, 1]
    wide = 0.0                                       # |B - A| times the largest distance
    for i in range(n):
        wide = max(wide, abs(dx * (pts[i, 1] - pts[a, 1]) - dy * (pts[i, 0] - pts[a, 0])))
    if not wide * n < dx * dx + dy * dy:             # (NaN or overflow: not thin)
        return none
    x = pts[:, 0].copy()
    y = pts[:, 1].copy()
    keys = (x if c == 0 else y).view(np.int64).copy()  # the doubles' bits, made monotone:
    for i in range(n):                                  # negative ones count down
        if keys[i] < 0:
            keys[i] ^= 0x7FFFFFFFFFFFFFFF
    return _sorted(keys, x, y)[0]


@njit(cache=True)
def _sorted(keys, x, y):
    """``(order, keys[order])``: the int64 ``keys`` sorted, equal keys by coordinates.  (One
    compiled sort shared by both orders: numba's ``argsort`` costs seconds to compile.)"""
    order = np.argsort(keys)
    skeys = keys[order]
    _fix_ties(order, skeys, x, y)
    return order, skeys


@njit(cache=True)
def small_order(x, y, brio):
    """``insertion_order`` in one compiled call, with the walk hints: ``(order, hints)``.

    For small inputs the fixed cost of several calls from Python is larger than the work."""
    order, skeys = _sorted(_order_keys(x, y, brio), x, y)
    return order, walk_hints(skeys)


@njit(cache=True)
def walk_hints(skeys):
    """For the sort keys in insertion order (``skeys``: sorted by round, then Hilbert index),
    for each position i a position ``hints[i] < i`` of the previous BRIO round whose Hilbert
    index is nearest to that of point i (-1 in the first round).

    Why: point location walks from the last inserted point, which is usually next door: but
    where the Hilbert curve leaves the data and comes back (it does so all along a nearly
    straight line of points) consecutive points are far apart, and a walk across thin
    triangles then crosses thousands of them (measured: the top 1% of walks were a third of
    all steps on 2e4 nearly collinear points).  A point of the previous round with a nearby
    Hilbert index is nearby in the plane, so the kernel starts from whichever of the two is
    closer.  Linear time: each round is merged with the one before (both sorted by index).
    """
    n = skeys.shape[0]
    hints = np.full(n, -1, dtype=np.int64)
    rnd = skeys >> 58
    hil = (skeys >> 26) & 0xFFFFFFFF
    prev_lo = -1          # the previous round occupies positions prev_lo .. prev_hi - 1
    prev_hi = -1
    lo = 0
    while lo < n:
        hi = lo
        while hi < n and rnd[hi] == rnd[lo]:
            hi += 1
        if prev_lo >= 0:
            j = prev_lo
            for i in range(lo, hi):
                h = hil[i]
                # advance j to the last position of the previous round with index <= h
                while j + 1 < prev_hi and hil[j + 1] <= h:
                    j += 1
                best = j
                if hil[j] <= h and j + 1 < prev_hi:    # (hil[j] > h: nothing of the round is below)
                    if hil[j + 1] - h < h - hil[j]:
                        best = j + 1
                hints[i] = best
        prev_lo = lo
        prev_hi = hi
        lo = hi
    return hints


SMALL = 4096  # below this, one compiled call; above, numpy's argsort (faster on large arrays)


def insertion_order(points: np.ndarray, brio: bool = True, with_hints: bool = False):
    """Return a permutation of ``range(len(points))`` to insert the points in (and, with
    ``with_hints``, the walk hints of ``walk_hints`` for that order).

    ``brio=False`` gives a plain Hilbert order (one round).  ``points`` is an (n, 2) float64
    array of finite values (as ``points.as_points`` returns).
    """
    n = len(points)
    if n == 0:
        empty = np.zeros(0, dtype=np.int64)
        return (empty, empty.copy()) if with_hints else empty
    x = np.ascontiguousarray(points[:, 0])
    y = np.ascontiguousarray(points[:, 1])
    if n < SMALL:
        order, hints = small_order(x, y, brio)
    else:
        keys = _order_keys(x, y, brio)
        order = np.argsort(keys, kind="quicksort")
        skeys = keys[order]
        _fix_ties(order, skeys, x, y)
        hints = walk_hints(skeys) if with_hints else None
    return (order, hints) if with_hints else order
