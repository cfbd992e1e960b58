"""Vertex removal for the fast Delaunay kernel (numba): delete a star, refill the hole.

Used by ``Delaunay.remove`` and ``Delaunay.vertex_neighbors`` (see ``delaunay.py``);
the mesh layout (32-byte triangle records, ghost triangles, ``INF``) is described
in ``kernel.py``.  The comment below explains the method and why it is right with
cocircular ties.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from reference_impl.mesh.kernel import (DEAD, INF, MARK, NBR, RECORD, SPARE, STATE_SIZE, S_LAST, S_NTRI, S_STAMP, VTX,
                                        insert, is_ghost, seed)
from reference_impl.exact.predicates import incircle_nb, orient2d_nb
from reference_impl.mesh.status import FLAT, LOST, OK


# ============================================================================ removal
#
# Removing vertex v (Devillers' setting: delete the star, re-triangulate the hole).
#
# The star of v is the ring of triangles around it, ghosts included; its *link* is the
# cycle l_0 .. l_{d-1} of their outer vertices, counter-clockwise around v, so that star
# triangle i is (v, l_i, l_{i+1}) and the hole left by the star is the polygon
# l_0 -> l_1 -> ... -> l_{d-1} -> l_0 with the hole on the LEFT of every edge.  For a hull
# vertex INF is one of the l_i: the polygon runs through the infinite vertex, and the hull
# between v's two hull neighbours changes.  Every triangulation of the sphere (ghosts
# included) has 2(n+1) - 4 triangles, so the hole is always refilled with d - 2 triangles,
# and exactly two slots are freed.
#
# Why any Delaunay re-triangulation of the hole restricted to the polygon is right (with
# ties too): a triangle outside the star keeps its empty circumcircle when v goes away, so
# every edge outside the hole stays locally Delaunay; across a boundary edge l_i l_{i+1}
# the outside triangle's circle is empty of every point, the new opposite vertex included;
# and inside the hole every new triangle has a circle with no link vertex strictly inside.
# Locally Delaunay everywhere is globally Delaunay (Delaunay's lemma; for ghosts the same
# local test is the convexity of the hull).
#
# How the hole is filled (the "local re-triangulation" variant of the ear method):
#
# 1. the Delaunay triangulation of the real link vertices is built with the same kernel
#    (``insert``) in a small scratch mesh; its triangles have circles with no link vertex
#    strictly inside;
# 2. every boundary edge a b = l_i l_{i+1} is an edge of it, cocircular ties included, so
#    the re-triangulation agrees with the outside.  Proof: if a scratch edge x y crossed a b,
#    both would have circles with no link vertex strictly inside, and two crossing segments
#    with that property are cocircular (in the convex quadrilateral a x b y each pair of
#    opposite angles adds up to at most pi, and all four add up to 2 pi): a, b, x, y lie on
#    one circle C, with x on v's side of a b and y on the other side.  The circle Cv of the
#    star triangle (v, a, b) is empty and passes through a and b; it cannot bulge beyond C
#    on y's side (y would be strictly inside), so unless Cv = C it bulges beyond C on v's
#    side and x is strictly inside it.  Hence Cv = C: v, a, b, x, y are cocircular, with v
#    and y on opposite arcs cut by the chord a b.  But y is a link vertex, so v y is an edge
#    of the triangulation, and the chords v y and a b cross: impossible.  (Nor can a scratch
#    vertex lie inside the segment a b, an edge of the triangulation.)  The code checks it
#    anyway and reports LOST rather than corrupt the mesh;
# 3. a flood fill from the boundary edges, never crossing them, collects the scratch
#    triangles inside the hole (ghosts included for a hull vertex: they are the new hull
#    edges); there are d - 2 of them;
# 4. they are copied into d - 2 of the star's slots and stitched to the outside triangles
#    across the boundary edges; the two spare slots are freed by moving the last records of
#    the mesh into them (the mesh stays dense: no dead slots, ``insert`` and ``extract``
#    are untouched).
#
# Cost: O(d) for the star, the flood and the copy.  The scratch triangulation is built in
# link order, so each point is inserted next to the previous one and its walk is short; for
# a convex link (a point removed from the middle of a circle: every link vertex on the
# hull of the others) each insertion is O(1), and for the typical d = 6 the whole removal
# is a few dozen predicate calls.  (A contrived non-convex link can make the scratch
# Bowyer-Watson quadratic in d; randomising its order would bound it by O(d log d).)
# The vertex -> triangle map
# ``start_of`` (index v + 1) locates the star in O(1): ``insert`` keeps it right for every
# vertex on a cavity boundary (the only vertices whose triangles it destroys), the caller
# sets it for the inserted vertex, and ``remove`` sets it for the link vertices.



@njit(cache=True, inline="always")
def _index_of(M, t, x):
    for k in range(3):
        if M[RECORD * t + VTX + k] == x:
            return k
    return -1


@njit(cache=True, inline="always")
def _face(M, o, x, y, s):
    # triangle o (which has edge x-y) now faces s across that edge
    for j in range(3):
        z = M[RECORD * o + VTX + j]
        if z != x and z != y:
            M[RECORD * o + NBR + j] = s
            return


@njit(cache=True)
def init_vertex_map(M, ntri, start_of):
    """start_of[v + 1] = a triangle incident to v, for every vertex of the mesh (INF too)."""
    for t in range(ntri):
        if M[RECORD * t + VTX] == DEAD:
            continue
        for k in range(3):
            start_of[M[RECORD * t + VTX + k] + 1] = t


@njit(cache=True)
def degree(M, start_of, v):
    """Number of triangles around vertex v (ghosts included)."""
    t0 = start_of[v + 1]
    t = t0
    d = 0
    while True:
        k = _index_of(M, t, v)
        d += 1
        t = M[RECORD * t + NBR + (k + 1) % 3]   # across edge (v, next link vertex): counter-clockwise
        if t == t0:
            return d


@njit(cache=True)
def link(M, start_of, v):
    """The link of v: its neighbours counter-clockwise (INF for the outside of a hull vertex)."""
    out = np.empty(degree(M, start_of, v), dtype=np.int64)
    t0 = start_of[v + 1]
    t = t0
    i = 0
    while True:
        k = _index_of(M, t, v)
        out[i] = M[RECORD * t + VTX + (k + 1) % 3]
        i += 1
        t = M[RECORD * t + NBR + (k + 1) % 3]
        if t == t0:
            return out


@njit(cache=True)
def _free_slot(M, f, state, start_of):
    # Free triangle slot f by moving the last record into it (the mesh stays dense).
    last = state[S_NTRI] - 1
    if f != last:
        for j in range(RECORD):
            M[RECORD * f + j] = M[RECORD * last + j]   # the whole record
        for k in range(3):
            o = M[RECORD * f + NBR + k]
            for j in range(3):
                if M[RECORD * o + NBR + j] == last:
                    M[RECORD * o + NBR + j] = f
            x = M[RECORD * f + VTX + k]
            if start_of[x + 1] == last:
                start_of[x + 1] = f
        if state[S_LAST] == last:
            state[S_LAST] = f
    M[RECORD * last + VTX] = DEAD
    state[S_NTRI] = last


@njit(cache=True)
def _find_edge(M, start_of, x, y):
    # The scratch triangle holding the directed edge x -> y (it lies on the left), or -1:
    # turn around the real end point.
    if x != INF:
        c, nxt = x, 1
    else:
        c, nxt = y, 2
    other = y if x != INF else x
    t0 = start_of[c + 1]
    t = t0
    while True:
        k = _index_of(M, t, c)
        if M[RECORD * t + VTX + (k + nxt) % 3] == other:
            return t
        t = M[RECORD * t + NBR + (k + 1) % 3]
        if t == t0:
            return -1


@njit(cache=True)
def remove(v, P, M, stack, bad, ba, bb, bo, start_of, pos, state, w):
    """Remove vertex v from the mesh, keeping it Delaunay (see the comment above).

    Returns OK, or FLAT when the remaining points are all collinear (the mesh is then
    left untouched: the caller switches to its flat representation), or LOST if a sanity
    check of the re-triangulation fails (never expected; the mesh is then left for the
    caller to rebuild).  ``pos`` is per-vertex scratch (index v + 1); ``stack`` .. ``bo``
    are the insertion scratch arrays.
    """
    # --- 1. the star: link vertices, star slots, outside triangles -------------------------
    d = degree(M, start_of, v)
    lk = np.empty(d, dtype=np.int64)
    tris = np.empty(d, dtype=np.int64)
    outer = np.empty(d, dtype=np.int64)
    t0 = start_of[v + 1]
    t = t0
    h = -1                                  # position of INF in the link, if v is on the hull
    for i in range(d):
        k = _index_of(M, t, v)
        lk[i] = M[RECORD * t + VTX + (k + 1) % 3]
        tris[i] = t
        outer[i] = M[RECORD * t + NBR + k]         # across boundary edge l_i -> l_{i+1}
        if lk[i] == INF:
            h = i
        t = M[RECORD * t + NBR + (k + 1) % 3]
    if h > 0:                               # rotate so that INF is l_0
        lk = np.concatenate((lk[h:], lk[:h]))
        tris = np.concatenate((tris[h:], tris[:h]))
        outer = np.concatenate((outer[h:], outer[:h]))
    hull = h >= 0
    first = 1 if hull else 0                # lk[first:] are the real link vertices
    inf_slot = start_of[0]

    # --- 2. hull vertex whose other neighbours are collinear: the chain becomes the hull --
    a0 = lk[first]
    a1 = lk[first + 1]
    j2 = -1
    for j in range(first + 2, d):
        c = lk[j]
        if orient2d_nb(P[a0, 0], P[a0, 1], P[a1, 0], P[a1, 1], P[c, 0], P[c, 1], w) != 0:
            j2 = j
            break
    if j2 < 0:
        # (an interior vertex's link surrounds it, so only a hull vertex gets here)
        if is_ghost(M, outer[1]):
            return FLAT                     # nothing but the chain's line is left
        # fan from INF: ghost (INF, l_i, l_{i+1}) on the new hull edge l_{i+1} -> l_i
        for i in range(1, d - 1):
            s = tris[i - 1]
            M[RECORD * s + VTX] = INF
            M[RECORD * s + VTX + 1] = lk[i]
            M[RECORD * s + VTX + 2] = lk[i + 1]
            M[RECORD * s + MARK] = 0
        for i in range(1, d - 1):
            s = tris[i - 1]
            o = outer[i]
            M[RECORD * s + NBR] = o
            _face(M, o, lk[i], lk[i + 1], s)
            if i + 1 <= d - 2:
                M[RECORD * s + NBR + 1] = tris[i]
            else:
                M[RECORD * s + NBR + 1] = outer[d - 1]
                _face(M, outer[d - 1], lk[d - 1], INF, s)
            if i >= 2:
                M[RECORD * s + NBR + 2] = tris[i - 2]
            else:
                M[RECORD * s + NBR + 2] = outer[0]
                _face(M, outer[0], INF, lk[1], s)
            start_of[lk[i] + 1] = s
            start_of[lk[i + 1] + 1] = s
        start_of[0] = tris[0]
        state[S_LAST] = tris[0]
        _free_slot(M, max(tris[d - 2], tris[d - 1]), state, start_of)
        _free_slot(M, min(tris[d - 2], tris[d - 1]), state, start_of)
        return OK

    # --- 3. Delaunay triangulation of the real link vertices, in a scratch mesh ------------
    L = np.zeros(RECORD * (2 * d + 8), dtype=np.int32)
    lst = np.zeros(STATE_SIZE, dtype=np.int64)
    seed(a0, a1, lk[j2], P, L, lst, w)
    for j in range(first + 2, d):
        if j != j2:
            insert(lk[j], P, L, stack, bad, ba, bb, bo, start_of, lst, w)
    top = lst[S_NTRI]

    # --- 4. boundary positions and the scratch mesh's vertex -> triangle map --------------
    for i in range(d):
        pos[lk[i] + 1] = i
    if not hull:
        pos[0] = -2                         # INF is not on the boundary
    for t in range(top):
        for k in range(3):
            start_of[L[RECORD * t + VTX + k] + 1] = t

    # --- 5. flood fill from the boundary edges: the scratch triangles inside the hole ------
    # Every boundary edge is a scratch edge (see above), so the fill cannot leak; the hole has
    # no vertex inside, so it holds exactly d - 2 triangles.
    stamp = lst[S_STAMP] + 1
    fill = np.empty(top, dtype=np.int64)
    nfill = 0
    sp = 0
    for i in range(d):
        t = _find_edge(L, start_of, lk[i], lk[(i + 1) % d])
        if t < 0:
            return LOST
        if L[RECORD * t + MARK] != stamp:
            L[RECORD * t + MARK] = stamp
            stack[sp] = t
            sp += 1
    while sp > 0:
        sp -= 1
        s = stack[sp]
        fill[nfill] = s
        nfill += 1
        for k in range(3):
            x = L[RECORD * s + VTX + (k + 1) % 3]
            y = L[RECORD * s + VTX + (k + 2) % 3]
            if pos[y + 1] == (pos[x + 1] + 1) % d:
                continue                    # a boundary edge: the outside is beyond
            o = L[RECORD * s + NBR + k]
            if L[RECORD * o + MARK] != stamp:
                L[RECORD * o + MARK] = stamp
                stack[sp] = o
                sp += 1
    if nfill != d - 2:
        return LOST

    # --- 6. copy into the star's slots, stitch to the outside, free the two spare slots ----
    for j in range(nfill):
        L[RECORD * fill[j] + SPARE] = tris[j]        # destination slot
    for j in range(nfill):
        t = fill[j]
        s = tris[j]
        for k in range(3):
            M[RECORD * s + VTX + k] = L[RECORD * t + VTX + k]
        for k in range(3):
            x = L[RECORD * t + VTX + (k + 1) % 3]
            y = L[RECORD * t + VTX + (k + 2) % 3]
            px = pos[x + 1]
            if pos[y + 1] == (px + 1) % d:
                o = outer[px]
                M[RECORD * s + NBR + k] = o
                _face(M, o, x, y, s)
            else:
                M[RECORD * s + NBR + k] = L[RECORD * L[RECORD * t + NBR + k] + SPARE]
        M[RECORD * s + MARK] = 0
        for k in range(3):
            start_of[M[RECORD * s + VTX + k] + 1] = s
    if not hull:
        start_of[0] = inf_slot
    state[S_LAST] = tris[0]
    _free_slot(M, max(tris[d - 2], tris[d - 1]), state, start_of)
    _free_slot(M, min(tris[d - 2], tris[d - 1]), state, start_of)
    return OK


@njit(cache=True)
def strict_link(M, P, start_of, v, w):
    """The neighbours of v in the unique Delaunay graph: its link without INF and without
    the diagonals of cocircular points.

    Edge v-x separates the triangles (v, a, x) and (v, x, b); it has a circle through v and
    x with every other point strictly outside (equivalently, the Voronoi cells of v and x
    share an edge of positive length) unless b lies on the circle of (v, a, x), i.e. the
    edge is one of several ways to triangulate a cocircular polygon.  Hull edges always
    qualify.  So the answer does not depend on how ties were triangulated.
    """
    lk = link(M, start_of, v)
    d = lk.shape[0]
    out = np.empty(d, dtype=np.int64)
    m = 0
    for i in range(d):
        x = lk[i]
        if x == INF:
            continue
        a = lk[(i + d - 1) % d]
        b = lk[(i + 1) % d]
        if (a == INF or b == INF
                or incircle_nb(P[v, 0], P[v, 1], P[a, 0], P[a, 1], P[x, 0], P[x, 1],
                               P[b, 0], P[b, 1], w) != 0):
            out[m] = x
            m += 1
    return out[:m]
