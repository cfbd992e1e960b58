"""Tests for reference_impl.structures.empty_circle.largest_empty_circle against an exact brute force.

Run:  .venv/bin/python -m pytest tests/structures/test_empty_circle.py -q

Oracle (``brute_force_radius``): in exact integer arithmetic, every candidate
centre of Toussaint's characterisation, enumerated blindly: the circumcentre of
every triple inside the hull, and every point where the bisector of any pair
meets any hull edge (O(n^3) candidates); its radius is the exact distance to the
nearest point.  Candidates are visited from the largest upper bound down, and
the search stops once no remaining bound can beat the best found (which changes
no result).  For sets too large for it, a dense sample of the hull gives a lower
bound.

Tolerances: radii and positions within TOL = 1e-9 times the diameter of the set
plus 64 ulps of the largest coordinate (the answer is a float: with an offset of
1e9 the centre itself can only be given to about 1e-7).
"""
from __future__ import annotations

import doctest
import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, strategies as st

import reference_impl.structures.empty_circle as ec_module
from pointsets import circle, clusters, collinear, degenerate_sets, grid, integer_circle, rotated_grid
from reference_impl.structures.empty_circle import largest_empty_circle
from reference_impl.exact.verify import convex_hull_exact, exact_coordinates, orient_exact


def _exact_points(points):
    """Distinct integer points (common power-of-two scale) and the scale as a Fraction."""
    pts = [(float(x), float(y)) for x, y in points]
    E = exact_coordinates(pts + [(1.0, 1.0)])
    unit = E[-1][0]                        # the integer that stands for 1.0
    distinct = sorted(set(E[:-1]))
    return distinct, Fraction(1, unit)


def brute_force_radius(points) -> float:
    """The optimal radius, exactly (returned as the nearest float)."""
    P, scale = _exact_points(points)
    H = [P[i] for i in convex_hull_exact(P, keep_collinear=False)]
    if len(H) < 3 or all(orient_exact(H[0], H[-1], p) == 0 for p in P):
        raise ValueError("flat set: use the gap rule")
    big = max(max(abs(x), abs(y)) for x, y in P) or 1
    norm = Fraction(1, big * big)

    def inside(X, Y, W):
        return all((v[0] - u[0]) * (Y - u[1] * W) - (v[1] - u[1]) * (X - u[0] * W) >= 0
                   for u, v in zip(H, H[1:] + H[:1]))

    cands = []          # (float upper bound on r^2 for sorting, X, Y, W, exact bound numerator)
    n = len(P)
    for i in range(n):
        a = P[i]
        for j in range(i + 1, n):
            b = P[j]
            bx, by = b[0] - a[0], b[1] - a[1]
            bb = bx * bx + by * by
            for k in range(j + 1, n):
                c = P[k]
                cx, cy = c[0] - a[0], c[1] - a[1]
                D = 2 * (bx * cy - by * cx)
                if D == 0:
                    continue
                cc = cx * cx + cy * cy
                X, Y, W = a[0] * D + (cy * bb - by * cc), a[1] * D + (bx * cc - cx * bb), D
                if W < 0:
                    X, Y, W = -X, -Y, -W
                if inside(X, Y, W):
                    num = (X - a[0] * W) ** 2 + (Y - a[1] * W) ** 2
                    cands.append((float(Fraction(num, W * W) * norm), X, Y, W))
            for u, v in zip(H, H[1:] + H[:1]):
                dx, dy = v[0] - u[0], v[1] - u[1]
                D = dx * (b[0] - a[0]) + dy * (b[1] - a[1])
                if D == 0:
                    continue
                N = (b[0] - u[0]) ** 2 + (b[1] - u[1]) ** 2 - (a[0] - u[0]) ** 2 - (a[1] - u[1]) ** 2
                W = 2 * D
                if W < 0:
                    N, W = -N, -W
                if not 0 <= N <= W:
                    continue
                X, Y = u[0] * W + N * dx, u[1] * W + N * dy
                num = (X - a[0] * W) ** 2 + (Y - a[1] * W) ** 2
                cands.append((float(Fraction(num, W * W) * norm), X, Y, W))
    cands.sort(key=lambda c: -c[0])
    best = Fraction(0)
    for bound, X, Y, W in cands:
        if bound < float(best * norm) * (1 - 1e-9):
            break
        r2 = min((X - p[0] * W) ** 2 + (Y - p[1] * W) ** 2 for p in P)
        best = max(best, Fraction(r2, W * W))
    return math.sqrt(float(best * norm)) * float(big * scale)


