"""Topology of a 2D triangle mesh in the public layout: slots, flips, edges, adjacency, union-find.

The layout (the one ``Delaunay``, ``ConstrainedDelaunay``, the flips and the
navigation mesh expose): ``tri`` (m, 3) vertex indices, every triangle
counter-clockwise; ``nbr`` (m, 3) with ``nbr[t, k]`` the triangle across the
edge *opposite* vertex k, that is the edge ``(tri[t, k+1], tri[t, k+2])``
(indices mod 3), -1 where there is none (the hull, a wall).  ``vt[v]`` is one
triangle having vertex v (-1 for none).  Nothing here looks at coordinates.

Compiled helpers (numba, for kernels; ``tri``/``nbr`` of any integer type, the
types are kept): ``slot``, ``third``, ``find_edge``, ``flip``, and the
union-find pair ``find_root``/``union_roots``.  Array helpers (numpy, for the
Python side): ``edge_keys``, ``triangle_neighbors``, ``triangles_left_of``,
``vertex_triangles``, ``each_edge_once``, ``unique_edges``, ``vertex_adjacency``.

>>> tri = np.array([[0, 1, 2], [0, 2, 3]])          # the unit square, diagonal 0-2
>>> nbr = triangle_neighbors(tri, 4)
>>> nbr.tolist()
[[-1, 1, -1], [-1, -1, 0]]
>>> unique_edges(tri, nbr).tolist()
[[0, 1], [0, 2], [0, 3], [1, 2], [2, 3]]
>>> flip(tri, nbr, 0, 1)                            # flip the diagonal: (removed edge)
(2, 0)
>>> tri.tolist(), nbr.tolist()
([[2, 3, 1], [3, 0, 1]], [[1, -1, -1], [-1, 0, -1]])
"""
from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["slot", "third", "find_edge", "flip", "find_root", "union_roots", "edge_keys",
           "triangle_neighbors", "triangles_left_of", "vertex_triangles", "each_edge_once",
           "unique_edges", "vertex_adjacency"]


# ----------------------------------------------------------------------------- compiled: one triangle
@njit(cache=True, inline="always")
def slot(rows, t, v):
    """Position (0, 1, 2) of value v in row t of ``rows``, -1 if absent.

    ``slot(tri, t, v)``: where vertex v is in triangle t; ``slot(nbr, o, t)``:
    which edge of o is shared with its neighbour t.
    """
    for k in range(3):
        if rows[t, k] == v:
            return k
    return -1


@njit(cache=True, inline="always")
def third(tri, t, u, v):
    """Position in triangle t of the vertex that is neither u nor v (-1 if none)."""
    for k in range(3):
        x = tri[t, k]
        if x != u and x != v:
            return k
    return -1


# ----------------------------------------------------------------------------- compiled: edges
# find_edge and flip are inlined into their callers like slot and third: a kernel compiled
# without reference counting (``constrained._insert_all``) then gets their code compiled the
# same way, instead of whichever version of a shared callee was compiled first.
@njit(cache=True, inline="always")
def find_edge(tri, nbr, vt, u, v):
    """A triangle t having edge (u, v) and the slot of its third vertex; (-1, -1) if absent.

    Turns around u from ``vt[u]``, counter-clockwise, then (at a boundary edge)
    clockwise from the start again.  By vertex index only, no geometry.
    """
    t0 = vt[u]
    if t0 < 0:
        return -1, -1
    t = t0
    ccw = True
    while True:
        k = slot(tri, t, u)
        if tri[t, (k + 1) % 3] == v:
            return t, (k + 2) % 3
        if tri[t, (k + 2) % 3] == v:
            return t, (k + 1) % 3
        nx = nbr[t, (k + 1) % 3] if ccw else nbr[t, (k + 2) % 3]
        if nx == t0:
            return -1, -1
        if nx < 0 and ccw:
            ccw = False
            t = t0
            nx = nbr[t, (slot(tri, t, u) + 2) % 3]
        if nx < 0:
            return -1, -1
        t = nx


