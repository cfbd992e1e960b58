"""One correctness suite for both Delaunay implementations: the teaching
``bowyer_watson`` and the fast ``Delaunay``.

Oracles: the exact checker ``reference_impl.exact.verify.check_delaunay`` (integer
arithmetic, proof in its docstring), a brute-force empty-circle check,
``scipy.spatial.Delaunay`` and the ``triangle`` package on general-position
input (where the triangulation is unique, the triangle sets must be identical).

Run: python -m pytest tests/test_delaunay_shared.py -q
"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.spatial
import triangle as shewchuk_triangle
from hypothesis import given, strategies as st

import pointsets
from reference_impl import Delaunay
from reference_impl.exact.verify import (brute_force_empty_circles, check_delaunay,
                                   check_triangulation_size, convex_hull_exact,
                                   exact_coordinates)
from exact_oracle import canon


def fast(points):
    return Delaunay(points).simplices


def teaching(points):
    from reference_impl.teaching.bowyer_watson import bowyer_watson
    return bowyer_watson(points)


# (name, function, largest n it is asked to handle in these tests)
IMPLS = [pytest.param(fast, 100_000, id="fast"), pytest.param(teaching, 400, id="teaching")]


def ccw(points, tris):
    """Re-orient triangles counter-clockwise (the anchors do not all promise it)."""
    p = np.asarray(points)[np.asarray(tris)]
    u, v = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    area = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
    t = np.array(tris)
    t[area < 0] = t[area < 0][:, [0, 2, 1]]
    return t


def assert_delaunay(points, tris):
    ok, msg = check_delaunay(points, tris)
    assert ok, msg


@pytest.mark.parametrize("impl,nmax", IMPLS)
@pytest.mark.parametrize("name,pts", pointsets.degenerate_sets(), ids=lambda v: v if isinstance(v, str) else "")
def test_degenerate_sets_are_exactly_delaunay(impl, nmax, name, pts):
    tris = impl(pts)
    assert tris.shape[1] == 3 and tris.dtype.kind == "i"
    assert_delaunay(pts, tris)
    P = exact_coordinates(pts)
    h = len(convex_hull_exact(P))
    assert check_triangulation_size(len(set(P)), h, len(tris))
    if len(pts) <= 200:
        ok, msg = brute_force_empty_circles(pts, tris)
        assert ok, msg


@pytest.mark.parametrize("impl,nmax", IMPLS)
def test_magnitudes_too_far_apart_for_expansions(impl, nmax):
    """Points at 1e-200, 1 and 1e100 in one set: many in-circle and orientation tests span
    more than 2**150, where the exact stage falls back to Python integers (the numba
    ``objmode`` path, reached from the kernel's reference-count-free insertion loop)."""
    rng = np.random.default_rng(7)
    pts = np.vstack([rng.random((15, 2)) * 1e-200, rng.random((15, 2)), rng.random((15, 2)) * 1e100,
                     [[0.0, 0.0], [-1e100, 1e-200], [1e-200, -1e100]]])
    for order in (np.arange(len(pts)), rng.permutation(len(pts))):
        tris = np.asarray(impl(pts[order]))
        assert_delaunay(pts[order], tris)
        ok, msg = brute_force_empty_circles(pts[order], tris)
        assert ok, msg


@pytest.mark.parametrize("impl,nmax", IMPLS)
@pytest.mark.parametrize("name,pts", pointsets.flat_sets(), ids=lambda v: v if isinstance(v, str) else "")
def test_flat_input_gives_no_triangles(impl, nmax, name, pts):
    tris = impl(pts)
    assert tris.shape == (0, 3)


@pytest.mark.parametrize("impl,nmax", IMPLS)
@pytest.mark.parametrize("n", [3, 10, 100, 400, 5000, 100_000])
def test_random_points_match_scipy_and_triangle(impl, nmax, n):
    if n > nmax:
        pytest.skip(f"{impl.__name__} is quadratic: covered up to n={nmax}")
    pts = pointsets.uniform(n, seed=n)
    ours = canon(impl(pts))
    qhull = canon(ccw(pts, scipy.spatial.Delaunay(pts).simplices))
    tri = canon(ccw(pts, shewchuk_triangle.triangulate({"vertices": pts})["triangles"]))
    assert ours == qhull == tri
    if n <= 5000:
        assert_delaunay(pts, impl(pts))


@pytest.mark.parametrize("impl,nmax", IMPLS)
@pytest.mark.parametrize("name,pts", [("grid", pointsets.grid(9)), ("circle", pointsets.circle(24, True)),
                                      ("duplicates", pointsets.with_duplicates(40)),
                                      ("integer-circle", pointsets.integer_circle())])
def test_result_does_not_depend_on_input_order(impl, nmax, name, pts):
    ref = canon(impl(pts))
    rng = np.random.default_rng(7)
    for _ in range(3):
        perm = rng.permutation(len(pts))
        tris = impl(pts[perm])
        # the smallest original index of each merged duplicate is the one used
        P = exact_coordinates(pts)
        first = {}
        for i, p in enumerate(P):
            first.setdefault(p, i)
        back = np.array([first[P[perm[i]]] for i in range(len(pts))])
        assert canon(back[tris]) == ref


@pytest.mark.parametrize("impl,nmax", IMPLS)
def test_duplicates_use_the_smallest_index(impl, nmax):
    pts = np.array([(0, 0), (1, 0), (0, 1), (1, 0), (0, 0), (1, 1)], dtype=float)
    used = set(np.asarray(impl(pts)).ravel().tolist())
    assert used == {0, 1, 2, 5}


@pytest.mark.parametrize("impl,nmax", IMPLS)
@pytest.mark.parametrize("bad,word", [
    ([(0.0, float("nan")), (1, 1), (2, 0)], "not finite"),
    ([(0.0, float("inf")), (1, 1), (2, 0)], "not finite"),
    ([(0.0, 1.0, 2.0)], "shape"),
    (np.zeros((3, 2, 2)), "shape"),
    ([("a", "b"), ("c", "d"), ("e", "f")], "text"),
    ("1 2 3 4", "text"),
    ([[0, 1], [2]], "numbers"),
    ([(1 + 2j, 0), (1, 1), (0, 1)], "complex"),
])
def test_bad_input_raises_a_clear_value_error(impl, nmax, bad, word):
    with pytest.raises(ValueError, match=word):
        impl(bad)


@pytest.mark.parametrize("impl,nmax", IMPLS)
def test_the_tutorials_own_examples(impl, nmax):
    four = [(1, 1), (3, 2), (5, 1), (4, 4)]
    assert canon(impl(four)) == {(0, 2, 1), (1, 2, 3), (0, 1, 3)}  # worked out by hand
    assert len(impl([(0, 0), (1, 0), (0, 1)])) == 1
    big = [(1e6, 1e6), (2e6, 3e6), (4e6, 1e6)]                    # breaks the +-1e5 super-triangle
    assert canon(impl(big)) == {(0, 2, 1)}
    near_zero = [(0, 0), (0, 0.000001), (0.000002, 0)]           # a valid triangle, not "zero area"
    assert canon(impl(near_zero)) == {(0, 2, 1)}
    assert len(impl([(1, 1), (1, 1), (2, 2), (3, 3)])) == 0       # collinear after de-duplication


small_ints = st.lists(st.tuples(st.integers(-6, 6), st.integers(-6, 6)), min_size=0, max_size=40)
any_floats = st.lists(st.tuples(st.floats(-1e6, 1e6, allow_nan=False), st.floats(-1e6, 1e6, allow_nan=False)),
                      min_size=0, max_size=40)


@pytest.mark.parametrize("impl,nmax", IMPLS)
@given(pts=small_ints)
def test_hypothesis_integer_points_full_of_ties(impl, nmax, pts):
    pts = np.array(pts, dtype=float).reshape(-1, 2)
    assert_delaunay(pts, impl(pts))


@pytest.mark.parametrize("impl,nmax", IMPLS)
@given(pts=any_floats, scale=st.sampled_from([1.0, 1e-300, 1e300, 2.0 ** -1000]))
def test_hypothesis_floats_any_scale(impl, nmax, pts, scale):
    pts = np.array(pts, dtype=float).reshape(-1, 2) * scale
    if not np.isfinite(pts).all():
        return
    assert_delaunay(pts, impl(pts))
