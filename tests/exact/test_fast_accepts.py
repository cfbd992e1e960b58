"""The checkers' fast acceptances agree with their full exact checks, on valid and corrupted answers.

* ``proximity-network`` and ``emst`` accept the reference's own edges at once
  (``reference_impl/exact/edgesets.py``), and ``emst`` compares another tree's lengths only where it
  differs from the reference's: each test here runs the checker as it is and again with those paths
  switched off, on the reference, the reference reordered and reversed, other optimal trees, and
  wrong answers (an edge dropped, repeated, reversed and repeated, replaced, a loop, an index out of
  range, a repeated point named by its larger index); verdict and message must be the same.
* ``verify.check_delaunay``'s numpy pass pairs edges by one sort of packed keys: it must agree with
  the searchsorted pairing it replaced (still used above 2^20 points) and with the integer-only check,
  on Delaunay triangulations, wrong ones (repeated, reversed, dropped, out-of-range triangles) and
  valid triangulations with one edge flipped, given as lists and as integer arrays (the edge-flip
  checker's compiled replay hands its final triangles over as an int64 array).
* The per-list caches (``edgesets.remembered``, largest-empty-circle's hull) follow a list changed
  in place.

Run: ``python -m pytest -q tests/exact/test_fast_accepts.py``
"""
from __future__ import annotations

import math
import random
import types

import numpy as np
import pytest

from grader.problems import load_problem
from reference_impl.exact import bulk, edgesets, verify

GABRIEL = load_problem("proximity-network").checker
EMST = load_problem("emst").checker
LEC = load_problem("largest-empty-circle").checker


def _points(rng: random.Random, kind: str, n: int) -> list[list[float]]:
    """Random, grid (many ties) or grid with repeated points, as lists of floats."""
    if kind == "random":
        return [[rng.random(), rng.random()] for _ in range(n)]
    pts = [[float(rng.randrange(4)) * 0.5, float(rng.randrange(4)) * 0.5] for _ in range(n)]
    if kind == "grid":
        seen: set = set()
        pts = [p for p in pts if tuple(p) not in seen and not seen.add(tuple(p))]
    return pts


def _gabriel(points) -> list[list[int]]:
    """The Gabriel graph by its definition (exact), repeated points named by their smallest index."""
    P = verify.exact_coordinates(points)
    first = [P.index(p) for p in P]
    ids = sorted(set(first))
    return [[i, j] for a, i in enumerate(ids) for j in ids[a + 1:]
            if not any((P[r][0] - P[i][0]) * (P[r][0] - P[j][0]) + (P[r][1] - P[i][1]) * (P[r][1] - P[j][1]) <= 0
                       for r in ids if r != i and r != j)]


def _kruskal(points, rng: random.Random) -> list[list[int]]:
    """A minimum spanning tree (exact lengths), ties broken at random: one of the optimal trees."""
    P = verify.exact_coordinates(points)
    n = len(P)
    pairs = sorted(((P[i][0] - P[j][0]) ** 2 + (P[i][1] - P[j][1]) ** 2, rng.random(), i, j)
                   for i in range(n) for j in range(i + 1, n))
    parent = list(range(n))

    def find(i: int) -> int:
        while parent[i] != i:
            i = parent[i]
        return i

    tree = []
    for _, _, i, j in pairs:
        a, b = find(i), find(j)
        if a != b:
            parent[a] = b
            tree.append([i, j] if rng.random() < 0.5 else [j, i])
    return tree


def _corrupted(edges: list, n: int, rng: random.Random) -> list:
    """The edges, reordered and reversed, and wrong variants of them."""
    out = [edges, [[j, i] for i, j in reversed(edges)]]
    if edges:
        k = rng.randrange(len(edges))
        i, j = edges[k]
        out += [edges[:k] + edges[k + 1:], edges + [edges[k]], edges + [[j, i]], edges[:k] + [[i, i]] + edges[k + 1:],
                edges[:k] + [[i, n]] + edges[k + 1:], edges[:k] + [[-1, j]] + edges[k + 1:]]
        u, v = rng.randrange(n), rng.randrange(n)
        if u != v:
            out += [edges[:k] + [[u, v]] + edges[k + 1:], edges + [[u, v]]]
    return out