@njit(cache=True, inline="always")
def flip(tri, nbr, t, k):
    """Flip the edge opposite vertex k of triangle t (in place); return (u, v), the removed edge.

    With t = (p, u, v) rotated so that p = tri[t, k] and o = nbr[t, k] = (q, v, u)
    beyond edge u-v, the new triangles are t = (u, q, p) and o = (q, v, p): the
    new diagonal q-p is opposite slot 0 of t and slot 1 of o.  The caller
    checks that the quadrilateral is strictly convex (and updates any ``vt``:
    p and u are in t, q and v in o).
    """
    o = nbr[t, k]
    ko = slot(nbr, o, t)
    p, u, v = tri[t, k], tri[t, (k + 1) % 3], tri[t, (k + 2) % 3]
    q = tri[o, ko]
    a = nbr[t, (k + 1) % 3]        # across v-p
    b = nbr[t, (k + 2) % 3]        # across p-u
    c = nbr[o, (ko + 1) % 3]       # across u-q
    d = nbr[o, (ko + 2) % 3]       # across q-v
    tri[t, 0], tri[t, 1], tri[t, 2] = u, q, p
    nbr[t, 0], nbr[t, 1], nbr[t, 2] = o, b, c
    tri[o, 0], tri[o, 1], tri[o, 2] = q, v, p
    nbr[o, 0], nbr[o, 1], nbr[o, 2] = a, t, d
    if a >= 0:
        nbr[a, slot(nbr, a, t)] = o
    if c >= 0:
        nbr[c, slot(nbr, c, o)] = t
    return u, v


# ----------------------------------------------------------------------------- compiled: union-find
@njit(cache=True, inline="always")
def find_root(parent, x):
    """Root of x's set (path halving)."""
    while parent[x] != x:
        parent[x] = parent[parent[x]]
        x = parent[x]
    return x


@njit(cache=True, inline="always")
def union_roots(parent, size, a, b):
    """Join the sets of two different roots a and b (union by size); return the new root.

    Start with ``parent = np.arange(n)`` and ``size = np.ones(n, np.int64)``.
    """
    if size[a] < size[b]:
        a, b = b, a
    parent[b] = a
    size[a] += size[b]
    return a


# ----------------------------------------------------------------------------- numpy: neighbours
def edge_keys(tri: np.ndarray, n: int) -> np.ndarray:
    """(m, 3) int64 keys ``u * n + v`` of the directed edge (u, v) opposite each vertex slot.

    >>> edge_keys(np.array([[0, 1, 2]]), 3).tolist()      # edges 1->2, 2->0, 0->1
    [[5, 6, 1]]
    """
    T = np.asarray(tri, dtype=np.int64).reshape(-1, 3)
    return T[:, [1, 2, 0]] * np.int64(n) + T[:, [2, 0, 1]]


