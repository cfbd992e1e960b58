"""Tests for reference_impl.structures.hull.convex_hull against exact and library oracles.

Run:  .venv/bin/python -m pytest tests/structures/test_hull.py -q

Oracles: a brute-force O(n^3) hull in Python integers (supporting lines), the
integer monotone chain ``verify.convex_hull_exact`` (for the order), and
scipy.spatial.ConvexHull on sets in general position.
"""
from __future__ import annotations

import doctest

import numpy as np
import pytest
from hypothesis import given, strategies as st
from scipy.spatial import ConvexHull

import reference_impl.structures.hull as hull_module
from pointsets import degenerate_sets, flat_sets
from reference_impl.structures.hull import convex_hull
from reference_impl.exact.verify import convex_hull_exact, exact_coordinates, orient_exact


def brute_hull(points) -> tuple[set[int], set[int], bool]:
    """(corner indices, boundary indices, flat?) by brute force over supporting lines.

    Indices are representatives (smallest index of equal points).  A directed pair
    (i, j) supports the set when no point is strictly right of i -> j; boundary
    points lie on a supporting segment; corners are boundary points strictly
    inside no supporting segment.
    """
    P = exact_coordinates(points)
    rep: dict[tuple[int, int], int] = {}
    for i, p in enumerate(P):
        rep.setdefault(p, i)
    ids = sorted(rep.values())
    flat = len(ids) < 3 or all(orient_exact(P[ids[0]], P[ids[1]], P[k]) == 0 for k in ids)
    if flat:
        return set(), set(), True

    def between(i, j, k):  # k on the closed segment ij (given collinear)
        return (min(P[i][0], P[j][0]) <= P[k][0] <= max(P[i][0], P[j][0])
                and min(P[i][1], P[j][1]) <= P[k][1] <= max(P[i][1], P[j][1]))

    boundary, interior_of_edge = set(), set()
    for i in ids:
        for j in ids:
            if i == j or any(orient_exact(P[i], P[j], P[k]) < 0 for k in ids):
                continue
            for k in ids:
                if orient_exact(P[i], P[j], P[k]) == 0 and between(i, j, k):
                    boundary.add(k)
                    if k not in (i, j):
                        interior_of_edge.add(k)
    return boundary - interior_of_edge, boundary, False


def sorted_chain(points) -> list[int]:
    P = exact_coordinates(points)
    rep: dict[tuple[int, int], int] = {}
    for i, p in enumerate(P):
        rep.setdefault(p, i)
    return sorted(rep.values(), key=lambda i: P[i])


def check_against_oracles(points, brute: bool = True) -> None:
    P = np.asarray(points, dtype=float).reshape(-1, 2)
    strict = convex_hull(P)
    full = convex_hull(P, collinear=True)
    assert strict.dtype == np.int64 and full.dtype == np.int64
    exact_pts = exact_coordinates(P)
    chain = convex_hull_exact(exact_pts, keep_collinear=True)
    corners_chain = convex_hull_exact(exact_pts, keep_collinear=False)
    flat = len(chain) < 3 or all(orient_exact(exact_pts[chain[0]], exact_pts[chain[-1]], exact_pts[i]) == 0
                                 for i in chain)
    if flat:
        srt = sorted_chain(P)
        assert full.tolist() == srt
        assert strict.tolist() == (srt[:1] + srt[-1:] if len(srt) > 1 else srt)
        return
    rot = lambda h: list(np.roll(h, -int(np.argmin(h))))  # noqa: E731
    assert full.tolist() == rot(chain)
    assert strict.tolist() == rot(corners_chain)
    if brute:
        corners, boundary, bflat = brute_hull(P)
        assert not bflat
        assert set(strict.tolist()) == corners
        assert set(full.tolist()) == boundary


def test_doctests():
    assert doctest.testmod(hull_module).failed == 0


