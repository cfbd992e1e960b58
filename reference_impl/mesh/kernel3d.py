"""The incremental 3D Delaunay kernel (numba): Bowyer-Watson on flat tetrahedron arrays.

This is the engine behind ``reference_impl.Delaunay3D`` (read ``delaunay3d.py``
for the public API).  It mirrors the 2D kernel ``kernel.py``:

* vertices are ``0 .. n-1`` (their insertion rank); ``INF = -1`` is the
  *infinite vertex*.  Every convex-hull facet has a *ghost tetrahedron* joining
  it to INF, so the outside of the hull is tetrahedralised too and no
  super-tetrahedron (with its coordinate limits) is needed;
* ``tet[4*t + k]`` is vertex k of tetrahedron t; every tetrahedron is positively
  oriented (``orient3d > 0``, see ``predicates3d``), ghosts too if INF is read as
  a point far outside the hull: the face ``FACES[k]`` opposite vertex k is
  counter-clockwise seen from outside the tetrahedron;
* ``nbr[4*t + k]`` is the tetrahedron across the face opposite vertex k;
* a dead slot has ``tet[4*t] == DEAD`` and sits on a free list.

Insertion of point p:

1. *locate*: a visibility walk from the last new tetrahedron, crossing a face
   when p is strictly beyond it (face order chosen pseudo-randomly, Devillers'
   stochastic walk); it ends in a real tetrahedron whose closure contains p, or
   in a ghost whose hull facet has p strictly beyond it.  A step limit guards
   against cycles (which Delaunay meshes do not have) with a linear scan;
2. *cavity*: depth-first search collecting the tetrahedra in *conflict* with p:
   p strictly inside the circumsphere (``insphere > 0``); for a ghost on hull
   facet f: p strictly beyond the plane of f, or in that plane and strictly
   inside the circumcircle of f.  The circle test is the textbook trick (CGAL's
   ``coplanar_side_of_bounded_circle`` uses a point off the plane): any sphere
   through f cuts f's plane in f's circumcircle, so for p in the plane, "inside
   the circle" is "inside the sphere of the real tetrahedron across f" -- one
   exact ``insphere`` on input doubles, no projection (projecting to a
   coordinate plane keeps orientation but maps circles to ellipses);
3. *fill*: one new tetrahedron (x, y, z, p) per cavity boundary face (x, y, z);
   new tetrahedra are glued to each other through the boundary edges they
   share (a half-edge list per vertex, cleared by a stamp).

Because every conflict test is strict and exact, each boundary face has p
strictly on its inner side, so no flat tetrahedron is ever created, even on
cospherical input such as integer grids.  Arrays fill up: ``insert`` then
returns ``GROW`` without touching the mesh and the caller enlarges them.

Driven from Python by ``delaunay3d.Mesh`` (points already in insertion order):

>>> import numpy as np
>>> from reference_impl.mesh.delaunay3d import Mesh
>>> m = Mesh(np.array([[0., 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.875, 0.875, 0.875]]))
>>> simplices, neighbors, _, hull = m.extract()
>>> simplices.tolist()                 # three tetrahedra around the edge 0-4
[[0, 1, 3, 4], [0, 3, 2, 4], [0, 2, 1, 4]]
>>> len(hull)
6
"""
from __future__ import annotations

import numpy as np
from numba import njit

from reference_impl.exact.predicates import orient2d_nb
from reference_impl.mesh.status import FLAT, GROW, OK
from reference_impl.exact.predicates3d import insphere_nb, orient3d_nb

INF = -1
DEAD = -2

# state fields
S_NTET, S_STAMP, S_LAST, S_NFREE, S_NEXT, S_RNG = 0, 1, 2, 3, 4, 5
S_SEED1, S_SEED2, S_SEED3, S_NEED = 6, 7, 8, 9          # seeds; what GROW needs (1 tets, 2 cavity)
S_STEPS, S_TESTS, S_BAD, S_SCANS = 10, 11, 12, 13       # statistics, never used for decisions
STATE_SIZE = 16

# results of insert() and build(): see status.py (OK, GROW, FLAT)

_F = np.array([[1, 3, 2], [0, 2, 3], [0, 3, 1], [0, 1, 2]], dtype=np.int64)  # = predicates3d.FACES


@njit(cache=True)
def inf_pos(tet, t):
    """Position of INF in tetrahedron t, or -1 for a real one."""
    for k in range(4):
        if tet[4 * t + k] == INF:
            return k
    return -1


@njit(cache=True)
def _face_orient(tet, t, k, X, Y, Z, px, py, pz, w):
    """orient3d(face k of t, p): > 0 when p is on t's side of the face, < 0 beyond it."""
    a = tet[4 * t + _F[k, 0]]
    b = tet[4 * t + _F[k, 1]]
    c = tet[4 * t + _F[k, 2]]
    return orient3d_nb(X[a], Y[a], Z[a], X[b], Y[b], Z[b], X[c], Y[c], Z[c], px, py, pz, w)


