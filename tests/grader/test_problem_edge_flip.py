"""The `edge-flip` package: the checker replays flips exactly (agreeing step by step with the
library's ``apply_flips``), accepts every legal order, rejects each kind of wrong flip, and the
input validator accepts exactly the valid triangulations.

Run: .venv/bin/python -m pytest tests/grader/test_problem_edge_flip.py -q
"""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from grader.contest.kattis import embed_checker
from grader.problems import load_problem
from reference_impl import apply_flips
from reference_impl.exact.verify import brute_force_empty_circles

from .conftest import REPO

PROBLEM = load_problem("edge-flip")
CHK = PROBLEM.checker
GEN = PROBLEM.generator
VALIDATOR = PROBLEM.path / "input_validators" / "validate_triangulation" / "validate_triangulation.py"
QUAD = [[[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 3.0]], [[0, 1, 3], [1, 2, 3]]]
SQUARE = [[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]], [[0, 1, 2], [0, 2, 3]]]
FAN = [[[0.0, 1.0], [2.0, 0.0], [6.0, 0.0], [8.0, 1.0], [6.0, 2.0], [2.0, 2.0]],
       [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]]]


def canon(tris) -> set:
    out = set()
    for t in tris:
        t = list(t)
        k = t.index(min(t))
        out.add(tuple(t[k:] + t[:k]))
    return out


def validator_accepts(args) -> bool:
    r = subprocess.run([sys.executable, str(VALIDATOR)], input=CHK.write_input(args), text=True, capture_output=True)
    assert r.returncode in (42, 43), r.stderr
    return r.returncode == 42


# ----------------------------------------------------------------------------- accepts
def test_every_legal_order_is_accepted():
    assert CHK.check(QUAD, [[1, 3]], None) == (True, "ok")
    assert CHK.check(QUAD, [[3, 1]], None) == (True, "ok")            # either order of the ends
    for order in ([[0, 3], [0, 4], [0, 2]], [[0, 3], [0, 2], [0, 4]]):
        assert CHK.check(FAN, order, None) == (True, "ok"), order
    assert CHK.check(SQUARE, [], None) == (True, "ok")


def test_reference_answers_pass_and_finals_match_the_library():
    for t in PROBLEM.tests():
        if t.group in ("large",):
            continue
        args = CHK.read_input(t.input_text)
        flips = CHK.read_output(t.answer_text, args)
        final, msg = CHK.replay(*args, flips)
        assert final is not None, (t.name, msg)
        assert CHK.check(args, flips, None)[0], t.name
        if args[1]:
            assert canon(final) == canon(apply_flips(args[0], args[1], flips).tolist()), t.name
        if len(args[0]) <= 40:
            assert brute_force_empty_circles(args[0], final)[0], t.name


def test_duplicate_indices_name_the_same_point():
    pts, tris = QUAD
    doubled = [pts + pts, tris]            # index i + 4 repeats point i
    assert CHK.check(doubled, [[5, 7]], None) == (True, "ok")


# ----------------------------------------------------------------------------- rejects
@pytest.mark.parametrize("args,flips,words", [
    (QUAD, [], "not Delaunay"),
    (SQUARE, [[0, 2]], "already locally Delaunay (point 1 is on the circumcircle"),
    (QUAD, [[1, 3], [0, 2]], "already locally Delaunay"),                 # flipping back
    (QUAD, [[0, 1]], "convex hull edge"),
    (QUAD, [[0, 2]], "not an edge"),
    (QUAD, [[1, 9]], "outside 0..3"),
    (FAN, [[0, 3], [0, 4]], "not Delaunay"),                              # one flip short
])
def test_rejects_each_kind_of_wrong_answer(args, flips, words):
    ok, msg = CHK.check(args, flips, None)
    assert not ok and words in msg, msg
    assert "points:" in msg                                               # small inputs are quoted


def test_answer_shape_and_size_are_checked_before_any_geometry():
    assert CHK.from_result([[1, 3]], QUAD) == [[1, 3]]
    for bad in ([[1.0, 3]], [[1, 3, 0]], [[True, 3]], "13", None, [[1, 3]] * 7):
        with pytest.raises(CHK.PresentationError):
            CHK.from_result(bad, QUAD)
    with pytest.raises(CHK.PresentationError):
        CHK.read_output("7\n" + "1 3\n" * 7, QUAD)
    assert CHK.read_output(CHK.write_output([[1, 3]]), QUAD) == [[1, 3]]
    assert CHK.read_input(CHK.write_input(FAN)) == FAN


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10 ** 6), st.sampled_from(["uniform", "grid", "duplicates", "circle"]),
       st.lists(st.integers(0, 10 ** 6), min_size=1, max_size=12))
