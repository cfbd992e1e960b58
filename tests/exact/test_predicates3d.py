"""Exact 3D predicates against an independent oracle: exact integer determinants.

Run: .venv/bin/python -m pytest tests/exact/test_predicates3d.py -q

The oracle turns every double into an integer (mantissa shifted to a per-case
common exponent, with numpy's frexp) and evaluates the determinants on numpy
object arrays of Python integers, so 100k+ cases run in about a second.  The
oracle itself is checked against ``fractions.Fraction`` on a sample.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, strategies as st

from reference_impl.exact.predicates3d import (FACES, exact_coordinates_3d, insphere, insphere_batch,
                                         insphere_exact, orient3d, orient3d_batch, orient3d_exact)


# ----------------------------------------------------------------------------- the oracle
def to_int(cases: np.ndarray) -> np.ndarray:
    """(k, p, 3) doubles -> object array of Python ints, one common power-of-two scale per case."""
    m, e = np.frexp(cases)
    mant = np.ldexp(m, 53).astype(np.int64)            # exact: 53-bit integer mantissas
    expo = (e - 53).astype(np.int64)
    expo = np.where(mant == 0, np.iinfo(np.int64).max, expo)
    emin = expo.reshape(len(cases), -1).min(axis=1)
    emin = np.where(emin == np.iinfo(np.int64).max, 0, emin)
    shift = np.where(mant == 0, 0, expo - emin[:, None, None])
    return mant.astype(object) * (np.full(shift.shape, 2, dtype=object) ** shift.astype(object))


def _det3(a, b, c):
    return (a[..., 2] * (b[..., 0] * c[..., 1] - c[..., 0] * b[..., 1])
            + b[..., 2] * (c[..., 0] * a[..., 1] - a[..., 0] * c[..., 1])
            + c[..., 2] * (a[..., 0] * b[..., 1] - b[..., 0] * a[..., 1]))


def _sign(v: np.ndarray) -> np.ndarray:
    return np.array([(x > 0) - (x < 0) for x in v], dtype=np.int8)


def oracle_orient(cases: np.ndarray) -> np.ndarray:
    P = to_int(cases)
    d = P[:, 3]
    return _sign(_det3(P[:, 0] - d, P[:, 1] - d, P[:, 2] - d))


def oracle_insphere(cases: np.ndarray) -> np.ndarray:
    P = to_int(cases)
    e = P[:, 4]
    r = [P[:, i] - e for i in range(4)]
    lift = [x[:, 0] * x[:, 0] + x[:, 1] * x[:, 1] + x[:, 2] * x[:, 2] for x in r]
    a, b, c, d = r
    det = (lift[3] * _det3(a, b, c) - lift[2] * _det3(d, a, b)
           + lift[1] * _det3(c, d, a) - lift[0] * _det3(b, c, d))
    return _sign(det)


def fraction_det(rows) -> Fraction:
    """Plain Laplace expansion over Fractions (the oracle's oracle)."""
    if len(rows) == 1:
        return rows[0][0]
    return sum((-1) ** j * rows[0][j] * fraction_det([r[:j] + r[j + 1:] for r in rows[1:]])
               for j in range(len(rows)))


def fraction_orient(p) -> int:
    q = [[Fraction(float(v)) for v in x] for x in p]
    v = fraction_det([[q[i][c] - q[3][c] for c in range(3)] for i in range(3)])
    return (v > 0) - (v < 0)


def fraction_insphere(p) -> int:
    q = [[Fraction(float(v)) for v in x] for x in p]
    rows = []
    for i in range(4):
        r = [q[i][c] - q[4][c] for c in range(3)]
        rows.append(r + [sum(x * x for x in r)])
    v = fraction_det(rows)
    return (v > 0) - (v < 0)


# ----------------------------------------------------------------------------- the cases
_LATTICE = np.array([(x, y, z) for x in range(-11, 12) for y in range(-11, 12) for z in range(-11, 12)
                     if x * x + y * y + z * z == 121], dtype=float)   # 30 integer points, one sphere
KINDS = ["uniform", "small-int", "coplanar-rounded", "unit-sphere", "int-cospherical",
         "int-coplanar", "ulp-off-tie", "offset-1e9", "scaled-1e300", "scaled-2^k-ties",
         "mixed-magnitudes", "huge-and-subnormal", "wide-coplanar", "float-box"]


def make_cases(kind: str, k: int, npts: int, rng: np.random.Generator) -> np.ndarray:
    """k cases of npts points in 3D of one family (vectorised)."""
    if kind == "uniform":
        return rng.random((k, npts, 3))
    if kind == "small-int":
        return rng.integers(-3, 4, (k, npts, 3)).astype(float)
    if kind == "coplanar-rounded":     # last point on the plane of the first three, rounded
        p = rng.random((k, npts, 3))
        s, t = rng.random((2, k, 1))
        p[:, -1] = p[:, 0] + s * (p[:, 1] - p[:, 0]) + t * (p[:, 2] - p[:, 0])
        return p
    if kind == "unit-sphere":          # all nearly cospherical (and nearly coplanar triples)
        p = rng.normal(size=(k, npts, 3))
        return p / np.linalg.norm(p, axis=2, keepdims=True)
    if kind == "int-cospherical":      # exactly cospherical lattice points, translated
        p = _LATTICE[rng.integers(0, len(_LATTICE), (k, npts))]
        return p + rng.integers(-1000, 1000, (k, 1, 3))
    if kind == "int-coplanar":         # exactly coplanar integer points (integer combinations)
        p = rng.integers(-50, 50, (k, npts, 3)).astype(float)
        i, j = rng.integers(-3, 4, (2, k, 1))
        p[:, -1] = p[:, 0] + i * (p[:, 1] - p[:, 0]) + j * (p[:, 2] - p[:, 0])
        return p
    if kind == "ulp-off-tie":          # one coordinate one ulp away from an exact tie
        p = make_cases("int-cospherical" if rng.random() < 0.5 else "int-coplanar", k, npts, rng)
        col = rng.integers(0, 3, k)
        direction = rng.choice([-np.inf, np.inf], k)
        p[np.arange(k), -1, col] = np.nextafter(p[np.arange(k), -1, col], direction)
        return p
    if kind == "offset-1e9":           # large offset, tiny spread: inexact differences
        return 1e9 + rng.random((k, npts, 3)) * 1e-6
    if kind == "scaled-1e300":
        p = rng.integers(-3, 4, (k, npts, 3)).astype(float)
        return p * 10.0 ** rng.choice([-300, -200, 200, 300], (k, 1, 1))
    if kind == "scaled-2^k-ties":      # exact ties scaled exactly to the ends of the range
        p = make_cases("int-cospherical", k, npts, rng) * 2.0 ** -4
        return np.ldexp(p, rng.integers(-1060, 1000, (k, 1, 1)))
    if kind == "mixed-magnitudes":     # the Python-integer fallback
        mags = 10.0 ** rng.choice([-310, -300, -150, 0, 150, 300], (k, npts, 3))
        return rng.choice([-1.0, 0.0, 1.0, 3.0], (k, npts, 3)) * mags
    if kind == "huge-and-subnormal":   # differences overflow, or everything is subnormal
        big = rng.uniform(-1, 1, (k, npts, 3)) * 1.7e308
        tiny = rng.integers(-40, 40, (k, npts, 3)) * 5e-324
        return np.where(rng.random((k, 1, 1)) < 0.5, big, tiny)
    if kind == "wide-coplanar":        # on one plane z = const, x and y of exponents 0..80:
        m = rng.integers(-7, 8, (k, npts, 2)) * 2.0 ** rng.integers(0, 80, (k, npts, 2))
        z = np.repeat(rng.choice([1.0, 0.1, -3.0], (k, 1, 1)), npts, axis=1)
        p = np.concatenate([m, z], axis=2)    # differences need up to 80 bits: inexact
        off = rng.random(k) < 0.5             # half of them: last point one ulp off the plane
        p[off, -1, 2] = np.nextafter(p[off, -1, 2], np.inf)
        return p
    if kind == "float-box":            # corners of boxes on a 0.1-spaced grid: ties whose
        lo = rng.integers(0, 300, (k, 1, 3))                  # differences are not exact doubles
        hi = lo + rng.integers(1, 4, (k, 1, 3))               # (the fixed-point stage)
        p = np.where(rng.integers(0, 2, (k, npts, 3)) == 1, hi, lo) * 0.1
        off = rng.random(k) < 0.3                            # some of them one ulp off
        p[off, -1, 0] = np.nextafter(p[off, -1, 0], np.inf)
        return p
    raise ValueError(kind)


# ----------------------------------------------------------------------------- tests
def test_oracle_agrees_with_fractions():
    rng = np.random.default_rng(7)
    for kind in KINDS:
        cases = make_cases(kind, 12, 5, rng)
        assert oracle_orient(cases[:, :4]).tolist() == [fraction_orient(c[:4]) for c in cases], kind
        assert oracle_insphere(cases).tolist() == [fraction_insphere(c) for c in cases], kind


@pytest.mark.parametrize("kind", KINDS)
def test_against_exact_oracle(kind):
    """12 families x 10k cases + 2k of the slow Python-integer fallback: 122k orient3d and
    122k insphere calls, every sign exact."""
    rng = np.random.default_rng(KINDS.index(kind))
    cases = make_cases(kind, 2_000 if kind == "mixed-magnitudes" else 10_000, 5, rng)
    c = [cases[:, i] for i in range(5)]
    got_o = orient3d_batch(c[0], c[1], c[2], c[3])
    want_o = oracle_orient(cases[:, :4])
    bad = np.flatnonzero(got_o != want_o)
    assert len(bad) == 0, (kind, cases[bad[:3]].tolist(), got_o[bad[:3]], want_o[bad[:3]])
    got_i = insphere_batch(*c)
    want_i = oracle_insphere(cases)
    bad = np.flatnonzero(got_i != want_i)
    assert len(bad) == 0, (kind, cases[bad[:3]].tolist(), got_i[bad[:3]], want_i[bad[:3]])


def test_families_really_are_degenerate():
    """The near-degenerate families must produce ties (else the test above could not fail there)."""
    rng = np.random.default_rng(1)
    cos = make_cases("int-cospherical", 2000, 5, rng)
    assert (oracle_insphere(cos) == 0).mean() > 0.5
    cop = make_cases("int-coplanar", 2000, 4, rng)
    assert (oracle_orient(cop) == 0).all()
    scaled = make_cases("scaled-2^k-ties", 2000, 5, rng)
    assert (oracle_insphere(scaled) == 0).mean() > 0.5
    wide = make_cases("wide-coplanar", 2000, 5, rng)
    assert 0.3 < (oracle_insphere(wide) == 0).mean() < 0.7
    assert 0.3 < (oracle_orient(wide[:, [0, 1, 2, 4]]) == 0).mean() < 0.7


def test_sign_conventions():
    a, b, c = (0, 0, 0), (1, 0, 0), (0, 1, 0)          # counter-clockwise seen from +z
    assert orient3d(a, b, c, (0, 0, -1)) == 1          # below: +1
    assert orient3d(a, b, c, (0, 0, 1)) == -1
    assert orient3d(a, c, b, (0, 0, -1)) == -1         # swapping two points flips the sign
    d = (0, 0, -1)
    assert insphere(a, b, c, d, (0.5, 0.5, -0.5)) == 1  # the circumcentre
    assert insphere(a, b, c, d, (2, 2, 2)) == -1
    assert insphere(b, a, c, d, (0.5, 0.5, -0.5)) == -1  # negatively oriented: flipped
    assert insphere(a, b, c, d, (1, 1, -1)) == 0       # the cube corner is on the sphere


def test_faces_are_outward_counter_clockwise():
    tet = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, -1.0)]
    assert orient3d(*tet) == 1
    for k, face in enumerate(FACES):
        assert sorted(face + (k,)) == [0, 1, 2, 3]
        # the opposite vertex is below the face (so the face is counter-clockwise from outside)
        assert orient3d(*(tet[i] for i in face), tet[k]) == 1
        out = np.mean([tet[i] for i in face], axis=0) * 2 - np.array(tet[k])
        assert orient3d(*(tet[i] for i in face), tuple(out)) == -1


