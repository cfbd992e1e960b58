"""The "circles" problems (obstacle-clearance, largest-empty-circle, voronoi): their packages
round-trip every test, and their checkers accept every valid answer (within the stated
tolerance) and reject each kind of wrong one with a useful message; exact oracles where the
checker relies on its own geometry (convex hull against scipy, emptiness by brute force).

Run: .venv/bin/python -m pytest tests/grader/test_problem_circles.py -q
"""
from __future__ import annotations

import math
import random
import subprocess
import sys

import pytest

from grader.problems import load_problem

CIRCLES = ["obstacle-clearance", "largest-empty-circle", "voronoi"]


def _problem(pid):
    return load_problem(pid)  # all three are built: a missing one fails, it is not skipped


@pytest.fixture(scope="module", params=CIRCLES)
def problem(request):
    return _problem(request.param)


def test_package_is_sound(problem):
    # the protocol round trips on every test are checked by `validate` (tests/grader/test_problems.py)
    assert problem.validate() == []
    assert {"sample", "tiny", "degenerate", "medium", "large"} <= {g.name for g in problem.groups}


def test_input_validator_accepts_every_test_and_rejects_garbage(problem):
    assert problem.validate_inputs() == []
    found = sorted((problem.path / "input_validators").rglob("*.py"))
    validator = next((v for v in found if v.name == "main.py"), found[0])   # main.py of a directory validator
    for bad in ("", "2\n0 0\n", "x\n", "1\n0 nan\n0 0\n0 0\n", "3\n0 0\n1 1\n2 2\n0 0 1 1\n"):
        r = subprocess.run([sys.executable, str(validator)], input=bad, text=True, capture_output=True)
        assert r.returncode == 43, (bad, r.stderr)


# ----------------------------------------------------------------------------- obstacle-clearance
def test_clearance_tolerance_and_infinity():
    chk = _problem("obstacle-clearance").checker
    args = [[[0.0, 0.0], [2.0, 0.0]], [1.0, 1.0], [1.0, -1.0]]
    assert chk.check(args, 1.0 + 5e-7, 1.0)[0]
    ok, msg = chk.check(args, 1.0 + 3e-6, 1.0)
    assert not ok and "too large" in msg
    ok, msg = chk.check(args, 0.99, 1.0)
    assert not ok and "too small" in msg
    none = [[], [0.0, 0.0], [1.0, 1.0]]
    assert chk.check(none, math.inf, math.inf) == (True, "ok")
    assert not chk.check(none, 1e308, math.inf)[0]
    assert not chk.check(args, math.inf, 1.0)[0]
    # absolute part: 1e-14 of the largest coordinate (coordinates near 1e9)
    far = [[[1e9, 1e9], [1e9 + 2, 1e9]], [1e9 + 1, 1e9 + 1], [1e9 + 1, 1e9 - 1]]
    assert chk.check(far, 1.0 + 1e-6 + 5e-6, 1.0)[0]
    assert not chk.check(far, 1.0 + 1e-6 + 2e-5, 1.0)[0]


def test_clearance_types_are_strict():
    chk = _problem("obstacle-clearance").checker
    assert chk.from_result(2, None) == 2.0 and chk.from_result(math.inf, None) == math.inf
    for bad in (True, "1.0", [1.0], None, math.nan, -1.0):
        with pytest.raises(chk.PresentationError):
            chk.from_result(bad, None)
    assert chk.read_output("inf\n", None) == math.inf
    for bad in ("", "1 2", "one", "nan", "-3"):
        with pytest.raises(chk.PresentationError):
            chk.read_output(bad, None)


def test_clearance_answers_are_critical_values():
    """The optimum is always a critical value: d(start), d(goal) or half the distance between two
    obstacles (brute force over all pairs), and never above d(start). (max_clearance itself is
    checked against a Voronoi-retraction oracle in the reference_impl tests.)"""
    from reference_impl import max_clearance

    rng = random.Random(4)
    for _ in range(30):
        pts = [[rng.random(), rng.random()] for _ in range(rng.randint(3, 12))]
        s, g = [rng.random(), rng.random()], [rng.uniform(-1, 2), rng.uniform(-1, 2)]
        r = max_clearance(pts, s, g)
        crit = [math.dist(p, s) for p in pts] + [math.dist(p, g) for p in pts]
        crit += [0.5 * math.dist(a, b) for a in pts for b in pts]
        assert min(abs(r - c) for c in crit) <= 1e-12
        assert r <= min(math.dist(p, s) for p in pts) + 1e-15


