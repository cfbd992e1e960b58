"""Tests of reference_impl.structures.proximity: EMST, closest pair, Gabriel graph, relative neighbourhood graph.

    .venv/bin/python -m pytest tests/structures/test_proximity.py -q

Oracles share no code with the library: every distance comparison here is done
on Python integers (all coordinates scaled by one power of two), brute force
over all pairs and triples; the MST oracle is networkx's Kruskal on the complete
graph weighted by the rank of the exact squared length.  Two spanning trees have
the same total length if their sorted lists of exact squared lengths are equal,
and every MST has the same sorted list, so that is what is compared.
scipy (Delaunay + csgraph MST, cKDTree) is the anchor on larger random input.
"""
from __future__ import annotations

import itertools
from fractions import Fraction

import networkx as nx
import numpy as np
import pytest
import scipy.sparse
import scipy.sparse.csgraph
import scipy.spatial
from hypothesis import given, settings, strategies as st

import pointsets
from reference_impl import Delaunay
from reference_impl.structures.proximity import (closest_pair, dot_sign, euclidean_mst, gabriel_graph,
                                      relative_neighborhood_graph, sq_dist_cmp)
from reference_impl.exact.verify import exact_coordinates


# ----------------------------------------------------------------------------- the exact oracle
class Oracle:
    """Exact brute-force answers for one point set."""

    def __init__(self, points) -> None:
        self.P = np.asarray(points, dtype=float).reshape(-1, 2)
        I = exact_coordinates(self.P)
        first: dict[tuple[int, int], int] = {}
        for i, p in enumerate(I):
            first.setdefault(p, i)
        self.ids = sorted(set(first.values()))            # representatives of distinct points
        n = len(I)
        X = np.array([p[0] for p in I], dtype=object)
        Y = np.array([p[1] for p in I], dtype=object)
        self.D2 = np.empty((n, n), dtype=object)           # exact squared distances
        for i in range(n):
            self.D2[i] = (X - X[i]) ** 2 + (Y - Y[i]) ** 2

    def d2(self, i, j) -> int:
        return self.D2[int(i), int(j)]

    def min_d2(self) -> int:
        n = len(self.P)
        return min(self.D2[i, j] for i in range(n) for j in range(i + 1, n))

    def mst_lengths(self) -> list[int]:
        ids = self.ids
        pairs = list(itertools.combinations(ids, 2))
        ranks = {w: k for k, w in enumerate(sorted({self.D2[i, j] for i, j in pairs}))}
        G = nx.Graph()
        G.add_nodes_from(ids)
        G.add_weighted_edges_from((i, j, ranks[self.D2[i, j]]) for i, j in pairs)
        return sorted(self.D2[i, j] for i, j in nx.minimum_spanning_tree(G).edges())

    def gabriel(self) -> set[tuple[int, int]]:
        """Closed disc on diameter pq empty: no r with |rp|^2 + |rq|^2 <= |pq|^2."""
        ids = np.array(self.ids)
        out = set()
        for p, q in itertools.combinations(self.ids, 2):
            others = ids[(ids != p) & (ids != q)]
            if not np.any(self.D2[others, p] + self.D2[others, q] <= self.D2[p, q]):
                out.add((p, q))
        return out

    def rng(self) -> set[tuple[int, int]]:
        """Open lune empty: no r with max(|rp|, |rq|) < |pq|."""
        ids = np.array(self.ids)
        out = set()
        for p, q in itertools.combinations(self.ids, 2):
            others = ids[(ids != p) & (ids != q)]
            d = self.D2[p, q]
            if not np.any((self.D2[others, p] < d) & (self.D2[others, q] < d)):
                out.add((p, q))
        return out


def edge_set(e) -> set[tuple[int, int]]:
    return set(map(tuple, np.asarray(e).reshape(-1, 2).tolist()))


def assert_edges_format(e) -> None:
    e = np.asarray(e)
    assert e.ndim == 2 and e.shape[1] == 2 and e.dtype.kind == "i"
    assert np.all(e[:, 0] < e[:, 1])
    assert len(e) < 2 or np.all(np.diff(e[:, 0] * (e.max() + 1) + e[:, 1]) > 0), "rows not sorted/unique"


def is_spanning_tree(edges, ids) -> bool:
    G = nx.Graph()
    G.add_nodes_from(ids)
    G.add_edges_from(map(tuple, np.asarray(edges).tolist()))
    return set(G.nodes) == set(ids) and nx.is_tree(G) if len(ids) > 0 else len(edges) == 0


