"""Edge flips and mesh improvement: Lawson's flip algorithm, Laplacian smoothing, mesh quality.

    python -c "from reference_impl.structures.flips import flip_to_delaunay; print(flip_to_delaunay([(0,0),(2,0),(2,1),(0,1)], [(0,1,2),(0,2,3)]))"

* ``lawson_flip(points, triangles)`` turns any triangulation of the points into
  a Delaunay one by flipping, one at a time, interior edges that are not
  locally Delaunay (the opposite vertex of one triangle strictly inside the
  circumcircle of the other).  ``flip_to_delaunay`` returns just the flipped
  edges (the entry function of the ``edge-flip`` problem).
* ``apply_flips(points, triangles, flips)`` replays a flip sequence and checks
  every step (the judge's side of ``edge-flip``).
* ``laplacian_smooth`` moves interior vertices towards the average of their
  neighbours, refusing any move that would invert a triangle.
* ``mesh_quality`` reports angles and aspect ratios.

A triangulation of the points (what ``validate_triangulation`` accepts) is a set
of counter-clockwise triangles of positive area that covers the convex hull
exactly, without overlap, and uses every distinct point as a vertex.  Indices of
duplicated points are replaced by their representative (the smallest index with
the same coordinates).  Every geometric decision is an exact predicate.

Why Lawson terminates and is right: each flip replaces two triangles by two
whose circumcircles are "lower" on the lifting paraboloid, so no triangulation
repeats (at most O(n^2) flips); when no edge is illegal, every edge is locally
Delaunay, hence the triangulation is Delaunay (Delaunay's lemma).  Delaunay
maximises the minimum angle, but that does not make it well shaped: thin point
sets give thin triangles (contrary to the original tutorial's claim); quality
meshing adds points.

>>> pts = [(0, 0), (2, 0), (2, 1), (0, 1), (1, 0.5)]
>>> tris = [(0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]
>>> flip_to_delaunay(pts, tris)      # already Delaunay: nothing to flip
[]
>>> round(mesh_quality(pts, tris)["min_angle"], 2)
26.57
"""
from __future__ import annotations

import numpy as np
from numba import njit

from reference_impl.mesh.delaunay import Delaunay
from reference_impl.mesh.topology import (edge_keys, find_edge, flip, slot, triangle_neighbors, unique_edges,
                                          vertex_triangles)
from reference_impl.validate import as_index_rows, as_points
from reference_impl.exact.predicates import WORKSPACE_SIZE, incircle_nb, orient2d_nb

__all__ = ["validate_triangulation", "lawson_flip", "flip_to_delaunay", "apply_flips",
           "laplacian_smooth", "mesh_quality"]


# ----------------------------------------------------------------------------- validation
@njit(cache=True)
def _workspace():
    """Scratch for the exact predicates (``predicates.workspace`` inside compiled code)."""
    return np.empty(WORKSPACE_SIZE, dtype=np.float64)


@njit(cache=True)
def _first_non_ccw(X, Y, T):
    """Index of the first triangle that is not strictly counter-clockwise, or -1 (and its sign)."""
    w = _workspace()
    for t in range(len(T)):
        a, b, c = T[t, 0], T[t, 1], T[t, 2]
        s = orient2d_nb(X[a], Y[a], X[b], Y[b], X[c], Y[c], w)
        if s <= 0:
            return t, s
    return -1, 1


def _canonical(T: np.ndarray) -> np.ndarray:
    """Rotate each triangle to start at its smallest index, then sort the rows."""
    if len(T) == 0:
        return T.reshape(0, 3)
    r = np.argmin(T, axis=1)
    T = np.stack([T[np.arange(len(T)), (r + k) % 3] for k in range(3)], axis=1)
    return T[np.lexsort((T[:, 2], T[:, 1], T[:, 0]))]