@njit(cache=True)
def _insphere_tet(tet, t, X, Y, Z, px, py, pz, w):
    a = tet[4 * t]
    b = tet[4 * t + 1]
    c = tet[4 * t + 2]
    d = tet[4 * t + 3]
    return insphere_nb(X[a], Y[a], Z[a], X[b], Y[b], Z[b], X[c], Y[c], Z[c],
                       X[d], Y[d], Z[d], px, py, pz, w)


@njit(cache=True)
def in_conflict(tet, nbr, t, X, Y, Z, px, py, pz, w):
    """Is p strictly inside the circumsphere of t (for a ghost: see the module docstring)?"""
    k = inf_pos(tet, t)
    if k < 0:
        return _insphere_tet(tet, t, X, Y, Z, px, py, pz, w) > 0
    # ghost: its face opposite INF is the hull facet; p beyond it <=> orient3d > 0
    o = _face_orient(tet, t, k, X, Y, Z, px, py, pz, w)
    if o != 0:
        return o > 0
    return _insphere_tet(tet, nbr[4 * t + k], X, Y, Z, px, py, pz, w) > 0


@njit(cache=True)
def _rand(state):
    x = state[S_RNG]
    x ^= (x << 13) & 0xFFFFFFFF
    x ^= x >> 17
    x ^= (x << 5) & 0xFFFFFFFF
    state[S_RNG] = x
    return x


@njit(cache=True)
def _scan(tet, X, Y, Z, px, py, pz, w, state):
    """Linear search for a real tetrahedron containing p or a ghost that sees p (fallback)."""
    state[S_SCANS] += 1
    for t in range(state[S_NTET]):
        if tet[4 * t] == DEAD:
            continue
        k = inf_pos(tet, t)
        if k >= 0:
            if _face_orient(tet, t, k, X, Y, Z, px, py, pz, w) > 0:
                return t
            continue
        inside = True
        for j in range(4):
            if _face_orient(tet, t, j, X, Y, Z, px, py, pz, w) < 0:
                inside = False
                break
        if inside:
            return t
    return -1


@njit(cache=True)
def locate(tet, nbr, X, Y, Z, px, py, pz, start, w, state):
    """Walk from ``start`` to a real tetrahedron whose closure contains p, or to a ghost
    whose hull facet has p strictly beyond it."""
    t = start
    k = inf_pos(tet, t)
    if k >= 0:
        t = nbr[4 * t + k]
    prev = -1
    limit = 4 * state[S_NTET] + 64
    steps = 0
    while True:
        r = _rand(state)
        moved = False
        for i in range(4):
            k = (r + i) & 3
            o = nbr[4 * t + k]
            if o == prev:
                continue
            if _face_orient(tet, t, k, X, Y, Z, px, py, pz, w) < 0:
                prev = t
                t = o
                moved = True
                break
        if not moved:
            return t
        steps += 1
        state[S_STEPS] += 1
        if inf_pos(tet, t) >= 0:
            return t
        if steps > limit:
            return _scan(tet, X, Y, Z, px, py, pz, w, state)