def check_all(points, oracle: Oracle | None = None) -> None:
    """Every function against the oracle on one point set."""
    o = oracle or Oracle(points)
    T = euclidean_mst(points)
    assert_edges_format(T)
    if len(o.ids) >= 1:
        assert is_spanning_tree(T, o.ids)
    assert sorted(o.d2(i, j) for i, j in T) == o.mst_lengths()
    G = gabriel_graph(points)
    assert_edges_format(G)
    assert edge_set(G) == o.gabriel()
    R = relative_neighborhood_graph(points)
    assert_edges_format(R)
    assert edge_set(R) == o.rng()
    if len(o.P) >= 2:
        i, j = closest_pair(points)
        assert 0 <= i < j < len(o.P)
        assert o.d2(i, j) == o.min_d2()


# ----------------------------------------------------------------------------- point families
def random_case(rng: np.random.Generator, k: int) -> np.ndarray:
    """Small sets, with many ties in most families."""
    n = int(rng.integers(2, 13))
    kind = k % 8
    if kind == 0:
        return rng.random((n, 2))
    if kind == 1:
        return rng.integers(0, 4, (n, 2)).astype(float)              # grid ties, duplicates
    if kind == 2:
        return rng.integers(-3, 4, (n, 2)) * 0.1                     # inexact decimals, near-ties
    if kind == 3:
        return rng.integers(0, 3, (n, 2)) * 1e-300 + rng.integers(0, 2) * 1e-300
    if kind == 4:
        return rng.integers(0, 5, (n, 2)) * 1e290 - 1e300
    if kind == 5:
        t = rng.integers(0, 12, n) * (np.pi / 6)                     # on a circle, maybe with centre
        return np.vstack([np.c_[np.cos(t), np.sin(t)], np.zeros((int(rng.integers(0, 2)), 2))])
    if kind == 6:
        return rng.integers(0, 6, (n, 2)) + 1e9                      # offset
    a = rng.random() * np.pi                                          # a rotated small grid
    g = rng.integers(0, 4, (n, 2)).astype(float)
    return g @ np.array([[np.cos(a), np.sin(a)], [-np.sin(a), np.cos(a)]])


def extra_degenerate_sets() -> list[tuple[str, np.ndarray]]:
    return [
        ("mixed-1e300-1e-300", np.array([(1e300, 0.0), (0.0, 0.0), (1e-300, 0.0), (0.0, 1e-300),
                                         (-1e300, 5e299), (3e-300, 2e-300), (0.0, -1e300)])),
        ("circle-160", pointsets.circle(160)),
        ("rotated-grid-15", pointsets.rotated_grid(15, 0.3)),
        ("two-scales", np.vstack([pointsets.grid(5) * 1e-9, pointsets.grid(5) + 10.0])),
        ("square", np.array([(0, 0), (1, 0), (1, 1), (0, 1)], dtype=float)),
        ("square+centre", np.array([(0, 0), (2, 0), (2, 2), (0, 2), (1, 1)], dtype=float)),
        ("equilateral", np.array([(0, 0), (2, 0), (1, 3 ** 0.5)])),
        ("all-same", np.ones((4, 2))),
    ]


ALL_SETS = pointsets.degenerate_sets() + pointsets.flat_sets() + extra_degenerate_sets()


# ----------------------------------------------------------------------------- tests
def test_1000_random_small_cases_against_brute_force():
    rng = np.random.default_rng(20240601)
    for k in range(1000):
        pts = random_case(rng, k)
        try:
            check_all(pts)
        except AssertionError:
            raise AssertionError(f"case {k}: points {pts.tolist()}") from None


@pytest.mark.parametrize("name,pts", ALL_SETS, ids=[s[0] for s in ALL_SETS])
def test_degenerate_sets_against_brute_force(name, pts):
    if len(pts) < 2:
        assert len(euclidean_mst(pts)) == 0 and len(gabriel_graph(pts)) == 0
        with pytest.raises(ValueError, match="at least 2 points"):
            closest_pair(pts)
        return
    check_all(pts)


@pytest.mark.parametrize("name,pts", ALL_SETS, ids=[s[0] for s in ALL_SETS])
def test_subgraph_chain(name, pts):
    """EMST ⊆ RNG ⊆ Gabriel ⊆ Delaunay edges (so the Delaunay graph is not a "minimal" network)."""
    T, R, G = edge_set(euclidean_mst(pts)), edge_set(relative_neighborhood_graph(pts)), edge_set(gabriel_graph(pts))
    D = edge_set(Delaunay(pts).edges()) if len(pts) else set()
    assert T <= R <= G <= D


def test_collinear_gives_the_chain():
    pts = pointsets.collinear(30, seed=3)
    d = Delaunay(pts)
    chain = edge_set(d.edges())
    assert edge_set(euclidean_mst(pts)) == chain
    assert edge_set(gabriel_graph(pts)) == chain
    assert edge_set(relative_neighborhood_graph(pts)) == chain