def _validate(P: np.ndarray, triangles) -> tuple[np.ndarray, np.ndarray, Delaunay]:
    """(triangles in canonical order, their neighbours, the Delaunay of P) or ValueError."""
    n = len(P)
    T = as_index_rows(triangles, n, 3, "triangles", allow_integral_floats=True)
    d = Delaunay(P)
    rep = d.index_map
    T = rep[T]
    if len(d.simplices) == 0:
        if len(T):
            raise ValueError("the points are all collinear (or fewer than 3 distinct): "
                             "the only triangulation has no triangles")
        return T, np.zeros((0, 3), dtype=np.int64), d
    t, s = _first_non_ccw(P[:, 0].copy(), P[:, 1].copy(), T)
    if t >= 0:
        what = "degenerate (zero area)" if s == 0 else "clockwise"
        raise ValueError(f"triangle {t} = {T[t].tolist()} is {what}; triangles must be "
                         "counter-clockwise with positive area")
    T = _canonical(T)
    nbr = triangle_neighbors(T, n)
    keys = edge_keys(T, n)
    hull = np.asarray(d.hull, dtype=np.int64)
    hull_keys = np.sort(hull * n + np.roll(hull, -1))
    boundary = np.sort(keys[nbr < 0])
    if len(boundary) != len(hull_keys) or not np.array_equal(boundary, hull_keys):
        extra = np.setdiff1d(boundary, hull_keys)
        if len(extra):
            e = extra[0]
            raise ValueError(f"edge {e // n}-{e % n} has a triangle on one side only but is not "
                             "a convex hull edge (a hole, a gap or an overlap)")
        e = np.setdiff1d(hull_keys, boundary)[0]
        raise ValueError(f"convex hull edge {e // n}-{e % n} is not covered by any triangle, "
                         "or the triangles overlap")
    missing = np.setdiff1d(np.flatnonzero(rep == np.arange(n)), T.ravel())
    if len(missing):
        raise ValueError(f"point {missing[0]} {P[missing[0]].tolist()} is not a vertex of any triangle")
    return T, nbr, d


def validate_triangulation(points, triangles) -> np.ndarray:
    """Check that ``triangles`` triangulate ``points``; return them as (m, 3) int64 in a
    canonical order (each rotated to start at its smallest index, rows sorted).

    Conditions (sufficient, see ``reference_impl.exact.verify``): every triangle strictly
    counter-clockwise; no directed edge used twice; the edges with a triangle on
    one side only are exactly the convex hull cycle (collinear hull points
    included); every distinct point is a vertex.  Duplicate indices become their
    representative.  Raises ``ValueError`` naming the first problem.

    >>> validate_triangulation([(0, 0), (1, 0), (0, 1)], [(0, 1, 2)]).tolist()
    [[0, 1, 2]]
    >>> validate_triangulation([(0, 0), (1, 0), (0, 1)], [(0, 2, 1)])
    Traceback (most recent call last):
    ...
    ValueError: triangle 0 = [0, 2, 1] is clockwise; triangles must be counter-clockwise with positive area
    """
    return _validate(as_points(points), triangles)[0]