def test_clearance_kattis_validator_exit_codes(tmp_path):
    from grader.judging.checker_runtime import embed

    p = _problem("obstacle-clearance")
    (tmp_path / "checker.py").write_text(embed(p.checker_path.read_text()))
    (tmp_path / "in").write_text("4\n0 0\n2 0\n2 2\n0 2\n1 1\n5 1\n")
    (tmp_path / "ans").write_text("1.0\n")
    for team, code in (("1.0000001\n", 42), ("1.4142135623730951\n", 43), ("1 2\n", 43), ("\xff", 43)):
        r = subprocess.run([sys.executable, str(tmp_path / "checker.py"), str(tmp_path / "in"), str(tmp_path / "ans"),
                            str(tmp_path)], input=team.encode("latin-1"), capture_output=True)
        assert r.returncode == code, (team, (tmp_path / "judgemessage.txt").read_text())



# ----------------------------------------------------------------------------- largest-empty-circle
SQUARE = [[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]]
OPT = [2.0, 2.0, 8 ** 0.5]


def test_lec_accepts_any_optimal_circle_and_rejects_each_fault():
    chk = _problem("largest-empty-circle").checker
    obtuse = [[[0.0, 0.0], [4.0, 0.0], [2.0, 1.0]]]
    assert chk.check(obtuse, [1.25, 0.0, 1.25], [1.25, 0.0, 1.25]) == (True, "ok")
    assert chk.check(obtuse, [2.75, 0.0, 1.25], [1.25, 0.0, 1.25]) == (True, "ok")   # the other optimum
    assert chk.check(obtuse, [2.0, -1.5, 2.5], [1.25, 0.0, 1.25])[1].startswith("the centre (2.0, -1.5) is outside")
    assert chk.check(SQUARE, [2.0, 2.0, 8 ** 0.5 * (1 + 5e-7)], OPT)[0]                # within tolerance
    assert "strictly inside" in chk.check(SQUARE, [2.0, 2.0, 3.0], OPT)[1]
    assert "not the largest" in chk.check(SQUARE, [2.0, 2.0, 2.8], OPT)[1]
    assert "strictly inside" in chk.check(SQUARE, [2.1, 2.0, 8 ** 0.5], OPT)[1]
    # centre on the hull boundary (right angle) within a few ulps outside is fine
    right = [[[0.0, 0.0], [2.0, 0.0], [1.0, 1.0]]]
    assert chk.check(right, [1.0, -1e-16, 1.0], [1.0, 0.0, 1.0]) == (True, "ok")
    assert not chk.check(right, [1.0, -1e-3, 1.0], [1.0, 0.0, 1.0])[0]
    # huge and tiny scales: no overflow, no division by zero, a far centre is rejected
    for scale in (1e-300, 1e300):
        pts = [[[x * scale, y * scale] for x, y in SQUARE[0]]]
        assert chk.check(pts, [2 * scale, 2 * scale, 8 ** 0.5 * scale], [2 * scale, 2 * scale, 8 ** 0.5 * scale])[0]
        assert not chk.check(pts, [1e308, 1e308, 8 ** 0.5 * scale], [2 * scale, 2 * scale, 8 ** 0.5 * scale])[0]
    mixed = [[[0.0, 0.0], [1e-300, 0.0], [2e-300, 1e-300], [1e300, 0.0], [0.0, 1e300]]]
    assert isinstance(chk.check(mixed, [1e299, 1e299, 1e299], [1e299, 1e299, 1e299])[0], bool)


