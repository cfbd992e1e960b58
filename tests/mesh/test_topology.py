"""Tests for reference_impl.mesh.topology: every helper against brute force on random triangulations.

The triangulations come from scipy's Delaunay (oriented counter-clockwise here) and from
``reference_impl.Delaunay``, on random points and on grids (many cocircular quadruples).

Run: .venv/bin/python -m pytest tests/mesh/test_topology.py -q
"""
from __future__ import annotations

import itertools

import numpy as np
import pytest
from scipy.spatial import Delaunay as ScipyDelaunay

from reference_impl.mesh.delaunay import Delaunay
from reference_impl.mesh.topology import (each_edge_once, edge_keys, find_edge, find_root, flip, slot, third,
                                          triangle_neighbors, triangles_left_of, union_roots, unique_edges,
                                          vertex_adjacency, vertex_triangles)


def ccw_scipy(pts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """scipy's triangles and neighbours, rows turned counter-clockwise."""
    d = ScipyDelaunay(pts)
    tri, nbr = d.simplices.astype(np.int64), d.neighbors.astype(np.int64)
    a, b, c = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
    cw = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]) < 0
    tri[cw] = tri[cw][:, [0, 2, 1]]
    nbr[cw] = nbr[cw][:, [0, 2, 1]]
    return tri, nbr


def meshes():
    rng = np.random.default_rng(9)
    for n in (3, 4, 10, 60, 300):
        pts = rng.random((n, 2))
        yield pts, *ccw_scipy(pts)
    grid = np.array([(i, j) for i in range(7) for j in range(5)], float)
    d = Delaunay(grid)
    yield grid, np.asarray(d.simplices, np.int64), np.asarray(d.neighbors, np.int64)
    pts = rng.random((200, 2))
    d = Delaunay(pts)
    yield pts, np.asarray(d.simplices, np.int64), np.asarray(d.neighbors, np.int64)


MESHES = list(meshes())


def brute_neighbors(tri: np.ndarray) -> np.ndarray:
    out = np.full(tri.shape, -1, dtype=np.int64)
    for t, o in itertools.permutations(range(len(tri)), 2):
        for k in range(3):
            e = {tri[t, (k + 1) % 3], tri[t, (k + 2) % 3]}
            if e <= set(tri[o].tolist()):
                out[t, k] = o
    return out


def brute_edges(tri: np.ndarray) -> set:
    return {tuple(sorted((int(t[i]), int(t[j])))) for t in tri for i, j in ((0, 1), (1, 2), (2, 0))}


def is_consistent(tri: np.ndarray, nbr: np.ndarray) -> bool:
    return np.array_equal(triangle_neighbors(tri, int(tri.max()) + 1), nbr)


# ----------------------------------------------------------------------------- neighbours
@pytest.mark.parametrize("case", range(len(MESHES)))
def test_triangle_neighbors_match_brute_force_and_scipy(case):
    pts, tri, nbr = MESHES[case]
    got = triangle_neighbors(tri, len(pts))
    assert got.dtype == np.int64
    assert np.array_equal(got, nbr)
    if len(tri) <= 120:
        assert np.array_equal(got, brute_neighbors(tri))


def test_triangle_neighbors_rejects_a_repeated_directed_edge():
    with pytest.raises(ValueError, match="directed edge 1->2 is used by two triangles"):
        triangle_neighbors(np.array([[0, 1, 2], [3, 1, 2]]), 4)
    assert triangle_neighbors(np.zeros((0, 3), np.int64), 0).shape == (0, 3)


def test_edge_keys_and_triangles_left_of():
    pts, tri, nbr = MESHES[3]
    n = len(pts)
    keys = edge_keys(tri, n)
    for t in range(len(tri)):
        for k in range(3):
            assert keys[t, k] == tri[t, (k + 1) % 3] * n + tri[t, (k + 2) % 3]
    u = np.repeat(np.arange(n), n)
    v = np.tile(np.arange(n), n)
    got = triangles_left_of(tri, n, u, v)
    want = np.full(len(u), -1)
    for t in range(len(tri)):
        for k in range(3):
            want[tri[t, (k + 1) % 3] * n + tri[t, (k + 2) % 3]] = t
    assert np.array_equal(got, want)
    assert triangles_left_of(np.zeros((0, 3), np.int64), 3, np.array([0]), np.array([1])).tolist() == [-1]


@pytest.mark.parametrize("case", range(len(MESHES)))
def test_vertex_triangles(case):
    pts, tri, _ = MESHES[case]
    vt = vertex_triangles(tri, len(pts) + 2)
    for v in range(len(pts)):
        assert vt[v] >= 0 and v in tri[vt[v]]
    assert vt[-2:].tolist() == [-1, -1]


# ----------------------------------------------------------------------------- edges
@pytest.mark.parametrize("case", range(len(MESHES)))
def test_each_edge_once_and_unique_edges(case):
    pts, tri, nbr = MESHES[case]
    t, k = each_edge_once(nbr)
    named = [tuple(sorted((int(tri[a, (b + 1) % 3]), int(tri[a, (b + 2) % 3])))) for a, b in zip(t, k)]
    assert len(named) == len(set(named))
    assert set(named) == brute_edges(tri)
    assert all(nbr[a, b] < 0 or nbr[a, b] > a for a, b in zip(t, k))
    e = unique_edges(tri, nbr)
    assert e.dtype == np.int64 and [tuple(r) for r in e.tolist()] == sorted(brute_edges(tri))
    mask = np.zeros(tri.shape, bool)
    for a, b in zip(t[::3], k[::3]):                      # mark some edges on both sides
        mask[a, b] = True
        if nbr[a, b] >= 0:
            mask[nbr[a, b], slot(nbr, nbr[a, b], a)] = True
    want = sorted(named[::3])
    assert [tuple(r) for r in unique_edges(tri, nbr, mask).tolist()] == want


