"""Exact predicates against an independent oracle: Python Fractions.

Run: python -m pytest tests/exact/test_predicates.py -q
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, strategies as st

from reference_impl.exact.predicates import incircle, orient2d


def _sign(v) -> int:
    return (v > 0) - (v < 0)


def f_orient(a, b, c) -> int:
    (ax, ay), (bx, by), (cx, cy) = [(Fraction(x), Fraction(y)) for x, y in (a, b, c)]
    return _sign((ax - cx) * (by - cy) - (ay - cy) * (bx - cx))


def f_incircle(a, b, c, d) -> int:
    (dx, dy) = Fraction(d[0]), Fraction(d[1])
    m = [(Fraction(x) - dx, Fraction(y) - dy) for x, y in (a, b, c)]
    lift = [x * x + y * y for x, y in m]
    det = (lift[0] * (m[1][0] * m[2][1] - m[2][0] * m[1][1])
           + lift[1] * (m[2][0] * m[0][1] - m[0][0] * m[2][1])
           + lift[2] * (m[0][0] * m[1][1] - m[1][0] * m[0][1]))
    return _sign(det)


def _cases(rng: np.random.Generator, count: int):
    """Random and near-degenerate quadruples of points, at many scales."""
    out = []
    for i in range(count):
        kind = i % 10
        if kind == 0:                                     # uniform
            pts = rng.random((4, 2))
        elif kind == 1:                                   # integer grid: exact ties
            pts = rng.integers(-3, 4, (4, 2)).astype(float)
        elif kind == 2:                                   # third point on segment ab, rounded
            a, b, d = rng.random((3, 2))
            pts = np.array([a, b, a + rng.random() * (b - a), d])
        elif kind == 3:                                   # on a circle, rounded
            t = rng.random(4) * 2 * np.pi
            pts = np.c_[np.cos(t), np.sin(t)]
        elif kind == 4:                                   # one-ulp perturbations of a tie
            pts = rng.integers(-2, 3, (4, 2)).astype(float)
            pts[3] = np.nextafter(pts[3], rng.choice([-np.inf, np.inf], 2))
        elif kind == 5:                                   # large offset, small spread
            pts = 1e9 + rng.random((4, 2)) * 1e-6
        elif kind == 6:                                   # extreme uniform scales
            pts = rng.integers(-3, 4, (4, 2)) * 10.0 ** rng.choice([-300, -200, 200, 300])
        elif kind == 7:                                   # mixed magnitudes in one call
            mags = 10.0 ** rng.choice([-310, -300, -150, 0, 150, 300], (4, 2))
            pts = rng.choice([-1.0, 0.0, 1.0, 3.0], (4, 2)) * mags
        elif kind == 8:                                   # float rectangle: cocircular, with
            (x0, x1), (y0, y1) = rng.random((2, 2)) * 10.0 ** rng.integers(-8, 9)   # exact or
            pts = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])[rng.permutation(4)]  # inexact
            if rng.random() < 0.5:                        # differences; or one ulp off
                pts[3] = np.nextafter(pts[3], rng.choice([-np.inf, np.inf], 2))
        else:                                             # a float lattice: base + k * step
            base, step = rng.random(2), rng.random() * 10.0 ** rng.integers(-6, 3)
            pts = base + rng.integers(-3, 4, (4, 2)) * step
        out.append([tuple(map(float, p)) for p in pts])
    return out


@pytest.mark.parametrize("seed", range(4))
def test_against_fractions_100k(seed):
    """4 x 25k quadruples = 100k orientation and 100k in-circle tests, all exact."""
    rng = np.random.default_rng(seed)
    wrong = []
    for a, b, c, d in _cases(rng, 25_000):
        if orient2d(a, b, c) != f_orient(a, b, c):
            wrong.append(("orient2d", a, b, c))
        if incircle(a, b, c, d) != f_incircle(a, b, c, d):
            wrong.append(("incircle", a, b, c, d))
    assert not wrong, wrong[:5]


def test_ties_are_detected_exactly():
    assert orient2d((0, 0), (1, 1), (2, 2)) == 0
    assert orient2d((1e300, 1e300), (2e300, 2e300), (-3e300, -3e300)) == 0
    assert orient2d((1e-300, 1e-300), (2e-300, 2e-300), (3e-300, 3e-300)) == 0
    assert incircle((0, 0), (1, 0), (1, 1), (0, 1)) == 0
    assert incircle((0, 0), (4e-300, 0), (4e-300, 4e-300), (0, 4e-300)) == 0
    assert incircle((-5, 0), (5, 0), (3, 4), (-4, -3)) == 0


def test_naive_floating_point_is_wrong_where_exact_is_right():
    """Kettner et al.'s classroom example: a point one ulp off the line y = x."""
    a, b, c = (0.5, 0.5000000000000001), (12.0, 12.0), (24.0, 24.0)
    naive = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])
    assert naive == 0.0                        # plain floating point says "collinear"
    assert orient2d(a, b, c) == f_orient(a, b, c) == 1


