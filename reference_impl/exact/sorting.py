"""``merge_sort(ids, buf, before, ctx)``: a stable merge sort of ids by a compiled comparison.

    from reference_impl.exact.sorting import merge_sort
    merge_sort(ids, buf, before, ctx)     # in an njit function; before(ctx, a, b) -> bool

The library sorts by exact comparisons that numpy cannot express: edges by exact length
(``distance.length_order``, for the EMST and the proximity graphs) and segments
lexicographically by their end points (``structures.constrained.canonical_segments``).  Both
need the same thing, a *stable* sort (ties keep their order, so results never depend on
how the input was ordered) driven by a comparison compiled into the loop: ``before`` is an
``@njit`` function, ``before(ctx, a, b)`` True when item a must come strictly before item b,
and ``ctx`` whatever it needs (a tuple of arrays).  numba compiles one copy of the sort per
comparison, with the comparison inlined; the sort is inlined into its callers (numba will
not cache a function that calls a non-inlined one with a function argument).

Bottom-up, O(n log n) comparisons, no allocation (``buf``: scratch as long as ``ids``).

>>> import numpy as np
>>> from numba import njit
>>> @njit
... def by_key(key, a, b):
...     return key[a] < key[b]
>>> ids = np.arange(5); key = np.array([3, 1, 3, 0, 1])
>>> merge_sort(ids, np.empty(5, np.int64), by_key, key); ids.tolist()   # ties in input order
[3, 1, 4, 0, 2]
"""
from __future__ import annotations

from numba import njit

__all__ = ["merge_sort"]


@njit(cache=True, inline="always")     # inlined: a caller passing a function stays cacheable
def merge_sort(ids, buf, before, ctx):
    """Sort ``ids`` in place, stably, by ``before(ctx, a, b)`` (module docstring)."""
    n = len(ids)
    width = 1
    while width < n:
        for lo in range(0, n - width, 2 * width):
            mid = lo + width
            hi = min(lo + 2 * width, n)
            a, b, k = lo, mid, 0
            while a < mid and b < hi:        # a right item goes first only when strictly before
                if before(ctx, ids[b], ids[a]):
                    buf[k] = ids[b]
                    b += 1
                else:
                    buf[k] = ids[a]
                    a += 1
                k += 1
            while a < mid:                   # (right items left over are already in place)
                buf[k] = ids[a]
                a += 1
                k += 1
            for i in range(k):
                ids[lo + i] = buf[i]
        width *= 2