@njit(cache=True)
def insert(p, X, Y, Z, tet, nbr, mark, free, stack, bad, bf, bo, bj,
           vst, vhead, enext, eto, etet, eface, state, w):
    """Insert vertex p.  Returns OK (-1) when inserted, the vertex p duplicates (mesh unchanged),
    or GROW when the arrays are too small (mesh unchanged; ``state[S_NEED]`` says which)."""
    px = X[p]
    py = Y[p]
    pz = Z[p]
    t = locate(tet, nbr, X, Y, Z, px, py, pz, state[S_LAST], w, state)
    if t < 0:
        raise RuntimeError("point location failed: the mesh is corrupt")
    if inf_pos(tet, t) < 0:
        for k in range(4):
            v = tet[4 * t + k]
            if X[v] == px and Y[v] == py and Z[v] == pz:
                return v
    ccap = bad.shape[0]
    # --- cavity: depth-first search from t (which is in conflict) ------------------------
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
        for k in range(4):
            o = nbr[4 * s + k]
            mo = mark[o]
            if mo == stamp:
                continue
            if mo == -stamp:
                conflict = False
            else:
                state[S_TESTS] += 1
                conflict = in_conflict(tet, nbr, o, X, Y, Z, px, py, pz, w)
            if conflict:
                if nbad >= ccap:
                    state[S_NEED] = 2
                    return GROW
                mark[o] = stamp
                bad[nbad] = o
                nbad += 1
                stack[top] = o
                top += 1
            else:
                if nb >= ccap:
                    state[S_NEED] = 2
                    return GROW
                mark[o] = -stamp
                for j in range(3):
                    bf[3 * nb + j] = tet[4 * s + _F[k, j]]
                bo[nb] = o
                for j in range(4):
                    if nbr[4 * o + j] == s:
                        bj[nb] = j
                        break
                nb += 1
    extra = nb - nbad - state[S_NFREE]
    if extra > 0 and state[S_NTET] + extra > tet.shape[0] // 4:
        state[S_NEED] = 1
        return GROW
    state[S_BAD] += nbad
    # --- fill: one tetrahedron (x, y, z, p) per boundary face (x, y, z) -----------------
    ne = 0
    last_real = -1
    for i in range(nb):
        if i < nbad:
            s = bad[i]
        elif state[S_NFREE] > 0:
            state[S_NFREE] -= 1
            s = free[state[S_NFREE]]
        else:
            s = state[S_NTET]
            state[S_NTET] = s + 1
        x = bf[3 * i]
        y = bf[3 * i + 1]
        z = bf[3 * i + 2]
        tet[4 * s] = x
        tet[4 * s + 1] = y
        tet[4 * s + 2] = z
        tet[4 * s + 3] = p
        o = bo[i]
        nbr[4 * s + 3] = o
        nbr[4 * o + bj[i]] = s
        mark[s] = 0
        if x != INF and y != INF and z != INF:
            last_real = s
        # glue through the boundary edges: x->y lies on face 2, y->z on face 0, z->x on face 1
        for h in range(3):
            if h == 0:
                u, v, f = x, y, 2
            elif h == 1:
                u, v, f = y, z, 0
            else:
                u, v, f = z, x, 1
            found = False
            if vst[v + 1] == stamp:
                e = vhead[v + 1]
                before = -1
                while e >= 0:
                    if eto[e] == u:
                        s2 = etet[e]
                        nbr[4 * s + f] = s2
                        nbr[4 * s2 + eface[e]] = s
                        if before < 0:
                            vhead[v + 1] = enext[e]
                        else:
                            enext[before] = enext[e]
                        found = True
                        break
                    before = e
                    e = enext[e]
            if not found:
                if vst[u + 1] != stamp:
                    vst[u + 1] = stamp
                    vhead[u + 1] = -1
                enext[ne] = vhead[u + 1]
                vhead[u + 1] = ne
                eto[ne] = v
                etet[ne] = s
                eface[ne] = f
                ne += 1
    for i in range(nb, nbad):          # more dead than new: free the rest
        d = bad[i]
        tet[4 * d] = DEAD
        free[state[S_NFREE]] = d
        state[S_NFREE] += 1
    # the next walk starts here (locate steps from a ghost to its real neighbour)
    state[S_LAST] = last_real if last_real >= 0 else s
    return OK


@njit(cache=True)
def _collinear(a, b, c, X, Y, Z, w):
    """Exactly: are the three points on one line (all three projections collinear)?"""
    return (orient2d_nb(X[a], Y[a], X[b], Y[b], X[c], Y[c], w) == 0
            and orient2d_nb(Y[a], Z[a], Y[b], Z[b], Y[c], Z[c], w) == 0
            and orient2d_nb(X[a], Z[a], X[b], Z[b], X[c], Z[c], w) == 0)


@njit(cache=True)
def _seed(a, b, c, d, X, Y, Z, tet, nbr, state, w):
    """Start with the tetrahedron (a, b, c, d) (reordered to be positive) and its 4 ghosts."""
    if orient3d_nb(X[a], Y[a], Z[a], X[b], Y[b], Z[b], X[c], Y[c], Z[c], X[d], Y[d], Z[d], w) < 0:
        b, c = c, b
    tet[0] = a
    tet[1] = b
    tet[2] = c
    tet[3] = d
    for k in range(4):
        g = k + 1
        x = tet[_F[k, 0]]
        y = tet[_F[k, 1]]
        z = tet[_F[k, 2]]
        tet[4 * g] = x          # ghost (x, z, y, INF): its face opposite INF is (x, z, y),
        tet[4 * g + 1] = z      # counter-clockwise seen from inside the hull
        tet[4 * g + 2] = y
        tet[4 * g + 3] = INF
    for i in range(5):          # glue the five by their shared faces
        for k in range(4):
            f0 = tet[4 * i + _F[k, 0]]
            f1 = tet[4 * i + _F[k, 1]]
            f2 = tet[4 * i + _F[k, 2]]
            for j in range(5):
                if j == i:
                    continue
                hits = 0
                for m in range(4):
                    v = tet[4 * j + m]
                    if v == f0 or v == f1 or v == f2:
                        hits += 1
                if hits == 3:
                    nbr[4 * i + k] = j
    state[S_NTET] = 5
    state[S_LAST] = 0


