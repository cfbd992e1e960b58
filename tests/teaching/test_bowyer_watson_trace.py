"""Tests of the teaching Bowyer-Watson's trace, dry run and input errors, and of the tutorial's bugs.

    .venv/bin/python -m pytest tests/teaching/test_bowyer_watson_trace.py -q

Every trace record is checked against an oracle that shares no code with the
module: exact integer predicates from ``reference_impl.exact.verify`` (and, for the
tutorial's example, circumcentres computed with ``Fraction``).  The general
correctness suite (shared with the fast ``Delaunay``) is ``test_delaunay_shared.py``.
"""
from __future__ import annotations

import itertools
import random
import re
from fractions import Fraction

import numpy as np
import pytest

from pointsets import circle, collinear, grid, integer_circle, uniform, with_duplicates
from reference_impl.teaching.bowyer_watson import (INFINITE, TUTORIAL_POINTS, Step, bowyer_watson,
                                          cavity_boundary, dry_run, insertion_order)
from reference_impl.teaching.tutorial_bugs import (ALL_FIXES, EXHIBITS, RING_25, SUPER_TRIANGLE, det_in_circumcircle,
                                          epsilon_says_degenerate, naive_bowyer_watson, tutorial_boundary,
                                          tutorial_det)
from reference_impl.exact.verify import check_delaunay, exact_coordinates, incircle_exact, orient_exact
from reference_impl.exact.predicates import incircle

# ----------------------------------------------------------------------------- oracles


def rotations(t):
    """The set of a triangle's rotations (a triangle has one orientation, three names)."""
    t = tuple(int(v) for v in t)
    return {t, t[1:] + t[:1], t[2:] + t[:2]}


def same_triangle(s, t) -> bool:
    return tuple(int(v) for v in s) in rotations(t)


def as_set(triangles):
    """Triangles as a set of rotation-normalised tuples."""
    return {min(rotations(t)) for t in np.asarray(triangles).reshape(-1, 3).tolist()}


def edges(t):
    a, b, c = t
    return [(a, b), (b, c), (c, a)]


class Exact:
    """Exact predicates on the input points (integers after one common power-of-two scaling)."""

    def __init__(self, points):
        self.P = exact_coordinates(np.asarray(points, dtype=float).reshape(-1, 2))

    def orient(self, a, b, c):
        return orient_exact(self.P[a], self.P[b], self.P[c])

    def conflicts(self, t, i) -> bool:
        """Is triangle t (real, or ghost (u, v, INFINITE) in any rotation) bad for point i?"""
        if INFINITE in t:
            k = t.index(INFINITE)
            u, v = t[(k + 1) % 3], t[(k + 2) % 3]
            s = self.orient(u, v, i)
            if s != 0:
                return s > 0
            (ux, uy), (vx, vy), (px, py) = self.P[u], self.P[v], self.P[i]
            return (px - ux) * (vx - px) + (py - uy) * (vy - py) > 0  # strictly inside segment uv
        a, b, c = t
        return incircle_exact(self.P[a], self.P[b], self.P[c], self.P[i]) > 0

    def in_closed_triangle(self, t, i) -> bool:
        return all(self.orient(a, b, i) >= 0 for a, b in edges(t))


def fraction_delaunay(points):
    """Brute force with Fractions: CCW triples whose circumcircle has no point inside (general position)."""
    P = [(Fraction(x), Fraction(y)) for x, y in points]
    found = set()
    for a, b, c in itertools.combinations(range(len(P)), 3):
        (ax, ay), (bx, by), (cx, cy) = P[a], P[b], P[c]
        d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
        if d == 0:
            continue
        la, lb, lc = ax * ax + ay * ay, bx * bx + by * by, cx * cx + cy * cy
        ux = (la * (by - cy) + lb * (cy - ay) + lc * (ay - by)) / d
        uy = (la * (cx - bx) + lb * (ax - cx) + lc * (bx - ax)) / d
        r2 = (ax - ux) ** 2 + (ay - uy) ** 2
        if all((x - ux) ** 2 + (y - uy) ** 2 >= r2 for k, (x, y) in enumerate(P) if k not in (a, b, c)):
            found.add(min(rotations((a, b, c) if d > 0 else (a, c, b))))
    return found


