"""One Bowyer-Watson insertion in 3D: the bad tetrahedra, the cavity's boundary faces, the new
tetrahedra (lesson 13).

Run the examples:  python -m pytest reference_impl/teaching/cavity3d.py

The 3D step is the 2D step one dimension up: a tetrahedron is *bad* for the new point q when its
circumsphere strictly contains q (the exact ``insphere`` test); the bad tetrahedra form the
*cavity*; its boundary is made of the triangular faces that belong to exactly one bad
tetrahedron; and every boundary face is joined to q.  Each face is stored oriented so that the
opposite vertex of its bad tetrahedron is on its positive side (``orient3d(face, vertex) > 0``):
the cavity is star-shaped from q, so q is on that side too and every new tetrahedron
(face + q) is positively oriented.

Assumptions: the tetrahedra are a Delaunay tetrahedralisation (each with ``orient3d > 0``), q lies
strictly inside its convex hull and is not a vertex; general position (no five points on a
sphere) makes the result the unique Delaunay tetrahedralisation of the points with q.

>>> pts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)]
>>> tets = [(0, 3, 2, 4), (0, 4, 2, 1), (0, 3, 4, 1)]      # delaunay_3d(pts)
>>> cav = cavity_3d(pts + [(0.3, 0.3, 0.3)], tets, 5)
>>> len(cav.bad), len(cav.boundary), len(cav.new)
(3, 6, 6)
"""
from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

import numpy as np

from reference_impl.exact.predicates3d import insphere_batch, orient3d
from reference_impl.validate import as_points

__all__ = ["cavity_3d", "Cavity3D", "surface_counts"]

Face = tuple[int, int, int]


@dataclass(frozen=True)
class Cavity3D:
    """One insertion of point ``q``: ``bad`` tetrahedra, cavity ``boundary`` faces (each oriented
    with the cavity on its positive side), ``new`` tetrahedra (face + q), and ``tetrahedra``:
    the tetrahedralisation after the insertion (the old ones minus the bad, plus the new)."""

    q: int
    bad: list[tuple[int, int, int, int]]
    boundary: list[Face]
    new: list[tuple[int, int, int, int]]
    tetrahedra: np.ndarray


def cavity_3d(points, tetrahedra, q: int) -> Cavity3D:
    """Insert point ``q`` (an index into ``points``, not yet a vertex) into ``tetrahedra``.

    Raises ``ValueError`` for a tetrahedron that is not positively oriented, or
    when no tetrahedron is bad (q is then outside the hull's circumspheres or a duplicate).

    >>> pts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (0.2, 0.2, 0.2)]
    >>> cav = cavity_3d(pts, [(0, 2, 1, 3)], 4)            # one tetrahedron, q inside it
    >>> cav.bad, len(cav.boundary), surface_counts(cav.boundary)
    ([(0, 2, 1, 3)], 4, (4, 6, 4, True))
    """
    P = as_points(points, dim=3)
    xyz = [tuple(p) for p in P.tolist()]
    T = [tuple(int(v) for v in t) for t in np.asarray(tetrahedra, dtype=np.int64).reshape(-1, 4).tolist()]
    q = int(q)
    if not 0 <= q < len(P):
        raise ValueError(f"q = {q} is not a point index (0..{len(P) - 1})")
    if any(q in t for t in T):
        raise ValueError(f"point {q} is already a vertex")
    for t in T:
        if orient3d(*(xyz[v] for v in t)) <= 0:
            raise ValueError(f"tetrahedron {t} is not positively oriented (orient3d must be > 0)")
    A = np.asarray(T, dtype=np.int64).reshape(-1, 4)
    inside = insphere_batch(P[A[:, 0]], P[A[:, 1]], P[A[:, 2]], P[A[:, 3]], np.repeat(P[[q]], len(A), axis=0))
    bad = [T[k] for k in np.flatnonzero(inside > 0).tolist()]
    if not bad:
        raise ValueError(f"no circumsphere contains point {q}: is it outside the hull or a duplicate?")
    count: dict[frozenset, list[Face]] = {}
    for t in bad:
        for face in combinations(t, 3):
            opposite = next(v for v in t if v not in face)
            a, b, c = face
            if orient3d(xyz[a], xyz[b], xyz[c], xyz[opposite]) < 0:
                face = (a, c, b)
            count.setdefault(frozenset(face), []).append(face)
    boundary = [faces[0] for faces in count.values() if len(faces) == 1]
    new = [(a, b, c, q) for a, b, c in boundary]
    for t in new:
        if orient3d(*(xyz[v] for v in t)) <= 0:
            raise ValueError(f"new tetrahedron {t} is not positively oriented: is q inside the convex hull?")
    gone = set(bad)
    result = [t for t in T if t not in gone] + new
    return Cavity3D(q, bad, boundary, new, np.array(result, dtype=np.int64).reshape(-1, 4))


def surface_counts(faces) -> tuple[int, int, int, bool]:
    """(V, E, F, closed) of a triangulated surface; closed: every edge is in exactly two faces.

    A closed surface that bounds a ball (a sphere) has V - E + F = 2.

    >>> surface_counts([(0, 1, 2), (0, 2, 3), (0, 3, 1), (1, 3, 2)])     # a tetrahedron's surface
    (4, 6, 4, True)
    """
    edges: dict[frozenset, int] = {}
    verts = set()
    for f in faces:
        verts.update(f)
        for e in combinations(f, 2):
            edges[frozenset(e)] = edges.get(frozenset(e), 0) + 1
    return len(verts), len(edges), len(faces), all(m == 2 for m in edges.values())