def test_unique_edges_of_nothing():
    assert unique_edges(np.zeros((0, 3), np.int64), np.zeros((0, 3), np.int64)).shape == (0, 2)


@pytest.mark.parametrize("case", range(len(MESHES)))
def test_vertex_adjacency(case):
    pts, tri, nbr = MESHES[case]
    n = len(pts) + 1                                        # one isolated vertex
    e = unique_edges(tri, nbr)
    rng = np.random.default_rng(case)
    rank = rng.permutation(n)
    for r in (None, rank):
        ptr, nb = vertex_adjacency(e[:, 0], e[:, 1], n, r)
        assert ptr[0] == 0 and ptr[-1] == 2 * len(e) and ptr[-1] == ptr[-2]
        for v in range(n):
            got = nb[ptr[v]:ptr[v + 1]].tolist()
            want = [int(b) for a, b in e.tolist() if a == v] + [int(a) for a, b in e.tolist() if b == v]
            assert sorted(got) == sorted(want)
            if r is not None:
                assert got == sorted(want, key=lambda x: rank[x])


# ----------------------------------------------------------------------------- compiled helpers
def test_slot_and_third():
    _, tri, nbr = MESHES[2]
    for t in range(len(tri)):
        for k in range(3):
            assert slot(tri, t, tri[t, k]) == k
            assert third(tri, t, tri[t, (k + 1) % 3], tri[t, (k + 2) % 3]) == k
            if nbr[t, k] >= 0:
                assert nbr[nbr[t, k], slot(nbr, nbr[t, k], t)] == t
        assert slot(tri, t, -5) == -1
        assert third(tri, t, tri[t, 0], tri[t, 0]) in (1, 2)


@pytest.mark.parametrize("case", range(len(MESHES)))
def test_find_edge_for_every_pair(case):
    pts, tri, nbr = MESHES[case]
    n = len(pts)
    vt = vertex_triangles(tri, n)
    edges = brute_edges(tri)
    pairs = list(itertools.permutations(range(n), 2))
    if n > 70:   # every edge both ways, and as many random pairs (all n^2 pairs would be slow)
        rng = np.random.default_rng(case)
        pairs = ([(u, v) for u, v in edges] + [(v, u) for u, v in edges]
                 + [pairs[i] for i in rng.choice(len(pairs), 2 * len(edges), replace=False)])
    for u, v in pairs:
        t, k = find_edge(tri, nbr, vt, u, v)
        if (min(u, v), max(u, v)) in edges:
            assert t >= 0 and {int(tri[t, (k + 1) % 3]), int(tri[t, (k + 2) % 3])} == {u, v}
        else:
            assert (t, k) == (-1, -1)
    vt[0] = -1
    assert find_edge(tri, nbr, vt, 0, 1) == (-1, -1)


def orient(p, a, b, c):
    return np.sign((p[b, 0] - p[a, 0]) * (p[c, 1] - p[a, 1]) - (p[b, 1] - p[a, 1]) * (p[c, 0] - p[a, 0]))


@pytest.mark.parametrize("case", [1, 3, 4, 6])
def test_flips_keep_the_mesh_consistent(case):
    pts, tri0, nbr0 = MESHES[case]
    tri, nbr = tri0.copy(), nbr0.copy()
    rng = np.random.default_rng(case)
    done = 0
    for _ in range(4 * len(tri)):
        t, k = int(rng.integers(len(tri))), int(rng.integers(3))
        o = nbr[t, k]
        if o < 0:
            continue
        p, u, v = tri[t, k], tri[t, (k + 1) % 3], tri[t, (k + 2) % 3]
        q = tri[o, slot(nbr, o, t)]
        if orient(pts, p, u, q) <= 0 or orient(pts, q, v, p) <= 0:
            continue                                       # not strictly convex
        before = brute_edges(tri)
        assert flip(tri, nbr, t, k) == (u, v)
        assert tri[t].tolist() == [u, q, p] and tri[o].tolist() == [q, v, p]
        assert nbr[t, 0] == o and nbr[o, 1] == t
        assert brute_edges(tri) == (before - {tuple(sorted((u, v)))}) | {tuple(sorted((p, q)))}
        assert is_consistent(tri, nbr)
        done += 1
    assert done > 0


def test_union_find_matches_components():
    rng = np.random.default_rng(4)
    n = 40
    parent, size = np.arange(n), np.ones(n, dtype=np.int64)
    label = list(range(n))                                 # brute force: relabel on every union
    for _ in range(60):
        a, b = (int(x) for x in rng.integers(n, size=2))
        ra, rb = find_root(parent, a), find_root(parent, b)
        assert (ra == rb) == (label[a] == label[b])
        if ra != rb:
            r = union_roots(parent, size, ra, rb)
            assert r in (ra, rb) and find_root(parent, a) == find_root(parent, b) == r
            old, new = label[b], label[a]
            label = [new if x == old else x for x in label]
    roots = np.array([find_root(parent, i) for i in range(n)])
    for i, j in itertools.combinations(range(n), 2):
        assert (roots[i] == roots[j]) == (label[i] == label[j])
    assert size[np.unique(roots)].sum() == n