def test_naive_floating_point_is_wrong_where_exact_is_right():
    """Plain float determinants get near-coplanar and near-cospherical signs wrong; we do not."""
    rng = np.random.default_rng(3)
    for kind, npts, oracle, pred in (("coplanar-rounded", 4, oracle_orient, orient3d_batch),
                                     ("unit-sphere", 5, oracle_insphere, insphere_batch)):
        cases = make_cases(kind, 3000, npts, rng)
        d = cases[:, :-1] - cases[:, -1:]
        if npts == 5:
            d = np.concatenate([d, (d * d).sum(axis=2, keepdims=True)], axis=2)
        naive = np.sign(np.linalg.det(d)).astype(np.int8)
        exact = oracle(cases)
        wrong = np.flatnonzero(naive != exact)
        assert len(wrong) > 10, kind           # the float determinant fails here ...
        got = pred(*(cases[wrong, i] for i in range(npts)))
        assert (got == exact[wrong]).all()     # ... and the exact predicate does not


def test_integer_helpers():
    pts = [(0.5, -0.25, 3.0), (1e-300, 0.0, 2.0), (7.0, 7.0, 7.0), (1.0, 2.0, 4.0), (0.0, 0.0, 1.0)]
    P = exact_coordinates_3d(pts)
    scale = Fraction(P[2][0], 7)
    assert all(Fraction(P[i][j]) == Fraction(pts[i][j]) * scale for i in range(5) for j in range(3))
    assert orient3d_exact(*P[:4]) == fraction_orient(pts[:4]) == orient3d(*pts[:4])
    assert insphere_exact(*P) == fraction_insphere(pts) == insphere(*pts)


