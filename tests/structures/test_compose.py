"""Composition (d3-delaunay style): derived structures built on a ``Delaunay`` the user has,
scipy's lazy adjacency (``vertex_neighbor_vertices``, ``vertex_to_simplex``), ``find_simplex``
shaped like its input, the NamedTuple return values, and the problem adapters moved out.

* each derived structure gives the same answer for points and for their ``Delaunay``, and on a
  ``Delaunay`` it triangulates nothing (``Delaunay._build`` is counted);
* on a ``Delaunay`` after ``remove``: the same answers as for the remaining points alone;
* the adjacency against ``scipy.spatial.Delaunay`` (general position: the same neighbour sets)
  and against brute force from the triangles on degenerate and flat sets.

Run: python -m pytest tests/structures/test_compose.py -q
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest
import scipy.spatial

import pointsets
from grader.problems import load_problem
from reference_impl import (Circle, Delaunay, Delaunay3D, NavMesh, Pair, closest_pair, convex_hull,
                            euclidean_mst, gabriel_graph, largest_empty_circle, max_clearance,
                            relative_neighborhood_graph, voronoi)
from reference_impl.mesh.delaunay import as_delaunay, live_points
from reference_impl.validate import as_queries

def box_of(pts):
    lo, hi = pts.min(0), pts.max(0)
    pad = (hi - lo).max() * 0.25 + 1e-300 if len(pts) else 1.0
    return (lo[0] - pad, lo[1] - pad, hi[0] + pad, hi[1] + pad)


@pytest.fixture
def builds(monkeypatch):
    """Count every triangulation made (each Delaunay(...) and every rebuild runs _build)."""
    count = [0]
    original = Delaunay._build

    def counted(self):
        count[0] += 1
        return original(self)

    monkeypatch.setattr(Delaunay, "_build", counted)
    return count


SETS = [("uniform", pointsets.uniform(200, 4))] + [
    (n, p) for n, p in pointsets.degenerate_sets()
    if n in ("grid", "circle+centre", "duplicates", "grid-duplicates", "collinear+1", "tiny-1e-300", "tutorial")
] + [(n, p) for n, p in pointsets.flat_sets() if n in ("collinear", "tutorial-duplicates", "two")]


def structures(x, pts):
    """Every derived structure of ``x`` (points or a Delaunay of ``pts``), as comparable values."""
    out = {
        "hull": convex_hull(x).tolist(),
        "hull-collinear": convex_hull(x, collinear=True).tolist(),
        "emst": euclidean_mst(x).tolist(),
        "gabriel": gabriel_graph(x).tolist(),
        "rng": relative_neighborhood_graph(x).tolist(),
        "voronoi": [c.tolist() for c in voronoi(x, box_of(pts))],
        "clearance": max_clearance(x, pts.mean(0) + 0.01, pts.max(0) + 1.0),
    }
    if len(np.unique(pts, axis=0)) >= 2:
        out["closest"] = tuple(closest_pair(x))
    if len(pts):
        out["circle"] = tuple(largest_empty_circle(x))
    return out


@pytest.mark.parametrize("name,pts", SETS, ids=[n for n, _ in SETS])
def test_structures_on_a_delaunay_equal_those_on_points_and_do_not_triangulate(name, pts, builds):
    want = structures(pts, pts)
    d = Delaunay(pts)
    before = builds[0]
    got = structures(d, pts)
    assert builds[0] == before, "a derived structure triangulated the Delaunay it was given again"
    assert got == want


def test_the_count_sees_triangulations(builds):
    pts = pointsets.uniform(50, 1)
    euclidean_mst(pts)
    gabriel_graph(pts)
    assert builds[0] == 2


def test_delaunay_methods_are_the_structures(builds):
    pts = pointsets.uniform(150, 7)
    d = Delaunay(pts)
    before = builds[0]
    box = box_of(pts)
    assert [c.tolist() for c in d.voronoi(box)] == [c.tolist() for c in voronoi(pts, box)]
    assert d.euclidean_mst().tolist() == euclidean_mst(pts).tolist()
    assert d.gabriel_graph().tolist() == gabriel_graph(pts).tolist()
    assert d.largest_empty_circle() == largest_empty_circle(pts)
    assert builds[0] == before + 4          # the four calls on points; none for the methods


def remap(edges, live):
    """Edges over indices of points[live] -> edges over the original indices."""
    return np.sort(live[np.asarray(edges, dtype=np.int64)], axis=1).tolist() if len(edges) else []


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_structures_after_removals_equal_those_of_the_remaining_points(seed):
    rng = np.random.default_rng(seed)
    pts = rng.random((120, 2))
    d = Delaunay(pts)
    for i in rng.permutation(120)[:45]:
        d.remove(int(i))
    rest, live = live_points(d)
    assert live.tolist() == np.flatnonzero(d.live).tolist() and np.array_equal(rest, pts[live])
    key = lambda e: sorted(map(tuple, e))       # noqa: E731
    assert key(euclidean_mst(d)) == key(remap(euclidean_mst(rest), live))
    assert key(gabriel_graph(d)) == key(remap(gabriel_graph(rest), live))
    assert key(relative_neighborhood_graph(d)) == key(remap(relative_neighborhood_graph(rest), live))
    i, j = closest_pair(rest)
    assert closest_pair(d) == tuple(sorted((int(live[i]), int(live[j]))))
    assert convex_hull(d).tolist() == live[convex_hull(rest)].tolist()      # live is increasing
    assert convex_hull(d, collinear=True).tolist() == live[convex_hull(rest, collinear=True)].tolist()
    assert np.allclose(largest_empty_circle(d), largest_empty_circle(rest), rtol=1e-12, atol=1e-12)
    s, g = (0.5, 0.5), (2.0, 2.0)
    assert max_clearance(d, s, g) == pytest.approx(max_clearance(rest, s, g), rel=1e-12)
    box = (-1.0, -1.0, 2.0, 2.0)
    cells, fresh = voronoi(d, box), voronoi(rest, box)
    assert all(len(cells[k]) == 0 for k in np.flatnonzero(~d.live))
    for k, i in enumerate(live.tolist()):
        a, b = cells[i], fresh[k]
        assert a.shape == b.shape and np.allclose(a, b, rtol=0, atol=1e-12)


def test_as_delaunay_reuses_and_builds():
    d = Delaunay([(0, 0), (1, 0), (0, 1)])
    assert as_delaunay(d) is d
    assert isinstance(as_delaunay([(0, 0), (1, 0), (0, 1)]), Delaunay)
    with pytest.raises(ValueError):
        voronoi([(0, float("nan"))], (0, 0, 1, 1))


# ----------------------------------------------------------------------------- adjacency
def brute_neighbours(d: Delaunay) -> list[set[int]]:
    """From the definition: j is a neighbour of i when an edge (a triangle side, or a link of
    the chain for flat input) joins them."""
    n = len(d.points)
    nb = [set() for _ in range(n)]
    if len(d.simplices):
        for tri in d.simplices.tolist():
            for a in tri:
                nb[a].update(b for b in tri if b != a)
    else:
        chain = d.hull.tolist()
        for a, b in zip(chain, chain[1:]):
            nb[a].add(b)
            nb[b].add(a)
    return nb


def csr_sets(indptr, indices) -> list[set[int]]:
    return [set(indices[indptr[k]:indptr[k + 1]].tolist()) for k in range(len(indptr) - 1)]


def check_adjacency(d: Delaunay) -> None:
    n = len(d.points)
    indptr, indices = d.vertex_neighbor_vertices
    assert indptr.shape == (n + 1,) and indptr[0] == 0 and indptr[-1] == len(indices)
    for k in range(n):       # sorted, no repeats
        row = indices[indptr[k]:indptr[k + 1]]
        assert (np.diff(row) > 0).all()
    assert csr_sets(indptr, indices) == brute_neighbours(d)
    v2s = d.vertex_to_simplex
    assert v2s.shape == (n,)
    in_a_triangle = np.zeros(n, dtype=bool)
    in_a_triangle[d.simplices.ravel()] = True
    assert ((v2s >= 0) == in_a_triangle).all()
    for k in np.flatnonzero(v2s >= 0).tolist():
        assert k in d.simplices[v2s[k]].tolist()
    live = d.live
    for k in range(n):
        if not live[k] or d.index_map[k] != k:    # removed or merged: no neighbours, no triangle
            assert indptr[k] == indptr[k + 1] and v2s[k] == -1
        else:
            assert set(d.vertex_neighbors(k).tolist()) == set(indices[indptr[k]:indptr[k + 1]].tolist())


@pytest.mark.parametrize("seed", range(5))
def test_adjacency_equals_scipy_in_general_position(seed):
    rng = np.random.default_rng(seed)
    pts = rng.random((int(rng.integers(5, 400)), 2))
    d, s = Delaunay(pts), scipy.spatial.Delaunay(pts)
    assert csr_sets(*d.vertex_neighbor_vertices) == csr_sets(*s.vertex_neighbor_vertices)
    for k, t in enumerate(d.vertex_to_simplex.tolist()):
        assert k in d.simplices[t].tolist()
    assert (s.vertex_to_simplex >= 0).all() and (d.vertex_to_simplex >= 0).all()
    check_adjacency(d)


@pytest.mark.parametrize("name,pts", pointsets.degenerate_sets() + pointsets.flat_sets(),
                         ids=[n for n, _ in pointsets.degenerate_sets() + pointsets.flat_sets()])
def test_adjacency_against_brute_force_on_degenerate_sets(name, pts):
    d = Delaunay(pts)
    check_adjacency(d)
    assert d.vertex_neighbor_vertices is d.vertex_neighbor_vertices     # cached
    assert d.vertex_to_simplex is d.vertex_to_simplex


def test_adjacency_is_refreshed_by_insert_and_remove():
    rng = np.random.default_rng(3)
    d = Delaunay(pointsets.grid(5))
    for step in range(30):
        first = d.vertex_neighbor_vertices, d.vertex_to_simplex
        if step % 3 == 2:
            d.remove(int(rng.choice(np.flatnonzero(d.live))))
        else:
            d.insert(tuple(rng.random(2) * 4))
        assert d.vertex_neighbor_vertices is not first[0]
        check_adjacency(d)
    d = Delaunay(pointsets.collinear(6))          # flat, then triangulated by an insert
    check_adjacency(d)
    d.insert((0.3, 7.0))
    check_adjacency(d)
    assert (d.vertex_to_simplex[d.live] >= 0).sum() >= 3


# ----------------------------------------------------------------------------- find_simplex shapes
def test_find_simplex_is_shaped_like_its_input():
    pts = pointsets.uniform(100, 2)
    d = Delaunay(pts)
    rng = np.random.default_rng(0)
    q = rng.random((4, 5, 2)) * 1.4 - 0.2
    flat = d.find_simplex(q.reshape(-1, 2))
    assert flat.shape == (20,)
    got = d.find_simplex(q)
    assert got.shape == (4, 5) and got.dtype == np.int64 and got.ravel().tolist() == flat.tolist()
    assert d.find_simplex(q.tolist()).tolist() == got.tolist()            # nested lists too
    one = d.find_simplex(q[0, 0])
    assert np.shape(one) == () and one == flat[0] and int(one) == flat[0]
    assert d.find_simplex(np.zeros((0, 2))).shape == (0,)
    assert d.find_simplex(q[:1, :1]).shape == (1, 1)
    assert Delaunay(pointsets.collinear(5)).find_simplex(q).shape == (4, 5)    # flat: all -1
    with pytest.raises(ValueError):
        d.find_simplex(np.zeros((2, 3, 3)))
    with pytest.raises(ValueError):
        d.find_simplex("0.5 0.5")


def test_find_simplex_3d_is_shaped_like_its_input():
    rng = np.random.default_rng(1)
    d = Delaunay3D(rng.random((60, 3)))
    q = rng.random((3, 2, 4, 3))
    got = d.find_simplex(q)
    assert got.shape == (3, 2, 4)
    assert got.ravel().tolist() == d.find_simplex(q.reshape(-1, 3)).tolist()
    assert np.shape(d.find_simplex(q[0, 0, 0])) == ()


def test_as_queries():
    assert as_queries((1, 2), 2)[1] == ()
    assert as_queries([(1, 2)], 2)[1] == (1,)
    assert as_queries([], 2)[0].shape == (0, 2)
    with pytest.raises(ValueError):
        as_queries([(1, 2), (3,)], 2)


# ----------------------------------------------------------------------------- return values
def test_pair_and_circle_are_named_tuples():
    p = closest_pair([(0, 0), (5, 5), (1, 1), (5, 6)])
    assert isinstance(p, Pair) and isinstance(p, tuple) and p == (1, 3) and (p.i, p.j) == (1, 3)
    i, j = p
    assert (i, j) == (1, 3)
    c = largest_empty_circle([(0, 0), (4, 0), (4, 4), (0, 4)])
    assert isinstance(c, Circle) and isinstance(c, tuple) and c == (2.0, 2.0, c.r)
    x, y, r = c
    assert (x, y) == (c.x, c.y) == (2.0, 2.0) and r == pytest.approx(8 ** 0.5)


# ----------------------------------------------------------------------------- adapters moved out
def test_dynamic_network_adapter_lives_with_its_problem():
    import reference_impl.structures.dynamic as dynamic
    assert not hasattr(dynamic, "process")
    gen = load_problem("dynamic-network").generator
    ops = [["join", 0, 0], ["join", 1, 0], ["neighbors", 1], ["count"]]
    assert gen.process(ops) == gen.solve(ops) == [0, 1, [0], 2]


def test_shortest_path_is_a_deprecated_alias():
    import reference_impl
    room = [(0, 0), (10, 0), (10, 10), (0, 10)]
    pillar = [(4, 4), (6, 4), (6, 6), (4, 6)]
    with pytest.warns(DeprecationWarning, match=r"NavMesh\(boundary, holes\)\.shortest_path"):
        old = reference_impl.shortest_path(room, [pillar], (2, 5.5), (8, 5.5))
    new = NavMesh(room, [pillar]).shortest_path((2, 5.5), (8, 5.5))
    gen = load_problem("navmesh").generator
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        adapted = gen.shortest_path(room, [pillar], (2, 5.5), (8, 5.5))
        solved = gen.solve(room, [pillar], (2, 5.5), (8, 5.5))
    assert old == new == adapted == [(2.0, 5.5), (4.0, 6.0), (6.0, 6.0), (8.0, 5.5)]
    assert solved == [list(p) for p in new]