# ----------------------------------------------------------------------------- Lawson flips
@njit(cache=True)
def _lawson(X, Y, tri, nbr):
    """Flip illegal edges until none is left; return the (k, 2) removed edges in order."""
    w = _workspace()
    m = len(tri)
    stack = np.empty(3 * m, dtype=np.int64)
    queued = np.zeros(3 * m, dtype=np.bool_)
    top = 0
    for t in range(m - 1, -1, -1):
        for k in range(2, -1, -1):
            if nbr[t, k] > t:
                stack[top] = 3 * t + k
                queued[3 * t + k] = True
                top += 1
    flips = np.empty((max(16, m), 2), dtype=np.int64)
    nf = 0
    while top > 0:
        top -= 1
        s = stack[top]
        queued[s] = False
        t, k = s // 3, s % 3
        o = nbr[t, k]
        if o < 0:
            continue
        w1, u, v = tri[t, k], tri[t, (k + 1) % 3], tri[t, (k + 2) % 3]
        w2 = tri[o, slot(nbr, o, t)]
        if incircle_nb(X[w1], Y[w1], X[u], Y[u], X[v], Y[v], X[w2], Y[w2], w) <= 0:
            continue
        a, b = flip(tri, nbr, t, k)
        if nf == len(flips):
            grown = np.empty((2 * nf, 2), dtype=np.int64)
            grown[:nf] = flips
            flips = grown
        flips[nf, 0], flips[nf, 1] = min(a, b), max(a, b)
        nf += 1
        for s2 in (3 * t + 1, 3 * t + 2, 3 * o, 3 * o + 2):   # the quadrilateral's sides
            if not queued[s2] and nbr[s2 // 3, s2 % 3] >= 0:
                queued[s2] = True
                stack[top] = s2
                top += 1
    return flips[:nf]


def lawson_flip(points, triangles) -> tuple[np.ndarray, list[tuple[int, int]]]:
    """Lawson's algorithm: (final Delaunay triangles, flipped edges in order).

    Each flip removes an interior edge (i, j), i < j, whose quadrilateral has the
    opposite vertex strictly inside the circumcircle (so the quadrilateral is
    strictly convex and the flip is legal).  The input triangle order does not
    matter (triangles are put in a canonical order first).  Worst case O(n^2)
    flips, as for any flip algorithm; typical inputs need O(n).

    >>> tris, flips = lawson_flip([(0, 0), (2, 0), (2, 1), (0, 1)], [(0, 1, 2), (0, 2, 3)])
    >>> flips, tris.tolist()
    ([], [[0, 1, 2], [0, 2, 3]])
    >>> lawson_flip([(0, 0), (4, 0), (4, 1), (0, 3)], [(0, 1, 3), (1, 2, 3)])[1]
    [(1, 3)]
    """
    P = as_points(points)
    T, nbr, _ = _validate(P, triangles)
    if len(T) == 0:
        return T, []
    flips = _lawson(P[:, 0].copy(), P[:, 1].copy(), T, nbr)
    return _canonical(T), [(int(a), int(b)) for a, b in flips]


def flip_to_delaunay(points, triangles) -> list[tuple[int, int]]:
    """The edges (i, j), i < j, flipped by Lawson's algorithm, in order (``edge-flip`` entry).

    >>> flip_to_delaunay([(0, 0), (4, 0), (4, 1), (0, 3)], [(0, 1, 3), (1, 2, 3)])
    [(1, 3)]
    """
    return lawson_flip(points, triangles)[1]


@njit(cache=True)
def _replay(X, Y, tri, nbr, fi, fj, vt, check_illegal):
    """Apply flips (fi[s], fj[s]); return (-1, 0) or (step, reason) for the first bad one.

    reason 1: not an edge, 2: a hull edge, 3: not strictly convex, 4: locally Delaunay."""
    w = _workspace()
    for s in range(len(fi)):
        i, j = fi[s], fj[s]
        t, k = find_edge(tri, nbr, vt, i, j)
        if t < 0:
            return s, 1
        o = nbr[t, k]
        if o < 0:
            return s, 2
        w1, u, v = tri[t, k], tri[t, (k + 1) % 3], tri[t, (k + 2) % 3]
        w2 = tri[o, slot(nbr, o, t)]
        if (orient2d_nb(X[u], Y[u], X[w2], Y[w2], X[w1], Y[w1], w) <= 0
                or orient2d_nb(X[w2], Y[w2], X[v], Y[v], X[w1], Y[w1], w) <= 0):
            return s, 3
        if check_illegal and incircle_nb(X[w1], Y[w1], X[u], Y[u], X[v], Y[v], X[w2], Y[w2], w) <= 0:
            return s, 4
        flip(tri, nbr, t, k)
        vt[u], vt[v], vt[w1], vt[w2] = t, o, t, t
    return -1, 0


def apply_flips(points, triangles, flips, only_illegal: bool = True) -> np.ndarray:
    """Replay ``flips`` on a triangulation and return the final triangles (canonical order).

    Each flip (i, j) must be an interior edge of the current triangulation whose
    quadrilateral is strictly convex; with ``only_illegal`` (the ``edge-flip``
    rule) the edge must also not be locally Delaunay before the flip.  Raises
    ``ValueError`` naming the first bad flip.

    >>> apply_flips([(0, 0), (4, 0), (4, 1), (0, 3)], [(0, 1, 3), (1, 2, 3)], [(1, 3)]).tolist()
    [[0, 1, 2], [0, 2, 3]]
    """
    P = as_points(points)
    T, nbr, d = _validate(P, triangles)
    F = d.index_map[as_index_rows(flips, len(P), 2, "flips", allow_integral_floats=True)]
    if len(F) and len(T) == 0:
        raise ValueError("flip 0: there is no triangle, so no edge can be flipped")
    vt = vertex_triangles(T, len(P))
    bad = np.flatnonzero(vt[F.ravel()] < 0)
    if len(bad):
        s = int(bad[0] // 2)
        raise ValueError(f"flip {s} = {F[s].tolist()} is not an edge of the triangulation")
    step, reason = _replay(P[:, 0].copy(), P[:, 1].copy(), T, nbr, F[:, 0].copy(), F[:, 1].copy(),
                           vt, only_illegal)
    if step >= 0:
        why = {1: "is not an edge of the current triangulation",
               2: "is a convex hull edge (only interior edges can be flipped)",
               3: "has a quadrilateral that is not strictly convex, so it cannot be flipped",
               4: "is already locally Delaunay (Lawson flips only illegal edges)"}[reason]
        raise ValueError(f"flip {step} = {tuple(F[step].tolist())} {why}")
    return _canonical(T)


# ----------------------------------------------------------------------------- smoothing
def _mesh(points, triangles) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Validated points, triangles (strictly CCW, manifold), their neighbours and the
    boundary-edge vertex mask."""
    P = as_points(points)
    T = as_index_rows(triangles, len(P), 3, "triangles", allow_integral_floats=True)
    t, s = _first_non_ccw(P[:, 0].copy(), P[:, 1].copy(), T)
    if t >= 0:
        what = "degenerate (zero area)" if s == 0 else "clockwise"
        raise ValueError(f"triangle {t} = {T[t].tolist()} is {what}; triangles must be "
                         "counter-clockwise with positive area")
    nbr = triangle_neighbors(T, len(P))
    on_boundary = np.zeros(len(P), dtype=bool)
    for k in range(3):
        open_edge = nbr[:, k] < 0
        on_boundary[T[open_edge, (k + 1) % 3]] = True
        on_boundary[T[open_edge, (k + 2) % 3]] = True
    return P, T, nbr, on_boundary


@njit(cache=True)
def _inverted(X, Y, T):
    """Mask of the triangles that are not strictly counter-clockwise (exact)."""
    w = _workspace()
    bad = np.zeros(len(T), dtype=np.bool_)
    for t in range(len(T)):
        a, b, c = T[t, 0], T[t, 1], T[t, 2]
        bad[t] = orient2d_nb(X[a], Y[a], X[b], Y[b], X[c], Y[c], w) <= 0
    return bad


def laplacian_smooth(points, triangles, iterations: int = 1, fixed=None,
                     guard: bool = True) -> np.ndarray:
    """Move every free vertex to the average of its mesh neighbours; return new points.

    Boundary vertices (on an edge with one triangle), vertices listed in ``fixed``
    and vertices in no triangle stay put.  All vertices move at once (Jacobi), so
    the result does not depend on the vertex numbering.  The average can leave
    the region a vertex "sees" (on non-convex meshes, or around reflex corners)
    and invert triangles; with ``guard`` every triangle is checked exactly after
    each iteration and the vertices of inverted ones are put back, repeatedly,
    until no triangle is inverted.  The triangles are not changed (no flips).

    >>> pts = [(0, 0), (2, 0), (2, 2), (0, 2), (1.5, 1.6)]
    >>> tris = [(0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]
    >>> laplacian_smooth(pts, tris)[4].tolist()
    [1.0, 1.0]
    """
    P, T, nbr, on_boundary = _mesh(points, triangles)
    if isinstance(iterations, bool) or not isinstance(iterations, (int, np.integer)) or iterations < 0:
        raise ValueError(f"iterations must be a non-negative integer, got {iterations!r}")
    n = len(P)
    free = ~on_boundary
    free[np.setdiff1d(np.arange(n), T.ravel())] = False
    if fixed is not None:
        idx = np.asarray(fixed).ravel()
        if idx.size and (idx.dtype.kind not in "iu" or (idx < 0).any() or (idx >= n).any()):
            raise ValueError(f"fixed must be point indices in 0..{n - 1}, got {idx.tolist()[:5]}")
        free[idx.astype(np.int64)] = False
    e = unique_edges(T, nbr) @ np.array([n, 1], dtype=np.int64)
    src, dst = np.r_[e // n, e % n], np.r_[e % n, e // n]    # each neighbour once, both ways
    keep = free[src]
    src, dst = src[keep], dst[keep]
    X = P.copy()
    for _ in range(iterations):
        new = X.copy()
        for c in range(2):
            # sum each vertex's neighbours in increasing order of value, so that the
            # rounding (and the result) does not depend on the numbering
            val = X[dst, c]
            order = np.lexsort((val, src))
            s_sorted = src[order]
            starts = np.flatnonzero(np.r_[True, s_sorted[1:] != s_sorted[:-1]]) if len(order) else order
            sums = np.add.reduceat(val[order], starts) if len(order) else val
            new[s_sorted[starts], c] = sums / np.diff(np.r_[starts, len(order)])
        if guard:
            moved = free.copy()
            while True:
                bad = _inverted(new[:, 0].copy(), new[:, 1].copy(), T)
                if not bad.any():
                    break
                back = np.unique(T[bad])
                back = back[moved[back]]
                new[back] = X[back]
                moved[back] = False
        X = new
    return X


# ----------------------------------------------------------------------------- quality
def mesh_quality(points, triangles) -> dict:
    """Shape statistics of a triangle mesh (angles in degrees).

    Keys: ``min_angle``, ``max_angle``, ``mean_min_angle`` (mean over triangles of
    their smallest angle), ``radius_ratio_max`` and ``radius_ratio_mean`` (R / 2r,
    circumradius over twice the inradius: 1 for an equilateral triangle, larger
    for worse shapes, infinite for a degenerate one), ``edge_ratio_max``
    (longest / shortest edge of a triangle), and the counts ``triangles``,
    ``vertices`` (used), ``interior_edges``, ``boundary_edges``,
    ``angles_below_30`` and ``obtuse_triangles``.  Triangles must be
    counter-clockwise with positive area (``ValueError`` otherwise).

    >>> q = mesh_quality([(0, 0), (2, 0), (1, 3 ** 0.5)], [(0, 1, 2)])
    >>> round(q["min_angle"], 6), round(q["radius_ratio_max"], 6), q["triangles"]
    (60.0, 1.0, 1)
    """
    P, T, nbr, _ = _mesh(points, triangles)
    if len(T) == 0:
        raise ValueError("mesh_quality needs at least one triangle")
    A, B, C = P[T[:, 0]], P[T[:, 1]], P[T[:, 2]]
    scale = np.max(np.abs(np.concatenate([B - A, C - A], axis=1)), axis=1)[:, None]
    ab, bc, ca = (B - A) / scale, (C - B) / scale, (A - C) / scale   # scale-free, no overflow
    la, lb, lc = (np.hypot(*bc.T), np.hypot(*ca.T), np.hypot(*ab.T))  # side opposite A, B, C

    def angle(u, v):   # angle between vectors u and v
        return np.degrees(np.arctan2(np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]),
                                     u[:, 0] * v[:, 0] + u[:, 1] * v[:, 1]))

    ang = np.stack([angle(ab, -ca), angle(bc, -ab), angle(ca, -bc)], axis=1)
    area2 = np.abs(ab[:, 0] * (-ca[:, 1]) - ab[:, 1] * (-ca[:, 0]))     # twice the area
    with np.errstate(divide="ignore"):
        ratio = la * lb * lc * (la + lb + lc) / (4.0 * area2 ** 2)       # R / 2r
    sides = np.stack([la, lb, lc], axis=1)
    return {
        "min_angle": float(ang.min()),
        "max_angle": float(ang.max()),
        "mean_min_angle": float(ang.min(axis=1).mean()),
        "radius_ratio_max": float(ratio.max()),
        "radius_ratio_mean": float(ratio.mean()),
        "edge_ratio_max": float((sides.max(axis=1) / sides.min(axis=1)).max()),
        "triangles": int(len(T)),
        "vertices": int(len(np.unique(T))),
        "interior_edges": int(np.count_nonzero(nbr >= 0) // 2),
        "boundary_edges": int(np.count_nonzero(nbr < 0)),
        "angles_below_30": int(np.count_nonzero(ang < 30.0)),
        "obtuse_triangles": int(np.count_nonzero(ang.max(axis=1) > 90.0)),
    }
