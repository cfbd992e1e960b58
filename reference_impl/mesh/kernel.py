"""The fast incremental Delaunay kernel (numba): Bowyer-Watson on flat arrays.

This is the engine behind ``reference_impl.Delaunay``; read ``delaunay.py`` for
the public API.  The mesh, in the style of Delaunator:

* vertices are ``0 .. n-1`` (their insertion rank; after removals the caller
  may reuse the id of a vertex that left the mesh); ``INF = -1`` is the
  *infinite vertex*: every convex-hull edge (u, v) has a *ghost triangle*
  (v, u, INF) outside it, so the outside of the hull is triangulated too and no
  super-triangle (with its coordinate limits) is needed;
* one flat int32 array ``M`` holds an aligned 32-byte record of ``RECORD = 8``
  fields per triangle t (two records per cache line, never one split across two);
  the fields are named by their offsets in the record:
  ``M[RECORD*t + VTX + k]`` (k = 0, 1, 2) is vertex k, counter-clockwise;
  ``M[RECORD*t + NBR + k]`` is the triangle across the edge opposite vertex k, that
  is across edge (vertex k+1, vertex k+2) (indices mod 3).  Every triangle has
  three neighbours, because ghosts close the surface;
  ``M[RECORD*t + MARK]`` is a scratch mark for the cavity search; ``M[RECORD*t + SPARE]``
  is unused (``remove`` uses it in its scratch mesh only);
* a dead triangle slot has ``M[RECORD*t + VTX] == DEAD`` (``remove`` keeps the records dense,
  so slots ``0 .. state[S_NTRI]-1`` are all alive);
* ``start_of[v + 1]`` is a triangle incident to vertex v (index 0: the infinite vertex):
  ``insert`` sets it for every vertex on the cavity boundary, ``remove`` keeps it, and
  for the inserted vertex itself the caller sets it to ``state[S_LAST]`` (``build`` and
  ``Delaunay.insert``); ``init_vertex_map`` makes it whole after a build.

Insertion of point p (Bowyer-Watson):

1. *locate*: walk from the last new triangle towards p, crossing any edge that
   has p strictly on its other side; stop in a triangle containing p, or in a
   ghost when p is outside the hull;
2. *cavity*: depth-first search over neighbours, collecting every triangle in
   *conflict* with p (p strictly inside its circumcircle; for a ghost (u, v,
   INF): p strictly left of u->v, or on the line strictly inside segment uv);
   the conflict region is connected and star-shaped from p, a disk, and the
   search walks around it, so its boundary edges come out in counter-clockwise order;
3. *fill*: connect p to every cavity boundary edge, each new triangle the neighbour of
   the ones before and after it; the new triangles reuse the dead slots (there are
   always two more new triangles than dead ones).

Removal of vertex v lives in ``removal.py``: delete its star and
re-triangulate the hole with the Delaunay triangulation of its neighbours,
restricted to the hole (that module says why this is right, ties included).

All geometric decisions use the exact predicates, so degenerate input (grids,
cocircular points, collinear runs) cannot corrupt the mesh.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from reference_impl.mesh.ordering import line_order, small_order
from reference_impl.exact.predicates import WORKSPACE_SIZE, incircle_nb, orient2d_nb
from reference_impl.mesh.status import BUDGET, FLAT, OK

INF = -1
DEAD = -2

# the triangle record: RECORD int32 fields, at these offsets (numba folds them into constants)
RECORD = 8
VTX = 0      # VTX + k: vertex k (counter-clockwise)
NBR = 3      # NBR + k: the triangle across the edge opposite vertex k
MARK = 6     # scratch mark of the cavity search
SPARE = 7    # unused by insertion; removal's scratch mesh keeps a destination slot here

# state array fields
S_NTRI, S_STAMP, S_LAST, S_NDEAD = 0, 1, 2, 3
# statistics (counted, never used for decisions): walk steps, conflict tests, cavity triangles
S_STEPS, S_TESTS, S_BAD = 4, 5, 6
STATE_SIZE = 8


@njit(cache=True, inline="always")
def is_ghost(M, t):
    """Whether triangle t has the infinite vertex (lies outside the convex hull)."""
    return M[RECORD * t + VTX] == INF or M[RECORD * t + VTX + 1] == INF or M[RECORD * t + VTX + 2] == INF


@njit(cache=True, inline="always")
def is_live_real(M, t):
    """Whether slot t holds a live real triangle: its three vertices are >= 0 (``INF`` and
    ``DEAD`` are negative).  One OR of the three compiles to a tight loop in a scan over all
    slots (the ``DEAD``-then-``is_ghost`` form made ``extract``'s count 9x slower)."""
    return (M[RECORD * t + VTX] | M[RECORD * t + VTX + 1] | M[RECORD * t + VTX + 2]) >= 0


@njit(cache=True, inline="always")
def _in_conflict(M, t, P, px, py, w):
    a = M[RECORD * t + VTX]
    b = M[RECORD * t + VTX + 1]
    c = M[RECORD * t + VTX + 2]
    if c == INF:
        u, v = a, b
    elif a == INF:
        u, v = b, c
    elif b == INF:
        u, v = c, a
    else:
        return incircle_nb(P[a, 0], P[a, 1], P[b, 0], P[b, 1], P[c, 0], P[c, 1], px, py, w) > 0
    o = orient2d_nb(P[u, 0], P[u, 1], P[v, 0], P[v, 1], px, py, w)
    if o != 0:
        return o > 0
    # on the hull line: in conflict only strictly inside the segment
    if P[u, 0] != P[v, 0]:
        return min(P[u, 0], P[v, 0]) < px < max(P[u, 0], P[v, 0])
    return min(P[u, 1], P[v, 1]) < py < max(P[u, 1], P[v, 1])


@njit(cache=True, inline="always")
def real_neighbour_of_ghost(M, t):
    """The real triangle across the hull edge of ghost t (t itself if it is real)."""
    for k in range(3):
        if M[RECORD * t + VTX + k] == INF:
            return M[RECORD * t + NBR + k]
    return t


@njit(cache=True, inline="always")
def locate(M, P, px, py, start, w, state):
    """Walk from triangle ``start`` to a triangle whose closure contains p.

    Returns a real triangle containing p, or a ghost triangle whose hull edge
    sees p strictly on its outer side.  Terminates because the mesh is Delaunay.
    """
    t = real_neighbour_of_ghost(M, start)
    prev = -1
    while True:
        moved = False
        for k in range(3):
            o = M[RECORD * t + NBR + k]
            if o == prev:
                continue
            k1 = k + 1 if k < 2 else 0      # (k + 1) % 3 without a division: 3-5% of a build
            k2 = k1 + 1 if k1 < 2 else 0
            u = M[RECORD * t + VTX + k1]
            v = M[RECORD * t + VTX + k2]
            if orient2d_nb(P[u, 0], P[u, 1], P[v, 0], P[v, 1], px, py, w) < 0:
                state[S_STEPS] += 1
                prev = t
                t = o
                moved = True
                break
        if not moved or is_ghost(M, t):
            return t


@njit(cache=True, inline="always")
def _new_slot(M, state, bad, nbad, used):
    if used < nbad:
        return bad[used]
    t = state[S_NTRI]
    state[S_NTRI] = t + 1
    return t


@njit(cache=True, inline="always")
def insert(p, P, M, stack, bad, ba, bb, bo, start_of, state, w):
    """Insert vertex p (coordinates P[p]) into a mesh with at least one triangle.

    Returns OK (-1) when inserted, or the vertex that p duplicates exactly (then the
    mesh is unchanged).  Scratch arrays: ``stack``, ``bad``, ``ba``, ``bb``, ``bo`` (per
    cavity; as long as the triangle arrays).  ``start_of`` is the vertex -> triangle map
    (module docstring): set here for every vertex on the cavity boundary, never read.
    """
    px = P[p, 0]
    py = P[p, 1]
    t = locate(M, P, px, py, state[S_LAST], w, state)
    if not is_ghost(M, t):
        for k in range(3):
            v = M[RECORD * t + VTX + k]
            if P[v, 0] == px and P[v, 1] == py:
                return v
    # --- cavity: a depth-first search from t (which is in conflict) that walks around the
    # cavity.  A triangle's edges are tried counter-clockwise (edge k, opposite vertex k, then
    # k + 1, k + 2); a neighbour in conflict is entered and tried from the edge after the one
    # it was entered by, and an edge whose other side is not in conflict is a boundary edge.
    # So the boundary edges come out counter-clockwise around p, each starting where the last
    # one ended: new triangle i is the neighbour of new triangles i - 1 and i + 1.
    # Stack entries are 4 * triangle + the next edge to try (3: none left).  Marks: +stamp in
    # the cavity, -stamp tested and outside (stamps only grow, so no mark is ever cleared).
    state[S_STAMP] += 1
    stamp = state[S_STAMP]
    M[RECORD * t + MARK] = stamp
    bad[0] = t
    nbad = 1
    stack[0] = 4 * t
    top = 1
    nb = 0
    while top > 0:
        e = stack[top - 1]
        s = e >> 2
        k = e & 3
        if k == 3:
            top -= 1
            continue
        k1 = k + 1 if k < 2 else 0      # (k + 1) % 3 without a division: 3-5% of a build
        k2 = k1 + 1 if k1 < 2 else 0
        # edge k is s's last when the next one is where the search came from (t: edge 2)
        if top == 1:
            last = k == 2
        else:
            last = M[RECORD * s + NBR + k1] == stack[top - 2] >> 2
        stack[top - 1] = 4 * s + (3 if last else k1)
        o = M[RECORD * s + NBR + k]
        mo = M[RECORD * o + MARK]
        if mo == stamp:
            continue                    # an edge inside the cavity
        if mo == -stamp:
            conflict = False
        else:
            state[S_TESTS] += 1
            conflict = _in_conflict(M, o, P, px, py, w)
        if conflict:
            M[RECORD * o + MARK] = stamp
            bad[nbad] = o
            nbad += 1
            j = 0                       # o's edge back to s, then the one after it
            while M[RECORD * o + NBR + j] != s:
                j += 1
            stack[top] = 4 * o + (j + 1 if j < 2 else 0)
            top += 1
        else:
            M[RECORD * o + MARK] = -stamp
            ba[nb] = M[RECORD * s + VTX + k1]
            bb[nb] = M[RECORD * s + VTX + k2]
            bo[nb] = o
            nb += 1
    state[S_BAD] += nbad
    # --- fill: one new triangle (a, b, p) per boundary edge (a, b), in order ---------------
    last_real = -1
    for i in range(nb):
        a = ba[i]
        b = bb[i]
        o = bo[i]
        s = _new_slot(M, state, bad, nbad, i)
        M[RECORD * s + VTX] = a
        M[RECORD * s + VTX + 1] = b
        M[RECORD * s + VTX + 2] = p
        M[RECORD * s + NBR + 2] = o
        # the outside triangle o now faces s across edge (b, a)
        for j in range(3):
            x = M[RECORD * o + VTX + j]
            if x != a and x != b:
                M[RECORD * o + NBR + j] = s
                break
        start_of[a + 1] = s             # the vertex -> triangle map stays right for a
        M[RECORD * s + MARK] = 0
        if a != INF and b != INF:
            last_real = s
        bo[i] = s  # reuse: bo now holds the new triangle of boundary edge i
    prev = bo[nb - 1]
    for i in range(nb):
        s = bo[i]                       # (a, b, p) follows (., a, p) and precedes (b, ., p)
        M[RECORD * s + NBR + 1] = prev
        M[RECORD * prev + NBR] = s
        prev = s
    state[S_LAST] = last_real
    return OK


@njit(cache=True)
def _link_brute(M, ntri):
    # link triangles 0 .. ntri-1 by their shared edges (a handful: used to seed the mesh)
    for i in range(ntri):
        for k in range(3):
            u = M[RECORD * i + VTX + (k + 1) % 3]
            v = M[RECORD * i + VTX + (k + 2) % 3]
            for j in range(ntri):
                if j == i:
                    continue
                for m in range(3):
                    if M[RECORD * j + VTX + (m + 1) % 3] == v and M[RECORD * j + VTX + (m + 2) % 3] == u:
                        M[RECORD * i + NBR + k] = j


@njit(cache=True)
def seed(a, b, c, P, M, state, w):
    """Start the mesh with the non-degenerate triangle (a, b, c) and its three ghosts."""
    if orient2d_nb(P[a, 0], P[a, 1], P[b, 0], P[b, 1], P[c, 0], P[c, 1], w) < 0:
        b, c = c, b
    vs = (a, b, c)
    M[0] = a
    M[1] = b
    M[2] = c
    for k in range(3):
        u = vs[k]
        v = vs[(k + 1) % 3]
        g = k + 1
        M[RECORD * g + VTX] = v
        M[RECORD * g + VTX + 1] = u
        M[RECORD * g + VTX + 2] = INF
    _link_brute(M, 4)
    state[S_NTRI] = 4
    state[S_LAST] = 0


@njit(cache=True, _nrt=False)
def build(P, M, stack, bad, ba, bb, bo, start_of, state, dup, hints, w, budget):
    """Triangulate vertices 0..n-1 in index order.  ``dup[i]`` receives the vertex that i
    duplicates (or -1).  Returns ``OK``, or ``FLAT`` when every point is collinear (nothing
    built), or ``BUDGET`` when ``budget > 0`` and the conflict tests and walk steps so far
    exceed it (the mesh is then unfinished: the caller builds again in another order).

    ``hints[p]`` (``ordering.walk_hints``; -1 for none) is an earlier vertex near p: the walk
    for p starts beside it when it is closer to p than the last inserted vertex is.  For that,
    ``start_of[v + 1]`` holds a triangle incident to each inserted vertex v when v is done
    (later cavities may destroy it; the walk starts correctly from any live triangle).

    Compiled without numba's reference counting (``_nrt=False``): every array the inlined
    helpers receive (``insert``, ``locate``, the predicates) would otherwise cost a pair of
    atomic ``NRT_incref``/``NRT_decref`` calls per call, about 60 per inserted point, which
    numba's pruning pass cannot remove across the helpers' loops and exits.  Measured: 0.69 ->
    0.40 us per point at 100 points, 7.8 -> 5.2 ms at 10^4.  The rule that makes it safe:
    nothing compiled into this function allocates an array (the callers own every array, and
    a numba compile error says so if that changes); the exact stages, which do, are compiled
    with reference counting of their own (``exact/predicates.py``)."""
    n = P.shape[0]
    for i in range(n):
        dup[i] = -1
    # first two distinct points, then the first point off their line
    i1 = -1
    for i in range(1, n):
        if P[i, 0] != P[0, 0] or P[i, 1] != P[0, 1]:
            i1 = i
            break
    if i1 < 0:
        return FLAT
    i2 = -1
    for i in range(i1 + 1, n):
        if orient2d_nb(P[0, 0], P[0, 1], P[i1, 0], P[i1, 1], P[i, 0], P[i, 1], w) != 0:
            i2 = i
            break
    if i2 < 0:
        return FLAT
    seed(0, i1, i2, P, M, state, w)
    start_of[1] = start_of[i1 + 1] = start_of[i2 + 1] = 0      # the seed triangle
    last = i2
    for p in range(1, n):
        if p == i1 or p == i2:
            continue
        h = hints[p] if p < hints.shape[0] else -1     # (no hints: an empty array)
        if h >= 0:
            px = P[p, 0]
            py = P[p, 1]
            dh = (P[h, 0] - px) ** 2 + (P[h, 1] - py) ** 2
            dl = (P[last, 0] - px) ** 2 + (P[last, 1] - py) ** 2
            if dh < dl:
                state[S_LAST] = start_of[h + 1]
        dup[p] = insert(p, P, M, stack, bad, ba, bb, bo, start_of, state, w)
        start_of[p + 1] = state[S_LAST]     # incident to p (to its duplicate's star when dup)
        if dup[p] < 0:
            last = p                        # state[S_LAST] is a triangle of the last inserted
        if budget > 0 and state[S_TESTS] + state[S_STEPS] > budget:
            return BUDGET
    return OK


@njit(cache=True, inline="always")
def line_budget(n):
    """The work (conflict tests + walk steps) a build in ``ordering.line_order`` may take
    before it is abandoned for the BRIO order: about three times what a thin strip needs
    (8.3 a point on a line with 1e-9 noise), so a bad case for sorted order costs at most
    about twice a build rather than quadratic time."""
    return 24 * n + 1024


@njit(cache=True, inline="always")
def _built(pts, order, hints, budget):
    """``build`` of ``pts[order]`` on new arrays: ``(code, P, M, start_of, state, dup)``.
    (Inlined: as a compiled callee of ``triangulate`` it would generate ``build``'s code a
    third time in a cold compile, 14 s.)"""
    n = order.shape[0]
    nv = max(n, 4)
    nt = 2 * n + 8
    P = np.empty((nv, 2))
    for i in range(n):
        P[i, 0] = pts[order[i], 0]
        P[i, 1] = pts[order[i], 1]
    M = np.zeros(RECORD * nt, dtype=np.int32)
    stack = np.empty(nt, dtype=np.int32)
    bad = np.empty(nt, dtype=np.int32)
    ba = np.empty(nt, dtype=np.int32)
    bb = np.empty(nt, dtype=np.int32)
    bo = np.empty(nt, dtype=np.int32)
    start_of = np.empty(nv + 1, dtype=np.int32)
    state = np.zeros(STATE_SIZE, dtype=np.int64)
    dup = np.full(nv, -1, dtype=np.int32)
    w = np.empty(WORKSPACE_SIZE)
    code = FLAT if n < 3 else build(P[:n], M, stack, bad, ba, bb, bo, start_of, state, dup, hints, w, budget)
    return code, P, M, start_of, state, dup


@njit(cache=True)
def triangulate(pts, order, hints, compute_order, extract_now, budget):
    """All of ``Delaunay(points)`` in one compiled call (the fixed cost of many small calls
    from Python is larger than the work below a few thousand points).

    ``pts``: (n, 2) validated input; ``order``, ``hints``: the insertion order (indices into
    ``pts``) and its walk hints (``ordering.insertion_order(..., with_hints=True)``), built
    with work ``budget`` (0: none; see ``build``).  With ``compute_order`` both are computed
    here instead: ``ordering.line_order`` for a thin strip (its work capped by ``budget``, or
    by ``line_budget`` when that is 0; then ``small_order`` if the cap is reached), else
    ``ordering.small_order``.  Allocates the mesh for ``pts[order]`` and builds it; with
    ``extract_now`` also the output triangles.  Returns ``(code, order, P, M, state, dup,
    simplices, rep)`` (the cavity scratch and the vertex -> triangle map stay here: every
    array returned costs its boxing, about 0.5 us); ``code`` is ``OK``, ``FLAT`` when nothing
    was built (fewer than three points, or all collinear), or ``BUDGET`` (only with an order
    given: the caller builds again in the BRIO order); ``simplices``/``rep`` are empty unless
    extracted."""
    if compute_order:
        order = line_order(pts)
        hints = np.empty(0, np.int64)
        if budget <= 0:
            budget = line_budget(order.shape[0])
        if order.shape[0] == 0:
            order, hints = small_order(pts[:, 0].copy(), pts[:, 1].copy(), True)
            budget = 0
    code, P, M, start_of, state, dup = _built(pts, order, hints, budget)
    if code == BUDGET and compute_order:
        order, hints = small_order(pts[:, 0].copy(), pts[:, 1].copy(), True)
        code, P, M, start_of, state, dup = _built(pts, order, hints, budget * 0)   # (a literal 0 would
        # compile build a second time, specialised for it)
    n = order.shape[0]
    if code == FLAT:
        dup[:] = -1                  # (flat results are computed from the coordinates)
    simp = np.empty((0, 3), dtype=np.int64)
    rep = np.empty(0, dtype=np.int64)
    if extract_now and code == OK:
        rep = smallest_labels(order, dup[:n])     # (= order when there are no duplicates)
        simp = extract(M, state[S_NTRI], rep)
    return code, order, P, M, state, dup, simp, rep


@njit(cache=True)
def extract(M, ntri, label):
    """The real triangles, (m, 3) int64, in slot order (row r is the r-th live real triangle).

    Vertex v is written as ``label[v]`` (the input index it stands for)."""
    m = 0
    for t in range(ntri):
        if is_live_real(M, t):
            m += 1
    out = np.empty((m, 3), dtype=np.int64)
    r = 0
    for t in range(ntri):
        if is_live_real(M, t):
            for k in range(3):
                out[r, k] = label[M[RECORD * t + VTX + k]]
            r += 1
    return out


@njit(cache=True)
def triangle_rows(M, ntri):
    """``rows[t]``: the row of triangle slot t in ``extract``'s output (-1 for a ghost or a
    dead slot), and one more -1 at the end, so that ``rows[-1]`` (outside) is -1 too.  int32:
    made only when neighbours or point location ask (at 10^7 points it is 80 MB)."""
    rows = np.empty(ntri + 1, dtype=np.int32)
    m = 0
    for t in range(ntri):
        if is_live_real(M, t):
            rows[t] = m
            m += 1
        else:
            rows[t] = -1
    rows[ntri] = -1
    return rows


@njit(cache=True)
def extract_neighbors(M, ntri, rows, m):
    """(m, 3) neighbours of the compacted triangles (-1 across the hull); ``rows`` from
    ``triangle_rows``."""
    out = np.empty((m, 3), dtype=np.int64)
    for t in range(ntri):
        r = rows[t]
        if r >= 0:
            for k in range(3):
                out[r, k] = rows[M[RECORD * t + NBR + k]]
    return out


@njit(cache=True)
def hull_cycle(M, ntri, nverts, label):
    """Hull vertices counter-clockwise (from the ghost triangles), as ``label[v]``, starting
    at the smallest label."""
    nxt = np.full(nverts, -1, dtype=np.int64)
    first = -1
    count = 0
    for t in range(ntri):
        if M[RECORD * t + VTX] == DEAD:
            continue
        for k in range(3):
            if M[RECORD * t + VTX + k] == INF:
                # ghost (x, y, INF) in cyclic order sits on hull edge y -> x
                x = M[RECORD * t + VTX + (k + 1) % 3]
                y = M[RECORD * t + VTX + (k + 2) % 3]
                nxt[y] = x
                first = y
                count += 1
    # start at the smallest label so that the answer does not depend on the insertion order
    v = first
    best = first
    for i in range(count):
        if label[v] < label[best]:
            best = v
        v = nxt[v]
    out = np.empty(count, dtype=np.int64)
    v = best
    for i in range(count):
        out[i] = label[v]
        v = nxt[v]
    return out


@njit(cache=True)
def smallest_labels(order, dup):
    """rep[v] = the smallest input index among the points equal to vertex v."""
    n = order.shape[0]
    best = order.copy()
    for v in range(n):
        r = dup[v]
        if r >= 0 and order[v] < best[r]:
            best[r] = order[v]
    rep = np.empty(n, dtype=np.int64)
    for v in range(n):
        r = dup[v]
        rep[v] = best[r] if r >= 0 else best[v]
    return rep


@njit(cache=True)
def find(M, P, Q, start, w, state):
    """For each query point Q[i], a real triangle containing it, or -1 outside the hull."""
    res = np.empty(Q.shape[0], dtype=np.int64)
    t = start
    for i in range(Q.shape[0]):
        t = locate(M, P, Q[i, 0], Q[i, 1], t, w, state)
        if is_ghost(M, t):
            res[i] = -1
            t = real_neighbour_of_ghost(M, t)
        else:
            res[i] = t
    return res
