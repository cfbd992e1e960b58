"""The insertion order's walk hints (``ordering.walk_hints``) against brute force, and the
walk they shorten.

Run: python -m pytest tests/mesh/test_ordering.py -q
"""
from __future__ import annotations

import numpy as np
import pytest

import pointsets
from reference_impl import Delaunay
from reference_impl.exact.verify import check_delaunay
from reference_impl.mesh import kernel
from reference_impl.mesh.ordering import insertion_order, _order_keys


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
        out = kernel.triangulate(pts, order, h, False, True)
        state, simplices = out[5], out[7]
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