def test_lec_types_are_strict():
    chk = _problem("largest-empty-circle").checker
    assert chk.from_result([1, 2.5, 3], None) == [1.0, 2.5, 3.0]
    for bad in ([1.0, 2.0], (1.0, 2.0, 3.0), [1.0, 2.0, -1.0], [1.0, True, 2.0], [1.0, 2.0, math.inf],
                [1.0, 2.0, math.nan], "1 2 3", None, [[1.0], 2.0, 3.0]):
        with pytest.raises(chk.PresentationError):
            chk.from_result(bad, None)
    for bad in ("", "1 2", "1 2 3 4", "a b c", "1 2 -3", "nan 0 1"):
        with pytest.raises(chk.PresentationError):
            chk.read_output(bad, None)


def test_lec_hull_matches_scipy_and_reference_passes_brute_force_emptiness():
    """The checker's exact hull equals scipy's on random and duplicated sets; the reference answer
    is empty and no random empty circle centred in the hull beats it (brute force)."""
    from scipy.spatial import ConvexHull

    from reference_impl import largest_empty_circle

    chk = _problem("largest-empty-circle").checker
    rng = random.Random(8)
    for trial in range(25):
        pts = [[float(rng.randint(0, 20)), float(rng.randint(0, 20))] for _ in range(rng.randint(4, 30))]
        if trial % 2:
            pts = [[rng.random(), rng.random()] for _ in range(20)]
        hull = chk.convex_hull(pts)
        ref = ConvexHull(pts)
        assert {tuple(pts[i]) for i in hull} == {tuple(pts[i]) for i in ref.vertices}
        x, y, r = largest_empty_circle(pts)
        assert chk.check([pts], [x, y, r], [x, y, r]) == (True, "ok")
        hx = [pts[i] for i in hull]
        for _ in range(200):   # random centres in the hull: never a larger empty circle
            w = [rng.random() for _ in hx]
            c = [sum(wi * p[0] for wi, p in zip(w, hx)) / sum(w), sum(wi * p[1] for wi, p in zip(w, hx)) / sum(w)]
            assert min(math.dist(c, p) for p in pts) <= r + 1e-12


# ----------------------------------------------------------------------------- voronoi
TUT = [[[1.0, 1.0], [3.0, 2.0], [5.0, 1.0], [4.0, 4.0]], [0.0, 0.0, 6.0, 5.0]]


def _ref_cells(args):
    from reference_impl import voronoi

    return [c.tolist() for c in voronoi(*args)]


def test_voronoi_accepts_every_valid_way_to_write_a_cell():
    chk = _problem("voronoi").checker
    ref = _ref_cells(TUT)
    rotated = [c[1:] + c[:1] for c in ref]
    assert chk.check(TUT, rotated, ref) == (True, "ok")
    a, b = ref[3][0], ref[3][1]
    extra = [ref[0], ref[1], ref[2], [a, [0.5 * a[0] + 0.5 * b[0], 0.5 * a[1] + 0.5 * b[1]], b] + ref[3][2:] + [ref[3][-1]]]
    assert chk.check(TUT, extra, ref) == (True, "ok")          # a vertex in an edge's middle, a repeated one
    nudged = [[[x + 1e-12, y - 1e-12] for x, y in c] for c in ref]
    assert chk.check(TUT, nudged, ref) == (True, "ok")         # within eps = 1e-9 * 6


def test_voronoi_rejects_each_kind_of_wrong_cell():
    chk = _problem("voronoi").checker
    ref = _ref_cells(TUT)
    cw = [ref[0][::-1]] + ref[1:]
    assert "counter-clockwise" in chk.check(TUT, cw, ref)[1]
    big = [[[0.0, 0.0], [3.0, 0.0], [3.0, 5.0], [0.0, 5.0]]] + ref[1:]
    assert "is not in the cell of point 0" in chk.check(TUT, big, ref)[1]
    small = [ref[0][:3]] + ref[1:]                             # a corner cut off
    assert "misses the corner" in chk.check(TUT, small, ref)[1]
    outside = [[[x * 1.001, y * 1.001] for x, y in ref[3]] if i == 3 else c for i, c in enumerate(ref)]
    assert not chk.check(TUT, outside, ref)[0]
    twice = [ref[0] + ref[0]] + ref[1:]                        # winds around twice
    assert "winds around" in chk.check(TUT, twice, ref)[1]
    bowtie = [[ref[0][0], ref[0][2], ref[0][1], ref[0][3]]] + ref[1:]
    assert not chk.check(TUT, bowtie, ref)[0]


