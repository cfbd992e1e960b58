"""Proximity graphs from the Delaunay triangulation: EMST, closest pair, Gabriel graph, RNG.

    python -c "from reference_impl.structures.proximity import euclidean_mst; print(euclidean_mst([(0,0),(1,0),(0,2)]))"

Every one of these graphs is a subgraph of the Delaunay graph, in a chain:

    EMST  ⊆  relative neighbourhood graph  ⊆  Gabriel graph  ⊆  Delaunay graph

so each is computed from the Delaunay edges (``reference_impl.Delaunay``) in
O(n log n), and the closest pair is the shortest Delaunay edge.

Exactness.  Every decision compares squared distances or signs of dot
products of differences of the input doubles, and sorts edges by exact length:
that arithmetic is ``reference_impl.exact.distance`` (``sq_dist_cmp``, ``dot_sign``,
``length_order``: a float filter, then expansions or Python fractions).  This module
holds only the graph code.  No epsilon anywhere.

Every function takes the points or a ``Delaunay`` of them (whose mesh it then
uses: no re-triangulation; points removed from it are left out).

Conventions (as in the rest of ``reference_impl``): edges are (k, 2) int arrays
with i < j in each row and rows sorted; duplicated points are merged, so only
the representative of a duplicate group (its smallest index, ``Delaunay.index_map``)
appears in an edge; all-collinear input gives the chain of consecutive points.
Ties (equal lengths) are broken by the coordinates of the endpoints, never by
their indices, so the results do not depend on the input order.

>>> pts = [(0, 0), (4, 0), (0, 3), (5, 5), (4, 1)]
>>> euclidean_mst(pts).tolist()
[[0, 1], [0, 2], [1, 4], [3, 4]]
>>> closest_pair(pts)
Pair(i=1, j=4)
>>> gabriel_graph([(0, 0), (2, 0), (1, 1), (1, -3)]).tolist()   # (1, 1) sits on the circle on 0-1
[[0, 2], [0, 3], [1, 2], [1, 3]]
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from reference_impl.mesh.delaunay import Delaunay, as_delaunay
from reference_impl.mesh.topology import each_edge_once, find_root, union_roots, vertex_adjacency
# sq_dist_cmp and dot_sign stay importable from here too
from reference_impl.exact.distance import dot_sign, length_order, scratch, sq_dist_cmp

__all__ = ["Pair", "euclidean_mst", "closest_pair", "gabriel_graph", "relative_neighborhood_graph"]


# ----------------------------------------------------------------------------- Delaunay edges
class _Graph:
    """The Delaunay edges of a point set, with the apex of each adjacent triangle."""

    def __init__(self, points) -> None:
        d = as_delaunay(points)            # a given Delaunay is used as it is
        self.P = d.points
        self.index_map = d.index_map
        s = np.asarray(d.simplices, dtype=np.int64)
        if len(s) == 0:  # collinear or fewer than 3 distinct points: the sorted chain
            chain = np.asarray(d.hull, dtype=np.int64)
            u, v = chain[:-1], chain[1:]
            a1 = a2 = np.full(len(u), -1, dtype=np.int64)
        else:
            nb = np.asarray(d.neighbors, dtype=np.int64)
            t, k = each_edge_once(nb)
            u, v = s[t, (k + 1) % 3], s[t, (k + 2) % 3]
            o = nb[t, k]
            a1 = s[t, k]
            a2 = np.where(o >= 0, s[np.maximum(o, 0)].sum(axis=1) - u - v, -1)
        self.u, self.v = np.minimum(u, v), np.maximum(u, v)
        self.a1, self.a2 = a1, a2

    def adjacency(self) -> tuple[np.ndarray, np.ndarray]:
        """CSR (indptr, indices) of the Delaunay graph."""
        return vertex_adjacency(self.u, self.v, len(self.P))


def _sorted_edges(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    e = np.stack([np.minimum(u, v), np.maximum(u, v)], axis=1).astype(np.int64)
    return e[np.lexsort((e[:, 1], e[:, 0]))] if len(e) else e.reshape(0, 2)


# ----------------------------------------------------------------------------- MST
@njit(cache=True)
def _kruskal(n, u, v, order, target):
    parent = np.arange(n)
    size = np.ones(n, dtype=np.int64)
    out = np.empty((target, 2), dtype=np.int64)
    k = 0
    for idx in order:
        if k == target:
            break
        a = find_root(parent, u[idx])
        b = find_root(parent, v[idx])
        if a == b:
            continue
        union_roots(parent, size, a, b)
        out[k, 0] = u[idx]
        out[k, 1] = v[idx]
        k += 1
    return out[:k]


def euclidean_mst(points: ArrayLike | Delaunay) -> np.ndarray:
    """Edges of a Euclidean minimum spanning tree, (n_distinct - 1, 2), i < j, rows sorted.

    Kruskal over the Delaunay edges with an exact length order, so the total
    length is optimal even among near-ties; equal lengths are broken by the
    endpoints' coordinates, so the tree is the same for any input order.
    Duplicates are merged: the tree spans the distinct points, and a duplicate
    index (``Delaunay(points).index_map[i] != i``) appears in no edge.
    Collinear input gives the chain; fewer than 2 distinct points give no edge.

    >>> euclidean_mst([(0, 0), (1, 0), (2, 0), (1, 0)]).tolist()
    [[0, 1], [1, 2]]
    """
    g = _Graph(points)
    n_distinct = int(np.count_nonzero(g.index_map == np.arange(len(g.P))))
    if n_distinct < 2:
        return np.zeros((0, 2), dtype=np.int64)
    order = length_order(g.P, g.u, g.v)
    tree = _kruskal(len(g.P), g.u, g.v, order, n_distinct - 1)
    return _sorted_edges(tree[:, 0], tree[:, 1])


class Pair(NamedTuple):
    """Two point indices (a tuple: ``i, j = pair`` and ``pair == (i, j)`` work)."""

    i: int
    j: int


def closest_pair(points: ArrayLike | Delaunay) -> Pair:
    """A pair ``Pair(i, j)``, i < j, of points at minimum distance (exact).

    If some points coincide the distance is 0, and the answer is the two smallest
    indices of the duplicated location with the smallest (x, y).  Otherwise it is
    the shortest Delaunay edge; among equally short ones, the one whose endpoints
    come first in (x, y) order.  Fewer than 2 points raise ``ValueError``.

    >>> closest_pair([(0, 0), (5, 5), (1, 1), (5, 6)])
    Pair(i=1, j=3)
    >>> closest_pair([(3, 3), (1, 1), (3, 3), (1, 1)])
    Pair(i=1, j=3)
    """
    d = as_delaunay(points)
    P = d.points
    n_live = int(np.count_nonzero(d.live))
    if n_live < 2:
        raise ValueError(f"closest_pair needs at least 2 points, got {n_live}")
    g = _Graph(d)
    rep = g.index_map
    dup = np.flatnonzero((rep != np.arange(len(P))) & (rep >= 0))    # removed points: rep -1
    if len(dup):
        groups = np.unique(rep[dup])
        first = groups[np.lexsort((P[groups, 1], P[groups, 0]))[0]]
        return Pair(int(first), int(np.min(dup[rep[dup] == first])))
    i = length_order(P, g.u, g.v, first_only=True)[0]
    return Pair(int(g.u[i]), int(g.v[i]))


# ----------------------------------------------------------------------------- Gabriel and RNG
@njit(cache=True)
def _gabriel_mask(X, Y, u, v, a1, a2):
    w = scratch()
    keep = np.ones(len(u), dtype=np.bool_)
    for i in range(len(u)):
        p, q = u[i], v[i]
        for r in (a1[i], a2[i]):
            if r >= 0 and dot_sign(X[p], Y[p], X[q], Y[q], X[r], Y[r], w) <= 0:
                keep[i] = False
    return keep


def gabriel_graph(points: ArrayLike | Delaunay) -> np.ndarray:
    """Edges (k, 2), i < j, rows sorted, of the Gabriel graph.

    p and q are joined when the *closed* disc with diameter pq contains no other
    point, that is (r - p) . (r - q) > 0 for every other point r (exact).  This
    is the standard definition; it makes the graph unique and a subgraph of every
    Delaunay triangulation (with "strictly inside" instead, both diagonals of a
    square would qualify and cross).  A Delaunay edge passes iff the apexes of its
    one or two triangles are outside that disc (any point in the disc would lie
    in an empty circumcircle otherwise).  Collinear input gives the chain;
    duplicates are merged (only representatives appear).

    >>> gabriel_graph([(0, 0), (1, 0), (1, 1), (0, 1)]).tolist()   # the square's diagonals fail
    [[0, 1], [0, 3], [1, 2], [2, 3]]
    """
    g = _Graph(points)
    keep = _gabriel_mask(g.P[:, 0].copy(), g.P[:, 1].copy(), g.u, g.v, g.a1, g.a2)
    return _sorted_edges(g.u[keep], g.v[keep])


@njit(cache=True, inline="always")
def _in_lune(X, Y, r, p, q, w):
    """max(|rp|, |rq|) < |pq| exactly."""
    return (sq_dist_cmp(X[r], Y[r], X[p], Y[p], X[p], Y[p], X[q], Y[q], w) < 0
            and sq_dist_cmp(X[r], Y[r], X[q], Y[q], X[p], Y[p], X[q], Y[q], w) < 0)


@njit(cache=True, inline="always")
def _disc_step(X, Y, indptr, indices, stack, st, seen, stamp, c, o, w):
    """One step of the search of the open disc centred c with radius |co|.

    ``st`` = [stack top, next adjacency slot, end of adjacency].  A step either
    takes the next vertex off the stack or looks at one neighbour.  Returns
    1 if a point of the lune of co was met, -1 if the disc is exhausted, else 0.
    """
    if st[1] == st[2]:
        if st[0] == 0:
            return -1
        st[0] -= 1
        x = stack[st[0]]
        st[1] = indptr[x]
        st[2] = indptr[x + 1]
        return 0
    y = indices[st[1]]
    st[1] += 1
    if seen[y] != stamp:
        seen[y] = stamp
        if sq_dist_cmp(X[y], Y[y], X[c], Y[c], X[c], Y[c], X[o], Y[o], w) < 0:
            if sq_dist_cmp(X[y], Y[y], X[o], Y[o], X[c], Y[c], X[o], Y[o], w) < 0:
                return 1
            stack[st[0]] = y
            st[0] += 1
    return 0


@njit(cache=True)
def _rng_mask(X, Y, u, v, a1, a2, indptr, indices):
    """For each candidate edge pq: is the open lune of pq empty?

    The points of S inside the open disc D(p, |pq|) induce a connected subgraph of
    any Delaunay triangulation containing p (every such t has a Delaunay
    neighbour strictly closer to p: the one whose Voronoi cell the segment from t
    to p enters first), so a search from p that only enters that disc meets every
    point of the lune.  The searches from p and from q advance one neighbour at a
    time in turns, and the first one to run out proves the lune empty.
    """
    w = scratch()
    n = len(X)
    keep = np.ones(len(u), dtype=np.bool_)
    seen_p = np.full(n, -1, dtype=np.int64)
    seen_q = np.full(n, -1, dtype=np.int64)
    stack_p = np.empty(n, dtype=np.int64)
    stack_q = np.empty(n, dtype=np.int64)
    st_p = np.zeros(3, dtype=np.int64)
    st_q = np.zeros(3, dtype=np.int64)
    for i in range(len(u)):
        p, q = u[i], v[i]
        if (a1[i] >= 0 and _in_lune(X, Y, a1[i], p, q, w)) or \
                (a2[i] >= 0 and _in_lune(X, Y, a2[i], p, q, w)):
            keep[i] = False
            continue
        seen_p[p] = seen_p[q] = i      # q is on the boundary of p's disc, not inside: skip
        seen_q[q] = seen_q[p] = i      # the exact (tie) evaluation of |pq| against itself
        stack_p[0], stack_q[0] = p, q
        st_p[0], st_p[1], st_p[2] = 1, 0, 0       # one vertex (p) on the stack, no neighbour pending
        st_q[0], st_q[1], st_q[2] = 1, 0, 0
        while True:
            r = _disc_step(X, Y, indptr, indices, stack_p, st_p, seen_p, i, p, q, w)
            if r == 0:
                r = _disc_step(X, Y, indptr, indices, stack_q, st_q, seen_q, i, q, p, w)
            if r != 0:
                keep[i] = r < 0
                break
    return keep


def relative_neighborhood_graph(points: ArrayLike | Delaunay) -> np.ndarray:
    """Edges (k, 2), i < j, rows sorted, of the relative neighbourhood graph (RNG).

    p and q are joined when no point r is closer to both than they are to each
    other: no r with max(|rp|, |rq|) < |pq| (the open lune is empty; exact).
    It lies between the EMST and the Gabriel graph, so only Gabriel edges are
    candidates.  Collinear input gives the chain; duplicates are merged.

    >>> relative_neighborhood_graph([(0, 0), (2, 0), (1, 1)]).tolist()   # (1, 1) is in the lune of 0-1
    [[0, 2], [1, 2]]
    """
    g = _Graph(points)
    X, Y = g.P[:, 0].copy(), g.P[:, 1].copy()
    gab = _gabriel_mask(X, Y, g.u, g.v, g.a1, g.a2)
    indptr, indices = g.adjacency()
    keep = _rng_mask(X, Y, g.u[gab], g.v[gab], g.a1[gab], g.a2[gab], indptr, indices)
    return _sorted_edges(g.u[gab][keep], g.v[gab][keep])
