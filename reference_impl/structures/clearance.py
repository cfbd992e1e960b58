"""Maximum clearance: the widest disk that can travel from start to goal among point obstacles.

Use it from Python::

    from reference_impl.structures.clearance import max_clearance
    r = max_clearance(obstacles, start, goal)

or run the examples: ``python -m pytest --doctest-modules reference_impl/structures/clearance.py``.

>>> max_clearance([(0, 0), (2, 0), (2, 2), (0, 2)], start=(1, 1), goal=(5, 1))   # leave the square
1.0

The problem.  A closed disk of radius r moves its centre along a continuous path
from ``start`` to ``goal``; no obstacle may ever be strictly inside it.  With
d(x) the distance from x to the nearest obstacle, the centre must stay in
F_r = {x : d(x) >= r}, and the answer is the largest r for which start and goal
lie in one connected piece of F_r (a bottleneck, or maximin, path problem).

The answer.  Triangulate the obstacles (Delaunay) and add one *outer face*
for everything outside the hull.  Then

    r* = min(d(start), d(goal), B),

where B is the bottleneck value between the face containing start and the face
containing goal in the graph whose nodes are the faces and whose edges are the
Delaunay edges, an edge (a, b) weighing |ab| / 2 (B = inf when both lie in the
same face).  B is computed by Kruskal's algorithm: join faces across edges in
decreasing weight until the two faces meet.

Why this is right.

* *Necessary.*  On the segment ab, d(x) <= min(|xa|, |xb|) <= |ab| / 2, and a
  path that avoids the obstacles (r > 0) passes from face to face through the
  interiors of Delaunay edges; so it can only cross edges with |ab| >= 2r, and
  it starts and ends at clearance d(start), d(goal) >= r.
* *Sufficient.*  Fix r below min(d(start), d(goal)) and away from the finitely
  many critical values (edge half-lengths and circumradii).  The obstacles'
  disks of radius r have a dual alpha complex K_r (Delaunay triangles with
  circumradius R < r, and edges ab with w(ab) < r, where w(ab) = |ab| / 2 if
  ab is Gabriel, i.e. both opposite angles are at most 90 degrees, and
  otherwise the smaller circumradius of its two faces: the least clearance
  along the dual Voronoi edge).  By Edelsbrunner's duality ("The union of balls
  and its dual shape", 1995) the union of the disks deformation-retracts onto
  K_r, so (Alexander duality in the plane) two free points lie in one piece of
  F_r exactly when their faces are joined by a chain of faces not in K_r,
  consecutive ones sharing an edge not in K_r.  The face of a free point is
  never in K_r (d(x) <= R on a triangle).  Since w(ab) >= |ab| / 2, this chain
  condition and ours (|ab| >= 2r) differ only on non-Gabriel edges with
  |ab| < 2r < 2 w(ab).  Such an edge is the longest edge of a triangle T that is
  obtuse opposite it; T's other edges are shorter still and can be crossed
  (w > r) only from triangles obtuse towards T, and so on: these triangles form
  trees hanging from ab, dead ends that join no two other components, and on
  each of them d(x) < (longest edge) / 2 < r (in an obtuse triangle every point
  is closer than half the longest side to some vertex), so they hold no free
  start or goal.  Hence start and goal are connected in F_r exactly when their
  faces are connected across edges with |ab| >= 2r; F_r shrinks as r grows and
  is closed, so the largest r is the formula.  The tests check it against the
  Voronoi-diagram retraction (O'Dunlaing and Yap 1985) computed with scipy and
  networkx, and against a union-of-disks computation in shapely.

Conventions and edge cases: duplicated obstacles count once; no obstacle gives
``inf``; a start or goal on an obstacle gives 0.0; start == goal gives
d(start); collinear obstacles (fewer than three distinct included) never
separate anything, so the answer is min(d(start), d(goal)).  The point
location (which face holds start and goal) uses exact predicates; distances
are floating point (``math.hypot``-accurate).
"""
from __future__ import annotations

import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from reference_impl.mesh.delaunay import Delaunay, as_delaunay, live_points
from reference_impl.mesh.topology import each_edge_once, find_root, union_roots
from reference_impl.validate import as_point

__all__ = ["max_clearance"]


@njit(cache=True)
def _bottleneck(a, b, order, weight, n_nodes, src, dst):
    """Kruskal in decreasing weight (``order``) until src and dst are joined; return the
    weight of the edge that joined them."""
    parent = np.arange(n_nodes)
    size = np.ones(n_nodes, dtype=np.int64)
    for e in order:
        ra = find_root(parent, a[e])
        rb = find_root(parent, b[e])
        if ra != rb:
            union_roots(parent, size, ra, rb)
            if find_root(parent, src) == find_root(parent, dst):
                return weight[e]
    return -1.0   # unreachable: the face graph of a triangulation is connected


def _nearest_distance(pts: np.ndarray, q: np.ndarray) -> float:
    """Distance from q to the nearest point (brute force: two queries per call)."""
    return float(np.min(np.hypot(pts[:, 0] - q[0], pts[:, 1] - q[1])))


def max_clearance(points: ArrayLike | Delaunay, start: ArrayLike, goal: ArrayLike) -> float:
    """Largest radius of a disk that can move from ``start`` to ``goal`` among point obstacles.

    ``points`` are the obstacles ((n, 2)), or a ``Delaunay`` of them (its mesh is used
    as it is: no re-triangulation; removed points are no obstacles); ``start`` and
    ``goal`` are the disk centre's end positions.  Returns ``inf`` when there is no obstacle, 0.0 when
    start or goal is an obstacle.  Raises ``ValueError`` for malformed input.

    >>> max_clearance([(0, 0), (4, 0), (2, 1)], (2, -3), (2, 3))   # go around: d(goal) binds
    2.0
    >>> max_clearance([(0, 0), (2, 0), (1, 3), (1, -3)], (1, 1), (1, -1))  # squeeze or go around
    1.4142135623730951
    >>> max_clearance([(0, 0), (1, 0)], (0, 5), (0, -5))           # collinear: go around
    5.0
    >>> max_clearance([], (0, 0), (1, 1))
    inf
    """
    d = as_delaunay(points)
    pts = d.points
    s = as_point(start, name="start")
    g = as_point(goal, name="goal")
    obstacles = live_points(d)[0]
    if len(obstacles) == 0:
        return float("inf")
    ends = min(_nearest_distance(obstacles, s), _nearest_distance(obstacles, g))
    simp, nbrs = d.simplices, d.neighbors
    m = len(simp)
    if m == 0 or ends == 0.0:
        return ends
    outer = m
    fs, fg = (outer if f < 0 else f for f in d.find_simplex(np.stack([s, g])))
    if fs == fg:
        return ends
    # each edge once: the face opposite vertex k of t and its neighbour (or the outer face)
    a, k = each_edge_once(nbrs)
    b = np.where(nbrs[a, k] < 0, outer, nbrs[a, k])
    u = simp[a, (k + 1) % 3]
    v = simp[a, (k + 2) % 3]
    half = 0.5 * np.hypot(pts[u, 0] - pts[v, 0], pts[u, 1] - pts[v, 1])
    order = np.argsort(-half, kind="stable")
    bottleneck = _bottleneck(a, b, order, half, m + 1, fs, fg)
    return float(min(ends, bottleneck))