@njit(cache=True)
def _spanning(X, Y, Z, w):
    """With vertex 0, the first vertices that span space: i1, the first point other than
    vertex 0; i2, the first after i1 off the line (0, i1); i3, the first after i2 off the
    plane (0, i1, i2).  Those not found are -1 (then the points are coplanar)."""
    i1 = i2 = i3 = -1                   # (no array: build, the caller, allocates nothing)
    for i in range(1, X.shape[0]):
        if i1 < 0:
            if X[i] != X[0] or Y[i] != Y[0] or Z[i] != Z[0]:
                i1 = i
        elif i2 < 0:
            if not _collinear(0, i1, i, X, Y, Z, w):
                i2 = i
        elif orient3d_nb(X[0], Y[0], Z[0], X[i1], Y[i1], Z[i1], X[i2], Y[i2], Z[i2],
                         X[i], Y[i], Z[i], w) != 0:
            i3 = i
            break
    return i1, i2, i3


@njit(cache=True, _nrt=False)
def build(X, Y, Z, tet, nbr, mark, free, stack, bad, bf, bo, bj,
          vst, vhead, enext, eto, etet, eface, state, dup, w):
    """Tetrahedralise vertices 0..n-1 in index order, resuming at ``state[S_NEXT]``.

    ``dup[i]`` receives the vertex that i duplicates (or -1).  Returns FLAT when
    all points are coplanar (nothing built), OK, or GROW when the arrays must be
    enlarged (see ``state[S_NEED]``) before calling again.

    Compiled without numba's reference counting, as the 2D ``kernel.build`` is (its
    docstring says why and what keeps it safe: nothing compiled into it allocates).
    """
    n = X.shape[0]
    if state[S_NEXT] == 0:
        for i in range(n):
            dup[i] = -1
        if state[S_RNG] == 0:
            state[S_RNG] = 2463534242
        i1, i2, i3 = _spanning(X, Y, Z, w)
        if i3 < 0:
            return FLAT
        _seed(0, i1, i2, i3, X, Y, Z, tet, nbr, state, w)
        state[S_SEED1] = i1
        state[S_SEED2] = i2
        state[S_SEED3] = i3
        state[S_NEXT] = 1
    for p in range(state[S_NEXT], n):
        if p == state[S_SEED1] or p == state[S_SEED2] or p == state[S_SEED3]:
            continue
        r = insert(p, X, Y, Z, tet, nbr, mark, free, stack, bad, bf, bo, bj,
                   vst, vhead, enext, eto, etet, eface, state, w)
        if r == GROW:
            state[S_NEXT] = p
            return GROW
        dup[p] = r
    state[S_NEXT] = n
    return OK


@njit(cache=True)
def extract(tet, nbr, ntet):
    """Compact the real tetrahedra: (simplices, neighbors, internal->output map, hull facets).

    Hull facets are listed counter-clockwise seen from outside the hull.
    """
    out_of = np.full(ntet, -1, dtype=np.int64)
    m = 0
    h = 0
    for t in range(ntet):
        if tet[4 * t] == DEAD:
            continue
        if inf_pos(tet, t) < 0:
            out_of[t] = m
            m += 1
        else:
            h += 1
    simp = np.empty((m, 4), dtype=np.int64)
    neig = np.empty((m, 4), dtype=np.int64)
    hull = np.empty((h, 3), dtype=np.int64)
    h = 0
    for t in range(ntet):
        if tet[4 * t] == DEAD:
            continue
        r = out_of[t]
        if r >= 0:
            for k in range(4):
                simp[r, k] = tet[4 * t + k]
                neig[r, k] = out_of[nbr[4 * t + k]]
        else:
            k = inf_pos(tet, t)
            # the ghost's face opposite INF is counter-clockwise from inside: reverse it
            hull[h, 0] = tet[4 * t + _F[k, 0]]
            hull[h, 1] = tet[4 * t + _F[k, 2]]
            hull[h, 2] = tet[4 * t + _F[k, 1]]
            h += 1
    return simp, neig, out_of, hull


@njit(cache=True)
def find(tet, nbr, X, Y, Z, q, start, w, state):
    """For each query point (row of q), a real tetrahedron containing it, or -1 outside."""
    res = np.empty(q.shape[0], dtype=np.int64)
    t = start
    for i in range(q.shape[0]):
        t = locate(tet, nbr, X, Y, Z, q[i, 0], q[i, 1], q[i, 2], t, w, state)
        k = inf_pos(tet, t)
        if k >= 0:
            res[i] = -1
            t = nbr[4 * t + k]
        else:
            res[i] = t
    return res
