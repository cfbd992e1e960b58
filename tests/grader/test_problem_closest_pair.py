"""The `closest-pair` checker: accepts exactly the pairs at the minimum distance (brute force with
Fractions as the oracle), on ties, repeats, near-ties and extreme scales; typed results strictly.

Run: .venv/bin/python -m pytest tests/grader/test_problem_closest_pair.py -q
"""
from __future__ import annotations

from fractions import Fraction
from itertools import combinations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from grader.problems import load_problem

P = load_problem("closest-pair")
CHK, GEN = P.checker, P.generator


def sq(points, i, j):
    return sum((Fraction(a) - Fraction(b)) ** 2 for a, b in zip(points[i], points[j]))


def verdicts(points):
    """(is a closest pair, checker accepts) for every ordered pair, against the reference."""
    expected = GEN.solve(points)
    best = min(sq(points, i, j) for i, j in combinations(range(len(points)), 2))
    assert sq(points, *expected) == best
    for i, j in combinations(range(len(points)), 2):
        for pair in ([i, j], [j, i]):
            yield sq(points, i, j) == best, CHK.check([points], pair, expected)[0]


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), min_size=2, max_size=8))
def test_accepts_exactly_the_closest_pairs(raw):
    points = [[float(x), float(y)] for x, y in raw]
    for closest, accepted in verdicts(points):
        assert closest == accepted


@pytest.mark.parametrize("case", [
    {"kind": "tutorial"}, {"kind": "grid", "w": 4, "h": 3}, {"kind": "near_ties", "count": 3},
    {"kind": "scaled", "n": 10, "scale": 1e300}, {"kind": "scaled", "n": 10, "scale": 1e-300},
    {"kind": "uniform", "n": 10, "offset": 1e9}, {"kind": "duplicates", "n": 5, "repeats": 3},
    {"kind": "clusters", "sizes": [8, 3], "spreads": [1e-6, 1.0]}])
def test_degenerate_sets_against_brute_force(case):
    points = GEN.generate(case, 3)
    for closest, accepted in verdicts(points):
        assert closest == accepted


def test_messages_say_what_is_wrong():
    pts = [[0.0, 0.0], [1.0, 2.0 ** -30], [8.0, 4.0], [9.0, 4.0]]
    assert CHK.check([pts], [2, 3], [2, 3]) == (True, "ok")
    ok, message = CHK.check([pts], [0, 1], [2, 3])
    assert not ok and "round to 1.0" in message and "exactly" in message
    assert "outside 0..3" in CHK.check([pts], [0, 4], [2, 3])[1]
    assert "must differ" in CHK.check([pts], [2, 2], [2, 3])[1]
    ok, message = CHK.check([pts], [0, 2], [2, 3])
    assert not ok and "points 2 and 3 are at distance 1.0" in message


@pytest.mark.parametrize("value", [None, 3, [1], [1, 2, 3], [1.0, 2], [True, 0], ["0", "1"], {"i": 0}])
def test_results_of_the_wrong_shape_are_presentation_errors(value):
    with pytest.raises(CHK.PresentationError):
        CHK.from_result(value, [[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]])


@pytest.mark.parametrize("text", ["", "1\n", "0 1 2\n", "0\n1\n", "a b\n", "0 1\n2 3\n"])
def test_malformed_output_is_a_presentation_error(text):
    with pytest.raises(CHK.PresentationError):
        CHK.read_output(text, None)


def test_output_round_trip_and_validator_needs_two_points():
    assert CHK.read_output(CHK.write_output([3, 1]), None) == [3, 1]
    assert CHK.read_output("  3   1  \n\n", None) == [3, 1]
    import subprocess
    import sys

    main = P.path / "input_validators" / "validate_points" / "main.py"
    for text, code in (("1\n0 0\n", 43), ("2\n0 0\n0 0\n", 42), ("2\n0 0\n", 43)):
        assert subprocess.run([sys.executable, str(main)], input=text, text=True, capture_output=True).returncode == code