def test_voronoi_types_and_sizes_are_strict():
    chk = _problem("voronoi").checker
    ref = _ref_cells(TUT)
    assert chk.from_result(ref, TUT) == ref
    for bad in (ref[:3], ref + [ref[0]], "cells", None, [ref[0], ref[1], ref[2], [[1.0, 2.0, 3.0]]],
                [ref[0], ref[1], ref[2], [[True, 1.0], [2.0, 2.0], [0.0, 3.0]]],
                [ref[0], ref[1], ref[2], [[math.nan, 1.0], [2.0, 2.0], [0.0, 3.0]]],
                [ref[0], ref[1], ref[2], [[0.0, 0.0]] * (chk.max_vertices(4)[0] + 1)]):   # over the stated bound
        with pytest.raises(chk.PresentationError):
            chk.from_result(bad, TUT)
    for bad in ("", "3 0 0 1 0\n" * 4, "x\n" * 4, "1 0 0\n"):
        with pytest.raises(chk.PresentationError):
            chk.read_output(bad, TUT)


@pytest.mark.parametrize("scale,offset", [(1.0, 0.0), (1e-300, 0.0), (1e300, 0.0), (1.0, 1e9)])
def test_voronoi_reference_cells_are_right_by_brute_force(scale, offset):
    """Independent of the checker's tolerance logic: every reference cell vertex is (to float
    accuracy) no farther from its own site than from the nearest site, the areas tile the box, and
    an independent O(n^2) construction (the box cut by every bisector) passes the checker."""
    import importlib.util

    from grader.problems import REPO

    spec = importlib.util.spec_from_file_location("_slow_vor", REPO / "solutions/voronoi/slow_all_pairs.py")
    slow = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(slow)
    chk = _problem("voronoi").checker
    rng = random.Random(11)
    for _ in range(6):
        pts = [[offset + scale * rng.randint(0, 6), offset + scale * rng.randint(0, 6)] for _ in range(rng.randint(1, 14))]
        box = [offset - scale, offset - scale, offset + 7 * scale, offset + 8 * scale]
        args = [pts, box]
        ref = _ref_cells(args)
        assert chk.check(args, slow.voronoi_cells(pts, box), ref) == (True, "ok")
        unit = 1.0 / scale
        total = 0.0
        seen = set()
        for i, cell in enumerate(ref):
            for x, y in cell:
                own = math.hypot((x - pts[i][0]) * unit, (y - pts[i][1]) * unit)
                near = min(math.hypot((x - p[0]) * unit, (y - p[1]) * unit) for p in pts)
                assert own <= near + 1e-6
            if tuple(pts[i]) not in seen:
                seen.add(tuple(pts[i]))
                total += chk._area([[(x - offset) * unit, (y - offset) * unit] for x, y in cell])
        assert total == pytest.approx(8 * 9, rel=1e-9)


def test_voronoi_kattis_validator_exit_codes(tmp_path):
    from grader.judging.checker_runtime import embed

    p = _problem("voronoi")
    (tmp_path / "checker.py").write_text(embed(p.checker_path.read_text()))
    (tmp_path / "in").write_text((p.path / "data/sample/2-two-sites.in").read_text())
    (tmp_path / "ans").write_text((p.path / "data/sample/2-two-sites.ans").read_text())
    good = "4 1.0 -1.0 1.0 1.0 -1.0 1.0 -1.0 -1.0\n4 1.0 -1.0 3.0 -1.0 3.0 1.0 1.0 1.0\n"
    for team, code in ((good, 42), (good.replace("3.0 1.0 1.0 1.0", "3.0 1.0 1.2 1.0"), 43), ("1 0 0\n", 43)):
        r = subprocess.run([sys.executable, str(tmp_path / "checker.py"), str(tmp_path / "in"), str(tmp_path / "ans"),
                            str(tmp_path)], input=team.encode(), capture_output=True)
        assert r.returncode == code, (team, (tmp_path / "judgemessage.txt").read_text())

