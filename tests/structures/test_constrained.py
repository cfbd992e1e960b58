"""Tests for reference_impl.structures.constrained: the constrained Delaunay triangulation.

Run:  .venv/bin/python -m pytest tests/structures/test_constrained.py -q

Oracles: Shewchuk's Triangle (the ``triangle`` package, 'p' switch) on inputs in
general position, where the CDT is unique; an exact checker written here with
Python integers (``verify.exact_coordinates``): positive orientation, the
triangles tile the convex hull, every segment is a chain of edges, every other
interior edge is locally Delaunay (which implies constrained Delaunay);
hand-made degenerate sets.  Polygons with holes are tested in test_navmesh.py.

The tests marked ``slow`` (at the end; until issue 9 they were ``test_constrained_1000.py``;
``-m "not slow"`` leaves them out): constrained_delaunay on 1000 random small cases and every
degenerate family, against oracles.

Oracles (nothing shared with the library):

* Shewchuk's Triangle (``triangle.triangulate(..., 'pc')``) on points in general
  position, where the constrained Delaunay triangulation is unique: the same set of
  triangles, and Triangle added no Steiner point;
* an exact checker written here on Python integers (every float times one common
  power of two): triangles strictly counter-clockwise, no directed edge used twice,
  the edges with one triangle are exactly the convex hull cycle (so the triangles
  tile the hull), every distinct point a vertex, neighbours consistent, every
  segment present as a chain of edges split at the points on it, the constraint
  edges reported are exactly those, and every other interior edge locally Delaunay
  (which makes the triangulation constrained Delaunay);
* an exact proper-crossing test: a segment that properly crosses another one must
  raise ``ValueError``.
"""
from __future__ import annotations

import math
import zlib

import numpy as np
import pytest
import triangle
from hypothesis import given, settings, strategies as st

import pointsets
from exact_oracle import exact, incircle, orient
from reference_impl.structures.constrained import ConstrainedDelaunay, canonical_segments, constrained_delaunay
from reference_impl.exact.verify import (convex_hull_exact, exact_coordinates, incircle_exact,
                                   orient_exact)


# ----------------------------------------------------------------------------- exact checker
def _between(P, i, j, k) -> bool:
    """Point k strictly inside segment i-j (exact)."""
    if orient_exact(P[i], P[j], P[k]) != 0 or P[k] in (P[i], P[j]):
        return False
    return (min(P[i], P[j]) < P[k] < max(P[i], P[j]))  # lexicographic order along the line


def required_edges(P, segments) -> set[tuple[int, int]]:
    """Each segment split at the points lying on it, as sorted index pairs of representatives."""
    first: dict = {}
    for i, p in enumerate(P):
        first.setdefault(p, i)
    out = set()
    distinct = sorted(set(first.values()))
    for i, j in segments:
        i, j = first[P[i]], first[P[j]]
        if i == j:
            continue
        chain = sorted([i, j] + [k for k in distinct if _between(P, i, j, k)], key=lambda k: P[k])
        out.update((min(u, v), max(u, v)) for u, v in zip(chain, chain[1:]))
    return out