def traced(points, **kw):
    steps: list[Step] = []
    result = bowyer_watson(points, trace=steps, **kw)
    return steps, result


# ----------------------------------------------------------------------------- trace invariants
TRACE_SETS = {
    "tutorial": np.array(TUTORIAL_POINTS),
    "uniform": uniform(40, seed=11),
    "grid": grid(5),
    "circle+centre": circle(12, centre=True),
    "integer-circle": integer_circle(),
    "collinear+1": np.vstack([collinear(8, seed=2), [[0.3, 5.0]]]),
    "collinear-start": np.array([(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, -1)], dtype=float),
    "duplicates": with_duplicates(20, seed=4),
    "huge": uniform(25, seed=5) * 1e300,
    "tiny": uniform(25, seed=6) * 1e-300,
    "mixed-scales": np.array([(0, 0), (1e-300, 2e-300), (1e300, 0), (0, 1e300), (3e-300, 1e-300)]),
}


def check_trace(points, steps, result):
    """Assert every documented property of a trace (see ``Step``)."""
    pts = np.asarray(points, dtype=float).reshape(-1, 2)
    ex = Exact(pts)
    distinct = {}
    for i, p in enumerate(map(tuple, pts.tolist())):
        distinct.setdefault(p, i)
    assert sorted(s.index for s in steps) == sorted(distinct.values())   # every distinct point once
    assert steps[0].bad == steps[0].boundary == steps[0].new == [] and steps[0].located is None
    assert steps[1].bad == steps[1].boundary == [] and steps[1].located is None
    a, b = steps[0].index, steps[1].index
    assert {min(rotations(t)) for t in steps[1].new} == {min(rotations((a, b, INFINITE))),
                                                         min(rotations((b, a, INFINITE)))}
    real = set()                        # triangulation so far, rotation-normalised
    ghosts = {min(rotations(t)) for t in steps[1].new}
    inserted = [a, b]
    for s in steps:
        assert s.point == tuple(pts[s.index].tolist())
        assert isinstance(s.triangles, np.ndarray) and s.triangles.dtype == np.int64
        assert s.triangles.shape[1:] == (3,)
    for s in steps[2:]:
        i = s.index
        # bad: exactly the triangles (real and ghost) whose circumcircle contains the point
        bad = {min(rotations(t)) for t in s.bad}
        assert len(bad) == len(s.bad), "a bad triangle is listed twice"
        assert bad == {t for t in real | ghosts if ex.conflicts(t, i)}
        assert all(ex.orient(*t) > 0 for t in bad if INFINITE not in t)
        # located: a real triangle containing the point, or None when no real triangle does
        if s.located is None:
            assert not any(ex.in_closed_triangle(t, i) for t in real)
        else:
            assert min(rotations(s.located)) in real & bad and ex.in_closed_triangle(s.located, i)
        # boundary: the edges of exactly one bad triangle, one closed loop, counter-clockwise
        bad_edges = [e for t in s.bad for e in edges(t)]
        assert sorted(s.boundary) == sorted(e for e in bad_edges if (e[1], e[0]) not in bad_edges)
        assert all(s.boundary[k][1] == s.boundary[(k + 1) % len(s.boundary)][0]
                   for k in range(len(s.boundary)))
        assert len({e[0] for e in s.boundary}) == len(s.boundary)
        assert all(ex.orient(u, v, i) > 0 for u, v in s.boundary if INFINITE not in (u, v))
        # new: the boundary edges joined to the point
        assert len(s.new) == len(s.boundary)
        assert all(same_triangle(t, (u, v, i)) for t, (u, v) in zip(s.new, s.boundary))
        assert all(ex.orient(*t) > 0 for t in s.new if INFINITE not in t)
        # counts: ghosts included, every step adds exactly two triangles (Euler on the sphere)
        assert len(s.new) - len(s.bad) == 2
        for t in bad:
            (ghosts if INFINITE in t else real).remove(t)
        for t in s.new:
            (ghosts if INFINITE in t else real).add(min(rotations(t)))
        inserted.append(i)
        k = len(inserted)
        assert len(real) + len(ghosts) == 2 * k - 2
        # real triangles: 2k - 2 - h with h the hull vertices (one ghost per hull edge)
        assert len(real) == 2 * k - 2 - len(ghosts)
        assert as_set(s.triangles) == real
        # the triangulation of the points inserted so far is Delaunay
        sub = sorted(inserted)
        local = {v: j for j, v in enumerate(sub)}
        ok, msg = check_delaunay(pts[sub], [[local[v] for v in t] for t in real])
        assert ok, f"after inserting point {i}: {msg}"
    assert as_set(steps[-1].triangles) == as_set(result)


