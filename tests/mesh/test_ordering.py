"""The insertion order's walk hints (``ordering.walk_hints``) against brute force, and the
walk they shorten; the sorted order of thin strips (``ordering.line_order``) and its work cap.

Run: python -m pytest tests/mesh/test_ordering.py -q
"""
from __future__ import annotations

import numpy as np
import pytest

import pointsets
from reference_impl import Delaunay
from reference_impl.exact.verify import check_delaunay
from reference_impl.mesh import kernel
from reference_impl.mesh.ordering import SMALL, insertion_order, line_order, _order_keys
from reference_impl.mesh.status import BUDGET, OK


def _rounds_and_indices(points, order):
    keys = _order_keys(np.ascontiguousarray(points[:, 0]), np.ascontiguousarray(points[:, 1]), True)[order]
    return keys >> 58, (keys.astype(np.uint64) >> np.uint64(26)) & np.uint64(0xFFFFFFFF)


def nearly_collinear(n, seed=0):
    rng = np.random.default_rng(seed)
    t = rng.random(n)
    return np.column_stack([t, 0.5 * t + rng.normal(0, 1e-9, n)])


@pytest.mark.parametrize("n", [50, 3000, 20000])          # both ordering paths (below and above SMALL)
@pytest.mark.parametrize("kind", ["uniform", "near-line", "grid"])
def test_each_hint_is_the_nearest_point_of_the_previous_round(n, kind):
    pts = {"uniform": np.random.default_rng(n).random((n, 2)), "near-line": nearly_collinear(n),
           "grid": pointsets.grid(int(n ** 0.5))}[kind]
    order, hints = insertion_order(pts, with_hints=True)
    assert (order == insertion_order(pts)).all()
    rnd, hil = _rounds_and_indices(pts, order)
    hil = hil.astype(np.int64)
    assert (np.diff(rnd) >= 0).all()
    for i in range(len(order)):
        previous = np.flatnonzero(rnd == rnd[i] - 1)
        if len(previous) == 0:
            assert hints[i] == -1
            continue
        h = hints[i]
        assert h < i and rnd[h] == rnd[i] - 1
        assert abs(hil[h] - hil[i]) == np.abs(hil[previous] - hil[i]).min()


def test_hints_shorten_the_walk_on_a_nearly_straight_line():
    pts = nearly_collinear(20000)
    order, hints = insertion_order(pts, with_hints=True)
    steps = {}
    for name, h in (("hints", hints), ("none", np.full_like(hints, -1))):
        out = kernel.triangulate(pts, order, h, False, True, 0)
        state, simplices = out[4], out[6]
        steps[name] = state[kernel.S_STEPS] / len(pts)
        assert check_delaunay(pts, simplices)[0]
    assert steps["hints"] < 0.7 * steps["none"], steps     # measured: 3.1 vs 6.5 steps per point


def test_a_hint_to_a_duplicate_still_starts_the_walk_in_the_mesh():
    rng = np.random.default_rng(3)
    base = rng.random((3000, 2))
    pts = np.vstack([base, base[:1500], base[::7]])          # many hint targets are duplicates
    d = Delaunay(pts)
    assert check_delaunay(pts, d.simplices)[0]
    assert (d.index_map[3000:4500] == np.arange(1500)).all()


# ----------------------------------------------------------------------------- thin strips
def _flat_curve(n):
    """A thin but curved set on which sorted insertion is quadratic (y = 1e-4 x^4)."""
    x = np.linspace(0.0, 1.0, n)
    return np.column_stack([x, 1e-4 * x ** 4])


def test_line_order_only_for_thin_sets_and_independent_of_input_order():
    rng = np.random.default_rng(3)
    line = nearly_collinear(500)
    order = line_order(line)
    assert len(order) == 500 and np.all(np.diff(line[order, 0]) >= 0)
    steep = line[:, ::-1].copy()                               # along y: sorted by y
    assert np.all(np.diff(steep[line_order(steep), 1]) >= 0)
    assert len(line_order((rng.random((500, 2))))) == 0
    assert len(line_order((np.column_stack([np.linspace(0, 1, 500), np.full(500, 0.01)])))) == 500
    wide = np.column_stack([np.linspace(0, 1, 500), 0.01 * (np.arange(500) % 2)])   # gap 0.01 x 500 > 1
    assert len(line_order(wide)) == 0
    perm = rng.permutation(500)
    again = line_order(line[perm])
    assert np.array_equal(line[perm][again], line[order])


@pytest.mark.parametrize("n", [2000, 2 * SMALL])             # the compiled path and the Python one
def test_sorted_build_that_runs_past_its_cap_starts_again_in_brio_order(n):
    pts = _flat_curve(n)
    order = line_order(pts)
    assert len(order) == n                                     # thin: sorted order is tried
    empty = np.empty(0, dtype=np.int64)
    assert kernel.triangulate(pts, order, empty, False, False, kernel.line_budget(n))[0] == BUDGET
    uncapped = kernel.triangulate(pts, order, empty, False, False, 0)[4]
    assert uncapped[kernel.S_TESTS] > 100 * n                   # quadratic without the cap
    d = Delaunay(pts)
    assert check_delaunay(pts, d.simplices)[0]
    assert d._state[kernel.S_TESTS] < uncapped[kernel.S_TESTS] / 10    # the BRIO build, not the sorted one


def test_cap_of_one_forces_the_brio_order_in_the_compiled_path():
    pts = nearly_collinear(300)
    code, order, *_, simplices, _rep = kernel.triangulate(pts, np.empty(0, np.int64), np.empty(0, np.int64),
                                                          True, True, 1)
    assert code == OK and check_delaunay(pts, simplices)[0]
    brio = insertion_order(pts)
    assert np.array_equal(order, brio)                          # not the sorted order
    assert not np.array_equal(order, line_order(pts))


@pytest.mark.parametrize("n", [1000, 3 * SMALL])
def test_two_row_grid_ties_do_not_depend_on_input_order(n):
    x = np.linspace(0.0, 1.0, n // 2)
    pts = np.vstack([np.column_stack([x, np.zeros_like(x)]), np.column_stack([x, np.full_like(x, 1e-7)])])
    assert len(line_order(pts)) == len(pts)            # thin, and every rectangle cocircular
    perm = np.random.default_rng(5).permutation(len(pts))
    a, b = Delaunay(pts), Delaunay(pts[perm])
    assert check_delaunay(pts, a.simplices)[0]
    as_set = lambda p, s: {frozenset(map(tuple, p[t].tolist())) for t in s}   # noqa: E731
    assert as_set(pts, a.simplices) == as_set(pts[perm], b.simplices)