def assert_valid_cdt(points, segments, cdt: ConstrainedDelaunay) -> None:
    P = exact_coordinates(points)
    T = [tuple(t) for t in cdt.simplices.tolist()]
    first: dict = {}
    for i, p in enumerate(P):
        first.setdefault(p, i)
    distinct = sorted(set(first.values()))
    hull = convex_hull_exact(P)
    if len(distinct) < 3 or all(orient_exact(P[hull[0]], P[hull[-1]], P[i]) == 0 for i in distinct):
        assert T == []
        return
    for t in T:
        assert orient_exact(*(P[v] for v in t)) > 0, f"triangle {t} not counter-clockwise"
    opposite = {}
    for t in T:
        for k in range(3):
            e = (t[(k + 1) % 3], t[(k + 2) % 3])
            assert e not in opposite, f"directed edge {e} used twice: overlap"
            opposite[e] = t[k]
    hull_edges = {(hull[i], hull[(i + 1) % len(hull)]) for i in range(len(hull))}
    boundary = {e for e in opposite if (e[1], e[0]) not in opposite}
    assert boundary == hull_edges, "triangles do not tile the convex hull"
    assert {v for t in T for v in t} == set(distinct), "some point is not a vertex"
    # neighbours agree with the triangles
    for ti, t in enumerate(T):
        for k in range(3):
            o = cdt.neighbors[ti, k]
            u, v = t[(k + 1) % 3], t[(k + 2) % 3]
            if o < 0:
                assert (u, v) in hull_edges
            else:
                assert {u, v} <= set(T[o])
    req = required_edges(P, segments)
    present = {(min(u, v), max(u, v)) for (u, v) in opposite}
    assert req <= present, f"constraint edges missing: {sorted(req - present)[:5]}"
    assert {tuple(e) for e in cdt.constraint_edges().tolist()} == req
    for (u, v), w in opposite.items():
        x = opposite.get((v, u))
        if x is not None and (min(u, v), max(u, v)) not in req:
            assert incircle_exact(P[u], P[v], P[w], P[x]) <= 0, f"edge {u}-{v} not locally Delaunay"


def _crosses(P, a, b, c, d) -> bool:
    """Closed segments a-b and c-d meet somewhere other than a shared endpoint (exact)."""
    shared = {a, b} & {c, d}
    if shared:
        (s,) = shared if len(shared) == 1 else (None,)
        if s is None:
            return True
        x = c if d == s else d
        y = a if b == s else b
        return orient_exact(P[s], P[x], P[y]) == 0 and (P[x] > P[s]) == (P[y] > P[s])
    o1, o2 = orient_exact(P[a], P[b], P[c]), orient_exact(P[a], P[b], P[d])
    o3, o4 = orient_exact(P[c], P[d], P[a]), orient_exact(P[c], P[d], P[b])
    if o1 == o2 == 0:
        return max(min(P[a], P[b]), min(P[c], P[d])) <= min(max(P[a], P[b]), max(P[c], P[d]))
    return o1 * o2 <= 0 and o3 * o4 <= 0


def random_segments(rng, pts, count, allow_touch=False):
    """Random segments that pairwise meet only at shared endpoints (or anywhere on a line if allow_touch)."""
    P = exact_coordinates(pts)
    segs: list[tuple[int, int]] = []
    for _ in range(count):
        a, b = (int(v) for v in rng.choice(len(pts), 2, replace=False))
        if P[a] == P[b]:
            continue
        if not allow_touch and any(_between(P, a, b, k) for k in range(len(P))):
            continue
        ok = True
        for c, d in segs:
            if allow_touch:
                o1, o2 = orient_exact(P[a], P[b], P[c]), orient_exact(P[a], P[b], P[d])
                o3, o4 = orient_exact(P[c], P[d], P[a]), orient_exact(P[c], P[d], P[b])
                if o1 * o2 < 0 and o3 * o4 < 0:
                    ok = False
            elif _crosses(P, a, b, c, d):
                ok = False
            if not ok:
                break
        if ok:
            segs.append((a, b))
    return np.array(segs, dtype=np.int64).reshape(-1, 2)


def triangle_set(tris) -> set:
    return {frozenset(t) for t in np.asarray(tris).reshape(-1, 3).tolist()}


