"""The `proximity-network` checker: accepts exactly the Gabriel graph (brute force over all pairs
and points with Fractions as the oracle), in any edge order; rejects extra, missing, repeated and
non-canonical edges with a reason; the reference agrees with the oracle on degenerate sets.

Run: .venv/bin/python -m pytest tests/grader/test_problem_proximity_network.py -q
"""
from __future__ import annotations

import random
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from grader.problems import load_problem

P = load_problem("proximity-network")
CHK, GEN = P.checker, P.generator


def brute_gabriel(points):
    """The definition, with exact rationals: O(n^3)."""
    F = [(Fraction(x), Fraction(y)) for x, y in points]
    first = {}
    reps = [i for i, p in enumerate(F) if first.setdefault(p, i) == i]
    out = []
    for a, i in enumerate(reps):
        for j in reps[a + 1:]:
            if all((F[r][0] - F[i][0]) * (F[r][0] - F[j][0]) + (F[r][1] - F[i][1]) * (F[r][1] - F[j][1]) > 0
                   for r in reps if r not in (i, j)):
                out.append([i, j])
    return out


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), min_size=0, max_size=10))
def test_reference_is_the_definition_and_is_accepted_in_any_order(raw):
    points = [[float(x), float(y)] for x, y in raw]
    expected = GEN.solve(points)
    assert expected == brute_gabriel(points)
    shuffled = [list(reversed(e)) if k % 2 else e for k, e in enumerate(expected)]
    random.Random(len(raw)).shuffle(shuffled)
    assert CHK.check([points], shuffled, expected) == (True, "ok")


@pytest.mark.parametrize("case", [
    {"kind": "squares", "n": 2}, {"kind": "grid", "w": 4, "h": 3}, {"kind": "cocircular", "r": 5},
    {"kind": "circle", "n": 12}, {"kind": "collinear", "n": 6}, {"kind": "duplicates", "n": 8, "repeats": 5},
    {"kind": "scaled", "n": 12, "scale": 1e300}, {"kind": "scaled", "n": 12, "scale": 1e-300},
    {"kind": "uniform", "n": 12, "offset": 1e9}, {"kind": "clusters", "sizes": [8, 3], "spreads": [1e-6, 1.0]}])
def test_degenerate_sets_against_the_definition(case):
    points = GEN.generate(case, 4)
    assert GEN.solve(points) == brute_gabriel(points)


SQUARE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]]   # point 4 repeats point 1
SIDES = [[0, 1], [0, 3], [1, 2], [2, 3]]


@pytest.mark.parametrize("edges,words", [
    (SIDES + [[0, 2]], "point 1 lies on the boundary of the closed disc with diameter 0-2"),
    (SIDES[:3], "missing the Gabriel edge [2, 3]"),
    (SIDES + [[1, 0]], "listed twice"),
    ([[0, 4], [0, 3], [1, 2], [2, 3]], "point 4 repeats point 1"),
    (SIDES + [[2, 2]], "joins a point to itself"),
    (SIDES + [[2, 5]], "outside 0..4"),
])
def test_wrong_graphs_are_rejected_with_a_reason(edges, words):
    ok, message = CHK.check([SQUARE], edges, SIDES)
    assert not ok and words in message, message


def test_interior_witness_is_named():
    pts = [[0.0, 0.0], [4.0, 0.0], [2.0, 0.5]]
    ok, message = CHK.check([pts], [[0, 1], [0, 2], [1, 2]], GEN.solve(pts))
    assert not ok and "point 2 lies inside" in message


@pytest.mark.parametrize("value", [None, [[0, 1.5]], [[0, False]], [[0]], [[0, 1]] * 100, "0 1"])
def test_results_of_the_wrong_shape_are_presentation_errors(value):
    with pytest.raises(CHK.PresentationError):
        CHK.from_result(value, [SQUARE])
