"""``Delaunay.remove``: after every removal the triangulation is Delaunay for the live points.

Oracles: a rebuild from scratch of the live points (the same triangle set in general
position, where the Delaunay triangulation is unique), the exact checker
``check_delaunay`` (Python integers; any valid answer when cocircular ties allow several),
the exact convex hull, and the tie-independent Delaunay graph (``strict`` neighbours).
Also the bookkeeping: indices stay stable, removed points appear nowhere, the mesh
stays dense (freed slots are reused), the vertex -> triangle map stays right.

Run: python -m pytest tests/mesh/test_delaunay_remove.py -q
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, strategies as st

import pointsets
from reference_impl import Delaunay
from reference_impl.mesh import kernel as _mesh
from reference_impl.exact.verify import (check_delaunay, convex_hull_exact, exact_coordinates,
                                   orient_exact)
from exact_oracle import canon


def smallest_equal(pts: np.ndarray, live: np.ndarray) -> np.ndarray:
    """For each live index: the smallest live index with the same coordinates; -1 if removed."""
    out = np.full(len(pts), -1)
    first: dict[tuple[float, float], int] = {}
    for i in np.flatnonzero(live):
        out[i] = first.setdefault((pts[i, 0], pts[i, 1]), int(i))
    return out


def assert_valid(d: Delaunay, same_as_rebuild: bool = False) -> None:
    """Everything ``d`` reports is right for its live points."""
    pts, live = d.points, d.live
    L = np.flatnonzero(live)
    im = d.index_map
    assert im.tolist() == smallest_equal(pts, live).tolist()
    s = d.simplices
    if len(s):
        assert live[s].all() and (im[s] == s).all()       # live representatives only
    inv = np.full(len(pts), -1)
    inv[L] = np.arange(len(L))
    ok, msg = check_delaunay(pts[L], inv[s] if len(s) else s)
    assert ok, msg
    fresh = Delaunay(pts[L])
    if same_as_rebuild:
        assert canon(s) == canon(L[fresh.simplices])
    # hull: the exact convex hull (collinear points included); flat: the sorted chain
    expected = [int(L[i]) for i in convex_hull_exact(exact_coordinates(pts[L]))] if len(L) else []
    got = d.hull.tolist()
    if len(s):
        k = expected.index(min(expected))
        assert got == expected[k:] + expected[:k]
    else:
        assert got == expected
    # neighbours of each triangle
    nb = d.neighbors
    for t in range(len(s)):
        for k in range(3):
            o = nb[t, k]
            if o >= 0:
                assert {s[t, (k + 1) % 3], s[t, (k + 2) % 3]} <= set(s[o].tolist()) and t in nb[o]
    # edges and the O(degree) neighbour walk agree, and the strict graph ignores tie-breaking
    e = d.edges()
    adj: dict[int, set[int]] = {}
    for a, b in e.tolist():
        adj.setdefault(a, set()).add(b)
        adj.setdefault(b, set()).add(a)
    for i in L.tolist():
        r = int(im[i])
        assert d.vertex_neighbors(i).tolist() == sorted(adj.get(r, ()))
        got_strict = d.vertex_neighbors(i, strict=True).tolist()
        want_strict = L[fresh.vertex_neighbors(int(inv[r]), strict=True)].tolist()
        assert got_strict == sorted(want_strict)
    # the mesh stays dense: n distinct points (+ INF) on the sphere make 2n - 2 triangles
    if not d._flat:
        nsites = len(np.unique(im[L]))
        ntri = int(d._state[_mesh.S_NTRI])
        assert ntri == 2 * nsites - 2
        if d._dyn:          # the vertex -> triangle map: every mesh vertex, INF included
            M = d._M[:8 * ntri].reshape(ntri, 8)
            for v in np.unique(M[:, :3]).tolist():
                assert v in M[d._start_of[v + 1], :3]


def remove_all(d: Delaunay, order, check_every: int = 1, same_as_rebuild: bool = False) -> None:
    for step, i in enumerate(order):
        d.remove(int(i))
        if step % check_every == 0 or step == len(order) - 1:
            assert_valid(d, same_as_rebuild)


@pytest.fixture(autouse=True)
def no_fallback():
    before = Delaunay.fallbacks
    yield
    assert Delaunay.fallbacks == before, "remove() failed a sanity check and rebuilt"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_random_points_same_as_rebuild_after_every_removal(seed):
    rng = np.random.default_rng(seed)
    pts = rng.random((70, 2))
    remove_all(Delaunay(pts), rng.permutation(len(pts)), same_as_rebuild=True)


@pytest.mark.parametrize("name,pts", pointsets.degenerate_sets(), ids=lambda v: v if isinstance(v, str) else "")
def test_degenerate_sets_stay_delaunay(name, pts):
    rng = np.random.default_rng(len(pts))
    order = rng.permutation(len(pts))
    d = Delaunay(pts)
    remove_all(d, order[:30])                                   # every step checked
    remove_all(d, order[30:], check_every=max(1, (len(pts) - 30) // 8))


@pytest.mark.parametrize("pts", [pointsets.circle(64, centre=True), pointsets.integer_circle()],
                         ids=["circle", "integer-circle"])
def test_removing_the_centre_of_a_circle(pts):
    d = Delaunay(pts)
    centre = len(pts) - 1
    assert len(d.vertex_neighbors(centre)) == len(pts) - 1     # the centre sees the whole ring
    d.remove(centre)
    assert_valid(d)
    assert len(d.simplices) == len(pts) - 3
    remove_all(d, range(0, len(pts) - 1, 2))                     # every other ring point


def test_hull_vertices_one_after_another():
    rng = np.random.default_rng(5)
    d = Delaunay(rng.random((60, 2)))
    while not d._flat:
        d.remove(int(d.hull[len(d.hull) // 2]))
        assert_valid(d, same_as_rebuild=True)


def test_hull_with_collinear_points():
    # a square's sides carry collinear hull points; remove corners and side points
    side = np.arange(5.0)
    pts = np.unique(np.r_[np.c_[side, 0 * side], np.c_[side, 4 + 0 * side], np.c_[0 * side, side],
                          np.c_[4 + 0 * side, side], [[2.0, 2.0], [1.0, 3.0]]], axis=0)
    for first in range(len(pts)):
        d = Delaunay(pts)
        order = [first] + [i for i in range(len(pts)) if i != first]
        remove_all(d, order)


def test_down_to_flat_and_back():
    pts = np.array([(0, 0), (1, 0), (2, 0), (3, 0), (1, 5), (2, -4)], dtype=float)
    d = Delaunay(pts)
    d.remove(4)
    assert_valid(d)
    assert len(d.simplices) == 3
    d.remove(5)                        # only the line is left: flat
    assert d.simplices.shape == (0, 3) and d.hull.tolist() == [0, 1, 2, 3]
    assert d.edges().tolist() == [[0, 1], [1, 2], [2, 3]]
    assert d.vertex_neighbors(1).tolist() == [0, 2] and d.find_simplex((1, 1)) == -1
    assert d.insert((4, 0)) == 6 and d.simplices.shape == (0, 3)   # still on the line
    d.remove(0)
    assert d.edges().tolist() == [[1, 2], [2, 3], [3, 6]]
    assert d.insert((2, 1)) == 7                                   # off the line: triangles again
    assert_valid(d, same_as_rebuild=True)
    assert len(d.simplices) == 3
    d.remove(2)
    assert_valid(d)


def test_remove_everything_then_insert_again():
    rng = np.random.default_rng(7)
    pts = rng.integers(0, 4, (25, 2)).astype(float)
    d = Delaunay(pts)
    remove_all(d, rng.permutation(len(pts)))
    assert d.simplices.shape == (0, 3) and d.hull.tolist() == [] and d.edges().shape == (0, 2)
    assert (d.index_map == -1).all() and not d.live.any()
    for p in [(0, 0), (1, 0), (5, 5), (0, 1)]:
        d.insert(p)
        assert_valid(d)
    assert len(d.simplices) == 2 and d.hull.tolist() == [25, 26, 27, 28]


def test_duplicates_leave_with_their_last_copy():
    pts = np.array([(0, 0), (4, 0), (0, 4), (4, 4), (1, 1), (1, 1), (2, 3), (1, 1)], dtype=float)
    d = Delaunay(pts)
    before = canon(d.simplices)
    assert 4 in d.vertex_neighbors(0)
    d.remove(4)                        # (1, 1) stays, now named 5
    assert_valid(d)
    assert canon(d.simplices) == canon([[5 if v == 4 else v for v in t] for t in before])
    assert d.index_map[[4, 5, 7]].tolist() == [-1, 5, 5]
    assert 5 in d.vertex_neighbors(0) and d.vertex_neighbors(7).tolist() == d.vertex_neighbors(5).tolist()
    d.remove(7)
    d.remove(5)                        # the last copy: (1, 1) leaves the triangulation
    assert_valid(d, same_as_rebuild=True)
    assert 5 not in d.simplices and d.insert((1, 1)) == 8
    assert_valid(d, same_as_rebuild=True)
    assert canon(d.simplices) == canon([[8 if v == 4 else v for v in t] for t in before])


def test_remove_then_reinsert_the_same_point():
    rng = np.random.default_rng(11)
    pts = rng.random((40, 2))
    d = Delaunay(pts)
    before = canon(d.simplices)
    for i in (3, 17, int(d.hull[0])):
        d.remove(i)
        j = d.insert(pts[i])
        assert_valid(d, same_as_rebuild=True)
        before = canon([[j if v == i else v for v in t] for t in before])
        assert canon(d.simplices) == before
    assert len(d.points) == 43 and np.array_equal(d.points[:40], pts)   # rows never move


@pytest.mark.parametrize("scale", [1e-300, 1e300, 2.0 ** -1000])
def test_extreme_scales(scale):
    rng = np.random.default_rng(13)
    pts = rng.random((40, 2)) * scale
    remove_all(Delaunay(pts), rng.permutation(40)[:25], same_as_rebuild=True)
    remove_all(Delaunay(pointsets.grid(5) * scale), rng.permutation(25))


def test_find_simplex_after_removals():
    rng = np.random.default_rng(17)
    pts = rng.random((80, 2))
    d = Delaunay(pts)
    for i in rng.permutation(80)[:50]:
        d.remove(int(i))
    q = rng.random((200, 2)) * 1.2 - 0.1
    t = d.find_simplex(q)
    s = d.simplices
    P = exact_coordinates(np.vstack([pts, q]))
    hull = [int(v) for v in d.hull]
    for k, tk in enumerate(t.tolist()):
        x = P[80 + k]
        if tk >= 0:
            a, b, c = (P[v] for v in s[tk])
            assert min(orient_exact(a, b, x), orient_exact(b, c, x), orient_exact(c, a, x)) >= 0
        else:      # outside: strictly right of some hull edge
            assert any(orient_exact(P[hull[j]], P[hull[(j + 1) % len(hull)]], x) < 0
                       for j in range(len(hull)))


def test_freed_slots_are_reused():
    rng = np.random.default_rng(19)
    d = Delaunay(rng.random((200, 2)))
    cap = d._cap_t, d._cap_v
    for _ in range(3):
        for i in np.flatnonzero(d.live)[rng.permutation(int(d.live.sum()))[:100]]:
            d.remove(int(i))
        for p in rng.random((100, 2)):
            d.insert(p)
        assert (d._cap_t, d._cap_v) == cap          # no growth: removals freed the room
        assert d._state[_mesh.S_NTRI] == 2 * 200 - 2
    assert_valid(d, same_as_rebuild=True)


@pytest.mark.parametrize("bad,message", [
    (-1, "out of range"), (10, "out of range"), (1.0, "integer"), ("3", "integer"),
    (True, "integer"), (None, "integer")])
def test_bad_indices_raise_value_error(bad, message):
    d = Delaunay(pointsets.uniform(10))
    with pytest.raises(ValueError, match=message):
        d.remove(bad)
    with pytest.raises(ValueError, match=message):
        d.vertex_neighbors(bad)
    assert d.live.all()


def test_removing_twice_raises_and_changes_nothing():
    d = Delaunay(pointsets.uniform(10))
    d.remove(np.int64(3))
    before = d.simplices.copy()
    with pytest.raises(ValueError, match="already removed"):
        d.remove(3)
    with pytest.raises(ValueError, match="already removed"):
        d.vertex_neighbors(3)
    assert np.array_equal(before, d.simplices)
    flat = Delaunay([(0, 0), (1, 1)])
    flat.remove(0)
    with pytest.raises(ValueError, match="already removed"):
        flat.remove(0)


ops = st.lists(st.one_of(st.tuples(st.just("insert"), st.integers(-4, 4), st.integers(-4, 4)),
                         st.tuples(st.just("remove"), st.integers(0, 10 ** 6))),
               min_size=1, max_size=40)


@given(start=st.lists(st.tuples(st.integers(-4, 4), st.integers(-4, 4)), max_size=30), ops=ops)
def test_hypothesis_interleaved_inserts_and_removals_on_integer_points(start, ops):
    d = Delaunay(np.array(start, dtype=float).reshape(-1, 2))
    for op in ops:
        if op[0] == "insert":
            d.insert((op[1], op[2]))
        else:
            live = np.flatnonzero(d.live)
            if not len(live):
                continue
            d.remove(int(live[op[1] % len(live)]))
        assert_valid(d)
