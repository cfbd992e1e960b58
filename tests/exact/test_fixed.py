"""The fixed-point stage (``reference_impl.exact.fixed``) against exact integer arithmetic.

Every answer is either the exact sign (``exact_oracle``: Python integers) or ``NO_ANSWER``,
and ``NO_ANSWER`` only when the differences of the call really span more than 60 bits.  The
families are the ones the stage exists for (float grids, float rectangles, squares at float
positions) and their one-ulp perturbations, plus any finite doubles (hypothesis).

Run: python -m pytest tests/exact/test_fixed.py -q
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, strategies as st

from exact_oracle import exact, incircle as x_incircle, orient as x_orient
from reference_impl.exact.fixed import NO_ANSWER, SCRATCH, incircle_fixed, orient_fixed

IW = np.zeros(SCRATCH, dtype=np.int64)


def _span_bits(pts) -> int:
    """Bits of max |D|, D = (difference from the last point) / 2**e, e the lowest set bit
    over the differences (that of their exact hi + lo parts): what decides whether the stage
    can answer."""
    from fractions import Fraction
    last = pts[-1]
    diffs = [abs(Fraction(p[k]) - Fraction(last[k])) for p in pts[:-1] for k in (0, 1)]
    nz = [d for d in diffs if d]
    if not nz:
        return 0

    def low_bit(d):                                      # d = n / 2**k, exactly (dyadic)
        n, k = d.numerator, d.denominator.bit_length() - 1
        return (n & -n).bit_length() - 1 - k

    e = min(low_bit(d) for d in nz)
    return (max(nz) / Fraction(2) ** e).numerator.bit_length()


def _check(pts, answers):
    a, b, c, d = pts
    ea, eb, ec, ed = exact(pts)
    o = orient_fixed(*a, *b, *c, IW)
    assert o == NO_ANSWER or o == x_orient(ea, eb, ec), (pts, o)
    s = incircle_fixed(*a, *b, *c, *d, IW)
    assert s == NO_ANSWER or s == x_incircle(ea, eb, ec, ed), (pts, s)
    # comfortably inside the stage's range (and no difference overflows): it must answer
    if _span_bits(pts) < 55 and max(abs(v) for p in pts for v in p) < 2.0 ** 1022:
        assert s != NO_ANSWER, pts
    answers.append(s)


def _family(rng, kind):
    """Four points of a neighbourhood (what the mesh's tests compare), half of them the corners
    of a rectangle (an exact tie)."""
    if kind == "float grid":                     # spacing 0.1 (inexact differences)
        ij = rng.integers(0, 300, 2) + rng.integers(-3, 4, (4, 2))
        if rng.random() < 0.5:
            ij[1, 0], ij[1, 1], ij[2, 0], ij[2, 1], ij[3, 0], ij[3, 1] = (
                ij[1, 0], ij[0, 1], ij[1, 0], ij[2, 1], ij[0, 0], ij[2, 1])
        return ij * 0.1
    if kind == "linspace grid":
        t = np.linspace(0.0, 1.0, 317)
        ij = np.clip(rng.integers(3, 314, 2) + rng.integers(-3, 4, (4, 2)), 0, 316)
        if rng.random() < 0.5:
            ij[1, 1], ij[2, 0], ij[3, 0], ij[3, 1] = ij[0, 1], ij[1, 0], ij[0, 0], ij[2, 1]
        return t[ij]
    if kind == "square holes":                   # corners of squares on a float grid
        side, s = 30, 0.01
        step = 0.6 / side
        i = rng.integers(0, side * side) + rng.integers(-1, 2, 4) + side * rng.integers(-1, 2, 4)
        i = np.clip(i, 0, side * side - 1)
        cx, cy = -0.3 + step * (i % side + 0.5), -0.3 + step * (i // side + 0.5)
        sx, sy = rng.choice([-s, s], 4), rng.choice([-s, s], 4)
        return np.stack([cx + sx, cy + sy], axis=1)
    if kind == "rectangle":                      # one float rectangle: cocircular
        (x0, x1), (y0, y1) = rng.random((2, 2)) * 10.0 ** rng.integers(-8, 9)
        return np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])[rng.permutation(4)]
    raise ValueError(kind)


@pytest.mark.parametrize("kind", ["float grid", "linspace grid", "square holes", "rectangle"])
def test_families_exact_and_answered(kind):
    rng = np.random.default_rng(len(kind))
    answers = []
    for i in range(4000):
        pts = _family(rng, kind)
        if i % 2:                                    # one ulp off a tie
            pts[3] = np.nextafter(pts[3], rng.choice([-np.inf, np.inf], 2))
        _check([tuple(map(float, p)) for p in pts], answers)
    answers = np.array(answers)
    # (not all: a corner of a square centred at 0.01 - 0.01 lands at 8.7e-18, and a call with it
    # and a coordinate near 0.1 spans 105 bits; such calls go to the expansions)
    assert (answers != NO_ANSWER).mean() > 0.95, kind
    assert (answers == 0).any() and (answers == 1).any() and (answers == -1).any(), kind


def test_overflowing_differences_give_no_answer():
    # 1.5e308 - (-1.5e308) overflows to infinity: the stage must not read its bits as a number
    big = [(1.5e308, 1.5e308), (-1.5e308, 1.5e308), (-1.5e308, -1.5e308), (1.5e308, -1.5e308)]
    assert incircle_fixed(*[v for p in big for v in p], IW) == NO_ANSWER
    assert orient_fixed(*[v for p in big[:3] for v in p], IW) == NO_ANSWER


def test_out_of_range_gives_no_answer_not_a_wrong_sign():
    # a coordinate near zero makes the lowest bit tiny while the differences stay large
    pts = [(1e-30, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    assert incircle_fixed(*pts[0], *pts[1], *pts[2], *pts[3], IW) == NO_ANSWER
    assert orient_fixed(*pts[0], *pts[1], *pts[2], IW) == NO_ANSWER
    same = [(0.0, 0.0)] * 4                          # all differences zero
    assert incircle_fixed(*[v for p in same for v in p], IW) == 0


finite = st.floats(allow_nan=False, allow_infinity=False)


@given(st.lists(st.tuples(finite, finite), min_size=4, max_size=4))
def test_hypothesis_any_doubles_exact_or_no_answer(pts):
    _check(pts, [])


@given(st.integers(-1000, 990), st.integers(1, 2 ** 20),
       st.lists(st.tuples(st.integers(-50, 50), st.integers(-50, 50)), min_size=4, max_size=4))
def test_hypothesis_scaled_lattices(e, step, ks):
    """Points base + k * step at any binary scale: ties everywhere, always in range."""
    h = math.ldexp(1.0, e)
    base = (0.3 * h, 0.7 * h)
    pts = [(base[0] + (x * step * 1e-3) * h, base[1] + (y * step * 1e-3) * h) for x, y in ks]
    answers = []
    _check(pts, answers)
