"""The fast incremental Delaunay kernel (numba): Bowyer-Watson on flat arrays.

This is the engine behind ``reference_impl.Delaunay``; read ``delaunay.py`` for
the public API.  The mesh, in the style of Delaunator:

* vertices are ``0 .. n-1`` (their insertion rank); ``INF = -1`` is the
  *infinite vertex*: every convex-hull edge (u, v) has a *ghost triangle*
  (v, u, INF) outside it, so the outside of the hull is triangulated too and no
  super-triangle (with its coordinate limits) is needed;
* ``tri[3*t + k]`` is vertex k of triangle t, counter-clockwise;
* ``nbr[3*t + k]`` is the triangle across the edge opposite vertex k, that is
  across edge (tri[3t + k+1], tri[3t + k+2]) (indices mod 3).  Every triangle
  has three neighbours, because ghosts close the surface;
* a dead triangle slot has ``tri[3*t] == DEAD``.

Insertion of point p (Bowyer-Watson):

1. *locate*: walk from the last new triangle towards p, crossing any edge that
   has p strictly on its other side; stop in a triangle containing p, or in a
   ghost when p is outside the hull;
2. *cavity*: depth-first search over neighbours, collecting every triangle in
   *conflict* with p (p strictly inside its circumcircle; for a ghost (u, v,
   INF): p strictly left of u->v, or on the line strictly inside segment uv);
   the conflict region is connected and star-shaped from p;
3. *fill*: connect p to every cavity boundary edge; the new triangles reuse the
   dead slots (there are always two more new triangles than dead ones).

All geometric decisions use the exact predicates, so degenerate input (grids,
cocircular points, collinear runs) cannot corrupt the mesh.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from .predicates import incircle_nb, orient2d_nb

INF = -1
DEAD = -2

# state array fields
S_NTRI, S_STAMP, S_LAST, S_NDEAD = 0, 1, 2, 3
# statistics (counted, never used for decisions): walk steps, conflict tests, cavity triangles
S_STEPS, S_TESTS, S_BAD = 4, 5, 6
STATE_SIZE = 8


@njit(cache=True, inline="always")
def _is_ghost(tri, t):
    return tri[3 * t] == INF or tri[3 * t + 1] == INF or tri[3 * t + 2] == INF


@njit(cache=True, inline="always")
def _in_conflict(tri, t, X, Y, px, py, w):
    a = tri[3 * t]
    b = tri[3 * t + 1]
    c = tri[3 * t + 2]
    if c == INF:
        u, v = a, b
    elif a == INF:
        u, v = b, c
    elif b == INF:
        u, v = c, a
    else:
        return incircle_nb(X[a], Y[a], X[b], Y[b], X[c], Y[c], px, py, w) > 0
    o = orient2d_nb(X[u], Y[u], X[v], Y[v], px, py, w)
    if o != 0:
        return o > 0
    # on the hull line: in conflict only strictly inside the segment
    if X[u] != X[v]:
        return min(X[u], X[v]) < px < max(X[u], X[v])
    return min(Y[u], Y[v]) < py < max(Y[u], Y[v])


@njit(cache=True, inline="always")
def real_neighbour_of_ghost(tri, nbr, t):
    """The real triangle across the hull edge of ghost t (t itself if it is real)."""
    for k in range(3):
        if tri[3 * t + k] == INF:
            return nbr[3 * t + k]
    return t


@njit(cache=True, inline="always")
def locate(tri, nbr, X, Y, px, py, start, w, state):
    """Walk from triangle ``start`` to a triangle whose closure contains p.

    Returns a real triangle containing p, or a ghost triangle whose hull edge
    sees p strictly on its outer side.  Terminates because the mesh is Delaunay.
    """
    t = real_neighbour_of_ghost(tri, nbr, start)
    prev = -1
    while True:
        moved = False
        for k in range(3):
            o = nbr[3 * t + k]
            if o == prev:
                continue
            u = tri[3 * t + (k + 1) % 3]
            v = tri[3 * t + (k + 2) % 3]
            if orient2d_nb(X[u], Y[u], X[v], Y[v], px, py, w) < 0:
                state[S_STEPS] += 1
                prev = t
                t = o
                moved = True
                break
        if not moved or _is_ghost(tri, t):
            return t


@njit(cache=True, inline="always")
def _new_slot(tri, nbr, state, bad, nbad, used):
    if used < nbad:
        return bad[used]
    t = state[S_NTRI]
    state[S_NTRI] = t + 1
    return t


@njit(cache=True, inline="always")
def insert(p, X, Y, tri, nbr, mark, stack, bad, ba, bb, bo, start_of, state, w):
    """Insert vertex p (coordinates X[p], Y[p]) into a mesh with at least one triangle.

    Returns -1 when inserted, or the vertex that p duplicates exactly (then the
    mesh is unchanged).  Scratch arrays: ``mark`` (per triangle), ``stack``,
    ``bad``, ``ba``, ``bb``, ``bo`` (per cavity; as long as the triangle arrays)
    and ``start_of`` (per vertex, index v + 1).
    """
    px = X[p]
    py = Y[p]
    t = locate(tri, nbr, X, Y, px, py, state[S_LAST], w, state)
    if not _is_ghost(tri, t):
        for k in range(3):
            v = tri[3 * t + k]
            if X[v] == px and Y[v] == py:
                return v
    # --- cavity: depth-first search from t (which is in conflict) -------------
    state[S_STAMP] += 1
    stamp = state[S_STAMP]
    mark[t] = stamp
    bad[0] = t
    nbad = 1
    stack[0] = t
    top = 1
    nb = 0
    while top > 0:
        top -= 1
        s = stack[top]
        for k in range(3):
            o = nbr[3 * s + k]
            mo = mark[o]
            if mo == stamp:
                continue
            if mo == -stamp:
                conflict = False
            else:
                state[S_TESTS] += 1
                conflict = _in_conflict(tri, o, X, Y, px, py, w)
            if conflict:
                mark[o] = stamp
                bad[nbad] = o
                nbad += 1
                stack[top] = o
                top += 1
            else:
                mark[o] = -stamp
                ba[nb] = tri[3 * s + (k + 1) % 3]
                bb[nb] = tri[3 * s + (k + 2) % 3]
                bo[nb] = o
                nb += 1
    state[S_BAD] += nbad
    # --- fill: one new triangle (a, b, p) per boundary edge (a, b) ------------
    last_real = -1
    for i in range(nb):
        a = ba[i]
        b = bb[i]
        o = bo[i]
        s = _new_slot(tri, nbr, state, bad, nbad, i)
        tri[3 * s] = a
        tri[3 * s + 1] = b
        tri[3 * s + 2] = p
        nbr[3 * s + 2] = o
        # the outside triangle o now faces s across edge (b, a)
        for j in range(3):
            x = tri[3 * o + j]
            if x != a and x != b:
                nbr[3 * o + j] = s
                break
        start_of[a + 1] = s
        mark[s] = 0
        if a != INF and b != INF:
            last_real = s
        bo[i] = s  # reuse: bo now holds the new triangle of boundary edge i
    for i in range(nb):
        s = bo[i]
        s2 = start_of[bb[i] + 1]   # the new triangle (b, c, p) that follows (a, b, p)
        nbr[3 * s] = s2
        nbr[3 * s2 + 1] = s
    state[S_LAST] = last_real
    return -1


@njit(cache=True)
def _link_brute(tri, nbr, ts):
    # link a handful of triangles by their shared edges (used to seed the mesh)
    for i in ts:
        for k in range(3):
            u = tri[3 * i + (k + 1) % 3]
            v = tri[3 * i + (k + 2) % 3]
            for j in ts:
                if j == i:
                    continue
                for m in range(3):
                    if tri[3 * j + (m + 1) % 3] == v and tri[3 * j + (m + 2) % 3] == u:
                        nbr[3 * i + k] = j


@njit(cache=True)
def seed(a, b, c, X, Y, tri, nbr, state, w):
    """Start the mesh with the non-degenerate triangle (a, b, c) and its three ghosts."""
    if orient2d_nb(X[a], Y[a], X[b], Y[b], X[c], Y[c], w) < 0:
        b, c = c, b
    vs = (a, b, c)
    tri[0] = a
    tri[1] = b
    tri[2] = c
    for k in range(3):
        u = vs[k]
        v = vs[(k + 1) % 3]
        g = k + 1
        tri[3 * g] = v
        tri[3 * g + 1] = u
        tri[3 * g + 2] = INF
    _link_brute(tri, nbr, np.arange(4))
    state[S_NTRI] = 4
    state[S_LAST] = 0


@njit(cache=True)
def build(X, Y, tri, nbr, mark, stack, bad, ba, bb, bo, start_of, state, dup, w):
    """Triangulate vertices 0..n-1 in index order.  ``dup[i]`` receives the vertex that i
    duplicates (or -1).  Returns False when every point is collinear (nothing built)."""
    n = X.shape[0]
    for i in range(n):
        dup[i] = -1
    # first two distinct points, then the first point off their line
    i1 = -1
    for i in range(1, n):
        if X[i] != X[0] or Y[i] != Y[0]:
            i1 = i
            break
    if i1 < 0:
        return False
    i2 = -1
    for i in range(i1 + 1, n):
        if orient2d_nb(X[0], Y[0], X[i1], Y[i1], X[i], Y[i], w) != 0:
            i2 = i
            break
    if i2 < 0:
        return False
    seed(0, i1, i2, X, Y, tri, nbr, state, w)
    for p in range(1, n):
        if p == i1 or p == i2:
            continue
        dup[p] = insert(p, X, Y, tri, nbr, mark, stack, bad, ba, bb, bo, start_of, state, w)
    return True


@njit(cache=True)
def extract(tri, nbr, ntri):
    """Compact the real triangles: returns (simplices, neighbors, internal->output map)."""
    out_of = np.full(ntri, -1, dtype=np.int64)
    m = 0
    for t in range(ntri):
        if tri[3 * t] != DEAD and not _is_ghost(tri, t):
            out_of[t] = m
            m += 1
    simp = np.empty((m, 3), dtype=np.int64)
    neig = np.empty((m, 3), dtype=np.int64)
    for t in range(ntri):
        r = out_of[t]
        if r < 0:
            continue
        for k in range(3):
            simp[r, k] = tri[3 * t + k]
            o = nbr[3 * t + k]
            neig[r, k] = out_of[o]
    return simp, neig, out_of


@njit(cache=True)
def hull_cycle(tri, nbr, ntri, nverts):
    """Vertices of the convex hull in counter-clockwise order (from the ghost triangles)."""
    nxt = np.full(nverts, -1, dtype=np.int64)
    first = -1
    count = 0
    for t in range(ntri):
        if tri[3 * t] == DEAD:
            continue
        for k in range(3):
            if tri[3 * t + k] == INF:
                # ghost (x, y, INF) in cyclic order sits on hull edge y -> x
                x = tri[3 * t + (k + 1) % 3]
                y = tri[3 * t + (k + 2) % 3]
                nxt[y] = x
                first = y
                count += 1
    out = np.empty(count, dtype=np.int64)
    v = first
    for i in range(count):
        out[i] = v
        v = nxt[v]
    return out


@njit(cache=True)
def find(tri, nbr, X, Y, qx, qy, start, w, state):
    """For each query point, a real triangle containing it, or -1 outside the hull."""
    res = np.empty(qx.shape[0], dtype=np.int64)
    t = start
    for i in range(qx.shape[0]):
        t = locate(tri, nbr, X, Y, qx[i], qy[i], t, w, state)
        if _is_ghost(tri, t):
            res[i] = -1
            t = real_neighbour_of_ghost(tri, nbr, t)
        else:
            res[i] = t
    return res
