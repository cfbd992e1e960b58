"""Tests for reference_impl.structures.clearance.max_clearance against two independent oracles.

Run:  .venv/bin/python -m pytest tests/structures/test_clearance.py -q

Oracles:
* ``retraction_oracle``: the Voronoi-diagram retraction of O'Dunlaing and Yap,
  built with scipy.spatial.Voronoi and networkx.  Start and goal are pushed away
  from their nearest obstacle onto the Voronoi diagram (the first bisector met,
  found by brute force over all obstacles); every Voronoi edge is weighted by
  its least clearance (the distance from its site to the segment or ray); the
  answer is min(d(start), d(goal), bottleneck of the maximum spanning tree).
  Shares no formula with the implementation (which uses Delaunay edge lengths
  and face location).  General position only (random doubles).
* ``shapely_oracle``: binary search on r, with the free space computed as a box
  minus the union of 256-gon disks; checks that start and goal lie in one piece.
  Fully independent of any Voronoi/Delaunay theory, works on degenerate sets; the
  polygons sit inside the true disks, so it answers within about 1e-4 above r*.
"""
from __future__ import annotations

import doctest
import math

import networkx as nx
import numpy as np
import pytest
import shapely
from hypothesis import given, strategies as st
from scipy.spatial import Voronoi

import reference_impl.structures.clearance as clearance_module
from pointsets import circle, collinear, grid, integer_circle, rotated_grid
from reference_impl.structures.clearance import max_clearance


# --------------------------------------------------------------------- oracle 1: retraction
def _seg_dist(p, a, b):
    ab = b - a
    t = 0.0 if not ab.any() else min(1.0, max(0.0, float(np.dot(p - a, ab) / np.dot(ab, ab))))
    return float(np.hypot(*(a + t * ab - p)))


def _ray_dist(p, a, d):
    t = max(0.0, float(np.dot(p - a, d)))
    return float(np.hypot(*(a + t * d - p)))


def retraction_oracle(P, s, g) -> float:
    P = np.asarray(P, dtype=float)
    s, g = np.asarray(s, float), np.asarray(g, float)
    ds = float(np.min(np.hypot(*(P - s).T)))
    dg = float(np.min(np.hypot(*(P - g).T)))
    if min(ds, dg) == 0.0:
        return 0.0
    vor = Voronoi(P)
    V = vor.vertices
    centre = P.mean(axis=0)
    ridges = {}
    for (i, j), rv in zip(vor.ridge_points, vor.ridge_vertices):
        i, j = int(i), int(j)
        if -1 in rv:
            u = rv[0] if rv[1] == -1 else rv[1]
            n = np.array([-(P[j, 1] - P[i, 1]), P[j, 0] - P[i, 0]])
            n /= np.hypot(*n)
            if np.dot(centre - P[i], n) > 0:
                n = -n
            ridges[frozenset((i, j))] = (i, ("v", u), ("ray", n))
        else:
            ridges[frozenset((i, j))] = (i, ("v", rv[0]), ("v", rv[1]))
    splits = {}
    G = nx.Graph()

    def link(u, v, w):         # parallel edges (two rays of one vertex): the widest one counts
        if u != v and (not G.has_edge(u, v) or G.edges[u, v]["w"] < w):
            G.add_edge(u, v, w=w)
    for name, q in (("S", s), ("G", g)):
        p = int(np.argmin(np.hypot(*(P - q).T)))
        e = q - P[p]
        best, bq = math.inf, -1
        for k in range(len(P)):
            proj = float(np.dot(P[k] - P[p], e))
            if k != p and proj > 0:
                mu = float(np.dot(P[k] - P[p], P[k] - P[p])) / 2 / proj
                if mu < best:
                    best, bq = mu, k
        if bq < 0:
            link(name, "inf", math.inf)       # retracts to infinity, clearance growing
        else:
            splits.setdefault(frozenset((p, bq)), []).append((name, P[p] + best * e))
    for key, (i, a, b) in ridges.items():
        pa = V[a[1]]
        if b[0] == "ray":
            d = b[1]
            pts = sorted(splits.get(key, []), key=lambda it: float(np.dot(it[1] - pa, d)))
            chain = [(a[1], pa)] + pts
            for (n1, x1), (n2, x2) in zip(chain, chain[1:]):
                link(n1, n2, _seg_dist(P[i], x1, x2))
            link(chain[-1][0], "inf", _ray_dist(P[i], chain[-1][1], d))
        else:
            pb = V[b[1]]
            pts = sorted(splits.get(key, []), key=lambda it: float(np.dot(it[1] - pa, pb - pa)))
            chain = [(a[1], pa)] + pts + [(b[1], pb)]
            for (n1, x1), (n2, x2) in zip(chain, chain[1:]):
                link(n1, n2, _seg_dist(P[i], x1, x2))
    tree = nx.maximum_spanning_tree(G, weight="w")
    path = nx.shortest_path(tree, "S", "G")
    bottleneck = min((tree.edges[u, v]["w"] for u, v in zip(path, path[1:])), default=math.inf)
    return min(ds, dg, bottleneck)