@pytest.mark.parametrize("name", list(TRACE_SETS))
@pytest.mark.parametrize("order", ["canonical", "input"])
def test_trace_is_consistent(name, order):
    points = TRACE_SETS[name]
    steps, result = traced(points, order=order)
    assert check_delaunay(points, result) == (True, "ok")
    check_trace(points, steps, result)


@pytest.mark.parametrize("name", ["tutorial", "grid", "integer-circle", "collinear-start", "duplicates"])
def test_scan_finds_the_same_steps_as_the_walk(name):
    points = TRACE_SETS[name]
    walk, r1 = traced(points)
    scan, r2 = traced(points, locate="scan")
    assert np.array_equal(r1, r2)
    for s, t in zip(walk, scan):
        assert s.index == t.index and set(s.bad) == set(t.bad)
        # (on an edge, the point is in two triangles: the walk and the scan may name different ones)
        assert (s.located is None) == (t.located is None)
        assert set(s.boundary) == set(t.boundary) and np.array_equal(s.triangles, t.triangles)
    check_trace(points, scan, r2)


def test_walked_counts_the_triangles_the_walk_stood_on():
    """Step.walked: 0 for the scan and the first three points; with the walk, at least 1, and the
    walk from the previous point's triangle is short in a curve order and long in a random one."""
    pts = uniform(400, seed=3)
    scan = []
    bowyer_watson(pts, locate="scan", order="input", trace=scan, snapshots=False)
    assert all(s.walked == 0 for s in scan)
    walks = {}
    for order in ("input", "canonical"):          # the points' own (random) order, and BRIO
        steps = []
        bowyer_watson(pts, locate="walk", order=order, trace=steps, snapshots=False)
        assert all(s.walked == 0 for s in steps[:3]) and all(s.walked >= 1 for s in steps[3:])
        walks[order] = np.mean([s.walked for s in steps[3:]])
    assert walks["canonical"] < 6 and walks["input"] > 2 * 6


def test_the_tutorials_mistake_1_is_latent_until_the_super_triangle_is_clockwise():
    only_1 = ["predicate", "boundary"]
    rand = random.Random(4)
    for _ in range(100):
        q = [(float(rand.randint(-50, 50)), float(rand.randint(-50, 50))) for _ in range(rand.randint(3, 12))]
        assert check_delaunay(q, naive_bowyer_watson(q, fix=only_1))[0]
    clockwise = SUPER_TRIANGLE[::-1]
    pts = EXHIBITS["clockwise"]
    assert naive_bowyer_watson(pts, fix=only_1, super_triangle=clockwise).shape == (0, 3)
    assert check_delaunay(pts, naive_bowyer_watson(pts, fix=ALL_FIXES, super_triangle=clockwise)) == (True, "ok")


def test_collinear_start_inserts_the_first_point_off_the_line_third():
    pts = TRACE_SETS["collinear-start"]
    assert insertion_order(pts, order="input") == [0, 1, 4, 2, 3, 5]
    steps, _ = traced(pts, order="input")
    assert [s.index for s in steps] == [0, 1, 4, 2, 3, 5]
    assert steps[3].located is None          # (2, 0) is on the line of hull edge 0-1, outside it


