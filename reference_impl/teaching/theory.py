"""The theory behind Bowyer-Watson, in code that can be checked: backwards analysis, the Delaunay
lemma and the max-min angle theorem (lesson 13).

Run the examples:  python -m pytest reference_impl/teaching/theory.py

* ``new_triangles_per_insertion``: how many triangles each insertion creates (ghost triangles
  included), from ``bowyer_watson``'s trace; ``star_sizes``: how many triangles surround each
  vertex of a finished triangulation, counted the same way.  Backwards analysis says the two are
  the same number, and that their mean over the vertices is exactly (6k - 6 - h) / k < 6.
* ``illegal_edges``, ``lawson``: the edges that are not locally Delaunay, and flip-until-done
  from any triangulation, recording every triangulation on the way (exact predicates).
* ``angle_vector``, ``compare_angle_vectors``, ``all_triangulations``: the sorted angles of a
  triangulation, their lexicographic comparison, and every triangulation of a small point set
  (found by flips: the flip graph of a planar point set is connected).

Triangles are index triples, counter-clockwise.  "General position" below means no three input
points on a line and no four on a circle; the functions still run without it, but the theorems
they illustrate assume it.

>>> pts = [(0, 0), (4, 0), (4, 1), (0, 3)]
>>> steps = lawson(pts, [(0, 1, 3), (1, 2, 3)])
>>> [sorted(map(tuple, s.tolist())) for s in steps]
[[(0, 1, 3), (1, 2, 3)], [(0, 1, 2), (0, 2, 3)]]
>>> illegal_edges(pts, steps[-1])
[]
"""
from __future__ import annotations

from collections import deque

import numpy as np

from reference_impl.exact.predicates import incircle, orient2d
from reference_impl.teaching.bowyer_watson import Step, bowyer_watson
from reference_impl.validate import as_points

__all__ = ["sweep_triangulation", "new_triangles_per_insertion", "star_sizes", "mean_star_size", "illegal_edges", "lawson",
           "angle_vector", "compare_angle_vectors", "all_triangulations", "flip_edge"]

Tri = tuple[int, int, int]


def _canon(t) -> Tri:
    """Rotate a triangle to start at its smallest index (orientation kept)."""
    a, b, c = (int(v) for v in t)
    if a < b and a < c:
        return (a, b, c)
    return (b, c, a) if b < c else (c, a, b)


def _as_triangles(triangles) -> list[Tri]:
    T = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    return [_canon(t) for t in T.tolist()]


def _checked(xy: list, triangles) -> list[Tri]:
    """The triangles, canonical, after checking indices and counter-clockwise orientation."""
    T = _as_triangles(triangles)
    for t in T:
        if min(t) < 0 or max(t) >= len(xy):
            raise ValueError(f"triangle {t} has an index outside 0..{len(xy) - 1}")
        if orient2d(xy[t[0]], xy[t[1]], xy[t[2]]) <= 0:
            raise ValueError(f"triangle {t} is not counter-clockwise (or has zero area)")
    return T


def _array(tris) -> np.ndarray:
    return np.array(sorted(tris), dtype=np.int64).reshape(-1, 3)


# ----------------------------------------------------------------------------- backwards analysis
def new_triangles_per_insertion(points, order=None) -> np.ndarray:
    """Triangles created by each insertion of ``bowyer_watson`` (walk location), in insertion order.

    ``order``: a permutation of the point indices (default: as given).  Ghost
    triangles (outside a hull edge, with the vertex at infinity) count: with
    them, every insertion of the k-th point into a triangulation of k - 1 points
    creates exactly as many triangles as surround the new point afterwards.  The
    two start-up insertions (first and second point) are left out, so the
    result has one entry per point from the third on.

    >>> new_triangles_per_insertion([(0, 0), (1, 0), (0, 1), (0.9, 0.8)]).tolist()
    [3, 4]
    """
    P = as_points(points)
    if order is not None:
        order = np.asarray(order, dtype=np.int64)
        if sorted(order.tolist()) != list(range(len(P))):
            raise ValueError(f"order must be a permutation of 0..{len(P) - 1}")
        P = P[order]
    steps: list[Step] = []
    bowyer_watson(P, trace=steps, locate="walk", order="input", snapshots=False)
    return np.array([len(s.new) for s in steps[2:]], dtype=np.int64)


def star_sizes(n: int, triangles) -> np.ndarray:
    """For each of the n vertices: the triangles around it, ghost triangles included.

    A vertex inside the hull is surrounded by its real triangles only; a vertex
    on the hull also touches the two ghost triangles outside its two hull edges.
    This equals the vertex's degree in the triangulation closed up by the vertex
    at infinity (a triangulation of the sphere).

    >>> star_sizes(4, [(0, 1, 3), (0, 3, 2)]).tolist()     # a square cut by the diagonal 0-3
    [4, 3, 3, 4]
    """
    T = _as_triangles(triangles)
    if T and (min(map(min, T)) < 0 or max(map(max, T)) >= n):
        raise ValueError(f"a triangle has a vertex index outside 0..{n - 1}")
    size = np.zeros(n, dtype=np.int64)
    directed = set()
    for a, b, c in T:
        size[[a, b, c]] += 1
        directed.update(((a, b), (b, c), (c, a)))
    for a, b in directed:
        if (b, a) not in directed:       # a hull edge: one ghost triangle outside it
            size[a] += 1
            size[b] += 1
    return size