# --------------------------------------------------------------------- oracle 2: union of disks
def shapely_oracle(P, s, g, steps: int = 34) -> float:
    P = np.asarray(P, dtype=float)
    hi = min(float(np.min(np.hypot(*(P - s).T))), float(np.min(np.hypot(*(P - g).T))))
    if hi == 0.0:
        return 0.0
    allp = np.vstack([P, [s], [g]])
    lo_xy, hi_xy = allp.min(axis=0) - 3 * hi - 1, allp.max(axis=0) + 3 * hi + 1
    box = shapely.box(*lo_xy, *hi_xy)
    S, Gp = shapely.Point(s), shapely.Point(g)

    def connected(r):
        disks = shapely.union_all([shapely.Point(p).buffer(r, quad_segs=64) for p in P])
        free = box.difference(disks)
        parts = getattr(free, "geoms", [free])
        return any(part.covers(S) and part.covers(Gp) for part in parts)

    top = hi * (1 - 1e-9)
    if connected(top):
        return hi
    lo = 0.0
    for _ in range(steps):
        mid = 0.5 * (lo + top)
        if connected(mid):
            lo = mid
        else:
            top = mid
    return lo


def test_doctests():
    assert doctest.testmod(clearance_module).failed == 0


def test_thousand_random_cases_against_the_retraction():
    rng = np.random.default_rng(17)
    inside_hull = 0

    def roomy(P, k=25):
        """A point in the hull far from the obstacles (so that bottlenecks bind): the best of
        k random convex combinations of three obstacles."""
        w = rng.dirichlet(np.ones(3), k)
        Q = np.einsum("kj,kjd->kd", w, P[rng.integers(0, len(P), (k, 3))])
        return Q[np.argmax([np.min(np.hypot(*(P - q).T)) for q in Q])]

    for case in range(1000):
        n = int(rng.integers(3, 20))
        P = rng.random((n, 2)) * 10
        if case % 2:                        # a jittered ring around the centre: a room with doors
            k = int(rng.integers(5, 13))
            t = (np.arange(k) + rng.random(k) * 0.6) * 2 * np.pi / k
            rad = 4 + rng.random(k)
            P = np.vstack([np.c_[5 + rad * np.cos(t), 5 + rad * np.sin(t)], P[: n // 4] * 0.6 + 2])
        s = roomy(P)
        if case % 2:
            a = rng.random() * 2 * np.pi
            g = roomy(P) if case % 3 == 0 else np.array([5 + 9 * np.cos(a), 5 + 9 * np.sin(a)])
        else:
            g = roomy(P) if case % 5 else rng.random(2) * 14 - 2
        got = max_clearance(P, s, g)
        want = retraction_oracle(P, s, g)
        assert got == pytest.approx(want, rel=1e-9, abs=1e-12), (case, P.tolist(), s, g)
        inside_hull += got < min(np.min(np.hypot(*(P - s).T)), np.min(np.hypot(*(P - g).T)))
    assert inside_hull > 250        # the bottleneck term, not only d(start), d(goal), decided often


@pytest.mark.parametrize("seed", range(12))
def test_random_cases_against_union_of_disks(seed):
    rng = np.random.default_rng(100 + seed)
    P = rng.random((int(rng.integers(3, 14)), 2)) * 4
    s, g = P.mean(axis=0) + rng.standard_normal(2) * 0.2, rng.random(2) * 6 - 1
    got = max_clearance(P, s, g)
    assert got == pytest.approx(shapely_oracle(P, s, g), rel=2e-4)


def degenerate_cases():
    """(name, obstacles, start, goal): small degenerate families with interesting starts."""
    ring = circle(12)
    return [
        ("ring-centre-out", ring, (0.0, 0.0), (3.0, 0.5)),
        ("ring+centre", circle(12, centre=True), (0.5, 0.1), (3.0, 0.5)),
        ("integer-circle", integer_circle(), (2.0, 1.0), (-2.5, -2.0)),
        ("grid-cells", grid(6), (1.5, 1.5), (3.5, 2.5)),
        ("grid-out", grid(6), (2.5, 2.5), (9.0, 9.0)),
        ("grid-rect", grid(2, 9), (0.5, 4.5), (0.5, 0.5)),
        ("rotated-grid", rotated_grid(5), (1.2, 2.0), (2.0, 1.0)),
        ("collinear", collinear(10), (0.0, 3.0), (0.1, -2.0)),
        ("duplicates", np.vstack([grid(4), grid(4)]), (1.5, 1.5), (10.0, 0.0)),
        ("grid-1e-300", grid(5) * 1e-300, (1.5e-300, 1.5e-300), (2.5e-300, 0.5e-300)),
        ("grid-1e300", grid(5) * 1e300, (1.5e300, 1.5e300), (9e300, 9e300)),
        ("offset-1e9", grid(5) + 1e9, (1e9 + 1.5, 1e9 + 1.5), (1e9 + 2.5, 1e9 + 3.5)),
        ("clusters", np.vstack([grid(3) * 1e-6, grid(3) * 1e3 + 5.0]), (0.5e-6, 0.5e-6), (1505.0, 1505.0)),
        ("tutorial", np.array([(1, 1), (3, 2), (5, 1), (4, 4)], float), (3.2, 2.1), (0.0, 0.0)),
    ]


@pytest.mark.parametrize("name,P,s,g", degenerate_cases(), ids=lambda v: v if isinstance(v, str) else "")
def test_degenerate_sets_against_union_of_disks(name, P, s, g):
    P = np.asarray(P, float)
    s, g = np.asarray(s, float), np.asarray(g, float)
    got = max_clearance(P, s, g)
    # the oracle runs at unit scale (r* scales and translates with the points)
    centre = P.mean(axis=0)
    size = float(np.abs(P - centre).max())
    want = shapely_oracle((P - centre) / size, (s - centre) / size, (g - centre) / size) * size
    assert got == pytest.approx(want, rel=2e-4)
    assert got == max_clearance(P[::-1], g, s)


def test_ring_needs_the_gap():
    ring = circle(12)
    assert max_clearance(ring, (0, 0), (3, 0)) == pytest.approx(math.sin(math.pi / 12), rel=1e-12)
    assert max_clearance(ring, (0, 0), (0.01, 0)) == pytest.approx(0.99, rel=1e-12)   # same face


def test_edge_cases():
    assert max_clearance([], (0, 0), (5, 5)) == math.inf
    assert max_clearance([(1, 1)], (0, 0), (5, 5)) == math.sqrt(2)
    assert max_clearance([(1, 1), (1, 1)], (4, 5), (-2, 1)) == 3.0
    assert max_clearance([(0, 0), (1, 0), (2, 0)], (1, 3), (1, -1)) == 1.0         # collinear: go around
    assert max_clearance([(0, 0), (2, 0), (0, 2)], (0, 0), (5, 5)) == 0.0           # start on an obstacle
    assert max_clearance([(0, 0), (2, 0), (0, 2)], (5, 5), (0, 2)) == 0.0           # goal on an obstacle
    assert max_clearance([(0, 0), (4, 0), (0, 4)], (1, 1), (1, 1)) == math.sqrt(2)  # start == goal
    # start on a Delaunay edge, goal outside: d(start) binds
    assert max_clearance([(0, 0), (4, 0), (0, 4)], (2, 0), (9, 9)) == 2.0


def test_permutation_and_duplicates_do_not_matter():
    rng = np.random.default_rng(8)
    P = rng.random((200, 2))
    s, g = (0.5, 0.5), (0.1, 0.95)
    base = max_clearance(P, s, g)
    assert max_clearance(P[rng.permutation(200)], s, g) == base
    assert max_clearance(np.vstack([P, P[:50]]), s, g) == base


def test_large_input_against_the_retraction():
    rng = np.random.default_rng(3)
    P = rng.random((3000, 2))
    for _ in range(3):
        s, g = rng.random(2), rng.random(2)
        assert max_clearance(P, s, g) == pytest.approx(retraction_oracle(P, s, g), rel=1e-9)


@given(st.lists(st.tuples(st.integers(-20, 20), st.integers(-20, 20)), min_size=1, max_size=25),
       st.tuples(st.integers(-25, 25), st.integers(-25, 25)), st.tuples(st.integers(-25, 25), st.integers(-25, 25)),
       st.tuples(st.integers(-20, 20), st.integers(-20, 20)))
def test_properties_symmetry_bounds_monotonicity(pts, s, g, extra):
    P = np.array(pts, dtype=float)
    r = max_clearance(P, s, g)
    assert r == max_clearance(P, g, s)
    ds = float(np.min(np.hypot(*(P - s).T)))
    dg = float(np.min(np.hypot(*(P - g).T)))
    assert r <= min(ds, dg)
    assert max_clearance(np.vstack([P, [extra]]), s, g) <= r      # an extra obstacle never helps


@pytest.mark.parametrize("args", [([(0, float("nan"))], (0, 0), (1, 1)), ([(0, 0)], (0, float("inf")), (1, 1)),
                                  ([(0, 0)], (0, 0, 0), (1, 1)), ([(0, 0)], (0, 0), "goal")])
def test_bad_input_raises(args):
    with pytest.raises(ValueError):
        max_clearance(*args)
