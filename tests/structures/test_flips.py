"""Tests of reference_impl.structures.flips: Lawson flips, flip replay, Laplacian smoothing, mesh quality.

    .venv/bin/python -m pytest tests/structures/test_flips.py -q

Oracles: an independent flip replayer written here on Python integers (a dict
of directed edges; convexity and the in-circle test decided exactly) checks that
every flip Lawson reports is legal and illegal-before-flip, and the exact
checker ``reference_impl.exact.verify.check_delaunay`` checks the final
triangulation.  Starting triangulations: fans of convex polygons, the
``triangle`` package's constrained (non-Delaunay) output, and random legal flips
applied to a Delaunay triangulation.  The max-min angle property (which does not make
triangles well shaped, whatever the original tutorial says) is checked against *all* triangulations of small convex polygons with
an exact angle comparison (squared cosines as Fractions).
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import triangle as shewchuk_triangle
from hypothesis import given, settings, strategies as st

import pointsets
from reference_impl import Delaunay
from reference_impl.structures.flips import (apply_flips, flip_to_delaunay, laplacian_smooth, lawson_flip,
                                  mesh_quality, validate_triangulation)
from reference_impl.exact.verify import check_delaunay, exact_coordinates, incircle_exact, orient_exact
from exact_oracle import canon


# ----------------------------------------------------------------------------- independent replay
class Mesh:
    """A triangulation as a dict directed edge (u, v) -> apex w of the CCW triangle (u, v, w)."""

    def __init__(self, points, triangles) -> None:
        self.I = exact_coordinates(points)
        self.apex: dict[tuple[int, int], int] = {}
        for a, b, c in np.asarray(triangles).reshape(-1, 3).tolist():
            for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
                assert (u, v) not in self.apex
                self.apex[(u, v)] = w

    def interior_edges(self) -> list[tuple[int, int]]:
        return sorted((u, v) for (u, v) in self.apex if u < v and (v, u) in self.apex)

    def quad(self, i, j):
        return self.apex[(i, j)], self.apex[(j, i)]

    def convex(self, i, j) -> bool:
        w1, w2 = self.quad(i, j)
        I = self.I
        return orient_exact(I[i], I[w2], I[w1]) > 0 and orient_exact(I[w2], I[j], I[w1]) > 0

    def illegal(self, i, j) -> bool:
        w1, _ = self.quad(i, j)
        I = self.I
        return incircle_exact(I[i], I[j], I[w1], I[self.apex[(j, i)]]) > 0

    def cocircular(self, i, j) -> bool:
        w1, w2 = self.quad(i, j)
        I = self.I
        return incircle_exact(I[i], I[j], I[w1], I[w2]) == 0

    def flip(self, i, j) -> None:
        w1, w2 = self.quad(i, j)
        for e in ((i, j), (j, w1), (w1, i), (j, i), (i, w2), (w2, j)):
            del self.apex[e]
        for u, v, w in ((i, w2, w1), (w2, w1, i), (w1, i, w2), (w2, j, w1), (j, w1, w2), (w1, w2, j)):
            self.apex[(u, v)] = w

    def triangles(self) -> set[tuple[int, int, int]]:
        out = set()
        for (u, v), w in self.apex.items():
            t = (u, v, w)
            k = t.index(min(t))
            out.add(t[k:] + t[:k])
        return out


def replay_checked(points, triangles, flips) -> set[tuple[int, int, int]]:
    """Replay flips; assert each is an interior edge, strictly convex and illegal before."""
    m = Mesh(points, triangles)
    for s, (i, j) in enumerate(flips):
        assert i < j, f"flip {s} {(i, j)} not ordered"
        assert (i, j) in m.apex and (j, i) in m.apex, f"flip {s} {(i, j)} is not an interior edge"
        assert m.convex(i, j), f"flip {s} {(i, j)}: quadrilateral not strictly convex"
        assert m.illegal(i, j), f"flip {s} {(i, j)} was already locally Delaunay"
        m.flip(i, j)
    return m.triangles()


# ----------------------------------------------------------------------------- starting triangulations
def randomly_flipped(points, rng, n_flips, only_ties=False) -> np.ndarray:
    """A Delaunay triangulation with random legal (strictly convex) flips applied;
    with ``only_ties``, only flips of cocircular quadrilaterals (the result stays Delaunay)."""
    m = Mesh(points, Delaunay(points).simplices)
    for _ in range(n_flips):
        edges = m.interior_edges()
        for _attempt in range(10):
            e = edges[rng.integers(len(edges))] if edges else None
            if e and m.convex(*e) and (not only_ties or m.cocircular(*e)):
                m.flip(*e)
                break
    return np.array(sorted(m.triangles()), dtype=np.int64).reshape(-1, 3)


def convex_polygon(rng, n) -> np.ndarray:
    """n points in strictly convex position, counter-clockwise (random angles on an ellipse)."""
    while True:
        t = np.sort(rng.random(n)) * 2 * np.pi
        pts = np.c_[3 * np.cos(t), np.sin(t)]
        I = exact_coordinates(pts)
        if all(orient_exact(I[k], I[(k + 1) % n], I[(k + 2) % n]) > 0 for k in range(n)):
            return pts


def fan(n) -> np.ndarray:
    return np.array([(0, k, k + 1) for k in range(1, n - 1)], dtype=np.int64)


def all_triangulations(n) -> list[list[tuple[int, int, int]]]:
    """Every triangulation of the convex polygon 0..n-1 (Catalan many)."""
    def rec(i, j):
        if j - i < 2:
            return [[]]
        out = []
        for k in range(i + 1, j):
            for left in rec(i, k):
                for right in rec(k, j):
                    out.append(left + [(i, k, j)] + right)
        return out
    return rec(0, n - 1)


def min_angle_key(points, tris) -> Fraction:
    """Largest squared cosine of an acute angle over all triangles: a larger key is a
    smaller minimum angle (the smallest angle of a triangle is at most 60 degrees)."""
    I = exact_coordinates(points)
    best = Fraction(0)
    for a, b, c in tris:
        for p, q, r in ((a, b, c), (b, c, a), (c, a, b)):
            ux, uy = I[q][0] - I[p][0], I[q][1] - I[p][1]
            vx, vy = I[r][0] - I[p][0], I[r][1] - I[p][1]
            dot = ux * vx + uy * vy
            if dot > 0:
                best = max(best, Fraction(dot * dot, (ux * ux + uy * uy) * (vx * vx + vy * vy)))
    return best


def check_lawson(points, tris, entry=True) -> list[tuple[int, int]]:
    final, flips = lawson_flip(points, tris)
    if entry:
        assert flip_to_delaunay(points, tris) == flips
    assert check_delaunay(points, final) == (True, "ok")
    assert replay_checked(points, tris, flips) == canon(final)
    return flips


# ----------------------------------------------------------------------------- Lawson
def test_1000_random_triangulations_flip_to_delaunay():
    rng = np.random.default_rng(99)
    total = 0
    for k in range(1000):
        n = int(rng.integers(4, 14))
        if k % 4 == 0:
            pts = convex_polygon(rng, n)
            tris = fan(n)
        elif k % 4 == 1:
            pts = rng.integers(0, 5, (n, 2)).astype(float)            # ties: cocircular quads
        elif k % 4 == 2:
            pts = rng.random((n, 2)) * 10.0 ** rng.integers(-300, 300)
        else:
            pts = rng.random((n, 2)) + 1e9
        if k % 4:
            if len(Delaunay(pts).simplices) == 0:
                continue
            tris = randomly_flipped(pts, rng, int(rng.integers(0, 2 * n)))
        try:
            total += len(check_lawson(pts, tris, entry=k % 10 == 0))
        except AssertionError:
            raise AssertionError(f"case {k}: points {pts.tolist()} triangles {tris.tolist()}") from None
    assert total > 1000          # the cases really needed flips


def test_triangle_package_constrained_output_is_repaired():
    rng = np.random.default_rng(5)
    needed = 0
    for k in range(20):
        pts = rng.random((60, 2))
        order = np.argsort(pts[:, 0])                 # an x-monotone polyline: never self-crossing
        segs = np.c_[order[:-1], order[1:]]
        out = shewchuk_triangle.triangulate({"vertices": pts, "segments": segs}, "pcQ")
        assert len(out["vertices"]) == len(pts)       # no Steiner points
        tris = out["triangles"]
        I = exact_coordinates(pts)
        cw = [orient_exact(I[a], I[b], I[c]) < 0 for a, b, c in tris]
        tris = np.where(np.array(cw)[:, None], tris[:, ::-1], tris)
        needed += len(check_lawson(pts, tris))
    assert needed > 20


@pytest.mark.parametrize("name,pts", pointsets.degenerate_sets(), ids=[s[0] for s in pointsets.degenerate_sets()])
def test_degenerate_sets_after_random_flips(name, pts):
    rng = np.random.default_rng(len(pts))
    d = Delaunay(pts)
    rep = d.index_map
    tris = randomly_flipped(pts, rng, len(pts))
    flips = check_lawson(pts, tris)
    assert all(rep[i] == i and rep[j] == j for i, j in flips)   # representatives only
    assert flip_to_delaunay(pts, d.simplices) == []              # Delaunay input: nothing to do


def test_cocircular_ties_are_not_flipped():
    pts = pointsets.grid(5)                                      # all unit squares cocircular
    rng = np.random.default_rng(0)
    tris = randomly_flipped(pts, rng, 40, only_ties=True)
    assert canon(tris) != canon(Delaunay(pts).simplices)         # another Delaunay triangulation
    assert check_delaunay(pts, tris) == (True, "ok")
    assert flip_to_delaunay(pts, tris) == []                     # so there is nothing to flip


def test_result_independent_of_triangle_listing_order():
    rng = np.random.default_rng(3)
    pts = rng.random((40, 2))
    tris = randomly_flipped(pts, rng, 100)
    base = lawson_flip(pts, tris)
    shuffled = tris[rng.permutation(len(tris))]
    rolled = np.roll(shuffled, 1, axis=1)                        # same triangles, other first vertex
    for t in (shuffled, rolled):
        again = lawson_flip(pts, t)
        assert again[1] == base[1] and np.array_equal(again[0], base[0])


def test_flat_input():
    assert lawson_flip(pointsets.collinear(8), [])[1] == []
    with pytest.raises(ValueError, match="collinear"):
        flip_to_delaunay([(0, 0), (1, 1), (2, 2)], [(0, 1, 2)])


@pytest.mark.parametrize("tris,message", [
    ([(0, 2, 1), (0, 2, 3)], "clockwise"),
    ([(0, 1, 2)], "not covered|not a vertex|hull"),
    ([(0, 1, 2), (0, 1, 3)], "two triangles|overlap"),
    ([(0, 1, 2), (0, 2, 3), (0, 1, 3)], "two triangles|overlap|clockwise"),
    ([(0, 1, 5)], "outside 0..3"),
    ([(0, 1)], "shape"),
    ([(0.5, 1, 2)], "integer"),
    ("abc", "text"),
])
def test_invalid_triangulations_are_rejected(tris, message):
    pts = [(0, 0), (2, 0), (2, 2), (0, 2)]
    with pytest.raises(ValueError, match=message):
        flip_to_delaunay(pts, tris)


def test_missing_point_and_hole_are_rejected():
    pts = [(0, 0), (4, 0), (4, 4), (0, 4), (2, 2)]
    with pytest.raises(ValueError, match="not a vertex"):
        validate_triangulation(pts, [(0, 1, 2), (0, 2, 3)])
    with pytest.raises(ValueError, match="hull edge|hole"):
        validate_triangulation(pts, [(0, 1, 4), (1, 2, 4), (2, 3, 4)])
    with pytest.raises(ValueError, match="zero area"):
        validate_triangulation([(0, 0), (1, 0), (2, 0), (1, 1)], [(0, 1, 2), (0, 1, 3)])


# ----------------------------------------------------------------------------- apply_flips
def test_apply_flips_matches_the_replay_and_rejects_bad_flips():
    rng = np.random.default_rng(8)
    pts = rng.random((30, 2))
    tris = randomly_flipped(pts, rng, 60)
    final, flips = lawson_flip(pts, tris)
    assert canon(apply_flips(pts, tris, flips)) == canon(final)
    m = Mesh(pts, tris)
    hull = Delaunay(pts).hull
    legal = next(e for e in m.interior_edges() if not m.illegal(*e) and m.convex(*e))
    nonconvex = [e for e in m.interior_edges() if not m.convex(*e)]
    with pytest.raises(ValueError, match="already locally Delaunay"):
        apply_flips(pts, tris, [legal])
    assert len(apply_flips(pts, tris, [legal], only_illegal=False)) == len(tris)
    with pytest.raises(ValueError, match="hull edge"):
        apply_flips(pts, tris, [tuple(sorted((int(hull[0]), int(hull[1]))))])
    if nonconvex:
        with pytest.raises(ValueError, match="not strictly convex"):
            apply_flips(pts, tris, [nonconvex[0]], only_illegal=False)
    with pytest.raises(ValueError, match="flip 1 .* not an edge"):
        apply_flips(pts, tris, flips[:1] + [flips[0]])          # the removed edge is gone
    with pytest.raises(ValueError, match="outside"):
        apply_flips(pts, tris, [(0, 99)])
    with pytest.raises(ValueError, match="integer"):
        apply_flips(pts, tris, [(0.5, 1)])
    with pytest.raises(ValueError, match="shape"):
        apply_flips(pts, tris, [(0, 1, 2)])


# ----------------------------------------------------------------------------- max-min angle
@pytest.mark.parametrize("n", [4, 5, 6, 7, 8])
def test_delaunay_maximises_the_minimum_angle_among_all_triangulations(n):
    rng = np.random.default_rng(n)
    for _ in range(3):
        pts = convex_polygon(rng, n)
        final, _ = lawson_flip(pts, fan(n))
        best = min_angle_key(pts, final.tolist())
        keys = [min_angle_key(pts, t) for t in all_triangulations(n)]
        assert best == min(keys)                                 # no triangulation does better


def test_cocircular_polygon_all_triangulations_have_the_same_min_angle():
    ring = [(5, 0), (4, 3), (3, 4), (0, 5), (-4, 3), (-5, 0), (-3, -4), (4, -3)]   # on x^2+y^2=25
    pts = np.array(ring, dtype=float)
    keys = {min_angle_key(pts, t) for t in all_triangulations(len(pts))}
    assert len(keys) == 1


@given(st.integers(0, 10 ** 6), st.integers(5, 25))
@settings(max_examples=25, deadline=None)
def test_random_flips_never_raise_the_minimum_angle(seed, n):
    rng = np.random.default_rng(seed)
    pts = rng.random((n, 2))
    d = Delaunay(pts).simplices.tolist()
    other = randomly_flipped(pts, rng, int(rng.integers(1, 2 * n)))
    assert min_angle_key(pts, d) <= min_angle_key(pts, other.tolist())


def test_delaunay_is_not_well_shaped_on_thin_input():
    """Delaunay maximises the minimum angle, yet the best triangulation of thin input is still thin."""
    t = np.linspace(0, np.pi, 30)
    pts = np.c_[np.cos(t) * 100, np.sin(t)]
    q = mesh_quality(pts, Delaunay(pts).simplices)
    assert q["min_angle"] < 2.0 and q["radius_ratio_max"] > 10


# ----------------------------------------------------------------------------- mesh quality
def test_quality_of_hand_computed_triangles():
    q = mesh_quality([(0, 0), (2, 0), (1, math.sqrt(3))], [(0, 1, 2)])
    assert q["min_angle"] == pytest.approx(60) and q["max_angle"] == pytest.approx(60)
    assert q["radius_ratio_max"] == pytest.approx(1) and q["edge_ratio_max"] == pytest.approx(1)
    assert (q["triangles"], q["vertices"], q["interior_edges"], q["boundary_edges"]) == (1, 3, 0, 3)
    # right isosceles, legs 1: R = sqrt(2)/2, r = (2 - sqrt(2))/2, so R / 2r = 1/(2 - sqrt 2) * sqrt(2)/2
    q = mesh_quality([(0, 0), (1, 0), (0, 1), (1, 1)], [(0, 1, 3), (0, 3, 2)])
    assert q["min_angle"] == pytest.approx(45) and q["max_angle"] == pytest.approx(90)
    assert q["radius_ratio_max"] == pytest.approx(math.sqrt(2) / 2 / (2 - math.sqrt(2)))
    assert q["edge_ratio_max"] == pytest.approx(math.sqrt(2))
    assert (q["interior_edges"], q["boundary_edges"], q["angles_below_30"], q["obtuse_triangles"]) == (1, 4, 0, 0)
    # scale-free: the same triangle at 1e-300 and 1e300
    for s in (1e-300, 1e300):
        assert mesh_quality(np.array([(0, 0), (2, 0), (1, math.sqrt(3))]) * s,
                            [(0, 1, 2)])["min_angle"] == pytest.approx(60)
    with pytest.raises(ValueError, match="clockwise"):
        mesh_quality([(0, 0), (1, 0), (0, 1)], [(0, 2, 1)])


# ----------------------------------------------------------------------------- smoothing
def grid_mesh(k):
    pts = pointsets.grid(k)
    idx = np.arange(k * k).reshape(k, k)              # point (i, j) has index i * k + j
    tris = []
    for i in range(k - 1):
        for j in range(k - 1):
            a, b, c, d = idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]
            tris += [(a, b, c), (a, c, d)]
    return pts, np.array(tris)


def test_smoothing_improves_a_perturbed_grid_and_keeps_boundary_and_orientation():
    pts, tris = grid_mesh(8)
    rng = np.random.default_rng(1)
    interior = (pts[:, 0] > 0) & (pts[:, 0] < 7) & (pts[:, 1] > 0) & (pts[:, 1] < 7)
    noisy = pts + np.where(interior[:, None], rng.uniform(-0.3, 0.3, pts.shape), 0.0)
    before = mesh_quality(noisy, tris)
    smooth = laplacian_smooth(noisy, tris, iterations=5)
    after = mesh_quality(smooth, tris)                   # raises if any triangle inverted
    assert np.array_equal(smooth[~interior], noisy[~interior])
    assert after["min_angle"] > before["min_angle"] + 5
    assert np.abs(laplacian_smooth(noisy, tris, iterations=200) - pts).max() < 1e-6   # back to the grid
    fixed = np.flatnonzero(interior)[:3]
    assert np.array_equal(laplacian_smooth(noisy, tris, 3, fixed=fixed)[fixed], noisy[fixed])


def test_smoothing_is_independent_of_vertex_numbering():
    pts, tris = grid_mesh(6)
    rng = np.random.default_rng(2)
    pts = pts + rng.uniform(-0.2, 0.2, pts.shape) * ((pts > 0) & (pts < 5)).all(axis=1)[:, None]
    perm = rng.permutation(len(pts))
    inv = np.argsort(perm)
    a = laplacian_smooth(pts, tris, 3)
    b = laplacian_smooth(pts[perm], inv[tris], 3)
    assert np.array_equal(a, b[inv])


def test_guard_rejects_moves_that_invert_triangles():
    """A star-shaped but non-convex neighbourhood: the average lies outside the polygon."""
    ring = [(-1, 0), (0, -1), (5, -1), (0.2, 0), (5, 1), (0, 1)]
    pts = np.array([(0.0, 0.0)] + ring)
    tris = [(0, 1 + k, 1 + (k + 1) % 6) for k in range(6)]
    mesh_quality(pts, tris)                              # a valid mesh (not convex: no hull check)
    unguarded = laplacian_smooth(pts, tris, guard=False)
    assert unguarded[0].tolist() == pytest.approx([np.mean([p[0] for p in ring]), 0.0])
    with pytest.raises(ValueError, match="clockwise|zero area"):
        mesh_quality(unguarded, tris)                    # the plain average inverts triangles
    guarded = laplacian_smooth(pts, tris)
    assert guarded[0].tolist() == [0.0, 0.0]             # the move was refused
    mesh_quality(guarded, tris)


def test_smoothing_rejects_bad_arguments():
    pts, tris = grid_mesh(3)
    with pytest.raises(ValueError, match="iterations"):
        laplacian_smooth(pts, tris, iterations=-1)
    with pytest.raises(ValueError, match="fixed"):
        laplacian_smooth(pts, tris, fixed=[100])
    with pytest.raises(ValueError, match="clockwise"):
        laplacian_smooth(pts, tris[:, ::-1])