def mean_star_size(n: int, triangles) -> tuple[float, int]:
    """(mean star size over the vertices used, h): the mean equals (6k - 6 - h) / k exactly.

    Why: close the triangulation with the vertex at infinity.  It becomes a
    triangulation of the sphere with V = k + 1 vertices, hence (Euler) 3V - 6
    edges, and the degrees add up to twice that, 6k - 6.  The vertex at infinity
    has degree h (one edge per hull vertex), so the k real vertices share 6k - 6 - h.

    >>> mean_star_size(4, [(0, 1, 3), (0, 3, 2)])      # k = 4, h = 4: (24 - 6 - 4) / 4
    (3.5, 4)
    """
    size = star_sizes(n, triangles)
    used = size > 0
    T = _as_triangles(triangles)
    directed = {e for a, b, c in T for e in ((a, b), (b, c), (c, a))}
    hull = {a for a, b in directed if (b, a) not in directed}
    return float(size[used].mean()), len(hull)


# ----------------------------------------------------------------------------- local Delaunay and Lawson
def sweep_triangulation(points) -> np.ndarray:
    """A triangulation that ignores circles: sweep the points by x, join each to the hull edges it sees.

    Points are taken in (x, y) order; each new point lies outside the hull of
    the earlier ones and is joined to every hull edge it sees (strictly).  The
    result is a valid triangulation of the points, usually far from Delaunay
    (long thin triangles).  Needs general position: three collinear points met
    on the way raise ``ValueError``.

    >>> sweep_triangulation([(0, 0), (1, 1), (2, -1), (3, 0.5)]).tolist()
    [[0, 2, 1], [1, 2, 3]]
    """
    P = as_points(points)
    xy = [tuple(p) for p in P.tolist()]
    order = sorted(range(len(xy)), key=lambda i: xy[i])
    if len(order) < 3:
        return np.zeros((0, 3), dtype=np.int64)
    a, b, c = order[:3]
    turn = orient2d(xy[a], xy[b], xy[c])
    if turn == 0:
        raise ValueError("the first three points (by x) are collinear: sweep_triangulation needs general position")
    hull = [a, b, c] if turn > 0 else [a, c, b]          # counter-clockwise
    tris = [_canon(hull)]
    for p in order[3:]:
        side = [orient2d(xy[hull[i]], xy[hull[(i + 1) % len(hull)]], xy[p]) for i in range(len(hull))]
        if 0 in side:
            raise ValueError(f"point {p} is collinear with a hull edge: sweep_triangulation needs general position")
        first = next(i for i in range(len(hull)) if side[i] < 0 and side[i - 1] > 0)
        hull = hull[first:] + hull[:first]              # the edges p sees are now 0 .. k-1
        side = side[first:] + side[:first]
        k = next(i for i in range(len(hull)) if side[i] > 0)
        tris += [_canon((hull[j + 1], hull[j], p)) for j in range(k)]
        hull = [hull[0], p] + hull[k:]
    return _array(tris)



def _opposite(T: list[Tri]) -> dict[tuple[int, int], int]:
    opp = {}
    for a, b, c in T:
        opp[(a, b)], opp[(b, c)], opp[(c, a)] = c, a, b
    return opp


def illegal_edges(points, triangles) -> list[tuple[int, int]]:
    """Interior edges (u < v) that are not locally Delaunay: the vertex across the edge lies
    strictly inside the circumcircle of the triangle on this side (exact ``incircle``).

    >>> illegal_edges([(0, 0), (4, 0), (4, 1), (0, 3)], [(0, 1, 3), (1, 2, 3)])
    [(1, 3)]
    """
    P = as_points(points).tolist()
    opp = _opposite(_as_triangles(triangles))
    bad = []
    for (u, v), w in opp.items():
        x = opp.get((v, u))
        if x is not None and u < v and incircle(P[u], P[v], P[w], P[x]) > 0:
            bad.append((u, v))
    return sorted(bad)


def flip_edge(T: set[Tri], opp: dict[tuple[int, int], int], u: int, v: int) -> tuple[int, int]:
    """Flip interior edge u-v in place: triangles (u, v, w) and (v, u, x) become (w, x, v) and
    (x, w, u); returns the new edge (w, x).  ``T`` and ``opp`` (directed edge -> apex) are updated.

    >>> T = {(0, 1, 3), (1, 2, 3)}; opp = {}
    >>> for a, b, c in T: opp[(a, b)], opp[(b, c)], opp[(c, a)] = c, a, b
    >>> flip_edge(T, opp, 1, 3), sorted(T)
    ((0, 2), [(0, 1, 2), (0, 2, 3)])
    """
    w, x = opp[(u, v)], opp[(v, u)]
    for t in ((u, v, w), (v, u, x)):
        T.discard(_canon(t))
        for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            del opp[e]
    for t in ((w, x, v), (x, w, u)):
        T.add(_canon(t))
        opp[(t[0], t[1])], opp[(t[1], t[2])], opp[(t[2], t[0])] = t[2], t[0], t[1]
    return (w, x)