# ----------------------------------------------------------------------------- CDT
@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(3, 70))
def test_matches_triangle_in_general_position(seed, n):
    rng = np.random.default_rng(seed)
    pts = rng.random((n, 2))
    segs = random_segments(rng, pts, 2 * n)
    cdt = ConstrainedDelaunay(pts, segs)
    assert_valid_cdt(pts, segs, cdt)
    data = {"vertices": pts}
    if len(segs):
        data["segments"] = segs
    ref = triangle.triangulate(data, "pc" if len(segs) else "c")
    assert len(ref["vertices"]) == n          # Triangle added no Steiner point
    assert triangle_set(cdt.simplices) == triangle_set(ref["triangles"])


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), side=st.integers(2, 8))
def test_grid_with_segments_through_vertices(seed, side):
    """Integer grid: cocircular everywhere, segments pass through grid points and overlap."""
    rng = np.random.default_rng(seed)
    g = np.arange(side, dtype=float)
    pts = np.array([(x, y) for x in g for y in g])
    segs = random_segments(rng, pts, 3 * side, allow_touch=True)
    cdt = ConstrainedDelaunay(pts, segs)
    assert_valid_cdt(pts, segs, cdt)
    # the same triangles (ties included) whatever the order of the segments, their
    # direction, and the order of the points
    perm = rng.permutation(len(segs))
    again = ConstrainedDelaunay(pts, segs[perm][:, ::-1])
    assert triangle_set(again.simplices) == triangle_set(cdt.simplices)
    shuffle = rng.permutation(len(pts))
    moved = ConstrainedDelaunay(pts[shuffle], np.argsort(shuffle)[segs])
    assert triangle_set(shuffle[moved.simplices]) == triangle_set(cdt.simplices)


def test_canonical_segments_is_a_stable_lexsort():
    """canonical_segments (a merge sort in numba) against numpy's stable lexsort, with many ties."""
    rng = np.random.default_rng(3)
    for k in (0, 1, 2, 3, 7, 64, 1000):
        pts = rng.integers(0, 4, (40, 2)).astype(float)
        seg = rng.integers(0, 40, (k, 2))
        X, Y = pts[:, 0].copy(), pts[:, 1].copy()
        a, b = seg[:, 0], seg[:, 1]
        swap = (X[a] > X[b]) | ((X[a] == X[b]) & (Y[a] > Y[b]))
        ends = np.where(swap[:, None], seg[:, ::-1], seg)
        want = np.lexsort((Y[ends[:, 1]], X[ends[:, 1]], Y[ends[:, 0]], X[ends[:, 0]]))
        oriented, order = canonical_segments(seg, X, Y)
        assert order.tolist() == want.tolist()
        assert oriented.tolist() == ends[want].tolist()


def test_segment_through_vertex_is_split():
    pts = [(0, 0), (2, 0), (4, 0), (2, 2), (2, -2)]
    cdt = ConstrainedDelaunay(pts, [(3, 4)])        # vertical through (2, 0)
    assert cdt.constraint_edges().tolist() == [[1, 3], [1, 4]]
    assert_valid_cdt(pts, [(3, 4)], cdt)


def test_segment_crossing_all_triangles_around_a_vertex():
    """Regression: the segment crosses every triangle around vertex 10 (a cavity with an inner vertex)."""
    pts = np.array([[0.01985877, 0.28875428], [0.53859445, 0.88773283], [0.16499393, 0.31096842],
                    [0.0976338, 0.37640609], [0.08718824, 0.3704421], [0.27121365, 0.62668673],
                    [0.16228733, 0.72021178]])
    d = ConstrainedDelaunay(pts)
    fan = [t for t in d.simplices.tolist() if 3 in t]
    P = exact_coordinates(pts)
    crossed = [t for t in fan if any(orient_exact(P[0], P[1], P[v]) > 0 for v in t)
               and any(orient_exact(P[0], P[1], P[v]) < 0 for v in t)]
    assert len(crossed) == len(fan) >= 3         # the premise: all of vertex 3's triangles are crossed
    cdt = ConstrainedDelaunay(pts, [(0, 1)])
    assert_valid_cdt(pts, [(0, 1)], cdt)