def test_thousand_random_small_sets_against_brute_force():
    rng = np.random.default_rng(1)
    count = 0
    for case in range(1000):
        n = int(rng.integers(1, 13))
        kind = case % 4
        if kind == 0:       # tiny integer range: many duplicates, collinear triples, flat sets
            P = rng.integers(0, 4, (n, 2)).astype(float)
        elif kind == 1:
            P = rng.integers(-20, 21, (n, 2)).astype(float)
        elif kind == 2:     # floats in general position
            P = rng.random((n, 2))
        else:               # dyadic points on a few lines through the origin, plus offsets
            t = rng.integers(-8, 9, n) / 8.0
            P = np.c_[t, t * rng.integers(-2, 3)] + rng.integers(0, 2, (n, 1)) * 0.5
        check_against_oracles(P)
        count += 1
    assert count == 1000


@pytest.mark.parametrize("name,pts", degenerate_sets() + flat_sets(), ids=lambda v: v if isinstance(v, str) else "")
def test_degenerate_sets(name, pts):
    check_against_oracles(pts, brute=len(pts) <= 60)


@pytest.mark.parametrize("seed", range(5))
def test_scipy_on_general_position(seed):
    rng = np.random.default_rng(seed)
    P = rng.standard_normal((2000, 2)) * [1.0, 1e-3 + seed]
    expected = ConvexHull(P).vertices          # counter-clockwise in 2D
    expected = np.roll(expected, -int(np.argmin(expected)))
    assert convex_hull(P).tolist() == expected.tolist()


def test_large_input_matches_scipy():
    P = np.random.default_rng(7).random((100_000, 2))
    expected = ConvexHull(P).vertices
    assert convex_hull(P).tolist() == np.roll(expected, -int(np.argmin(expected))).tolist()


def test_one_ulp_dent_is_kept_and_exact_collinear_dropped():
    # (0.5, 0.5 + ulp) is strictly outside the segment (0,0)-(1,1); 0.5,0.5 exactly on it
    up = np.nextafter(0.5, 1.0)
    P = [(0, 0), (1, 1), (0.5, up), (1, 0), (0.5, 0.5)]
    assert convex_hull(P).tolist() == [0, 3, 1, 2]
    assert convex_hull(P, collinear=True).tolist() == [0, 3, 1, 2]
    P2 = [(0, 0), (1, 1), (0.5, 0.5), (1, 0)]
    assert convex_hull(P2).tolist() == [0, 3, 1]
    assert convex_hull(P2, collinear=True).tolist() == [0, 3, 1, 2]


def test_duplicates_use_smallest_index_and_start_is_smallest():
    P = [(5, 5), (0, 0), (5, 5), (5, 0), (0, 5), (0, 0)]
    assert convex_hull(P).tolist() == [0, 4, 1, 3]


def test_permutation_gives_same_hull_points():
    rng = np.random.default_rng(3)
    P = np.vstack([rng.integers(0, 6, (40, 2)).astype(float)])
    base = [tuple(p) for p in P[convex_hull(P, collinear=True)]]
    for _ in range(5):
        perm = rng.permutation(len(P))
        h = convex_hull(P[perm], collinear=True)
        got = [tuple(p) for p in P[perm][h]]
        k = got.index(base[0])
        assert got[k:] + got[:k] == base


@given(st.lists(st.tuples(st.integers(-50, 50), st.integers(-50, 50)), min_size=1, max_size=40))
def test_every_point_inside_the_hull(pts):
    P = np.array(pts, dtype=float)
    h = convex_hull(P, collinear=True)
    E = exact_coordinates(P)
    if len(h) >= 3 and any(orient_exact(E[h[0]], E[h[1]], E[h[k]]) != 0 for k in range(len(h))):
        for a, b in zip(h, np.roll(h, -1)):
            assert all(orient_exact(E[a], E[b], p) >= 0 for p in E)
        strict = convex_hull(P)
        for a, b, c in zip(strict, np.roll(strict, -1), np.roll(strict, -2)):
            assert orient_exact(E[a], E[b], E[c]) > 0


@pytest.mark.parametrize("bad", [[(0, float("nan"))], [(0, 1, 2)], "abc", [(0, float("inf")), (1, 1)]])
def test_bad_input_raises(bad):
    with pytest.raises(ValueError):
        convex_hull(bad)


def test_empty_and_single():
    assert convex_hull(np.zeros((0, 2))).tolist() == []
    assert convex_hull([(3, 4)]).tolist() == [0]
    assert convex_hull([(3, 4), (3, 4)], collinear=True).tolist() == [0]