def test_duplicates_are_merged_and_closest_pair_reports_them():
    pts = np.array([(5, 5), (0, 0), (3, 1), (0, 0), (5, 5), (0, 0), (9, 9)], dtype=float)
    for e in (euclidean_mst(pts), gabriel_graph(pts), relative_neighborhood_graph(pts)):
        assert not set(np.ravel(e)) & {3, 4, 5}         # only representatives
    assert len(euclidean_mst(pts)) == 3                 # 4 distinct points
    assert closest_pair(pts) == (1, 3)                  # (0, 0) comes before (5, 5) in (x, y) order
    assert closest_pair(pts[[0, 6, 4]]) == (0, 2)


@given(st.lists(st.tuples(st.integers(-4, 4), st.integers(-4, 4)), min_size=2, max_size=14),
       st.sampled_from([1.0, 0.1, 2.0 ** -1000, 1e300, 3.0]), st.floats(0, 3.2),
       st.randoms(use_true_random=False))
@settings(max_examples=60, deadline=None)
def test_property_against_brute_force_and_order_independence(ints, scale, angle, rnd):
    pts = np.array(ints, dtype=float) * scale
    if angle:
        c, s = np.cos(angle), np.sin(angle)
        pts = pts @ np.array([[c, s], [-s, c]])
    check_all(pts)
    perm = list(range(len(pts)))
    rnd.shuffle(perm)
    q = pts[perm]

    def geo(points, edges):
        return {frozenset([tuple(points[i]), tuple(points[j])]) for i, j in np.asarray(edges).tolist()}

    for f in (euclidean_mst, gabriel_graph, relative_neighborhood_graph):
        assert geo(pts, f(pts)) == geo(q, f(q)), f.__name__
    assert geo(pts, [closest_pair(pts)]) == geo(q, [closest_pair(q)])


def test_kernels_are_exact_against_fractions():
    rng = np.random.default_rng(7)
    w = np.empty(128)
    mags = [1.0, 1e-300, 1e300, 1e-160, 1e160, 2.0 ** -1070]
    for k in range(3000):
        base = rng.integers(-3, 4, 8).astype(float)
        v = base * rng.choice(mags, 8) if k % 3 == 0 else base * rng.choice(mags[:1] + [0.1])
        if k % 5 == 0:
            v = v + rng.random(8) * 1e-16
        a, b, c, d = v[0:2], v[2:4], v[4:6], v[6:8]
        F = [Fraction(float(x)) for x in v]
        lhs = (F[0] - F[2]) ** 2 + (F[1] - F[3]) ** 2 - (F[4] - F[6]) ** 2 - (F[5] - F[7]) ** 2
        assert sq_dist_cmp(*a, *b, *c, *d, w) == (lhs > 0) - (lhs < 0), v.tolist()
        dot = (F[0] - F[4]) * (F[2] - F[4]) + (F[1] - F[5]) * (F[3] - F[5])
        assert dot_sign(*a, *b, *c, w) == (dot > 0) - (dot < 0), v.tolist()


def test_against_scipy_on_random_points():
    pts = pointsets.uniform(3000, seed=11)
    tri = scipy.spatial.Delaunay(pts)
    ind, nb = tri.vertex_neighbor_vertices
    rows = np.repeat(np.arange(len(pts)), np.diff(ind))
    w = np.linalg.norm(pts[rows] - pts[nb], axis=1)
    M = scipy.sparse.csgraph.minimum_spanning_tree(scipy.sparse.csr_matrix((w, (rows, nb)),
                                                                          shape=(len(pts),) * 2))
    T = euclidean_mst(pts)
    ours = np.linalg.norm(pts[T[:, 0]] - pts[T[:, 1]], axis=1).sum()
    assert abs(ours - M.sum()) <= 1e-9 * M.sum()         # general position: the same tree
    assert edge_set(T) == edge_set(np.sort(np.c_[M.nonzero()], axis=1))
    d, k = scipy.spatial.cKDTree(pts).query(pts, k=2)
    i = int(np.argmin(d[:, 1]))
    assert set(closest_pair(pts)) == {i, int(k[i, 1])}


def test_bad_input_raises_clear_errors():
    with pytest.raises(ValueError, match="not finite"):
        euclidean_mst([(0, 0), (float("nan"), 1)])
    with pytest.raises(ValueError, match="shape"):
        gabriel_graph([(0, 0, 0)])
    with pytest.raises(ValueError, match="at least 2 points, got 1"):
        closest_pair([(1, 1)])
    with pytest.raises(ValueError, match="numbers"):
        relative_neighborhood_graph([("a", "b")])