def _full(chk, monkeypatch, **off):
    """``chk.check`` with ``edgesets.same_edge_set`` (and the names in ``off``) switched off."""
    def check(args, answer, expected):
        with monkeypatch.context() as m:
            m.setattr(chk, "edgesets", types.SimpleNamespace(same_edge_set=lambda *a: False,
                                                             edge_keys=edgesets.edge_keys,
                                                             remembered=lambda p, r, k, build: build()))
            for name, value in off.items():
                m.setattr(chk, name, value)
            return chk.check(args, answer, expected)
    return check


@pytest.mark.parametrize("kind", ["random", "grid", "repeats"])
def test_gabriel_fast_acceptance_agrees_with_the_full_check(kind, monkeypatch):
    rng = random.Random(kind)
    full = _full(GABRIEL, monkeypatch)
    for _ in range(12):
        points = _points(rng, kind, rng.randrange(3, 14))
        args, expected = [points], _gabriel(points)
        answers = _corrupted(expected, len(points), rng)
        first = [verify.exact_coordinates(points).index(p) for p in verify.exact_coordinates(points)]
        larger = [k for k, f in enumerate(first) if f != k]
        if larger and expected:   # a repeated point named by its larger index
            k = larger[0]
            answers.append([[k if v == first[k] else v for v in e] for e in expected])
        for answer in answers:
            assert GABRIEL.check(args, answer, expected) == full(args, answer, expected), (points, answer)
        assert GABRIEL.check(args, expected, expected) == (True, "ok")


@pytest.mark.parametrize("kind", ["random", "grid", "repeats"])
def test_emst_fast_acceptances_agree_with_the_full_check(kind, monkeypatch):
    rng = random.Random(kind)
    full = _full(EMST, monkeypatch, _lengths_agree_off_common=lambda *a: False)
    verdicts = set()
    for _ in range(12):
        points = _points(rng, kind, rng.randrange(2, 14))
        args, expected = [points], _kruskal(points, rng)
        others = [_kruskal(points, rng) for _ in range(3)]    # on grids: other optimal trees
        longer = [e[:] for e in expected]
        if len(points) > 2:                                  # a spanning tree, not a minimum one (usually)
            longer = [[0, k] for k in range(1, len(points))]
        for answer in _corrupted(expected, len(points), rng) + others + [longer]:
            got = EMST.check(args, answer, expected)
            assert got == full(args, answer, expected), (points, answer)
            verdicts.add(got[0])
    assert verdicts == {True, False}


def test_emst_lengths_compared_off_the_common_edges():
    points = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]   # a unit square: four optimal trees
    expected = [[0, 1], [0, 2], [1, 3]]
    assert EMST._lengths_agree_off_common(points, [[0, 1], [0, 2], [2, 3]], expected)
    assert not EMST._lengths_agree_off_common(points, [[0, 1], [0, 2], [0, 3]], expected)   # a diagonal
    assert not EMST._lengths_agree_off_common(points, [[0, 1], [0, 2], [0, 2]], expected)   # a repeat: ask the full one


def test_remembered_follows_lists_changed_in_place():
    points, reference = [[0.0, 0.0], [1.0, 0.0]], [[0, 1]]
    calls = []

    def build():
        calls.append(1)
        return len(calls)

    assert edgesets.remembered(points, reference, "t", build) == 1
    assert edgesets.remembered(points, reference, "t", build) == 1
    reference[0][1] = 0                                       # the same list, changed in place
    assert edgesets.remembered(points, reference, "t", build) == 2
    points[1][0] = 5.0
    assert edgesets.remembered(points, reference, "t", build) == 3
    assert edgesets.remembered(points, [[0, 0]], "t", build) == 4   # an equal list, another object
    assert edgesets.same_edge_set(points, [[0, 1]], [[1, 0]], lambda: False) is False   # a reference that fails