def test_collinear_overlapping_and_shared_endpoints():
    pts = [(0, 0), (1, 0), (2, 0), (3, 0), (1.5, 1), (1.5, -1), (1.5, 3)]
    segs = [(0, 2), (1, 3), (0, 3), (4, 6), (4, 0), (4, 3), (5, 0), (5, 3)]
    cdt = ConstrainedDelaunay(pts, segs)
    assert_valid_cdt(pts, segs, cdt)
    assert {(0, 1), (1, 2), (2, 3)} <= {tuple(e) for e in cdt.constraint_edges().tolist()}


def test_crossing_segments_raise_naming_both():
    pts = [(0, 0), (2, 2), (0, 2), (2, 0), (5, 5)]
    with pytest.raises(ValueError, match=r"segments\[2\].*crosses segments\[0\]"):
        ConstrainedDelaunay(pts, [(0, 1), (1, 4), (2, 3)])


def test_crossing_at_a_shared_vertex_is_allowed():
    pts = [(0, 0), (2, 2), (0, 2), (2, 0), (1, 1)]
    cdt = ConstrainedDelaunay(pts, [(0, 1), (2, 3)])   # both pass through point 4
    assert cdt.constraint_edges().tolist() == [[0, 4], [1, 4], [2, 4], [3, 4]]


def test_duplicates_zero_length_and_collinear_input():
    pts = [(0, 0), (1, 0), (0, 1), (0, 0), (1, 1)]
    cdt = ConstrainedDelaunay(pts, [(0, 3), (3, 4)])   # 0-3 has zero length; 3 is 0's duplicate
    assert cdt.index_map.tolist() == [0, 1, 2, 0, 4]
    assert cdt.constraint_edges().tolist() == [[0, 4]]
    assert_valid_cdt(pts, [(0, 4)], cdt)
    flat = ConstrainedDelaunay([(0, 0), (1, 1), (2, 2)], [(0, 2)])
    assert flat.simplices.shape == (0, 3) and flat.constraint_edges().shape == (0, 2)
    assert ConstrainedDelaunay([(0, 0), (1, 0)], [(0, 1)]).simplices.shape == (0, 3)


@pytest.mark.parametrize("segments, message", [
    ([(0, 5)], "outside"),
    ([(0, -1)], "outside"),
    ([(0.0, 1.0)], "integer"),
    ([(0, 1, 2)], "shape"),
    ("01", "text"),
])
def test_bad_segments_raise(segments, message):
    with pytest.raises(ValueError, match=message):
        ConstrainedDelaunay([(0, 0), (1, 0), (0, 1)], segments)


def test_bad_points_raise():
    with pytest.raises(ValueError, match="not finite"):
        constrained_delaunay([(0, 0), (1, math.nan), (0, 1)], [])


@pytest.mark.parametrize("scale", [1e-300, 1e-5, 1e300])
def test_scale_invariance(scale):
    rng = np.random.default_rng(7)
    pts = rng.random((40, 2))
    segs = random_segments(rng, pts, 60)
    base = triangle_set(constrained_delaunay(pts, segs))
    scaled = ConstrainedDelaunay(pts * scale, segs)
    assert triangle_set(scaled.simplices) == base
    assert_valid_cdt(pts * scale, segs, scaled)


# =================================================================================================
# slow: 1000 random small cases and every degenerate family (was test_constrained_1000.py)
# =================================================================================================
CASES = 1000


# ----------------------------------------------------------------------------- exact arithmetic


def strictly_between(P, a, b, k) -> bool:
    """Point k lies in the open segment a-b."""
    if orient(P[a], P[b], P[k]) != 0 or P[k] in (P[a], P[b]):
        return False
    return min(P[a], P[b]) < P[k] < max(P[a], P[b])


def proper_cross(P, a, b, c, d) -> bool:
    """Segments a-b and c-d cross at a single point interior to both."""
    o1, o2 = orient(P[a], P[b], P[c]), orient(P[a], P[b], P[d])
    o3, o4 = orient(P[c], P[d], P[a]), orient(P[c], P[d], P[b])
    return o1 * o2 < 0 and o3 * o4 < 0


