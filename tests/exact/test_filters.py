"""The exact checkers' float filters never decide a sign wrongly, and the fast passes never accept
what the integer-only checks reject.

``verify``'s one-at-a-time filters (``orient_filtered``, ``incircle_filtered``) and ``bulk``'s
numpy ones return a sign only where a proven error bound decides it; these tests hold them to the
Python-integer predicates on random, near-degenerate (grid, cocircular, cospherical, one ulp off)
and badly scaled inputs, and compare ``check_delaunay`` / ``check_delaunay_3d`` (fast pass, with
and without ``bulk``) with their integer-only versions on valid and corrupted answers.

Run: ``python -m pytest -q tests/exact/test_filters.py``
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from reference_impl.exact import bulk, verify
from reference_impl.exact.verify import (exact_coordinates, exact_coordinates_3d, incircle_exact, insphere_exact,
                                         orient3d_exact, orient_exact)


def _near_degenerate_2d(rng, n: int) -> np.ndarray:
    """Grid points, points on a circle, and both nudged by one ulp here and there."""
    grid = np.array([(x, y) for x in range(8) for y in range(8)], dtype=float) * 0.1
    t = rng.random(n) * 2 * math.pi
    circle = np.c_[np.cos(t), np.sin(t)]
    pts = np.concatenate([grid, circle, rng.random((n, 2))])
    nudge = (rng.random(pts.shape) < 0.2) & (pts != 0)   # (one ulp above 0 would leave the filters' range)
    pts[nudge] = np.nextafter(pts[nudge], np.inf)
    return pts


def _sign_cases(rng, dim: int, k: int, count: int):
    """``count`` tuples of ``k`` point indices into a near-degenerate set (repeats allowed)."""
    pts = _near_degenerate_2d(rng, 200) if dim == 2 else np.concatenate(
        [np.array([(x, y, z) for x in range(4) for y in range(4) for z in range(4)], float),
         rng.normal(size=(200, 3)) / np.linalg.norm(rng.normal(size=(200, 3)), axis=1)[:, None], rng.random((200, 3))])
    idx = rng.integers(0, len(pts), size=(count, k))
    return pts, idx


@pytest.mark.parametrize("seed", range(3))
def test_2d_filters_agree_with_integers(seed):
    rng = np.random.default_rng(seed)
    pts, idx = _sign_cases(rng, 2, 4, 20000)
    F = [tuple(p) for p in pts.tolist()]
    P = exact_coordinates(F)
    assert verify._tame(F)
    o = bulk.orient2d(*(pts[idx[:, j], i] for j in range(3) for i in range(2)))
    c = bulk.incircle(*(pts[idx[:, j], i] for j in range(4) for i in range(2)))
    undecided = [0, 0]
    for k, (a, b, cc, d) in enumerate(idx.tolist()):
        so, si = orient_exact(P[a], P[b], P[cc]), incircle_exact(P[a], P[b], P[cc], P[d])
        assert verify.orient_filtered(F, P, a, b, cc) == so
        assert verify.incircle_filtered(F, P, a, b, cc, d) == si
        assert o[k] in (0, so) and c[k] in (0, si), (k, F[a], F[b], F[cc], F[d])
        undecided[0] += o[k] == 0
        undecided[1] += c[k] == 0
    assert 0 < undecided[1] < len(idx)  # the degenerate cases reach the integers, most do not


@pytest.mark.parametrize("seed", range(2))
def test_3d_filters_agree_with_integers(seed):
    rng = np.random.default_rng(seed)
    pts, idx = _sign_cases(rng, 3, 5, 20000)
    Q = exact_coordinates_3d(pts.tolist())
    o = bulk.orient3d(*(pts[idx[:, j]] for j in range(4)))
    s = bulk.insphere(*(pts[idx[:, j]] for j in range(5)))
    for k, (a, b, c, d, e) in enumerate(idx.tolist()):
        assert o[k] in (0, orient3d_exact(Q[a], Q[b], Q[c], Q[d]))
        assert s[k] in (0, insphere_exact(Q[a], Q[b], Q[c], Q[d], Q[e]))
    assert (o != 0).mean() > 0.5 and (s != 0).mean() > 0.5


def test_untame_sets_are_left_to_the_integers():
    for pts in ([(1e-300, 0.0), (2e-300, 1e-300), (0.0, 3e-300)], [(1e200, 0.0), (0.0, 1e200), (1.0, 1.0)]):
        assert not verify._tame(pts)
        P, _, orient, incircle = verify.indexed_predicates(pts)
        assert orient(0, 1, 2) == orient_exact(*P)


def _corruptions(tris: np.ndarray, rng) -> list:
    """Valid triangles, and wrong variants: a clockwise triangle, one dropped, one duplicated,
    an edge flipped, two vertices swapped between triangles, an index out of range."""
    out = [tris.tolist()]
    t = tris.copy()
    t[0, [1, 2]] = t[0, [2, 1]]
    out.append(t.tolist())
    out.append(tris[1:].tolist())
    out.append(tris.tolist() + [tris[0].tolist()])
    k = int(rng.integers(len(tris)))
    t = tris.copy()
    t[k, 0] = t[(k + 1) % len(tris), 0]
    out.append(t.tolist())
    out.append(tris.tolist()[:-1] + [[0, 1, len(tris) * 9]])
    return out


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("kind", ["uniform", "grid", "circle"])
def test_check_delaunay_fast_pass_agrees(seed, kind):
    from reference_impl import Delaunay
    rng = np.random.default_rng(seed)
    n = 300
    if kind == "uniform":
        pts = rng.random((n, 2))
    elif kind == "grid":
        pts = np.array([(x, y) for x in range(18) for y in range(17)], float) * 0.5
    else:
        t = rng.random(n) * 2 * math.pi
        pts = np.c_[np.cos(t), np.sin(t)]
    tris = Delaunay(pts).simplices
    points = pts.tolist()
    flips = _flip_one(points, tris)
    for answer in _corruptions(tris, rng) + flips:
        want = verify._check_delaunay_integers(points, answer)
        assert verify.check_delaunay(points, answer) == want
        assert verify.check_delaunay(points, answer, bulk) == want


def _flip_one(points, tris) -> list:
    """The triangulation with one interior edge flipped (a valid triangulation, not Delaunay unless cocircular)."""
    opp = {}
    for k, (a, b, c) in enumerate(tris.tolist()):
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            opp[(u, v)] = (k, w)
    for (u, v), (k, w) in opp.items():
        if (v, u) in opp:
            j, x = opp[(v, u)]
            P = exact_coordinates(points)
            if orient_exact(P[w], P[x], P[v]) > 0 and orient_exact(P[x], P[w], P[u]) > 0:
                t = [list(r) for r in tris.tolist()]
                t[k], t[j] = [w, u, x], [x, v, w]
                return [t]
    return []


def test_the_cache_follows_a_list_changed_in_place():
    pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]
    tris = [[0, 1, 3], [0, 3, 2]]
    assert verify.check_delaunay(pts, tris) == (True, "ok")
    pts[3][0] = pts[3][1] = 2.0   # the same list, changed in place: point 2 is now inside circle (0, 1, 3)
    assert verify.check_delaunay(pts, tris) == verify._check_delaunay_integers(pts, tris)
    assert not verify.check_delaunay(pts, tris)[0]


@pytest.mark.parametrize("seed", range(2))
def test_check_delaunay_3d_fast_pass_agrees(seed):
    from reference_impl import delaunay_3d
    rng = np.random.default_rng(seed)
    for pts in (rng.random((120, 3)), np.array([(x, y, z) for x in range(4) for y in range(4) for z in range(3)], float)):
        tets = np.asarray(delaunay_3d(pts).simplices if hasattr(delaunay_3d(pts), "simplices") else delaunay_3d(pts))
        points = pts.tolist()
        answers = [tets.tolist(), tets[1:].tolist(), tets.tolist() + [tets[0].tolist()]]
        t = tets.copy()
        t[0, 0] = t[1, 0] if t[1, 0] not in t[0] else t[2, 0]
        answers.append(t.tolist())
        for answer in answers:
            want = verify._check_delaunay_3d_integers(points, answer)
            assert verify.check_delaunay_3d(points, answer) == want
            assert verify.check_delaunay_3d(points, answer, bulk) == want
