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

The tests marked ``slow`` (at the end; until issue 9 they were ``test_flips_1000.py``;
``-m "not slow"`` leaves them out): laplacian_smooth and mesh_quality: 1000 random small meshes each and the degenerate
families, against oracles written here.

Oracles (nothing shared with the library):

* ``mesh_quality``: per triangle, the squared side lengths as exact ``Fraction``s, the
  angles from the law of cosines (cos A = (b^2 + c^2 - a^2) / 2bc, with cos^2 A formed
  exactly and only its square root and arccos in floating point), the radius ratio
  R / 2r = abc (a + b + c) / 16 K^2 with 16 K^2 formed exactly, the edge ratio from the
  exact squared lengths; the counts from a plain edge count (an edge in one triangle is
  a boundary edge, in two an interior edge), "below 30 degrees" and "obtuse" decided
  exactly (cos^2 A > 3/4 with cos A > 0; b^2 + c^2 - a^2 < 0).
* ``laplacian_smooth``: a networkx graph of the mesh edges; boundary vertices are the
  ends of edges used by one triangle; every free vertex moves to the plain average of
  its neighbours' previous positions (Jacobi), all at once; with the guard, while some
  triangle is inverted (exact orientation <= 0 with Fractions), the vertices of the
  inverted triangles that moved are put back.  Also checked directly: boundary, fixed
  and unused vertices do not move (bit for bit), and no triangle is inverted.