def hull_cycle(P, idx) -> list[int]:
    """Convex hull of the points idx (distinct), counter-clockwise, collinear boundary points kept."""
    order = sorted(idx, key=lambda i: P[i])

    def chain(seq):
        out: list[int] = []
        for i in seq:
            while len(out) >= 2 and orient(P[out[-2]], P[out[-1]], P[i]) < 0:
                out.pop()
            out.append(i)
        return out

    return chain(order)[:-1] + chain(order[::-1])[:-1]


def required_edges_of_representatives(P, rep, distinct, segments) -> set[tuple[int, int]]:
    """Every segment split at the points lying on it, as sorted pairs of representatives."""
    out = set()
    for a, b in segments:
        a, b = rep[a], rep[b]
        if a == b:
            continue
        chain = sorted([a, b] + [k for k in distinct if strictly_between(P, a, b, k)], key=lambda k: P[k])
        out.update((min(u, v), max(u, v)) for u, v in zip(chain, chain[1:]))
    return out


def check_cdt(points, segments, tris, neighbors=None, constraint_edges=None) -> None:
    """Exact: ``tris`` is the constrained Delaunay triangulation of points and segments."""
    P = exact(points)
    first: dict = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    distinct = sorted(set(rep))
    T = [tuple(t) for t in np.asarray(tris).reshape(-1, 3).tolist()]
    flat = len(distinct) < 3 or all(orient(P[distinct[0]], P[distinct[1]], P[k]) == 0 for k in distinct)
    if flat:
        assert T == [], "collinear input (or < 3 distinct points) must give no triangles"
        return
    for t in T:
        assert all(v == rep[v] for v in t), f"triangle {t} uses a duplicate, not its representative"
        assert orient(*(P[v] for v in t)) > 0, f"triangle {t} is not strictly counter-clockwise"
    apex = {}
    for t in T:
        for k in range(3):
            e = (t[(k + 1) % 3], t[(k + 2) % 3])
            assert e not in apex, f"directed edge {e} used twice: triangles overlap"
            apex[e] = t[k]
    hull = hull_cycle(P, distinct)
    hull_edges = {(hull[i], hull[(i + 1) % len(hull)]) for i in range(len(hull))}
    boundary = {e for e in apex if (e[1], e[0]) not in apex}
    assert boundary == hull_edges, "the triangles do not tile the convex hull"
    assert {v for t in T for v in t} == set(distinct), "a point is not a vertex"
    if neighbors is not None:
        N = np.asarray(neighbors).tolist()
        for i, t in enumerate(T):
            for k in range(3):
                u, v = t[(k + 1) % 3], t[(k + 2) % 3]
                o = N[i][k]
                assert (o < 0) == ((v, u) not in apex), f"neighbour {i},{k} wrong"
                if o >= 0:
                    assert set(T[o]) == {u, v, apex[(v, u)]}, f"neighbour {i},{k} wrong"
    req = required_edges_of_representatives(P, rep, distinct, segments)
    present = {(min(e), max(e)) for e in apex}
    assert req <= present, f"constraint edges missing: {sorted(req - present)[:5]}"
    if constraint_edges is not None:
        assert {tuple(e) for e in np.asarray(constraint_edges).tolist()} == req
    for (u, v), w in apex.items():
        x = apex.get((v, u))
        if x is not None and (min(u, v), max(u, v)) not in req:
            assert incircle(P[u], P[v], P[w], P[x]) <= 0, f"edge {u}-{v} is not locally Delaunay"


# ----------------------------------------------------------------------------- generators
def random_exact_segments(rng, P, count, touch=False) -> np.ndarray:
    """Random segments meeting only at shared endpoints (touch: anywhere but a proper crossing)."""
    segs: list[tuple[int, int]] = []
    n = len(P)
    for _ in range(count):
        a, b = (int(v) for v in rng.choice(n, 2, replace=False))
        if P[a] == P[b] and not touch:
            continue
        if not touch and any(strictly_between(P, a, b, k) for k in range(n)):
            continue
        ok = True
        for c, d in segs:
            if proper_cross(P, a, b, c, d):
                ok = False
            elif not touch and len({a, b, c, d}) == 4 and (
                    any(strictly_between(P, c, d, k) for k in (a, b))
                    or any(strictly_between(P, a, b, k) for k in (c, d))):
                ok = False
            if not ok:
                break
        if ok:
            segs.append((a, b))
    return np.array(segs, dtype=np.int64).reshape(-1, 2)


