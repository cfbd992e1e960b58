"""The theory lesson's code against independent oracles: the fast ``Delaunay``, ``ConstrainedDelaunay``,
``delaunay_3d``, brute force and exact integer predicates.

    .venv/bin/python -m pytest tests/teaching/test_theory.py -n 0 -q

Covers reference_impl/teaching/{theory,locate,segment,cavity3d}.py (lesson 13).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial import ConvexHull

from exact_oracle import canon
from reference_impl import ConstrainedDelaunay, Delaunay, bowyer_watson, delaunay_3d
from reference_impl.exact.verify import brute_force_empty_circles, check_delaunay, check_delaunay_3d
from reference_impl.kit.player import scrambled_triangulation
from reference_impl.teaching.cavity3d import cavity_3d, surface_counts
from reference_impl.teaching.locate import BVH, HashGrid, KDTree, QuadTree, TriMesh
from reference_impl.teaching.segment import insert_segment
from reference_impl.teaching.theory import (all_triangulations, angle_vector, compare_angle_vectors, illegal_edges,
                                            lawson, mean_star_size, new_triangles_per_insertion, star_sizes,
                                            sweep_triangulation)


def _sorted_tris(T) -> list[tuple[int, ...]]:
    return sorted(tuple(sorted(t)) for t in np.asarray(T).tolist())


# ----------------------------------------------------------------------------- backwards analysis
@pytest.mark.parametrize("seed", range(3))
def test_created_triangles_equal_the_new_points_star_in_the_prefix_triangulation(seed):
    rng = np.random.default_rng(seed)
    P = rng.random((120, 2))
    created = new_triangles_per_insertion(P)
    for k in (3, 10, 57, 120):           # the k-th point, inserted into the first k - 1
        star = star_sizes(k, Delaunay(P[:k]).simplices)
        assert created[k - 3] == star[k - 1]


def test_mean_star_size_is_six_k_minus_six_minus_h_over_k():
    rng = np.random.default_rng(4)
    for k in (3, 4, 20, 300):
        P = rng.random((k, 2))
        d = Delaunay(P)
        mean, h = mean_star_size(k, d.simplices)
        assert h == len(ConvexHull(P).vertices)
        assert mean * k == pytest.approx(6 * k - 6 - h)


def test_backwards_analysis_average_over_which_point_is_last():
    """Inserting each point last: the created counts average exactly (6k - 6 - h) / k."""
    rng = np.random.default_rng(5)
    k = 25
    P = rng.random((k, 2))
    counts = []
    for last in range(k):
        order = [i for i in range(k) if i != last] + [last]
        counts.append(int(new_triangles_per_insertion(P, order)[-1]))
    h = len(ConvexHull(P).vertices)
    assert sum(counts) == 6 * k - 6 - h
    assert counts == star_sizes(k, Delaunay(P).simplices).tolist()


def test_new_triangles_bad_order():
    with pytest.raises(ValueError, match="permutation"):
        new_triangles_per_insertion([(0, 0), (1, 0), (0, 1)], [0, 0, 1])


# ----------------------------------------------------------------------------- Lawson, lemma, angles
@pytest.mark.parametrize("seed", range(3))
def test_lawson_from_a_scrambled_triangulation_reaches_delaunay_and_each_flip_raises_the_angles(seed):
    rng = np.random.default_rng(seed)
    P = rng.random((60, 2))
    start = scrambled_triangulation(P, flips=100, seed=seed)
    assert illegal_edges(P, start)              # something to do
    states = lawson(P, start)
    assert len(states) > 1
    final = states[-1]
    assert illegal_edges(P, final) == []
    assert check_delaunay(P, final)[0] and brute_force_empty_circles(P, final)[0]
    assert _sorted_tris(final) == _sorted_tris(Delaunay(P).simplices)
    vectors = [angle_vector(P, s) for s in states]
    assert all(compare_angle_vectors(b, a) == 1 for a, b in zip(vectors, vectors[1:]))


def test_illegal_edges_agree_with_brute_force_circles():
    rng = np.random.default_rng(9)
    P = rng.random((30, 2))
    T = scrambled_triangulation(P, flips=20, seed=1)
    assert bool(illegal_edges(P, T)) == (not brute_force_empty_circles(P, T)[0])


def test_all_triangulations_counts_and_the_delaunay_maximum():
    hexagon = [(math.cos(t), math.sin(t) * 0.9 + 0.01 * k) for k, t in enumerate(np.linspace(0, 2 * math.pi, 7)[:-1])]
    assert len(all_triangulations(hexagon)) == 14           # Catalan(4): convex position
    rng = np.random.default_rng(2)
    P = rng.random((8, 2))
    every = all_triangulations(P)
    assert len({frozenset(canon(T)) for T in every}) == len(every)
    assert all(len(T) == len(every[0]) for T in every)
    dt = bowyer_watson(P)
    best = max(every, key=lambda T: tuple(angle_vector(P, T)))
    assert _sorted_tris(best) == _sorted_tris(dt)
    assert all(compare_angle_vectors(angle_vector(P, dt), angle_vector(P, T)) >= 0 for T in every)
    with pytest.raises(ValueError, match="more than 3"):
        all_triangulations(P, limit=3)


def test_angle_vector_of_a_right_triangle():
    assert np.degrees(angle_vector([(0, 0), (2, 0), (0, 2)], [(0, 1, 2)])).round(9).tolist() == [45, 45, 90]


# ----------------------------------------------------------------------------- point location
def test_every_locator_finds_a_really_bad_triangle_and_the_true_nearest_vertex():
    rng = np.random.default_rng(3)
    P = np.r_[[(0, 0), (1, 0), (1, 1), (0, 1)], rng.random((400, 2))]
    m = TriMesh(P, Delaunay(P).simplices)
    structures = [KDTree(P), QuadTree(P), HashGrid(P)]
    bvh = BVH(m)
    start = 0
    for q in rng.random((60, 2)):
        brute = np.array([m.is_bad(t, q) for t in range(len(m.T))])
        assert (m.bad_mask(q) == brute).all()
        assert m.scan(q) == int(np.flatnonzero(brute)[0]) + 1
        assert 1 <= m.walk(q, start) <= len(m.T)
        t, _ = m.containing(q, start)
        assert brute[t]
        start = t
        nearest = int(np.argmin(((P - q) ** 2).sum(axis=1)))
        for s in structures:
            assert s.nearest(q)[0] == nearest
        assert 1 <= m.around_vertex(nearest, q) <= len(m.around[nearest])
        tested, visited = bvh.first_bad(q)
        assert 1 <= tested <= visited


def test_walk_outside_the_hull_is_an_error():
    m = TriMesh([(0, 0), (1, 0), (0, 1)], [(0, 1, 2)])
    with pytest.raises(ValueError, match="outside the convex hull"):
        m.containing((2, 2))


# ----------------------------------------------------------------------------- segment insertion
def test_segment_insertion_matches_constrained_delaunay():
    rng = np.random.default_rng(0)
    crossed = 0
    for _ in range(80):
        n = int(rng.integers(5, 50))
        P = rng.random((n, 2))
        a, b = (int(v) for v in rng.choice(n, 2, replace=False))
        ins = insert_segment(P, bowyer_watson(P), a, b)
        crossed += len(ins.crossed)
        assert _sorted_tris(ins.triangles) == _sorted_tris(ConstrainedDelaunay(P, [(a, b)]).simplices)
        assert len(ins.new) == len(ins.crossed)          # a polygon of k + 2 vertices has k triangles
        assert len(ins.left) + len(ins.right) == len(ins.crossed)
    assert crossed > 80


def test_segment_through_a_vertex_is_refused_and_an_existing_edge_changes_nothing():
    P = [(0, 0), (1, 0), (2, 0), (1, 1), (1, -1), (3, 0)]
    T = bowyer_watson(P)
    with pytest.raises(ValueError, match="passes through"):
        insert_segment(P, T, 0, 5)
    a, b = (int(v) for v in T[0][:2])
    ins = insert_segment(P, T, a, b)
    assert ins.crossed == [] and ins.new == [] and _sorted_tris(ins.triangles) == _sorted_tris(T)
    with pytest.raises(ValueError, match="zero length"):
        insert_segment(P, T, 1, 1)


# ----------------------------------------------------------------------------- 3D cavity
@pytest.mark.parametrize("seed", range(4))
def test_cavity_3d_matches_delaunay_3d(seed):
    rng = np.random.default_rng(seed)
    P = rng.random((80, 3))
    P2 = np.r_[P, [[0.5, 0.45, 0.55]]]
    cav = cavity_3d(P2, delaunay_3d(P), 80)
    assert _sorted_tris(cav.tetrahedra) == _sorted_tris(delaunay_3d(P2))
    assert check_delaunay_3d(P2, cav.tetrahedra)[0]
    V, E, F, closed = surface_counts(cav.boundary)
    assert closed and V - E + F == 2 and F == 2 * V - 4
    assert len(cav.new) == len(cav.boundary)


def test_cavity_3d_bad_input():
    pts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (5, 5, 5)]
    good = delaunay_3d(pts[:4])
    with pytest.raises(ValueError, match="already a vertex"):
        cavity_3d(pts, good, 0)
    with pytest.raises(ValueError, match="not positively oriented"):
        cavity_3d(pts, good[:, [1, 0, 2, 3]], 4)


# ----------------------------------------------------------------------------- the players (kit/theory.py)
def test_segment_player_frames_follow_the_insertion():
    from reference_impl.kit.theory import segment_player

    rng = np.random.default_rng(21)
    P = rng.random((20, 2))
    a, b = int(np.argmin(P[:, 0])), int(np.argmax(P[:, 0]))
    player = segment_player(P, a, b)
    ins = insert_segment(P, Delaunay(P).simplices, a, b)
    phases = [f.phase for f in player.steps]
    assert phases == ["start"] + ["cross"] * len(ins.crossed) + ["cavity"] + ["new"] * len(ins.new) + ["done"]
    player.index = len(phases) - 1
    assert player.current_line == "done" and f"{len(ins.crossed)} triangles out" in player.caption.value
    assert player.static_png()[:4] == b"\x89PNG"


def test_cavity_player_turns_and_says_what_it_shows():
    from reference_impl.kit.theory import cavity_player

    P = np.random.default_rng(1).random((40, 3))
    P2 = np.r_[P, [[0.5, 0.5, 0.5]]]
    cav = cavity_3d(P2, delaunay_3d(P), 40)
    player = cavity_player(P2, cav, turns=4)
    assert len(player.steps) == 4
    player.next.click()
    assert player.caption.value.startswith("<b>step 2/4</b>: turned 45 degrees")
    assert f"{len(cav.boundary)} boundary faces" in player.caption.value and "tetrahedra new" in player.caption.value


def test_sweep_triangulation_is_a_triangulation_and_lawson_repairs_it():
    from reference_impl.structures.flips import validate_triangulation

    P = np.random.default_rng(8).random((150, 2))
    T = sweep_triangulation(P)
    assert len(validate_triangulation(P, T)) == len(Delaunay(P).simplices)
    assert _sorted_tris(lawson(P, T)[-1]) == _sorted_tris(Delaunay(P).simplices)
    with pytest.raises(ValueError, match="general position"):
        sweep_triangulation([(0, 0), (1, 1), (2, 2), (3, 0)])


def test_bad_triangulations_are_refused():
    with pytest.raises(ValueError, match="not counter-clockwise"):
        lawson([(0, 0), (1, 0), (0, 1)], [(0, 2, 1)])
    with pytest.raises(ValueError, match="outside 0..2"):
        lawson([(0, 0), (1, 0), (0, 1)], [(0, 1, 3)])
    with pytest.raises(ValueError, match="outside 0..1"):
        star_sizes(2, [(0, 1, 2)])


def test_flip_angle_player_shows_every_flip_raising_the_smallest_angle():
    from reference_impl.kit.theory import flip_angle_player

    P = np.random.default_rng(5).random((14, 2))
    T = sweep_triangulation(P)
    player = flip_angle_player(P, T)
    assert len(player.steps) == 2 * (len(lawson(P, T)) - 1)
    for flip, phase in player.steps[::2]:
        assert flip.new_angles[0] > flip.old_angles[0] and len(flip.old_angles) == len(flip.new_angles) == 6
    player.next.click()
    assert "the smallest went from" in player.caption.value
    with pytest.raises(ValueError, match="already Delaunay"):
        flip_angle_player(P, Delaunay(P).simplices)


def test_star_player_counts_what_the_insertions_create():
    from reference_impl.kit.theory import star_player

    P = np.random.default_rng(3).random((25, 2))
    order = np.random.default_rng(1).permutation(25)
    player = star_player(P, order)
    created = new_triangles_per_insertion(P, order)
    assert len(player.steps) == len(created)
    player.index = len(created) - 1
    assert f"creates {created[-1]} triangles" in player.caption.value
    assert f"mean so far {created.mean():.2f}" in player.caption.value
    with pytest.raises(ValueError, match="permutation"):
        star_player(P, [0] * 25)
