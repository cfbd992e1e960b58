"""The `delaunay-3d` package: its exact checker accepts every valid answer (ties included) and
rejects each kind of wrong one; oracles: Qhull in general position, brute-force empty spheres,
the hull volume from Qhull's facets.

Run: .venv/bin/python -m pytest tests/grader/test_problem_delaunay_3d.py -q
"""
from __future__ import annotations

import itertools
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy.spatial import ConvexHull, Delaunay as QhullDelaunay

from grader.contest.kattis import embed_checker
from grader.problems import load_problem
from reference_impl import delaunay_3d
from reference_impl.exact.verify import brute_force_empty_spheres, exact_coordinates_3d, orient3d_exact

from .conftest import REPO

PROBLEM = load_problem("delaunay-3d")
CHK = PROBLEM.checker
CUBE = [[float(x), float(y), float(z)] for x in (0, 1) for y in (0, 1) for z in (0, 1)]   # index 4x + 2y + z
FIVE = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.875, 0.875, 0.875]]


def check(points, tets):
    return CHK.check([points], [list(map(int, t)) for t in tets], None)


def cube_triangulations() -> list[list[tuple[int, ...]]]:
    """Different triangulations of the cube (all Delaunay: its 8 corners are cospherical): the
    six-tetrahedra fan around each of the 4 long diagonals, and the two five-tetrahedra ones."""
    out = []
    for a in range(8):
        b = 7 - a
        if a > b:
            continue
        path_tets = []
        for perm in itertools.permutations(range(3)):
            v, chain = a, [a]
            for axis in perm:
                v ^= 1 << (2 - axis)
                chain.append(v)
            path_tets.append(tuple(chain))
        assert all(t[-1] == b for t in path_tets)
        out.append(path_tets)
    for even in (True, False):       # corners of one parity form a regular tetrahedron
        corners = [i for i in range(8) if (bin(i).count("1") % 2 == 0) == even]
        cut = [tuple([c] + [c ^ 1, c ^ 2, c ^ 4]) for c in range(8) if c not in corners]
        out.append([tuple(corners)] + cut)
    return out


def hull_volume6(points) -> int:
    """6 x the hull volume, exactly, from Qhull's facets (checked to be supporting)."""
    P = exact_coordinates_3d(points)
    hull = ConvexHull(np.asarray(points, dtype=float))
    inner = tuple(sum(P[i][k] for i in hull.vertices[:4]) for k in range(3))
    P4 = [tuple(4 * v for v in p) for p in P]
    total = 0
    for f in hull.simplices:
        a, b, c = (P4[i] for i in f)
        d = [(p[0] - inner[0], p[1] - inner[1], p[2] - inner[2]) for p in (a, b, c)]
        det = (d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0])
               + d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]))
        total += abs(det)
    return total // 64


def volume6(points, tets) -> int:
    P = exact_coordinates_3d(points)
    tot = 0
    for t in tets:
        a, b, c, d = (P[v] for v in t)
        r = [(p[0] - d[0], p[1] - d[1], p[2] - d[2]) for p in (a, b, c)]
        tot += abs(r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0])
                   + r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]))
    return tot


# ----------------------------------------------------------------------------- accepts
def test_every_triangulation_of_the_cube_is_accepted():
    tris = cube_triangulations()
    assert len(tris) == 6
    for tets in tris:
        assert check(CUBE, tets) == (True, "ok"), tets
        assert brute_force_empty_spheres(CUBE, tets)[0]
        assert volume6(CUBE, tets) == 6


def test_either_orientation_and_any_duplicate_index():
    tets = delaunay_3d(np.array(FIVE)).tolist()
    assert check(FIVE, tets)[0]
    assert check(FIVE, [[b, a, c, d] for a, b, c, d in tets])[0]
    doubled = FIVE + FIVE                                      # index i + 5 repeats point i
    mixed = [[v + 5 if (k + v) % 2 else v for v in t] for k, t in enumerate(tets)]
    assert check(doubled, mixed)[0]


def test_qhull_agrees_in_general_position():
    pts = np.random.default_rng(3).random((300, 3))
    assert check(pts.tolist(), QhullDelaunay(pts).simplices.tolist())[0]
    assert check(pts.tolist(), delaunay_3d(pts).tolist())[0]


def test_reference_answer_of_every_generated_test_passes():
    for t in PROBLEM.tests():
        if t.group in ("sample", "tiny", "degenerate"):
            args = CHK.read_input(t.input_text)
            ok, msg = CHK.check(args, CHK.read_output(t.answer_text, args), None)
            assert ok, (t.name, msg)


# ----------------------------------------------------------------------------- rejects
def test_rejects_each_kind_of_wrong_answer():
    grid = [[float(x), float(y), float(z)] for x in range(3) for y in range(3) for z in range(3)]
    tets = delaunay_3d(np.array(grid)).tolist()
    assert check(grid, tets)[0]
    cases = {
        "a hole": (tets[1:], "gaps"),
        "an overlap (a repeated tetrahedron)": (tets + tets[:1], "more than two"),
        "a flat tetrahedron": (tets[1:] + [[0, 1, 2, 2]], "flat"),
        "an index out of range": (tets[:-1] + [[0, 1, 2, 99]], "outside 0..26"),
        "nothing": ([], "not coplanar"),
    }
    for what, (answer, words) in cases.items():
        ok, msg = check(grid, answer)
        assert not ok and words in msg, (what, msg)
    # every other tetrahedron: a checkerboard of gaps, rejected by the hull-size bound before the
    # O(faces x vertices) hull test
    big = [[float(x), float(y), float(z)] for x in range(5) for y in range(5) for z in range(5)]
    sparse = delaunay_3d(np.array(big)).tolist()[::2]
    ok, msg = check(big, sparse)
    assert not ok and "more than a convex hull" in msg, msg
    # the two-tetrahedra split of sample 2 tiles the hull but is not Delaunay
    ok, msg = check(FIVE, [[0, 1, 2, 3], [4, 1, 2, 3]])
    assert not ok and "not Delaunay" in msg and "point" in msg
    assert not brute_force_empty_spheres(FIVE, [[0, 1, 2, 3], [4, 2, 1, 3]])[0]
    # a point left out: the tetrahedron 0123 alone
    ok, msg = check(FIVE, [[0, 1, 2, 3]])
    assert not ok and "not a vertex" in msg
    # coplanar points have no tetrahedra
    flat = [[0.0, 0.0, 0.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0], [1.0, 1.0, 2.0]]
    assert check(flat, []) == (True, "ok")
    assert not check(flat, [[0, 1, 2, 3]])[0]