def test_replay_agrees_with_the_library_step_by_step(seed, kind, picks):
    """Random flip sequences (any edge, legal or not): the checker stops at the same flip as
    ``reference_impl.apply_flips`` and ends with the same triangles; it accepts exactly when the
    final triangulation has empty circles (brute force)."""
    case = {"kind": kind, "n": 9, "w": 3, "h": 3, "repeats": 4}
    pts, tris = GEN.generate_args(case, seed)
    if not tris:
        return
    edges = sorted({tuple(sorted((t[i], t[(i + 1) % 3]))) for t in tris for i in range(3)})
    legal = [list(e) for e in edges]
    flips = [legal[p % len(legal)] for p in picks]
    final, msg = CHK.replay(pts, tris, flips)
    for cut in range(len(flips), -1, -1):          # the longest prefix the library accepts
        try:
            ref = apply_flips(pts, tris, flips[:cut])
            break
        except ValueError as exc:
            ref_error = str(exc)
    if final is not None:
        assert cut == len(flips)
        assert canon(final) == canon(ref.tolist())
        assert CHK.check([pts, tris], flips, None)[0] == brute_force_empty_circles(pts, final)[0]
    else:
        assert cut < len(flips), msg
        assert msg.split(":")[0].split(" is ")[0] == f"flip {cut} = {flips[cut]}".replace("(", "[").replace(")", "]")
        assert ref_error


# ----------------------------------------------------------------------------- input validator
def test_input_validator_rejects_broken_triangulations():
    pts = QUAD[0]
    assert validator_accepts(QUAD)
    for tris in ([[0, 3, 1], [1, 2, 3]],               # clockwise
                 [[0, 1, 3]],                          # a point left out
                 [[0, 1, 3], [1, 2, 3], [1, 2, 3]],    # a repeated triangle
                 [[0, 1, 2], [0, 1, 3]],               # overlapping
                 []):                                  # nothing, but not collinear
        assert not validator_accepts([pts, tris]), tris
    notch = [[0.0, 0.0], [4.0, 0.0], [2.0, 1.0], [2.0, 3.0]]   # boundary with a reflex corner
    assert not validator_accepts([notch, [[0, 1, 2], [0, 2, 3]]])
    assert validator_accepts([[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]], []])


def test_kattis_output_validator_exit_codes(tmp_path):
    exported = tmp_path / "checker.py"
    exported.write_text(embed_checker(PROBLEM))
    (tmp_path / "in").write_text(CHK.write_input(QUAD))
    (tmp_path / "ans").write_text("1\n1 3\n")
    for team, code, words in (("1\n3 1\n", 42, "ok"), ("0\n", 43, "not Delaunay"), ("x\n", 43, "presentation")):
        r = subprocess.run([sys.executable, "-I", str(exported), str(tmp_path / "in"), str(tmp_path / "ans"),
                            str(tmp_path)], input=team, text=True, capture_output=True)
        assert r.returncode == code, r.stderr
        assert words in (tmp_path / "judgemessage.txt").read_text()


def test_solutions_run_as_programs_on_the_samples():
    for f in sorted((PROBLEM.path / "data" / "sample").glob("*.in")):
        args = CHK.read_input(f.read_text())
        r = subprocess.run([sys.executable, str(REPO / "solutions" / "edge-flip" / "accepted_lawson.py")],
                           input=f.read_text(), text=True, capture_output=True, timeout=60)
        assert CHK.check(args, CHK.read_output(r.stdout, args), None)[0], f.name


def test_generated_starts_are_far_from_delaunay():
    """The large tests need many flips, and the strip a quadratic number (the worst case)."""
    pts, tris = GEN.generate_args({"kind": "strip", "n": 40}, 0)
    assert len(GEN.solve(pts, tris)) >= (20 * 19) // 2 - 20
    assert np.isfinite(np.asarray(pts)).all()