def coordinate_set(points, tris) -> set:
    pts = np.asarray(points, dtype=float)
    return {frozenset(map(tuple, pts[t].tolist())) for t in np.asarray(tris).reshape(-1, 3)}


# ----------------------------------------------------------------------------- 1000 random cases
@pytest.mark.slow
def test_1000_random_cases_match_triangle_and_exact_checker():
    rng = np.random.default_rng(20240611)
    crossing_cases = 0
    for case in range(CASES):
        n = int(rng.integers(4, 16))
        pts = rng.random((n, 2)) * (10.0 ** rng.integers(-3, 4))
        P = exact(pts)
        segs = random_exact_segments(rng, P, int(rng.integers(0, 2 * n)))
        tris = constrained_delaunay(pts, segs)
        cdt = ConstrainedDelaunay(pts, segs)
        assert np.array_equal(tris, cdt.simplices), case
        check_cdt(pts, segs, tris, cdt.neighbors, cdt.constraint_edges())
        data = {"vertices": pts}
        if len(segs):
            data["segments"] = segs
        ref = triangle.triangulate(data, "pc" if len(segs) else "c")
        assert len(ref["vertices"]) == n, f"case {case}: Triangle added a Steiner point"
        assert triangle_set(tris) == triangle_set(ref["triangles"]), f"case {case}: differs from Triangle"
        # one more random segment: a proper crossing must raise, anything else must work
        a, b = (int(v) for v in rng.choice(n, 2, replace=False))
        more = np.vstack([segs, [(a, b)]])
        if any(proper_cross(P, a, b, c, d) for c, d in segs.tolist()):
            crossing_cases += 1
            with pytest.raises(ValueError, match="properly crosses"):
                constrained_delaunay(pts, more)
        else:
            check_cdt(pts, more, constrained_delaunay(pts, more))
    assert crossing_cases > CASES // 10             # both branches were exercised


@pytest.mark.slow
def test_1000_random_integer_grid_cases_exact_checker():
    """Small integer grids: cocircular everywhere, segments through vertices, collinear overlaps,
    T-junctions, duplicates; the answer must be valid and not depend on the input order."""
    rng = np.random.default_rng(7)
    for case in range(CASES):
        side = int(rng.integers(2, 5))
        g = [(x, y) for x in range(side) for y in range(int(rng.integers(1, 5)))]
        pts = np.array(g, dtype=float)[rng.permutation(len(g))][: int(rng.integers(3, 16))]
        if rng.random() < 0.3:                                  # duplicates
            pts = np.vstack([pts, pts[rng.integers(0, len(pts), 3)]])
        n = len(pts)
        if n < 2:
            continue
        P = exact(pts)
        segs = random_exact_segments(rng, P, int(rng.integers(0, 2 * n)), touch=True)
        cdt = ConstrainedDelaunay(pts, segs)
        check_cdt(pts, segs, cdt.simplices, cdt.neighbors, cdt.constraint_edges())
        perm = rng.permutation(n)
        inv = np.argsort(perm)
        again = constrained_delaunay(pts[perm], inv[segs][:, ::-1] if len(segs) else segs)
        assert coordinate_set(pts[perm], again) == coordinate_set(pts, cdt.simplices), case


