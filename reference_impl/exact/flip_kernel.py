"""Compiled replay of an edge-flip answer's topology (numba): which two triangles each flip joins.

The ``edge-flip`` checker's fast pass (``flip_replay.accepts``) replays the flips' connectivity
before it decides their predicates; in Python that loop is about a microsecond a flip, most of the
checker's time on large tests. :func:`replay` does the same replay in machine code. It is written
from the problem's definition alone (a triangulation is a map from each directed edge ``u -> v`` to
the third vertex ``w`` of its counter-clockwise triangle; flipping the interior edge ``a b`` of the
triangles ``a b c`` and ``b a d`` replaces them with ``c a d`` and ``d b c``) and shares no code
with the library's triangulations or flips, which the checker checks. It decides no predicate: the
caller tests every flip's in-circle and orientation signs exactly on the vertices it returns.

The map is an open-addressing hash table of ``u * n + v`` keys (linear probing, deletion by
backward shift, so no tombstones pile up over 10^5 flips). Integer arithmetic only; no fastmath.

``flip_replay`` imports this module only when it can (an exported Kattis validator has no numba)
and falls back to its Python replay; ``python -m reference_impl warm`` compiles it ("checkers").

Run the doctest: ``python -m pytest --doctest-modules reference_impl/exact/flip_kernel.py``

>>> import numpy as np
>>> ok, cs, ds, final = replay(4, np.array([[0, 1, 3], [1, 2, 3]]), np.array([[1, 3]]))
>>> ok, cs.tolist(), ds.tolist(), sorted(final.tolist())
(True, [0], [2], [[0, 1, 2], [0, 2, 3]])
"""
from __future__ import annotations

import numpy as np
from numba import njit

_EMPTY = np.int64(-1)
_GOLDEN = np.uint64(0x9E3779B97F4A7C15)   # Fibonacci hashing: the top bits of key * 2^64 / phi


@njit(cache=True)
def _slot(key, shift):
    """The home slot of ``key`` in a table of ``2^(64 - shift)`` slots."""
    return np.int64((np.uint64(key) * _GOLDEN) >> np.uint64(shift))


@njit(cache=True)
def _find(keys, key, shift, mask):
    """The slot holding ``key``, or -1."""
    i = _slot(key, shift)
    while keys[i] != _EMPTY:
        if keys[i] == key:
            return i
        i = (i + 1) & mask
    return -1


@njit(cache=True)
def _insert(keys, vals, key, val, shift, mask):
    """Add ``key -> val``; False (and nothing changed) when ``key`` is already there."""
    i = _slot(key, shift)
    while keys[i] != _EMPTY:
        if keys[i] == key:
            return False
        i = (i + 1) & mask
    keys[i] = key
    vals[i] = val
    return True


@njit(cache=True)
def _remove(keys, vals, i, shift, mask):
    """Empty slot ``i`` and shift back the entries of its probe run (no tombstones)."""
    j = i
    while True:
        j = (j + 1) & mask
        if keys[j] == _EMPTY:
            break
        home = _slot(keys[j], shift)
        # the entry at j may move to i when its home is not cyclically within (i, j]
        if (j > i and (home <= i or home > j)) or (j < i and (home <= i and home > j)):
            keys[i] = keys[j]
            vals[i] = vals[j]
            i = j
    keys[i] = _EMPTY


@njit(cache=True)
def _pop(keys, vals, key, shift, mask):
    """Remove ``key`` and return its value, or -1 when it is absent."""
    i = _find(keys, key, shift, mask)
    if i < 0:
        return -1
    val = vals[i]
    _remove(keys, vals, i, shift, mask)
    return val


@njit(cache=True)
def _set(keys, vals, key, val, shift, mask):
    """Change the value of a key that is there; False when it is not."""
    i = _find(keys, key, shift, mask)
    if i < 0:
        return False
    vals[i] = val
    return True