"""
from __future__ import annotations

import math
from collections import Counter
from fractions import Fraction

import networkx as nx
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


# =================================================================================================
# slow (was test_flips_1000.py): laplacian_smooth and mesh_quality, 1000 meshes, degenerate families
# =================================================================================================
CASES = 1000


# ----------------------------------------------------------------------------- oracles
def frac(p):
    return (Fraction(float(p[0])), Fraction(float(p[1])))


def sq(p, q) -> Fraction:
    return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2


def cross(a, b, c) -> Fraction:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def triangle_quality(A, B, C) -> dict:
    """Angles (degrees), exact flags, radius ratio and edge ratio of one triangle (exact inputs)."""
    a2, b2, c2 = sq(B, C), sq(C, A), sq(A, B)          # sides opposite A, B, C
    angles, below30, obtuse = [], 0, False
    for opp, s1, s2 in ((a2, b2, c2), (b2, c2, a2), (c2, a2, b2)):
        num = s1 + s2 - opp                            # = 2 s1' s2' cos(angle)
        cos2 = num * num / (4 * s1 * s2)
        cos = math.sqrt(float(cos2)) * (1 if num >= 0 else -1)
        angles.append(math.degrees(math.acos(min(1.0, cos))))
        below30 += num > 0 and cos2 > Fraction(3, 4)   # cos > sqrt(3) / 2
        obtuse |= num < 0
    m = max(a2, b2, c2)
    u, v, w = float(a2 / m), float(b2 / m), float(c2 / m)
    k16 = 4 * cross(A, B, C) ** 2 / (m * m)            # 16 K^2 / m^2
    ratio = math.sqrt(u * v * w) * (math.sqrt(u) + math.sqrt(v) + math.sqrt(w)) / float(k16)
    edge = math.sqrt(float(m / min(a2, b2, c2)))
    return {"angles": angles, "below30": below30, "obtuse": obtuse, "ratio": ratio, "edge": edge}


def quality_oracle(points, tris) -> dict:
    F = [frac(p) for p in np.asarray(points, dtype=float)]
    per = [triangle_quality(*(F[v] for v in t)) for t in np.asarray(tris).tolist()]
    angles = [a for q in per for a in q["angles"]]
    edges = Counter(frozenset((t[i], t[(i + 1) % 3])) for t in np.asarray(tris).tolist() for i in range(3))
    return {
        "min_angle": min(angles), "max_angle": max(angles),
        "mean_min_angle": sum(min(q["angles"]) for q in per) / len(per),
        "radius_ratio_max": max(q["ratio"] for q in per),
        "radius_ratio_mean": sum(q["ratio"] for q in per) / len(per),
        "edge_ratio_max": max(q["edge"] for q in per),
        "triangles": len(per),
        "vertices": len({v for t in np.asarray(tris).tolist() for v in t}),
        "interior_edges": sum(1 for c in edges.values() if c == 2),
        "boundary_edges": sum(1 for c in edges.values() if c == 1),
        "angles_below_30": sum(q["below30"] for q in per),
        "obtuse_triangles": sum(q["obtuse"] for q in per),
    }


def assert_quality(points, tris) -> None:
    got = mesh_quality(points, tris)
    want = quality_oracle(points, tris)
    assert set(got) == set(want)
    for key in ("triangles", "vertices", "interior_edges", "boundary_edges", "angles_below_30",
                "obtuse_triangles"):
        assert got[key] == want[key], (key, got[key], want[key])
    for key in ("min_angle", "max_angle", "mean_min_angle"):
        assert math.isclose(got[key], want[key], rel_tol=1e-12, abs_tol=1e-7), (key, got[key], want[key])
    if want["radius_ratio_max"] > 1e12:
        # a needle: its float area (a difference of near-equal products) has lost most digits
        assert got["radius_ratio_max"] > 1e10, (got["radius_ratio_max"], want["radius_ratio_max"])
        assert got["radius_ratio_mean"] >= got["radius_ratio_max"] / want["triangles"]
    else:
        # the float area of a thin triangle loses about eps * ratio of relative accuracy
        tol = max(1e-9, 1e-13 * want["radius_ratio_max"])
        for key in ("radius_ratio_max", "radius_ratio_mean"):
            assert math.isclose(got[key], want[key], rel_tol=tol), (key, got[key], want[key])
    assert math.isclose(got["edge_ratio_max"], want["edge_ratio_max"], rel_tol=1e-12)


def smooth_oracle(points, tris, iterations=1, fixed=(), guard=True):
    """(new points as float pairs, number of vertices the guard put back)."""
    X = [tuple(map(float, p)) for p in np.asarray(points, dtype=float)]
    T = [tuple(t) for t in np.asarray(tris).tolist()]
    g = nx.Graph()
    uses = Counter()
    for t in T:
        for i in range(3):
            g.add_edge(t[i], t[(i + 1) % 3])
            uses[frozenset((t[i], t[(i + 1) % 3]))] += 1
    boundary = {v for e, c in uses.items() if c == 1 for v in e}
    free = set(g.nodes) - boundary - set(int(v) for v in fixed)
    reverted = 0
    for _ in range(iterations):
        new = list(X)
        for v in free:
            nb = list(g.neighbors(v))
            new[v] = (math.fsum(X[u][0] for u in nb) / len(nb), math.fsum(X[u][1] for u in nb) / len(nb))
        if guard:
            moved = set(free)
            while True:
                bad = [t for t in T if cross(*(frac(new[v]) for v in t)) <= 0]
                if not bad:
                    break
                back = {v for t in bad for v in t} & moved
                assert back, "an inverted triangle with no moved vertex"
                for v in back:
                    new[v] = X[v]
                moved -= back
                reverted += len(back)
        X = new
    return np.array(X, dtype=float).reshape(-1, 2), free, reverted


def assert_smooth(points, tris, iterations=1, fixed=None, guard=True) -> int:
    pts = np.asarray(points, dtype=float)
    got = laplacian_smooth(pts, tris, iterations, fixed=fixed, guard=guard)
    want, free, reverted = smooth_oracle(pts, tris, iterations, () if fixed is None else fixed, guard)
    still = np.setdiff1d(np.arange(len(pts)), sorted(free))
    assert np.array_equal(got[still], pts[still]), "a boundary, fixed or unused vertex moved"
    scale = np.abs(pts).max()
    assert np.allclose(got, want, rtol=0, atol=8 * np.spacing(scale)), np.abs(got - want).max()
    if guard:
        for t in np.asarray(tris).tolist():
            assert cross(*(frac(got[v]) for v in t)) > 0, f"triangle {t} inverted"
    return reverted


# ----------------------------------------------------------------------------- random meshes
def random_mesh(rng):
    """Delaunay triangles of 4-15 points, some removed (non-convex meshes, unused vertices)."""
    n = int(rng.integers(4, 16))
    kind = rng.integers(0, 3)
    pts = rng.random((n, 2))
    if kind == 1:                                   # a star: a centre and a jagged ring
        ang = np.sort(rng.uniform(0, 2 * np.pi, n - 1))
        r = rng.uniform(0.2, 1.0, n - 1)
        pts = np.vstack([[0.0, 0.0], np.c_[r * np.cos(ang), r * np.sin(ang)]])
    pts = pts * 10.0 ** int(rng.integers(-3, 4)) + (1e6 if rng.random() < 0.1 else 0.0)
    tris = Delaunay(pts).simplices
    if kind == 1:                                   # the fan around the centre, not Delaunay
        k = n - 1
        tris = np.array([(0, 1 + i, 1 + (i + 1) % k) for i in range(k)])
        P = [frac(p) for p in pts]
        tris = np.array([t for t in tris.tolist() if cross(*(P[v] for v in t)) > 0]).reshape(-1, 3)
    elif kind == 2 and len(tris) > 2:
        tris = tris[rng.permutation(len(tris))[: max(1, len(tris) - int(rng.integers(1, len(tris) // 2 + 1)))]]
    return pts, tris


@pytest.mark.slow
def test_1000_random_meshes_mesh_quality():
    rng = np.random.default_rng(55)
    done = 0
    for _ in range(CASES):
        pts, tris = random_mesh(rng)
        if len(tris) == 0:
            continue
        assert_quality(pts, tris)
        done += 1
    assert done > 0.95 * CASES


@pytest.mark.slow
def test_1000_random_meshes_laplacian_smooth():
    rng = np.random.default_rng(56)
    reverted = unguarded = 0
    for _ in range(CASES):
        pts, tris = random_mesh(rng)
        if len(tris) == 0:
            continue
        iterations = int(rng.integers(1, 4))
        fixed = rng.choice(len(pts), int(rng.integers(1, 3)), replace=False) if rng.random() < 0.3 else None
        guard = rng.random() < 0.85
        unguarded += not guard
        reverted += assert_smooth(pts, tris, iterations, fixed, guard)
    assert reverted > 20 and unguarded > 50             # the guard had work to do


# ----------------------------------------------------------------------------- degenerate families
def _mesh(pts):
    return Delaunay(pts).simplices


FAMILIES = [(name, pts) for name, pts in pointsets.degenerate_sets()] + [
    ("grid+1e9", pointsets.grid(6) + 1e9),
    ("grid*0.5+1e9", pointsets.grid(6) * 0.5 + 1e9),
    ("integer-right-triangles", np.array([(0, 0), (2, 1), (1, 3), (3, 4), (4, 2), (-1, 2)], dtype=float)),
    ("rotated-squares", np.array([(3 * i - 4 * j, 4 * i + 3 * j) for i in range(4) for j in range(4)], dtype=float)),
]


@pytest.mark.slow
@pytest.mark.parametrize("name,pts", FAMILIES, ids=[f[0] for f in FAMILIES])
def test_degenerate_families(name, pts):
    tris = _mesh(pts)
    assert_quality(pts, tris)
    for iterations in (1, 3):
        assert_smooth(pts, tris, iterations)
    assert_smooth(pts, tris, 2, fixed=np.arange(0, len(pts), 3))
    assert_smooth(pts, tris, 1, guard=False)
    # perturbed interior (a non-Delaunay, non-uniform mesh on the same triangles)
    rng = np.random.default_rng(len(name))
    span = np.ptp(pts, axis=0).max()
    noisy = pts + rng.uniform(-0.02, 0.02, pts.shape) * span / np.sqrt(len(pts))
    P = [frac(p) for p in noisy]
    if all(cross(*(P[v] for v in t)) > 0 for t in tris.tolist()):
        assert_quality(noisy, tris)
        assert_smooth(noisy, tris, 2)