def test_two_overlapping_tilings_of_the_same_size_are_rejected():
    """Half of one cube triangulation plus half of another has the right count and volume
    but tetrahedra that cross: the checker must see it."""
    a, b = cube_triangulations()[0], cube_triangulations()[1]
    mixed = a[:3] + b[3:]
    if volume6(CUBE, mixed) == 6:
        assert not check(CUBE, mixed)[0]
    assert not check(CUBE, a + b[:1])[0]


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 2), st.integers(0, 2), st.integers(0, 2)), min_size=4, max_size=14),
       st.integers(0, 10 ** 6))
def test_checker_agrees_with_brute_force_and_hull_volume(raw, seed):
    """On small degenerate integer sets: the reference answer passes; so does a 'random flip' of
    it exactly when it is still a tiling with empty spheres (brute force + Qhull volume)."""
    pts = [list(map(float, p)) for p in raw]
    tets = delaunay_3d(np.array(pts)).tolist()
    ok, msg = check(pts, tets)
    assert ok, msg
    if not tets:
        return
    assert brute_force_empty_spheres(pts, tets)[0]
    assert volume6(pts, tets) == hull_volume6(pts)
    rng = np.random.default_rng(seed)
    broken = [list(t) for t in tets]
    k, slot = int(rng.integers(len(broken))), int(rng.integers(4))
    broken[k][slot] = int(rng.integers(len(pts)))                   # move one vertex
    P = exact_coordinates_3d(pts)
    if orient3d_exact(*(P[v] for v in broken[k])) == 0 or P[broken[k][slot]] == P[tets[k][slot]]:
        return                                                      # flat (rejected elsewhere) or the same point
    valid = (volume6(pts, broken) == hull_volume6(pts) and brute_force_empty_spheres(pts, broken)[0]
             and {v for t in broken for v in t} >= set(range(len(pts))) - set(dup_indices(P)))
    if not valid:
        assert not check(pts, broken)[0], broken


def dup_indices(P) -> list[int]:
    first = {}
    return [i for i, p in enumerate(P) if first.setdefault(p, i) != i]


# ----------------------------------------------------------------------------- formats
def test_from_result_types_strictly():
    args = [FIVE]
    assert CHK.from_result([[0, 1, 2, 3]], args) == [[0, 1, 2, 3]]
    for bad in ([[0.0, 1, 2, 3]], [[0, 1, 2]], "0123", [[True, 1, 2, 3]], None, [[0, 1, 2, "3"]],
                [[0, 1, 2, 3]] * 10):
        with pytest.raises(CHK.PresentationError):
            CHK.from_result(bad, args)


def test_text_formats_round_trip():
    args = [FIVE]
    assert CHK.read_input(CHK.write_input(args)) == args
    tets = [[0, 3, 2, 4], [0, 4, 2, 1]]
    assert CHK.read_output(CHK.write_output(tets), args) == tets
    for bad in ("", "2\n0 1 2 3\n", "1\n0 1 2\n", "1\n0 1 2 x\n", "x\n"):
        with pytest.raises(CHK.PresentationError):
            CHK.read_output(bad, args)


def test_kattis_output_validator_exit_codes(tmp_path):
    """The exported, self-contained checker (verify.py embedded) as problemtools runs it."""
    exported = tmp_path / "checker.py"
    exported.write_text(embed_checker(PROBLEM))
    inp = tmp_path / "in"
    inp.write_text(CHK.write_input([FIVE]))
    ans = tmp_path / "ans"
    ans.write_text("3\n0 3 2 4\n0 4 2 1\n0 3 4 1\n")
    for team, code, words in (("3\n0 2 3 4\n0 1 2 4\n0 3 4 1\n", 42, "ok"),
                              ("2\n0 1 2 3\n4 1 2 3\n", 43, "not Delaunay"),
                              ("three\n", 43, "presentation error")):
        r = subprocess.run([sys.executable, "-I", str(exported), str(inp), str(ans), str(tmp_path)],
                           input=team, text=True, capture_output=True)
        assert r.returncode == code, r.stderr
        assert words in (tmp_path / "judgemessage.txt").read_text()


def test_solutions_run_as_programs_on_the_sample():
    text = (PROBLEM.path / "data" / "sample" / "2-five-points.in").read_text()
    for name in ("accepted_bw3d.py", "too_slow_scan.py"):
        r = subprocess.run([sys.executable, str(REPO / "solutions" / "delaunay-3d" / name)], input=text,
                           text=True, capture_output=True, timeout=60)
        tets = CHK.read_output(r.stdout, [FIVE])
        assert CHK.check([FIVE], tets, None)[0], (name, r.stdout)
