"""The shared exact-arithmetic helpers against brute force (Python Fractions and sorting).

Covers ``reference_impl.exact.scaling`` (power-of-two scaling), the expansion helpers
(``compress``, ``accumulate``, ``sign_of``, ``certain_sign``), ``verify.exact_sign``,
``reference_impl.exact.distance`` (``sq_dist_cmp``, ``dot_sign``, ``length_order``) and the
validators that moved into ``reference_impl.validate``.

Run: python -m pytest tests/exact/test_helpers.py -q
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest

from reference_impl.exact.distance import dot_sign, length_order, scratch, sq_dist_cmp
from reference_impl.exact.expansion import accumulate, add, certain_sign, compress, sign, sign_of, two_product
from reference_impl.exact.predicates import incircle, orient2d
from reference_impl.exact.predicates3d import insphere, orient3d
from reference_impl.exact.scaling import pow2_exponent, pow2_scale
from reference_impl.exact.verify import exact_sign
from reference_impl.validate import as_bbox, as_point_rows, as_ring, as_rings, as_xy, as_xyz

MAGS = [1.0, 1e-300, 1e300, 1e-160, 1e160, 2.0 ** -1070, 0.1]


def _sign(v) -> int:
    return (v > 0) - (v < 0)


def _values(rng, k, wide):
    base = rng.integers(-5, 6, k).astype(float)
    v = base * rng.choice(MAGS, k) if wide else base * rng.choice(MAGS[:1] + [0.1, 2.0 ** -30])
    if rng.random() < 0.3:
        v = v + rng.random(k) * 1e-16
    return v


# ----------------------------------------------------------------------------- scaling
def test_pow2_scale_is_exact_and_normalises():
    rng = np.random.default_rng(1)
    for trial in range(2000):
        v = _values(rng, 8, trial % 2 == 0)
        lo = 2.0 ** -150
        orig = v.copy()
        ok = pow2_scale(v, lo)
        nz = orig[orig != 0]
        if len(nz) == 0:
            assert ok and (v == orig).all()
            continue
        e = math.frexp(float(np.abs(orig).max()))[1]
        expect_ok = all(abs(x) * 2.0 ** 0 >= math.ldexp(lo, e) for x in nz)
        assert ok == expect_ok, orig.tolist()
        if not ok:
            assert (v == orig).all()
            continue
        assert 0.5 <= np.abs(v).max() < 1.0
        for x, y in zip(orig, v):      # y == x * 2**-e exactly
            assert Fraction(float(y)) == Fraction(float(x)) * Fraction(2) ** -e


def test_pow2_exponent_brute_force():
    rng = np.random.default_rng(2)
    for trial in range(500):
        a, b = _values(rng, 6, True).reshape(3, 2), _values(rng, 3, True)
        m = max(abs(float(x)) for x in np.concatenate([a.ravel(), b]))
        e = pow2_exponent(a, b)
        if m == 0:
            assert e == 0
        else:
            assert 0.5 <= Fraction(m) / Fraction(2) ** e < 1
        rows = pow2_exponent(a, np.c_[b, b][:3], axis=1)
        for i in range(3):
            assert rows[i] == pow2_exponent(a[i], np.r_[b[i], b[i]])
    assert pow2_exponent(np.zeros(3)) == 0 and pow2_exponent(np.zeros(0)) == 0


def test_pow2_exponent_keep_normal_scales_losslessly():
    rng = np.random.default_rng(3)
    for trial in range(500):
        P = _values(rng, 9, True).reshape(3, 3)
        e = pow2_exponent(P, keep_normal=True)
        S = np.ldexp(P, -e)
        assert (np.ldexp(S, e) == P).all()
        nz = np.abs(S[S != 0])
        if e > 0 and len(nz):
            assert nz.min() >= np.finfo(float).tiny
        assert e <= pow2_exponent(P)


# ----------------------------------------------------------------------------- expansions
def _value(e, n) -> Fraction:
    return sum((Fraction(float(x)) for x in e[:n]), Fraction(0))


def test_compress_accumulate_sign_of():
    rng = np.random.default_rng(4)
    for trial in range(500):
        terms = [_values(rng, 2, False) * rng.choice([1.0, 1e-100, 1e100]) for _ in range(4)]
        acc, scratch_ = np.empty(64), np.empty(64)
        n = 0
        total = Fraction(0)
        for squeeze in (False, True):
            acc[:] = 0.0
            n = 0
            total = Fraction(0)
            for a, b in terms:
                x, y = two_product(a, b)
                t = np.array([y, x]) if y != 0 else np.array([x])
                n = accumulate(acc, n, t, len(t), scratch_, squeeze)
                total += Fraction(float(a)) * Fraction(float(b))
                assert _value(acc, n) == total
            assert sign_of(acc, n) == _sign(total)
        h = np.empty(64)
        m = add(acc, n, np.array([-1.0]), 1, h)
        before = _value(h, m)
        k = compress(h, m)
        assert k <= m and _value(h, k) == before and sign_of(h, k) == _sign(before)
    assert (sign(2.0), sign(-0.0), sign(-3.0)) == (1, 0, -1)


def test_certain_sign_only_outside_the_bound():
    assert certain_sign(1.0, 1.0, 1.0, 2.0, 0.5, 0.25, 0.0) == 1
    assert certain_sign(-1.0, 1.0, 1.0, 2.0, 0.5, 0.25, 0.0) == -1
    assert certain_sign(0.2, 1.0, 1.0, 2.0, 0.5, 0.25, 0.0) == 0      # within the error bound
    assert certain_sign(1.0, 1.0, 3.0, 2.0, 0.5, 0.25, 0.0) == 0      # dmax out of range
    assert certain_sign(1.0, 0.4, 1.0, 2.0, 0.5, 0.25, 0.0) == 0      # permanent too small


def test_exact_sign_matches_the_predicates():
    rng = np.random.default_rng(5)
    for trial in range(300):
        v = _values(rng, 15, trial % 3 == 0)
        p2 = [tuple(v[i:i + 2]) for i in range(0, 8, 2)]
        assert exact_sign(v[:6], 2) == orient2d(*p2[:3])
        assert exact_sign(v[:8], 2) == incircle(*p2)
        p3 = [tuple(v[i:i + 3]) for i in range(0, 15, 3)]
        assert exact_sign(v[:12], 3) == orient3d(*p3[:4])
        assert exact_sign(v, 3) == insphere(*p3)


# ----------------------------------------------------------------------------- distance
def test_distance_predicates_against_fractions():
    rng = np.random.default_rng(6)
    w = scratch()
    for trial in range(3000):
        v = _values(rng, 8, trial % 3 == 0)
        if trial % 4 == 0:          # grid ties
            v = rng.integers(-3, 4, 8).astype(float) * rng.choice([1.0, 2.0 ** -600, 2.0 ** 500])
        F = [Fraction(float(x)) for x in v]
        lhs = (F[0] - F[2]) ** 2 + (F[1] - F[3]) ** 2 - (F[4] - F[6]) ** 2 - (F[5] - F[7]) ** 2
        assert sq_dist_cmp(*v, w) == _sign(lhs), v.tolist()
        dot = (F[0] - F[4]) * (F[2] - F[4]) + (F[1] - F[5]) * (F[3] - F[5])
        assert dot_sign(*v[:6], w) == _sign(dot), v.tolist()


def _edge_key(P, a, b):
    """(exact squared length, smaller endpoint, larger endpoint): the documented order."""
    lo, hi = sorted([tuple(P[a].tolist()), tuple(P[b].tolist())])
    return sum((Fraction(x) - Fraction(y)) ** 2 for x, y in zip(lo, hi)), lo, hi


@pytest.mark.parametrize("kind", ["grid", "random", "wide", "near-ties"])
def test_length_order_against_brute_force(kind):
    rng = np.random.default_rng(7)
    for trial in range(40):
        n = int(rng.integers(2, 30))
        if kind == "grid":
            P = rng.integers(0, 5, (n, 2)).astype(float)
        elif kind == "random":
            P = rng.random((n, 2))
        elif kind == "wide":
            P = rng.integers(-3, 4, (n, 2)) * rng.choice(MAGS[:6], (n, 2))
        else:
            P = rng.integers(0, 4, (n, 2)) + rng.integers(-1, 2, (n, 2)) * 2.0 ** -50
        m = int(rng.integers(1, 40))
        u = rng.integers(0, n, m)
        v = rng.integers(0, n, m)
        keys = [_edge_key(P, u[i], v[i]) for i in range(m)]
        got = length_order(P, u, v)
        assert sorted(got.tolist()) == list(range(m))
        assert [keys[i] for i in got] == sorted(keys), (kind, trial)
        first = length_order(P, u, v, first_only=True)[0]
        assert keys[first] == min(keys)


# ----------------------------------------------------------------------------- validators
def test_moved_validators_keep_their_messages():
    assert as_xy((1, 2)) == (1.0, 2.0)
    with pytest.raises(ValueError, match="a must be a pair of numbers"):
        as_xy((1, 2, 3), "a")
    with pytest.raises(ValueError, match=r"is not finite \(NaN or infinity\)"):
        as_xy((1, float("nan")), "b")
    assert as_xyz((1, 2, 3)) == (1.0, 2.0, 3.0)
    with pytest.raises(ValueError, match="c must be three numbers"):
        as_xyz("xyz", "c")
    a, b = as_point_rows(([0, 0, 0], [[1, 1, 1]]), ("a", "b"))
    assert a.shape == b.shape == (1, 3)
    with pytest.raises(ValueError, match="b has 2 points but a has 1"):
        as_point_rows(([0, 0, 0], [[1, 1, 1], [2, 2, 2]]), ("a", "b"))
    assert as_bbox((0, 0, 1, 1)).tolist() == [0.0, 0.0, 1.0, 1.0]
    with pytest.raises(ValueError, match="bbox must be finite"):
        as_bbox((0, 0, float("inf"), 1))
    assert as_ring([(0, 0), (1, 0), (1, 0), (1, 1), (0, 0)], "boundary").tolist() == [[0, 0], [1, 0], [1, 1]]
    with pytest.raises(ValueError, match="holes\\[0\\] needs at least 3 distinct vertices, got 2"):
        as_ring([(0, 0), (1, 0), (0, 0)], "holes[0]")


def _ring_or_error(ring, name):
    try:
        return as_ring(ring, name)
    except ValueError as exc:
        return str(exc)


def test_as_rings_is_as_ring_ring_by_ring():
    """The batched check gives as_ring's answers, or the first bad ring's error, on rings with
    repeated vertices, closing copies, NaN, too few vertices, -0.0, ints, lists and bools."""
    rng = np.random.default_rng(5)
    kinds = 0
    for _ in range(400):
        rings = []
        for _ in range(rng.integers(1, 6)):
            k = int(rng.integers(1, 7))
            r = rng.integers(-2, 3, (k, 2)).astype(float)
            if rng.random() < 0.3:
                r = np.repeat(r, rng.integers(1, 3, k), axis=0)       # repeated vertices
            if rng.random() < 0.2:
                r = np.vstack([r, r[:1]])                             # closing copy
            if rng.random() < 0.05:
                r[rng.integers(len(r)), rng.integers(2)] = np.nan
            if rng.random() < 0.5:
                r = np.where(r == 0, -0.0, r)                         # -0.0 for every zero
            form = int(rng.integers(4)) if np.isfinite(r).all() else 0
            rings.append(r if form == 0 else r.astype(np.int64) if form == 1 else r.tolist() if form == 2 else r != 0)
            kinds |= 1 << form
        names = [f"ring{i}" for i in range(len(rings))]
        want = [_ring_or_error(r, nm) for r, nm in zip(rings, names)]
        error = next((w for w in want if isinstance(w, str)), None)
        if error is not None:
            with pytest.raises(ValueError) as caught:
                as_rings(rings, names)
            assert str(caught.value) == error
            continue
        pts, sizes = as_rings(rings, names)
        assert sizes.tolist() == [len(w) for w in want]
        np.testing.assert_array_equal(pts, np.vstack(want))
        assert not (np.signbit(pts) & (pts == 0)).any()                # -0.0 normalised
    assert kinds == 15