# ----------------------------------------------------------------------------- degenerate families
DEGENERATE = pointsets.degenerate_sets() + pointsets.flat_sets() + [
    ("grid+1e9", pointsets.grid(6) + 1e9),
    ("grid-0.5+1e9", pointsets.grid(6) * 0.5 + 1e9),
    ("rotated-grid+1e9", pointsets.rotated_grid(6) + 1e9),
    ("collinear+2", np.vstack([pointsets.collinear(12), [[0.3, 5.0], [0.1, -4.0]]])),
]


@pytest.mark.slow
@pytest.mark.parametrize("name,pts", DEGENERATE, ids=[d[0] for d in DEGENERATE])
def test_degenerate_families(name, pts):
    rng = np.random.default_rng(zlib.crc32(name.encode()))      # hash() is salted per process
    P = exact(pts)
    n = len(pts)
    for trial in range(3):
        segs = random_exact_segments(rng, P, min(3 * n, 120), touch=trial > 0) if n >= 2 else \
            np.zeros((0, 2), dtype=np.int64)
        cdt = ConstrainedDelaunay(pts, segs)
        check_cdt(pts, segs, cdt.simplices, cdt.neighbors, cdt.constraint_edges())
        assert np.array_equal(constrained_delaunay(pts, segs), cdt.simplices)
        perm = rng.permutation(n)
        inv = np.argsort(perm)
        moved = constrained_delaunay(pts[perm], inv[segs] if len(segs) else segs)
        assert coordinate_set(pts[perm], moved) == coordinate_set(pts, cdt.simplices)


@pytest.mark.slow
@pytest.mark.parametrize("scale", [2.0 ** -1000, 1e-300, 1e-5, 1e300, 2.0 ** 1000])
def test_scaled_and_offset_rooms(scale):
    """A room outline with collinear vertices and a diagonal wall: the same triangles at any scale."""
    outline = [(x, 0) for x in range(5)] + [(4, y) for y in range(1, 5)] + \
              [(x, 4) for x in range(3, -1, -1)] + [(0, y) for y in range(3, 0, -1)]
    inner = [(1, 1), (2, 1), (3, 1), (3, 3), (1, 3), (2, 2)]
    pts = np.array(outline + inner, dtype=float)
    k = len(outline)
    segs = np.array([(i, (i + 1) % k) for i in range(k)] + [(k, k + 2), (k + 2, k + 3), (k + 4, k + 3),
                                                            (k + 5, 0)], dtype=np.int64)
    base = ConstrainedDelaunay(pts, segs)
    check_cdt(pts, segs, base.simplices, base.neighbors, base.constraint_edges())
    cdt = ConstrainedDelaunay(pts * scale, segs)
    check_cdt(pts * scale, segs, cdt.simplices, cdt.neighbors, cdt.constraint_edges())
    assert triangle_set(cdt.simplices) == triangle_set(base.simplices)
    if scale >= 1e-5:                          # offsets of 1e9 (1e9 + tiny would merge points)
        p = pts * scale + 1e9
        cdt = ConstrainedDelaunay(p, segs)
        check_cdt(p, segs, cdt.simplices, cdt.neighbors, cdt.constraint_edges())
        if scale >= 1:                         # exact after the offset: the same triangles
            assert triangle_set(cdt.simplices) == triangle_set(base.simplices)


@pytest.mark.slow
def test_crossing_and_duplicate_errors():
    pts = np.array([(0, 0), (2, 2), (0, 2), (2, 0), (1, 1), (0, 0)], dtype=float)
    with pytest.raises(ValueError, match="properly crosses"):
        constrained_delaunay(pts[:4], [(0, 1), (2, 3)])
    # crossing exactly at a vertex is allowed (both are split there)
    cdt = ConstrainedDelaunay(pts, [(0, 1), (2, 3)])
    check_cdt(pts, [(0, 1), (2, 3)], cdt.simplices, cdt.neighbors, cdt.constraint_edges())
    # a segment from a point to its own duplicate has zero length: ignored
    cdt = ConstrainedDelaunay(pts, [(0, 5), (5, 1)])
    assert cdt.constraint_edges().tolist() == [[0, 4], [1, 4]]