def test_point_on_a_hull_edge_conflicts_with_its_ghost():
    pts = [(0, 0), (2, 0), (1, 2), (1, 0)]
    steps, result = traced(pts, order="input")
    last = steps[-1]
    assert last.located is not None and INFINITE not in last.located
    assert any(INFINITE in t for t in last.bad)    # the ghost outside edge 0-1 is bad too
    assert as_set(result) == {(0, 3, 2), (1, 2, 3)}


def test_no_trace_records_without_triangles():
    for pts in ([], [(1, 2)], [(0, 0), (1, 1), (2, 2)], [(1, 1)] * 4):
        steps, result = traced(pts)
        assert steps == [] and result.shape == (0, 3) and result.dtype == np.int64


def test_results_do_not_depend_on_input_order():
    rng = np.random.default_rng(3)
    for pts in (grid(5), integer_circle(), with_duplicates(30, seed=1), circle(16, centre=True)):
        base = bowyer_watson(pts)
        first = {}
        for i, p in enumerate(map(tuple, pts.tolist())):
            first.setdefault(p, i)
        rep = np.array([first[tuple(p)] for p in pts.tolist()])
        for _ in range(3):
            perm = rng.permutation(len(pts))
            again = bowyer_watson(pts[perm])
            assert as_set(rep[perm[again]]) == as_set(base)


def test_scaled_copies_have_the_same_triangles():
    base = as_set(bowyer_watson(TRACE_SETS["uniform"]))
    for scale in (1e-300, 2.0 ** -1000, 1e300, 2.0 ** 1000):
        assert as_set(bowyer_watson(TRACE_SETS["uniform"] * scale)) == base


def test_output_format():
    result = bowyer_watson(uniform(30, seed=8))
    assert result.dtype == np.int64 and result.shape[1] == 3
    assert result.tolist() == sorted(result.tolist())            # rows sorted
    assert all(t[0] == min(t) for t in result.tolist())           # each starts at its smallest index


# ----------------------------------------------------------------------------- the dry run
def test_tutorial_result_matches_a_fraction_brute_force():
    by_hand = {(0, 2, 1), (1, 2, 3), (0, 1, 3)}   # (3, 2) is inside triangle (1, 1), (5, 1), (4, 4)
    assert {min(rotations(t)) for t in by_hand} == fraction_delaunay(TUTORIAL_POINTS)
    for order in ("canonical", "input"):
        assert as_set(bowyer_watson(TUTORIAL_POINTS, order=order)) == fraction_delaunay(TUTORIAL_POINTS)


def test_dry_run_text_for_the_tutorial_points():
    text = dry_run()
    lines = text.splitlines()
    assert lines[0] == "Bowyer-Watson dry run on 4 points: 0: (1, 1), 1: (3, 2), 2: (5, 1), 3: (4, 4)"
    assert "Insertion order (as given, duplicates dropped): 0, 1, 2, 3" in lines
    summaries = [line for line in lines if line.startswith("Step ")]
    assert summaries == [
        "Step 1 (point 0). insert (1, 1): first point, no triangle yet",
        "Step 2 (point 1). insert (3, 2): second point, no triangle yet: the line through the first "
        "two points splits the plane into 2 ghost triangles",
        "Step 3 (point 2). insert (5, 1): 1 bad triangle, cavity boundary of 3 edges, 3 new triangles",
        "Step 4 (point 3). insert (4, 4): 2 bad triangles, cavity boundary of 4 edges, 4 new triangles",
    ]
    assert "   bad triangles (circumcircle contains the point): (0, 1, inf), (1, 2, inf)" in lines
    assert "   cavity boundary (counter-clockwise): 0->1, 1->2, 2->inf, inf->0" in lines
    assert "   new triangles: (0, 1, 3), (1, 2, 3), (3, 2, inf), (0, 3, inf)" in lines
    assert lines[-1] == "Result: 3 triangles: (0, 1, 3), (0, 2, 1), (1, 2, 3)"
    # the result line is the Fraction brute force
    printed = re.findall(r"\((\d+), (\d+), (\d+)\)", lines[-1])
    assert {min(rotations(tuple(map(int, t)))) for t in printed} == fraction_delaunay(TUTORIAL_POINTS)