@pytest.mark.parametrize("bad", [(float("nan"), 0, 0), (0, float("inf"), 0), ("x", 1, 2),
                                 (1, 2), 5, "abc"])
def test_bad_input_raises_value_error(bad):
    with pytest.raises(ValueError):
        orient3d(bad, (0, 0, 0), (1, 1, 1), (2, 0, 1))
    with pytest.raises(ValueError):
        insphere((0, 0, 0), (1, 1, 1), (2, 0, 1), (0, 1, 0), bad)


def test_batch_shape_mismatch_is_an_error():
    with pytest.raises(ValueError, match="has 2 points"):
        orient3d_batch(np.zeros((3, 3)), np.zeros((2, 3)), np.zeros((3, 3)), np.zeros((3, 3)))


finite = st.floats(allow_nan=False, allow_infinity=False)
point = st.tuples(finite, finite, finite)


@given(st.lists(point, min_size=5, max_size=5))
def test_hypothesis_any_finite_doubles(pts):
    assert orient3d(*pts[:4]) == fraction_orient(pts[:4])
    assert insphere(*pts) == fraction_insphere(pts)


small = st.tuples(st.integers(-3, 3), st.integers(-3, 3), st.integers(-3, 3))


@given(st.integers(-1070, 1015), st.lists(small, min_size=5, max_size=5))
def test_hypothesis_scaled_integer_ties(e, pts):
    s = math.ldexp(1.0, e)
    p = [(x * s, y * s, z * s) for x, y, z in pts]
    assert orient3d(*p[:4]) == fraction_orient(p[:4])
    assert insphere(*p) == fraction_insphere(p)


@given(st.lists(small, min_size=5, max_size=5), st.permutations(range(4)))
def test_hypothesis_permutation_parity(pts, perm):
    """Both predicates are alternating in (a, b, c, d): an odd permutation flips the sign."""
    inv = sum(1 for i in range(4) for j in range(i + 1, 4) if perm[i] > perm[j])
    sgn = -1 if inv % 2 else 1
    q = [pts[i] for i in perm]
    assert orient3d(*q) == sgn * orient3d(*pts[:4])
    assert insphere(*q, pts[4]) == sgn * insphere(*pts)