@njit(cache=True)
def _replay(n, tri, flips, cs, ds, final):
    """The replay proper; the number of final triangles written to ``final``, or -1 (refused)."""
    m, f = tri.shape[0], flips.shape[0]
    size, shift = 8, 61
    while size < 2 * 3 * m:
        size *= 2
        shift -= 1
    mask = size - 1
    keys = np.full(size, _EMPTY, dtype=np.int64)
    vals = np.zeros(size, dtype=np.int64)
    for t in range(m):
        a, b, c = tri[t, 0], tri[t, 1], tri[t, 2]
        if a < 0 or b < 0 or c < 0 or a >= n or b >= n or c >= n or a == b or b == c or c == a:
            return -1
        if not (_insert(keys, vals, a * n + b, c, shift, mask) and _insert(keys, vals, b * n + c, a, shift, mask)
                and _insert(keys, vals, c * n + a, b, shift, mask)):
            return -1                      # a directed edge in two triangles
    for s in range(f):
        a, b = flips[s, 0], flips[s, 1]
        if a < 0 or b < 0 or a >= n or b >= n:
            return -1
        c = _pop(keys, vals, a * n + b, shift, mask)
        if c < 0:
            return -1                      # not an edge, or a hull edge: the Python replay says which
        d = _pop(keys, vals, b * n + a, shift, mask)
        if d < 0 or c == d:
            return -1
        # triangles (a, b, c), (b, a, d) -> (c, a, d), (d, b, c): four edges stay, c d is new
        if not (_set(keys, vals, c * n + a, d, shift, mask) and _set(keys, vals, a * n + d, c, shift, mask)
                and _set(keys, vals, d * n + b, c, shift, mask) and _set(keys, vals, b * n + c, d, shift, mask)):
            return -1
        if not (_insert(keys, vals, d * n + c, a, shift, mask) and _insert(keys, vals, c * n + d, b, shift, mask)):
            return -1                      # c d already an edge
        cs[s] = c
        ds[s] = d
    k = 0
    for i in range(size):
        key = keys[i]
        if key != _EMPTY:
            u, v, w = key // n, key % n, vals[i]
            if u < v and u < w:            # each triangle once, from its smallest vertex
                final[k, 0], final[k, 1], final[k, 2] = u, v, w
                k += 1
    return k


def replay(n: int, triangles, flips) -> tuple[bool, np.ndarray, np.ndarray, np.ndarray]:
    """Replay the flips' topology on ``n`` points: ``(ok, cs, ds, final)``.

    ``triangles`` is an (m, 3) and ``flips`` an (f, 2) array of integer indices (duplicated points
    already mapped to one index). For each flip ``[a, b]``, ``cs[s]`` is the vertex left of
    ``a -> b`` and ``ds[s]`` the one right of it at its turn; ``final`` holds the last
    triangulation's triangles (each counter-clockwise as given, smallest vertex first, in no
    particular order). ``ok`` is False, and the arrays meaningless, when an index is outside
    0..n-1, a triangle repeats a vertex, a directed edge is in two triangles, or a flip is not an
    interior edge at its turn or would create an edge that is already there.

    Raises ValueError when the arrays are not shaped (m, 3) and (f, 2), or n is not in 1..2^31-1.

    >>> replay(4, np.array([[0, 1, 3], [1, 2, 3]]), np.array([[1, 2]]))[0]   # a hull edge
    False
    """
    tri = np.ascontiguousarray(triangles, dtype=np.int64)
    fl = np.ascontiguousarray(flips, dtype=np.int64)
    tri, fl = (tri.reshape(0, 3) if tri.size == 0 else tri), (fl.reshape(0, 2) if fl.size == 0 else fl)
    if tri.ndim != 2 or tri.shape[1] != 3:
        raise ValueError(f"triangles must be an (m, 3) array of indices, got shape {tri.shape}")
    if fl.ndim != 2 or fl.shape[1] != 2:
        raise ValueError(f"flips must be an (f, 2) array of indices, got shape {fl.shape}")
    if not 0 < n < 1 << 31:
        raise ValueError(f"n must be in 1..2^31-1 (keys u * n + v fit in int64), got {n}")
    cs = np.empty(fl.shape[0], dtype=np.int64)
    ds = np.empty(fl.shape[0], dtype=np.int64)
    final = np.empty((tri.shape[0], 3), dtype=np.int64)
    k = _replay(np.int64(n), tri, fl, cs, ds, final)
    return k >= 0, cs, ds, final[:max(k, 0)]