def lawson(points, triangles, max_flips: int = 100_000) -> list[np.ndarray]:
    """Flip illegal edges until none is left; the triangulations before and after every flip.

    Starts from any triangulation of the points (``triangles``, counter-clockwise).
    An illegal edge always has a strictly convex quadrilateral, so it can be
    flipped.  Each flip increases the sorted angle vector (see ``angle_vector``),
    and there are finitely many triangulations, so the loop ends; when it does,
    every edge is locally Delaunay and (the Delaunay lemma) the triangulation is
    Delaunay.  The edges to recheck after a flip are the four outer edges of the
    quadrilateral, kept on a stack.

    >>> [len(s) for s in lawson([(0, 0), (1, 0), (0, 1)], [(0, 1, 2)])]
    [1]
    """
    P = as_points(points).tolist()
    T = set(_checked(P, triangles))
    opp = _opposite(sorted(T))
    states = [_array(T)]
    stack = [e for e in opp if e[0] < e[1]]
    while stack:
        u, v = stack.pop()
        if (u, v) not in opp or (v, u) not in opp:
            continue
        w, x = opp[(u, v)], opp[(v, u)]
        if incircle(P[u], P[v], P[w], P[x]) <= 0:
            continue
        if len(states) > max_flips:
            raise ValueError(f"more than {max_flips} flips: is this a triangulation of the points?")
        flip_edge(T, opp, u, v)
        stack.extend([(v, w), (w, u), (u, x), (x, v)])
        states.append(_array(T))
    return states


# ----------------------------------------------------------------------------- angles
def angle_vector(points, triangles) -> np.ndarray:
    """All 3m angles of a triangulation in radians, sorted ascending (floating point).

    >>> np.degrees(angle_vector([(0, 0), (1, 0), (0, 1)], [(0, 1, 2)])).round(6).tolist()
    [45.0, 45.0, 90.0]
    """
    P = as_points(points)
    T = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    out = []
    for k in range(3):
        a, b, c = P[T[:, k]], P[T[:, (k + 1) % 3]], P[T[:, (k + 2) % 3]]
        u, v = b - a, c - a
        cross = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
        dot = (u * v).sum(axis=1)
        out.append(np.arctan2(np.abs(cross), dot))
    return np.sort(np.concatenate(out)) if out else np.zeros(0)


def compare_angle_vectors(first: np.ndarray, second: np.ndarray, tol: float = 1e-12) -> int:
    """+1 if ``first`` is lexicographically larger, -1 if smaller, 0 if equal within ``tol``.

    The angles are floating point, so entries closer than ``tol`` count as equal.

    >>> compare_angle_vectors(np.array([0.2, 1.0]), np.array([0.1, 2.0]))
    1
    """
    first, second = np.asarray(first), np.asarray(second)
    if first.shape != second.shape:
        raise ValueError(f"angle vectors of different lengths: {first.shape} and {second.shape}")
    diff = first - second
    where = np.flatnonzero(np.abs(diff) > tol)
    return 0 if where.size == 0 else int(np.sign(diff[where[0]]))


def all_triangulations(points, limit: int = 20_000) -> list[np.ndarray]:
    """Every triangulation of a small point set, by a breadth-first search over edge flips.

    Starts from the Delaunay triangulation and flips every interior edge whose
    quadrilateral is strictly convex (exact ``orient2d``), in every
    triangulation found.  The flip graph of a planar point set is connected
    (Lawson, 1972), so this finds them all.  ``limit`` guards against a set too
    large to enumerate (raises ``ValueError``).

    >>> len(all_triangulations([(0, 0), (2, 0), (3, 2), (1, 3), (-1, 2)]))   # convex pentagon: Catalan(3)
    5
    """
    P = as_points(points).tolist()
    start = frozenset(_as_triangles(bowyer_watson(P)))
    seen = {start}
    queue = deque([start])
    while queue:
        T = queue.popleft()
        opp = _opposite(list(T))
        for (u, v), w in opp.items():
            x = opp.get((v, u))
            if x is None or u > v:
                continue
            if orient2d(P[w], P[x], P[u]) * orient2d(P[w], P[x], P[v]) >= 0:
                continue                       # not strictly convex: the other diagonal is outside
            flipped = set(T)
            flip_edge(flipped, dict(opp), u, v)
            key = frozenset(flipped)
            if key not in seen:
                if len(seen) >= limit:
                    raise ValueError(f"more than {limit} triangulations: use fewer points")
                seen.add(key)
                queue.append(key)
    return [_array(T) for T in seen]