def check_valid(points, answer, r_opt=None):
    """Centre in the hull, no point strictly inside, radius optimal (all within TOL)."""
    assert all(isinstance(v, float) for v in answer)
    P = np.asarray(points, dtype=float).reshape(-1, 2)
    k = math.frexp(float(np.abs(P).max()) or 1.0)[1]          # work at scale 1 (1e300 would overflow)
    P = np.ldexp(P, -k)
    cx, cy, r = (math.ldexp(v, -k) for v in answer)
    r_opt = None if r_opt is None else math.ldexp(r_opt, -k)
    diam = float(np.hypot(*(P.max(axis=0) - P.min(axis=0)))) or 1.0
    tol = 1e-9 * diam + 64 * np.finfo(float).eps * float(np.abs(P).max())
    d = float(np.min(np.hypot(P[:, 0] - cx, P[:, 1] - cy)))
    assert r <= d + tol, ("a point is inside the circle", r, d)
    assert r >= d - tol, ("the radius is not the distance to the nearest point", r, d)
    hull = convex_hull_exact(exact_coordinates(P), keep_collinear=False)
    if len(hull) >= 3:
        for a, b in zip(hull, hull[1:] + hull[:1]):
            (ax, ay), (bx, by) = P[a], P[b]
            cross = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
            assert cross / math.hypot(bx - ax, by - ay) >= -tol, "centre outside the hull"
    if r_opt is not None:
        assert abs(r - r_opt) <= tol, (r, r_opt)


def test_doctests():
    assert doctest.testmod(ec_module).failed == 0


def test_thousand_random_small_sets_against_brute_force():
    rng = np.random.default_rng(21)
    done = 0
    while done < 1000:
        n = int(rng.integers(3, 9))
        kind = done % 3
        if kind == 0:
            P = rng.integers(0, 6, (n, 2)).astype(float)        # ties: cocircular, collinear, duplicates
        elif kind == 1:
            P = np.round(rng.random((n, 2)) * 256) / 64
        else:
            P = rng.random((n, 2)) * 10 - 5
        try:
            r_opt = brute_force_radius(P)
        except ValueError:
            continue                                           # flat: tested separately
        check_valid(P, largest_empty_circle(P), r_opt)
        done += 1


def small_degenerate_sets():
    rng = np.random.default_rng(4)
    return [
        ("grid5", grid(5)),
        ("grid-rect", grid(2, 9)),
        ("rotated-grid", rotated_grid(5)),
        ("circle", circle(24)),
        ("circle+centre", circle(24, centre=True)),
        ("integer-circle", integer_circle()),
        ("collinear+1", np.vstack([collinear(12), [[0.3, 5.0]]])),
        ("duplicates", np.vstack([grid(4), grid(4)[::3]])),
        ("grid-1e-300", grid(5) * 1e-300),
        ("grid-1e300", grid(5) * 1e300),
        ("random-1e-300", rng.random((20, 2)) * 1e-300),
        ("random-1e300", rng.random((20, 2)) * 1e300),
        ("offset-1e9", rng.random((20, 2)) + 1e9),
        ("clusters", np.vstack([rng.random((8, 2)) * 1e-6, rng.random((8, 2)) * 1e6, rng.random((8, 2)) + 3])),
        ("nearly-collinear-hull", np.vstack([np.c_[np.linspace(0, 1, 12), np.linspace(0, 0.3, 12)
                                                   + np.tile([0, 5.6e-17], 6)], [[0.5, 2.0], [0.2, -1.5]]])),
        ("tutorial", np.array([(1, 1), (3, 2), (5, 1), (4, 4)], dtype=float)),
        ("right-triangle", np.array([(0, 0), (2, 0), (1, 1)], dtype=float)),
        ("obtuse-fan", np.array([(0, 0), (10, 0), (5, 0.5), (5, -0.5), (2, 0.2), (8, -0.2)])),
    ]


@pytest.mark.parametrize("name,pts", small_degenerate_sets(), ids=lambda v: v if isinstance(v, str) else "")
def test_small_degenerate_sets_exact(name, pts):
    check_valid(pts, largest_empty_circle(pts), brute_force_radius(pts))