def test_lec_hull_cache_follows_a_list_changed_in_place():
    points = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [1.0, 1.0]]
    circle = [2.0, 2.0, math.sqrt(2.0)]
    assert LEC.check([points], circle, circle) == (True, "ok")
    points[2][0] = points[2][1] = 1.0   # the hull is now the triangle (0, 0), (4, 0), (0, 4)
    assert LEC._hull_of(points) == LEC.convex_hull(points)
    far = [3.9, 3.9, 0.1]
    assert LEC.check([points], far, far)[1].startswith("the centre (3.9, 3.9) is outside the convex hull")


def _delaunay_answers(rng, kind: str):
    from reference_impl import Delaunay
    n = 200
    if kind == "uniform":
        pts = rng.random((n, 2))
    elif kind == "grid":
        pts = np.array([(x, y) for x in range(15) for y in range(14)], float) * 0.25
    else:
        t = rng.random(n) * 2 * math.pi
        pts = np.c_[np.cos(t), np.sin(t)]
    tris = Delaunay(pts).simplices.tolist()
    k = int(rng.integers(len(tris)))
    a, b, c = tris[k]
    answers = [tris, tris + [tris[k]], tris + [[a, c, b]], tris[:k] + tris[k + 1:], tris[:k] + [[b, c, a]] + tris[k + 1:],
               tris[:k] + [[a, b, -1]] + tris[k + 1:], tris[:k] + [[a, b, len(pts)]] + tris[k + 1:],
               tris[:k] + [[a, b, c], [a, b, c]] + tris[k + 1:], [t[::-1] for t in tris]]
    outer = [t[:] for t in tris]
    outer[k] = [a, b, (c + 1) % len(pts)]
    answers.append(outer)
    return pts.tolist(), answers + _flips(pts.tolist(), tris, 6)


def _flips(points, tris: list, count: int) -> list:
    """Up to ``count`` triangulations with one interior edge flipped each (valid triangulations, not
    Delaunay unless the four points are cocircular), edges taken in both directions."""
    P = verify.exact_coordinates(points)
    opp = {}
    for k, (a, b, c) in enumerate(tris):
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            opp[(u, v)] = (k, w)
    out = []
    for (u, v), (k, w) in opp.items():
        if (v, u) in opp and len(out) < count:
            j, x = opp[(v, u)]
            if verify.orient_exact(P[w], P[x], P[v]) > 0 and verify.orient_exact(P[x], P[w], P[u]) > 0:
                t = [r[:] for r in tris]
                t[k], t[j] = [w, u, x], [x, v, w]
                out.append(t)
    return out


@pytest.mark.parametrize("kind", ["uniform", "grid", "circle"])
def test_delaunay_packed_pairing_agrees_with_searchsorted_and_integers(kind, monkeypatch):
    rng = np.random.default_rng(7)
    points, answers = _delaunay_answers(rng, kind)
    assert len(answers) > 10
    for answer in answers:
        want = verify._check_delaunay_integers(points, answer)
        assert verify.check_delaunay(points, answer, bulk) == want, answer[:3]
        for dtype in (np.int64, np.int32):   # an integer array goes to the numpy pass without lists
            assert verify.check_delaunay(points, np.array(answer, dtype=dtype), bulk) == want, answer[:3]
        with monkeypatch.context() as m:
            m.setattr(verify, "_PACKED_MAX_N", 0)   # the searchsorted pairing, as above 2^20 points
            assert verify.check_delaunay(points, answer, bulk) == want
    assert verify.check_delaunay(points, answers[0], bulk) == (True, "ok")