def test_dry_run_canonical_order_and_flat_input():
    last = dry_run(order="canonical").splitlines()[-1]
    assert last == "Result: 3 triangles: (0, 1, 3), (0, 2, 1), (1, 2, 3)"
    flat = dry_run([(0, 0), (1, 1), (2, 2)])
    assert "none: no triangle is possible" in flat and flat.endswith("Result: 0 triangles")


def test_step_str():
    empty = np.zeros((0, 3), dtype=np.int64)
    s = Step(3, (4.0, 4.0), None, [(1, 2, -1), (0, 1, -1)], [(1, 2), (2, -1), (-1, 0), (0, 1)],
             [(1, 2, 3), (3, 2, -1), (0, 3, -1), (0, 1, 3)], empty)
    assert str(s) == "insert (4, 4): 2 bad triangles, cavity boundary of 4 edges, 4 new triangles"
    one = Step(1, (0.5, 1e300), (0, 2, 3), [(0, 2, 3)], [(0, 2), (2, 3), (3, 0)],
               [(0, 2, 1), (2, 3, 1), (3, 0, 1)], empty)
    assert str(one) == "insert (0.5, 1e+300): 1 bad triangle, cavity boundary of 3 edges, 3 new triangles"
    with pytest.raises(AttributeError):
        s.index = 4  # frozen


def test_cavity_boundary_drops_shared_edges_entirely():
    bad = [(0, 1, 2), (2, 1, 3), (2, 3, 4)]
    assert cavity_boundary(bad) == [(0, 1), (1, 3), (3, 4), (4, 2), (2, 0)]
    assert cavity_boundary([]) == []
    # the tutorial keeps one copy of each shared edge (1-2 and 2-3)
    kept = tutorial_boundary(bad)
    assert (1, 2) in kept and (3, 2) in kept and len(kept) == 7


# ----------------------------------------------------------------------------- the tutorial's bugs
@pytest.mark.parametrize("name", list(EXHIBITS))
def test_naive_version_fails_where_bowyer_watson_passes(name):
    pts = EXHIBITS[name]
    ok, msg = check_delaunay(pts, naive_bowyer_watson(pts))
    assert not ok, msg
    assert check_delaunay(pts, bowyer_watson(pts)) == (True, "ok")
    if name not in ("square", "cocircular"):  # these have ties: several valid answers
        assert as_set(bowyer_watson(pts)) == fraction_delaunay(pts)


def test_each_exhibit_fails_for_the_stated_reason():
    def check(name, fix=()):
        pts = EXHIBITS[name]
        return check_delaunay(pts, naive_bowyer_watson(pts, fix=fix))

    # cavity boundary: fixing it alone cures these
    for name in ("overlap", "square", "clockwise", "zero-area"):
        assert not check(name)[0]
        assert check(name, fix=["boundary"]) == (True, "ok")
    assert "clockwise" in check("clockwise")[1] and "zero area" in check("zero-area")[1]
    # the floating determinant: orientation and boundary fixed is not enough, the exact predicate is
    orders = [random.Random(seed).sample(RING_25, 12) for seed in range(10)]  # BLAS decides which break
    assert any(not check_delaunay(q, naive_bowyer_watson(q, fix=["orientation", "boundary"]))[0] for q in orders)
    assert all(check_delaunay(q, naive_bowyer_watson(q, fix=ALL_FIXES))[0] for q in orders)
    assert check("cocircular", fix=ALL_FIXES) == (True, "ok")
    # the finite super-triangle: nothing but the vertex at infinity cures these
    assert naive_bowyer_watson(EXHIBITS["large"], fix=ALL_FIXES).shape == (0, 3)
    lost = naive_bowyer_watson(EXHIBITS["hull-lost"], fix=ALL_FIXES)
    assert as_set(lost) == {(0, 1, 3), (1, 2, 3)}                   # (0, 2, 1) is missing
    assert as_set(bowyer_watson(EXHIBITS["hull-lost"])) == {(0, 1, 3), (1, 2, 3), (0, 2, 1)}