@pytest.mark.parametrize("name,pts", degenerate_sets(), ids=lambda v: v if isinstance(v, str) else "")
def test_degenerate_sets_valid_and_beat_a_dense_sample(name, pts):
    ans = largest_empty_circle(pts)
    check_valid(pts, ans)
    # lower bound: the best of many points of the hull (a fine grid clipped to the hull)
    P = np.asarray(pts, dtype=float)
    lo, hi = P.min(axis=0), P.max(axis=0)
    g = np.linspace(0, 1, 90)
    Q = lo + (hi - lo) * np.stack(np.meshgrid(g, g), axis=-1).reshape(-1, 2)
    hull = convex_hull_exact(exact_coordinates(P), keep_collinear=False)
    inside = np.ones(len(Q), dtype=bool)
    for a, b in zip(hull, hull[1:] + hull[:1]):
        (ax, ay), (bx, by) = (P[a] - lo) / (hi - lo), (P[b] - lo) / (hi - lo)
        qx, qy = ((Q - lo) / (hi - lo)).T
        inside &= (bx - ax) * (qy - ay) - (by - ay) * (qx - ax) >= 0
    sample = max(float(np.min(np.hypot(P[:, 0] - x, P[:, 1] - y))) for x, y in Q[inside])
    assert ans[2] >= sample * (1 - 1e-9)


def test_grid_answer_is_the_cell_centre():
    cx, cy, r = largest_empty_circle(grid(12) * 3.0)
    assert r == pytest.approx(1.5 * math.sqrt(2), rel=1e-15)
    assert (cx / 3.0) % 1 == 0.5 and (cy / 3.0) % 1 == 0.5
    assert (cx, cy) == (1.5, 1.5)                      # ties: the smallest (x, y)


def test_circle_with_and_without_centre():
    assert largest_empty_circle(circle(400))[2] == pytest.approx(1.0, rel=1e-9)
    assert largest_empty_circle(circle(400, centre=True))[2] == pytest.approx(0.5, rel=1e-3)


def test_nearly_collinear_doubles():
    # (0.1 k, 0.3 k) is collinear on paper, not in doubles: a hull of width ~1e-14, full of slivers
    k = np.arange(800.0)
    P = np.c_[0.1 * k, 0.3 * k]
    ans = largest_empty_circle(P)
    check_valid(P, ans)
    gaps = np.hypot(*np.diff(P, axis=0).T)
    assert ans[2] == pytest.approx(0.5 * gaps.max(), rel=1e-9)


def test_flat_inputs():
    assert largest_empty_circle([(3, 4)]) == (3.0, 4.0, 0.0)
    assert largest_empty_circle([(3, 4), (3, 4)]) == (3.0, 4.0, 0.0)
    assert largest_empty_circle([(0, 0), (2, 2)]) == (1.0, 1.0, math.sqrt(2))
    assert largest_empty_circle([(0, 5), (0, 0), (0, 1), (0, 4)]) == (0.0, 2.5, 1.5)
    # equal longest gaps: the first along the chain
    assert largest_empty_circle([(4, 0), (0, 0), (2, 0)]) == (1.0, 0.0, 1.0)
    pts = collinear(40, seed=3)
    cx, cy, r = largest_empty_circle(pts)
    xs = np.unique(pts[:, 0])
    k = int(np.argmax(np.diff(xs)))
    assert cx == pytest.approx(0.5 * (xs[k] + xs[k + 1]), abs=1e-12)
    assert r == pytest.approx(0.5 * math.hypot(xs[k + 1] - xs[k], 2 * (xs[k + 1] - xs[k])), rel=1e-12)
    assert largest_empty_circle(np.array([(0, 0), (1, 1), (3, 3)]) * 1e300)[2] == pytest.approx(math.sqrt(2) * 1e300)


def test_permutation_gives_identical_answer():
    rng = np.random.default_rng(9)
    for P in (grid(9), rng.integers(0, 5, (30, 2)).astype(float), rng.random((300, 2)), circle(64, True),
              clusters()):
        base = largest_empty_circle(P)
        for _ in range(3):
            assert largest_empty_circle(P[rng.permutation(len(P))]) == base


def test_large_input_is_valid():
    P = np.random.default_rng(0).random((20_000, 2))
    check_valid(P, largest_empty_circle(P))


@given(st.lists(st.tuples(st.integers(-30, 30), st.integers(-30, 30)), min_size=3, max_size=8))
def test_property_matches_brute_force(pts):
    P = np.array(pts, dtype=float)
    try:
        r_opt = brute_force_radius(P)
    except ValueError:
        return
    check_valid(P, largest_empty_circle(P), r_opt)


@pytest.mark.parametrize("bad", [[], [(0, float("nan"))], [(0, 1, 2)], "xy"])
def test_bad_input_raises(bad):
    with pytest.raises(ValueError):
        largest_empty_circle(bad)