def test_incircle_sign_convention():
    a, b, c = (0, 0), (2, 0), (0, 2)            # counter-clockwise
    assert incircle(a, b, c, (1, 1)) == 1
    assert incircle(a, b, c, (5, 5)) == -1
    assert incircle(a, c, b, (1, 1)) == -1      # clockwise flips the sign


@pytest.mark.parametrize("bad", [(float("nan"), 0), (0, float("inf")), ("x", 1), (1, 2, 3), 5])
def test_bad_input_raises_value_error(bad):
    with pytest.raises(ValueError):
        orient2d(bad, (0, 0), (1, 1))


finite = st.floats(allow_nan=False, allow_infinity=False)


@given(st.lists(st.tuples(finite, finite), min_size=4, max_size=4))
def test_hypothesis_any_finite_doubles(pts):
    a, b, c, d = pts
    assert orient2d(a, b, c) == f_orient(a, b, c)
    assert incircle(a, b, c, d) == f_incircle(a, b, c, d)


@given(st.integers(-1070, 1020), st.lists(st.tuples(st.integers(-4, 4), st.integers(-4, 4)),
                                          min_size=4, max_size=4))
def test_hypothesis_scaled_integer_ties(e, pts):
    s = math.ldexp(1.0, e)
    a, b, c, d = [(x * s, y * s) for x, y in pts]
    assert orient2d(a, b, c) == f_orient(a, b, c)
    assert incircle(a, b, c, d) == f_incircle(a, b, c, d)


@given(st.tuples(finite, finite), st.tuples(finite, finite),
       st.lists(st.tuples(st.integers(0, 1), st.integers(0, 1)), min_size=4, max_size=4))
def test_hypothesis_corners_of_an_axis_parallel_rectangle_are_a_tie(xs, ys, corners):
    """Stage "grid cell": four points among a rectangle's corners (repeats allowed, the
    rectangle possibly flat) answer 0 without arithmetic; the oracle agrees."""
    a, b, c, d = [(xs[i], ys[j]) for i, j in corners]
    assert incircle(a, b, c, d) == f_incircle(a, b, c, d) == 0


@given(st.tuples(finite, finite), st.tuples(finite, finite), st.permutations(range(4)),
       st.integers(0, 7), st.booleans())
def test_hypothesis_a_rectangle_one_ulp_off(xs, ys, perm, which, up):
    """One coordinate of a rectangle's corner moved by one ulp: three x (or y) values, so
    the shortcut must not answer; the exact stages must agree with the oracle."""
    pts = [[xs[i], ys[j]] for i, j in ((0, 0), (1, 0), (1, 1), (0, 1))]
    k, axis = divmod(which, 2)
    pts[k][axis] = float(np.nextafter(pts[k][axis], math.inf if up else -math.inf))
    if not math.isfinite(pts[k][axis]):
        return
    a, b, c, d = [tuple(pts[i]) for i in perm]
    assert incircle(a, b, c, d) == f_incircle(a, b, c, d)


@given(finite, st.lists(finite, min_size=3, max_size=3), st.booleans())
def test_hypothesis_points_on_an_axis_parallel_line_are_collinear(c, ts, vertical):
    """Stage "grid line" of orient2d: three points sharing x (or y) answer 0."""
    a, b, d = [(c, t) if vertical else (t, c) for t in ts]
    assert orient2d(a, b, d) == f_orient(a, b, d) == 0


def test_linspace_grid_cells_and_their_neighbours_against_fractions():
    """Every quadruple of a 4 x 4 linspace grid (rectangles, and the non-rectangles that the
    shortcut must leave to the exact stages) and every triple for orient2d."""
    g = np.linspace(0.0, 0.3, 4)
    pts = [(float(x), float(y)) for x in g for y in g]
    rng = np.random.default_rng(11)
    for _ in range(3000):
        a, b, c, d = (pts[i] for i in rng.choice(len(pts), 4))
        assert incircle(a, b, c, d) == f_incircle(a, b, c, d)
        assert orient2d(a, b, c) == f_orient(a, b, c)