def test_predicate_level_bugs():
    assert det_in_circumcircle([(0, 0), (2, 0), (0, 2)], (1, 1))
    assert not det_in_circumcircle([(0, 0), (0, 2), (2, 0)], (1, 1))   # clockwise: sign flipped
    quads = list(itertools.combinations(RING_25, 4))
    assert all(incircle(*q) == 0 for q in quads)                        # every quadruple is a tie...
    assert any(tutorial_det(q[:3], q[3]) != 0 for q in quads)          # ...that det does not always see
    assert epsilon_says_degenerate((0, 0), (0, 1e-6), (2e-6, 0))         # a valid triangle
    assert bowyer_watson([(0, 0), (0, 1e-6), (2e-6, 0)]).shape == (1, 3)


# ----------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("bad, message", [
    ([(0, 0), (1, float("nan")), (2, 0)], r"points\[1\] = \[1.0, nan\] is not finite"),
    ([(0, 0), (float("inf"), 1)], r"points\[1\] .* not finite"),
    ([(0, 0, 0), (1, 1, 1)], r"shape \(n, 2\), got \(2, 3\)"),
    ([1.0, 2.0, 3.0], r"shape \(n, 2\), got \(3,\)"),
    ("0 0 1 1 2 0", r"got text"),
    ([("a", "b"), ("c", "d")], r"must contain numbers"),
    ([(0, 0), (1,), (2, 2)], r"\(n, 2\) array of numbers"),
])
def test_bad_points_raise_value_error(bad, message):
    with pytest.raises(ValueError, match=message):
        bowyer_watson(bad)
    with pytest.raises(ValueError, match=message):
        naive_bowyer_watson(bad)


def test_bad_options_raise_value_error():
    pts = TUTORIAL_POINTS
    with pytest.raises(ValueError, match="trace must be a list"):
        bowyer_watson(pts, trace=())
    with pytest.raises(ValueError, match="locate must be 'walk' or 'scan'"):
        bowyer_watson(pts, locate="kd-tree")
    with pytest.raises(ValueError, match="order must be 'canonical' or 'input'"):
        bowyer_watson(pts, order="random")
    with pytest.raises(ValueError, match="unknown fix 'super'"):
        naive_bowyer_watson(pts, fix=["super"])


def test_trace_without_snapshots_has_the_same_counts_and_no_copies():
    pts = np.random.default_rng(4).random((80, 2))
    full, light = [], []
    bowyer_watson(pts, trace=full, locate="walk")
    bowyer_watson(pts, trace=light, locate="walk", snapshots=False)
    assert [(s.index, s.bad, s.boundary, s.new) for s in full] == [(s.index, s.bad, s.boundary, s.new) for s in light]
    assert all(len(s.triangles) == 0 for s in light)


def test_recursive_version_matches_until_the_recursion_limit():
    import sys

    from reference_impl.teaching.bowyer_watson import recursive_bowyer_watson

    pts = np.random.default_rng(6).random((300, 2))
    assert recursive_bowyer_watson(pts).tolist() == bowyer_watson(pts).tolist()
    deep = np.random.default_rng(7).random((sys.getrecursionlimit() + 50, 2))
    with pytest.raises(RecursionError):
        recursive_bowyer_watson(deep)
    assert len(bowyer_watson(deep, locate="walk")) > 0


def test_tutorial_log_shows_the_kept_shared_edge():
    from reference_impl.teaching.tutorial_bugs import ALL_FIXES, EXHIBITS, naive_bowyer_watson

    broken, fixed = [], []
    naive_bowyer_watson(EXHIBITS["overlap"], log=broken)
    naive_bowyer_watson(EXHIBITS["overlap"], fix=ALL_FIXES, log=fixed)
    assert broken[0] == fixed[0] and broken[1] != fixed[1]
    assert "S2->0" in broken[1] and "S2->0" not in fixed[1]