def _sorted_keys(tri: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    keys = edge_keys(tri, n).ravel()
    order = np.argsort(keys, kind="stable")
    return keys[order], order


def _lookup(sorted_keys: np.ndarray, order: np.ndarray, want: np.ndarray) -> np.ndarray:
    """Flat slot index 3 t + k of each directed-edge key in ``want``, -1 where absent."""
    if len(sorted_keys) == 0:
        return np.full(np.shape(want), -1, dtype=np.int64)
    at = np.minimum(np.searchsorted(sorted_keys, want), len(sorted_keys) - 1)
    return np.where(sorted_keys[at] == want, order[at], -1)


def triangle_neighbors(tri: np.ndarray, n: int) -> np.ndarray:
    """``nbr`` (m, 3) int64 of counter-clockwise triangles over vertices 0..n-1 (-1: no neighbour).

    Two triangles are neighbours across an edge that one has as u -> v and the
    other as v -> u.  Raises ``ValueError`` when a directed edge is used twice
    (overlapping or clockwise triangles), so that the answer is well defined.

    >>> triangle_neighbors(np.array([[0, 1, 2], [2, 1, 3]]), 4).tolist()
    [[1, -1, -1], [-1, -1, 0]]
    """
    T = np.asarray(tri, dtype=np.int64).reshape(-1, 3)
    n = np.int64(n)
    sk, order = _sorted_keys(T, n)
    rep = np.flatnonzero(sk[1:] == sk[:-1])
    if len(rep):
        e = sk[rep[0]]
        raise ValueError(f"the directed edge {e // n}->{e % n} is used by two triangles: "
                         "triangles overlap or are not all counter-clockwise")
    twin = (T[:, [2, 0, 1]] * n + T[:, [1, 2, 0]]).ravel()
    at = _lookup(sk, order, twin)
    return np.where(at >= 0, at // 3, -1).reshape(len(T), 3)


def triangles_left_of(tri: np.ndarray, n: int, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The triangle having the directed edge u[i] -> v[i] (the one on its left), -1 if none.

    >>> triangles_left_of(np.array([[0, 1, 2]]), 3, np.array([0, 1]), np.array([1, 0])).tolist()
    [0, -1]
    """
    sk, order = _sorted_keys(tri, n)
    at = _lookup(sk, order, np.asarray(u, dtype=np.int64) * np.int64(n) + np.asarray(v, dtype=np.int64))
    return np.where(at >= 0, at // 3, -1)


@njit(cache=True)
def vertex_triangles(tri: np.ndarray, n: int) -> np.ndarray:
    """``vt`` (n,) int64: a triangle having vertex v (the last one), -1 for none (as
    ``find_edge`` wants).  Compiled, so that compiled callers (``constrained._prepare``) use it too.

    >>> vertex_triangles(np.array([[0, 1, 2], [0, 2, 3]]), 5).tolist()
    [1, 0, 1, 1, -1]
    """
    vt = np.full(n, -1, np.int64)
    for t in range(tri.shape[0]):
        for j in range(3):
            vt[tri[t, j]] = t
    return vt


# ----------------------------------------------------------------------------- numpy: edges
def each_edge_once(nbr: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(t, k) int64 arrays naming every undirected edge once, as the edge opposite slot k of t.

    An interior edge is named by the smaller of its two triangles, a boundary edge
    (``nbr[t, k] < 0``) by its only one; in the order of t, then k.

    >>> t, k = each_edge_once(np.array([[-1, 1, -1], [-1, -1, 0]]))
    >>> t.tolist(), k.tolist()
    ([0, 0, 0, 1, 1], [0, 1, 2, 0, 1])
    """
    N = np.asarray(nbr).reshape(-1, 3)
    keep = (N < 0) | (N > np.arange(len(N))[:, None])
    t, k = np.nonzero(keep)
    return t.astype(np.int64), k.astype(np.int64)


def unique_edges(tri: np.ndarray, nbr: np.ndarray, mask: np.ndarray | None = None) -> np.ndarray:
    """(e, 2) int64 undirected edges (i, j), i < j, rows sorted; only those with ``mask[t, k]``.

    ``mask`` (m, 3) bool marks edges by the slot opposite them (it must agree on
    both sides of an edge, as ``ConstrainedDelaunay.constrained`` does).

    >>> unique_edges(np.array([[0, 1, 2]]), np.array([[-1, -1, -1]])).tolist()
    [[0, 1], [0, 2], [1, 2]]
    """
    T = np.asarray(tri, dtype=np.int64).reshape(-1, 3)
    t, k = each_edge_once(nbr)
    if mask is not None:
        keep = np.asarray(mask)[t, k]
        t, k = t[keep], k[keep]
    u, v = T[t, (k + 1) % 3], T[t, (k + 2) % 3]
    e = np.stack([np.minimum(u, v), np.maximum(u, v)], axis=1)
    return e[np.lexsort((e[:, 1], e[:, 0]))] if len(e) else np.zeros((0, 2), dtype=np.int64)


def vertex_adjacency(u: np.ndarray, v: np.ndarray, n: int,
                     rank: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """CSR ``(ptr, nbr)`` of the undirected graph with edges (u[i], v[i]) over vertices 0..n-1.

    The neighbours of vertex i are ``nbr[ptr[i]:ptr[i + 1]]``, each edge listed
    once in ``u, v``; they come in increasing ``rank`` (a permutation of 0..n-1,
    for instance the vertices' (x, y) order), or in edge order without it.

    >>> ptr, nb = vertex_adjacency(np.array([0, 0]), np.array([2, 1]), 3)
    >>> ptr.tolist(), nb.tolist()
    ([0, 2, 3, 4], [2, 1, 0, 0])
    """
    src = np.concatenate([u, v]).astype(np.int64)
    dst = np.concatenate([v, u]).astype(np.int64)
    key = src if rank is None else src * np.int64(n) + np.asarray(rank, dtype=np.int64)[dst]
    order = np.argsort(key, kind="stable")
    ptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(src, minlength=n), out=ptr[1:])
    return ptr, dst[order]
