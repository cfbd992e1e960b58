"""Spherical Delaunay triangulation against independent oracles.

Run: .venv/bin/python -m pytest tests/structures/test_spherical.py -q

Oracles: ``scipy.spatial.ConvexHull`` on general-position sets (the hull facets
of points on a sphere are the spherical Delaunay triangles), and a brute-force
exact empty-cap check written here with Python integers: no point strictly on
the cap side (outside) of any triangle's plane, every point used, edges paired.

The tests marked ``slow`` (at the end; until issue 9 they were ``test_spherical_1000.py``;
``-m "not slow"`` leaves them out): spherical_delaunay: 1000 random small cases and the degenerate families on the sphere,
against independent oracles.

Oracles (nothing shared with the library):

* ``scipy.spatial.ConvexHull`` (Qhull) of the unit vectors, normalised here: in general
  position the spherical Delaunay triangles are exactly the hull facets that have the
  centre strictly on their inner side (each facet proposed by Qhull is checked exactly
  to be supporting; the side of the centre is decided exactly);
* an exact empty-cap checker on Python integers (``check_sphere``): every triangle
  counter-clockwise seen from outside (centre strictly inside), no point strictly on the
  outer side of any triangle's plane (its circumcap is empty), no directed edge used
  twice, every boundary edge a spherical-hull edge (all points on one side of its great
  circle), every distinct point a vertex, and Euler's count: 2n - 4 triangles when the
  sphere is covered, 2n - h - 2 with one simple boundary cycle of h vertices otherwise;
* input-order independence: the same triangles (as coordinates) for a shuffled input.
"""
from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, strategies as st
from scipy.spatial import ConvexHull

from reference_impl.structures.spherical import SphericalDelaunay, lonlat_to_xyz, spherical_delaunay


def int_points(points) -> list[tuple[int, int, int]]:
    ratios = [[float(v).as_integer_ratio() for v in p] for p in np.asarray(points, dtype=float)]
    den = max([d for r in ratios for _, d in r], default=1)
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def orient(a, b, c, d) -> int:
    """Shewchuk's orient3d on integers: > 0 when d is below abc seen counter-clockwise."""
    u, v, w = ([p[i] - d[i] for i in range(3)] for p in (a, b, c))
    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
           + u[2] * (v[0] * w[1] - v[1] * w[0]))
    return (det > 0) - (det < 0)


def check_spherical(xyz, tris) -> tuple[bool, str]:
    """Exact checks of a spherical Delaunay triangulation (see the module docstring)."""
    P = int_points(np.vstack([xyz, [[0.0, 0.0, 0.0]]]))
    O = P.pop()
    first: dict = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    T = [tuple(rep[int(v)] for v in t) for t in np.asarray(tris).reshape(-1, 3)]
    for t in T:
        a, b, c = (P[v] for v in t)
        if orient(a, b, c, O) <= 0:
            return False, f"triangle {t} is not counter-clockwise from outside (centre not inside)"
        if any(orient(a, b, c, q) < 0 for q in P):
            return False, f"triangle {t} has a point strictly inside its circumcap"
    directed = [(t[i], t[(i + 1) % 3]) for t in T for i in range(3)]
    dset = set(directed)
    if len(dset) != len(directed):
        return False, "a directed edge is used twice: triangles overlap"
    boundary = [(u, v) for u, v in directed if (v, u) not in dset]
    for u, v in boundary:        # the boundary must be spherical convex hull edges
        s = [orient(P[u], P[v], O, q) for q in P]
        if min(s) < 0 and max(s) > 0:
            return False, f"boundary edge {u}-{v} has points on both sides of its great circle"
    used = {v for t in T for v in t}
    distinct = set(rep)
    if T and used != distinct:
        return False, f"points {sorted(distinct - used)[:5]} are not vertices"
    return True, "ok"


def random_sphere(n, seed=0):
    return np.random.default_rng(seed).normal(size=(n, 3))


# ----------------------------------------------------------------------------- conversion
def test_lonlat_conversion_is_exact_where_it_can_be():
    xyz = lonlat_to_xyz([(0, 0), (90, 0), (180, 0), (270, 0), (-90, 0), (360, 0), (720, 45),
                         (17.5, 90), (-33, -90)])
    assert xyz[:5].tolist() == [[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [0, -1, 0]]
    assert xyz[5].tolist() == [1, 0, 0] and xyz[6].tolist() == lonlat_to_xyz([(0, 45)])[0].tolist()
    assert xyz[7].tolist() == [0, 0, 1] and xyz[8].tolist() == [0, 0, -1]
    rng = np.random.default_rng(0)
    ll = np.c_[rng.integers(-180, 180, 500) + rng.random(500).round(3),
               rng.integers(-89, 89, 500) + rng.random(500).round(3)]
    a = lonlat_to_xyz(ll)
    b = lonlat_to_xyz(np.c_[ll[:, 0] + 180, -ll[:, 1]])       # antipodes
    exact_shift = (ll[:, 0] + 180) - 180 == ll[:, 0]
    assert np.array_equal(a[exact_shift], -b[exact_shift])
    assert np.allclose(np.linalg.norm(a, axis=1), 1, atol=4e-16)
    lon, lat = np.radians(ll.T)
    assert np.allclose(a, np.c_[np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)],
                       atol=1e-15)


@pytest.mark.parametrize("bad", [[(0, 91)], [(0, -90.5)], [(float("nan"), 0)], [(0, 0, 0)],
                                 [(1, 2, 3, 4)], "abc", [(1, float("inf"), 0)], [("a", "b")]])
def test_bad_input_raises(bad):
    with pytest.raises(ValueError):
        SphericalDelaunay(bad)


# ----------------------------------------------------------------------------- whole sphere
@pytest.mark.parametrize("n,seed", [(20, 0), (300, 1), (5000, 2)])
def test_matches_convex_hull_in_general_position(n, seed):
    sd = SphericalDelaunay(random_sphere(n, seed))
    ours = {tuple(sorted(t)) for t in sd.simplices.tolist()}
    qhull = {tuple(sorted(t)) for t in ConvexHull(sd.xyz).simplices.tolist()}
    assert ours == qhull and sd.covers_sphere
    assert len(ours) == 2 * n - 4
    if n <= 300:
        assert check_spherical(sd.xyz, sd.simplices) == (True, "ok")


def test_neighbors():
    sd = SphericalDelaunay(random_sphere(200, 5))
    T, N = sd.simplices, sd.neighbors
    assert (N >= 0).all()
    for t in range(len(T)):
        for k in range(3):
            edge = {T[t, (k + 1) % 3], T[t, (k + 2) % 3]}
            assert edge <= set(T[N[t, k]].tolist()) and t in N[N[t, k]].tolist()


@pytest.mark.parametrize("name,lonlat,count", [
    ("octahedron", [(0, 0), (90, 0), (180, 0), (270, 0), (0, 90), (0, -90)], 8),
    ("equator+poles", [(k * 30, 0) for k in range(12)] + [(0, 90), (0, -90)], 24),
    ("cube", [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], 12),  # 4-point faces
    ("equator+north", [(k * 45, 0) for k in range(8)] + [(10, 90)], 8),
])
def test_cospherical_and_great_circle_sets(name, lonlat, count):
    sd = SphericalDelaunay(lonlat)
    ok, msg = check_spherical(sd.xyz, sd.simplices)
    assert ok, msg
    assert len(sd.simplices) == count
    assert sd.covers_sphere == (name != "equator+north")


def test_great_circle_and_tiny_sets_give_no_triangles():
    assert spherical_delaunay([(k * 10.0, 0.0) for k in range(36)]).shape == (0, 3)
    assert spherical_delaunay([(0, 0, 1), (0, 0, -1)]).shape == (0, 3)          # antipodal pair
    assert spherical_delaunay([]).shape == (0, 3)
    assert spherical_delaunay([(10, 20)] * 4).shape == (0, 3)
    diagonal = [(np.cos(t), np.cos(t), np.sin(t)) for t in np.linspace(0, 6, 20)]
    assert spherical_delaunay(diagonal).shape == (0, 3)    # the plane x = y survives rounding
    # on z = x + y the rounded unit vectors are *not* coplanar with the centre: the answer is
    # the exact one for the doubles (thin triangles), and it is still a valid triangulation
    tilted = [(np.cos(t), np.sin(t), np.cos(t) + np.sin(t)) for t in np.linspace(0, 6, 20)]
    sd = SphericalDelaunay(tilted)
    assert check_spherical(sd.xyz, sd.simplices)[0]
    assert len(spherical_delaunay([(0, 0), (40, 0), (20, 30)])) == 1           # one small triangle


# ----------------------------------------------------------------------------- hemispheres
@pytest.mark.parametrize("n,seed,lat_min", [(40, 0, 5.0), (400, 1, 30.0), (300, 2, 0.0)])
def test_hemisphere_sets_cover_the_spherical_hull(n, seed, lat_min):
    rng = np.random.default_rng(seed)
    ll = np.c_[rng.uniform(-180, 180, n), rng.uniform(lat_min, 90 if lat_min else 60, n)]
    if lat_min == 0.0:                         # a cap that is not centred on a pole
        ll[:, 1] = rng.uniform(-60, 60, n)
        ll[:, 0] = rng.uniform(-60, 60, n)
    sd = SphericalDelaunay(ll)
    assert not sd.covers_sphere
    ok, msg = check_spherical(sd.xyz, sd.simplices)
    assert ok, msg
    T = sd.simplices.tolist()
    directed = {(t[i], t[(i + 1) % 3]) for t in T for i in range(3)}
    boundary = [(u, v) for u, v in directed if (v, u) not in directed]
    h = len({u for u, _ in boundary})
    assert len(boundary) == h                          # one simple boundary cycle
    assert len(T) == 2 * n - h - 2                     # Euler for a triangulated disc
    assert (sd.neighbors < 0).sum() == h


def test_the_hole_is_what_is_left_out():
    """With points in one hemisphere the hull has facets facing the centre: not triangles."""
    rng = np.random.default_rng(3)
    ll = np.c_[rng.uniform(-180, 180, 200), rng.uniform(20, 90, 200)]
    sd = SphericalDelaunay(ll)
    hull = ConvexHull(sd.xyz)
    kept = {tuple(sorted(t)) for t in sd.simplices.tolist()}
    qh = {tuple(sorted(t)) for t in hull.simplices.tolist()}
    hole = qh - kept
    assert kept < qh and len(hole) > 0
    P = int_points(np.vstack([sd.xyz, [[0.0, 0.0, 0.0]]]))
    inside = P[-1]
    for f in hole:           # the centre is not strictly on the points' side of a hole facet
        a, b, c = (P[v] for v in f)
        s_centre = orient(a, b, c, inside)
        s_rest = {orient(a, b, c, P[q]) for q in range(200)} - {0}
        assert len(s_rest) == 1 and (s_centre == 0 or s_rest == {-s_centre})


# ----------------------------------------------------------------------------- invariances
def test_duplicates_are_merged():
    ll = [(0, 0), (360, 0), (90, 0), (180, 0), (0, 90), (55, 90), (-720, 0), (0, -90), (270, 0)]
    sd = SphericalDelaunay(ll)
    assert sd.index_map.tolist() == [0, 0, 2, 3, 4, 4, 0, 7, 8]
    assert len(sd.simplices) == 8 and set(sd.simplices.ravel().tolist()) == {0, 2, 3, 4, 7, 8}


def test_direction_input_scale_does_not_matter():
    v = random_sphere(300, 7)
    base = spherical_delaunay(v)
    assert np.array_equal(spherical_delaunay(np.ldexp(v, 900)), base)
    assert np.array_equal(spherical_delaunay(np.ldexp(v, -1000)), base)


@given(st.lists(st.tuples(st.integers(-4, 4), st.integers(-2, 2)), min_size=1, max_size=25),
       st.randoms(use_true_random=False))
def test_hypothesis_grid_lonlat(raw, rnd):
    """Longitudes/latitudes on a 45-degree grid: poles, antipodes, great circles, duplicates."""
    ll = [(45.0 * a, 45.0 * b) for a, b in raw]
    sd = SphericalDelaunay(ll)
    ok, msg = check_spherical(sd.xyz, sd.simplices)
    assert ok, msg
    perm = list(range(len(ll)))
    rnd.shuffle(perm)
    sd2 = SphericalDelaunay([ll[i] for i in perm])

    def as_coords(s):
        return {frozenset(map(tuple, s.xyz[t].tolist())) for t in s.simplices}

    assert as_coords(sd2) == as_coords(sd)


# =================================================================================================
# slow: 1000 random small cases and the degenerate families on the sphere (was test_spherical_1000.py)
# =================================================================================================
CASES = 1000


# ----------------------------------------------------------------------------- exact checker
def exact(points) -> list[tuple[int, int, int]]:
    ratios = [[float(v).as_integer_ratio() for v in p] for p in np.asarray(points, dtype=float).reshape(-1, 3)]
    den = max([d for r in ratios for _, d in r], default=1)
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def check_sphere(xyz, tris, covers=None) -> None:
    P = exact(np.vstack([np.asarray(xyz, dtype=float).reshape(-1, 3), [[0.0, 0.0, 0.0]]]))
    O = P.pop()
    first: dict = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    distinct = sorted(set(rep))
    T = [tuple(t) for t in np.asarray(tris).reshape(-1, 3).tolist()]
    a = P[distinct[0]] if distinct else O
    off = [j for j in distinct if (a[1] * P[j][2] - a[2] * P[j][1], a[2] * P[j][0] - a[0] * P[j][2],
                                   a[0] * P[j][1] - a[1] * P[j][0]) != (0, 0, 0)]   # not +-a
    if not off or all(orient(a, P[off[0]], P[k], O) == 0 for k in distinct):
        assert T == [], "points on one great circle (or < 3 distinct) must give no triangles"
        assert not covers
        return
    for t in T:
        assert all(rep[v] == v for v in t), f"triangle {t} uses a duplicate index"
        a, b, c = (P[v] for v in t)
        assert orient(a, b, c, O) > 0, f"triangle {t}: not counter-clockwise from outside (centre not inside)"
        assert all(orient(a, b, c, P[q]) >= 0 for q in distinct), f"triangle {t}: its circumcap holds a point"
    directed = [(t[i], t[(i + 1) % 3]) for t in T for i in range(3)]
    dset = set(directed)
    assert len(dset) == len(directed), "a directed edge is used twice: triangles overlap"
    boundary = [(u, v) for u, v in directed if (v, u) not in dset]
    for u, v in boundary:
        s = {orient(P[u], P[v], O, P[q]) for q in distinct} - {0}
        assert len(s) <= 1, f"boundary edge {u}-{v} has points on both sides of its great circle"
    assert {v for t in T for v in t} == set(distinct), "a point is not a vertex"
    n = len(distinct)
    if not boundary:
        assert covers is None or covers
        assert len(T) == 2 * n - 4
    else:
        assert not covers
        succ = dict(boundary)
        assert len(succ) == len(boundary), "the boundary is not a simple cycle"
        u, h = boundary[0][0], 0
        while True:
            u, h = succ[u], h + 1
            if u == boundary[0][0]:
                break
        assert h == len(boundary), "the boundary is not one cycle"
        assert len(T) == 2 * n - h - 2, "Euler's count for a triangulated disc"


def unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    v = v / np.abs(v).max(axis=1, keepdims=True)
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def lonlat_unit(ll) -> np.ndarray:
    lon, lat = np.radians(np.asarray(ll, dtype=float)).T
    return np.c_[np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)]


def qhull_oracle(vectors) -> set:
    """Hull facets with the centre strictly inside, Qhull proposing and exact arithmetic deciding."""
    P = exact(np.vstack([vectors, [[0.0, 0.0, 0.0]]]))
    O = P.pop()
    out = set()
    for f in ConvexHull(vectors).simplices.tolist():
        a, b, c = (P[v] for v in f)
        sides = {orient(a, b, c, q) for q in P} - {0}
        assert len(sides) == 1, "Qhull facet is not supporting"
        centre = orient(a, b, c, O)
        if centre != 0 and {centre} == sides:
            out.add(frozenset(f))
    return out


def coordinate_set(xyz, tris) -> set:
    return {frozenset(map(tuple, np.asarray(xyz)[t].tolist())) for t in np.asarray(tris).reshape(-1, 3)}


@pytest.mark.slow
def test_oracle_sanity():
    octa = np.array([(1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)], dtype=float)
    good = spherical_delaunay(octa)
    check_sphere(octa, good, covers=True)
    for bad in (good[1:], good[:, ::-1], np.vstack([good, good[:1]])):
        with pytest.raises(AssertionError):
            check_sphere(octa, bad)
    rnd = np.random.default_rng(0).normal(size=(10, 3))
    tri = spherical_delaunay(rnd).tolist()
    (a, b, c), = tri[:1]
    (d,) = [t[(t.index(b) + 2) % 3] for t in tri[1:] if a in t and b in t and t[(t.index(b) + 1) % 3] == a]
    flipped = [t for t in tri if not {a, b} <= set(t)] + [(c, a, d), (d, b, c)]
    with pytest.raises(AssertionError, match="circumcap"):          # one edge flipped
        check_sphere(rnd, flipped)
    cap = np.array([(1, 0, 0.2), (0, 1, 0.2), (-1, 0, 0.2), (0, -1, 0.2), (0, 0, 1)], dtype=float)
    with pytest.raises(AssertionError, match="centre not inside|counter-clockwise"):   # the hull's bottom
        check_sphere(cap, [(0, 2, 1), (0, 3, 2)] + [(k, (k + 1) % 4, 4) for k in range(4)])
    with pytest.raises(AssertionError, match="Euler|cycle|both sides"):   # a triangle missing
        check_sphere(octa, good[[i for i in range(8) if i != 3]][:7])


# ----------------------------------------------------------------------------- 1000 random cases
@pytest.mark.slow
def test_1000_random_cases_match_qhull_and_exact_checker():
    rng = np.random.default_rng(8128)
    covering = 0
    for case in range(CASES):
        n = int(rng.integers(4, 16))
        kind = case % 3
        if kind == 0:                                   # directions anywhere, any length
            given = rng.normal(size=(n, 3)) * 10.0 ** int(rng.integers(-5, 6))
            mine = unit(given)
        elif kind == 1:                                 # a cap around a random axis
            axis = rng.normal(size=3)
            given = rng.normal(size=(n, 3)) * rng.uniform(0.1, 1.5) + axis / np.linalg.norm(axis)
            mine = unit(given)
        else:                                           # longitude / latitude in degrees
            given = np.c_[rng.uniform(-540, 540, n), rng.uniform(-90, 90, n) * rng.uniform(0.2, 1)]
            mine = lonlat_unit(given)
        sd = SphericalDelaunay(given)
        assert np.allclose(sd.xyz, mine, rtol=0, atol=4e-16 if kind < 2 else 1e-13), case
        tris = spherical_delaunay(given)
        assert np.array_equal(tris, sd.simplices)
        check_sphere(sd.xyz, tris, sd.covers_sphere)
        assert {frozenset(t) for t in tris.tolist()} == qhull_oracle(mine), f"case {case}"
        covering += sd.covers_sphere
    assert 100 < covering < CASES - 100                 # whole spheres and caps both occur


# ----------------------------------------------------------------------------- degenerate families
def _ll(pairs):
    return np.array(pairs, dtype=float)


_rng = np.random.default_rng(5)
LONLAT = {
    "octahedron": _ll([(0, 0), (90, 0), (180, 0), (270, 0), (0, 90), (0, -90)]),
    "poles-any-longitude": _ll([(0, 0), (120, 0), (240, 0), (17, 90), (-33, 90), (0, -90), (200, -90)]),
    "grid-45": _ll([(45 * a, 45 * b) for a in range(8) for b in range(-2, 3)]),
    "grid-30": _ll([(30 * a, 30 * b) for a in range(12) for b in range(-3, 4)]),
    "equator+poles": _ll([(k * 30, 0) for k in range(12)] + [(0, 90), (0, -90)]),
    "equator+north": _ll([(k * 45, 0) for k in range(8)] + [(10, 90)]),
    "semicircle+1": _ll([(k * 30, 0) for k in range(6)] + [(15, 40)]),
    "great-circle": _ll([(k * 10, 0) for k in range(36)]),
    "meridian": _ll([(0, k * 15 - 90) for k in range(13)] + [(180, 45)]),
    "wrapped-duplicates": _ll([(0, 0), (360, 0), (-720, 0), (90, 0), (450, 0), (180, 0), (0, 90), (0, -90),
                               (270, 0), (-90, 0)]),
    "antipodal-pairs": _ll([(0, 0), (180, 0), (90, 0), (270, 0), (0, 90), (0, -90), (45, 45), (225, -45)]),
    "clusters": np.vstack([np.c_[10 + _rng.random(8) * 1e-4, 20 + _rng.random(8) * 1e-4],
                           np.c_[_rng.uniform(-180, 180, 8), _rng.uniform(-80, 80, 8)],
                           np.c_[-50 + _rng.random(5) * 1e-3, -30 + _rng.random(5) * 1e-3]]),
    "one-cap-lonlat": np.c_[_rng.uniform(0, 10, 15), _rng.uniform(80, 90, 15)],
}
VECTORS = {
    "cube": np.array(list(itertools.product((-1, 1), repeat=3)), dtype=float),
    "lattice-directions": np.array([p for p in itertools.product((-1, 0, 1), repeat=3) if any(p)], dtype=float),
    "lattice-sphere-9": np.array([p for p in itertools.product(range(-3, 4), repeat=3)
                                  if p[0] ** 2 + p[1] ** 2 + p[2] ** 2 == 9], dtype=float),
    "same-direction-duplicates": np.array([(1, 2, 3), (2, 4, 6), (0.5, 1, 1.5), (-1, 0, 0), (0, -1, 0), (0, 0, -1),
                                           (3, -1, 2)], dtype=float),
    "offset-1e9": np.c_[np.full(16, 1e9), np.array(list(itertools.product(range(4), range(4))), dtype=float)],
    "offset-1e9-both-sides": np.vstack([np.c_[np.full(9, 1e9), np.array(list(itertools.product(range(3), range(3))))],
                                        np.c_[np.full(9, -1e9), np.array(list(itertools.product(range(3), range(3))))],
                                        [[0, 1, 0], [0, 0, 1]]]).astype(float),
    "tiny-1e-300": _rng.normal(size=(20, 3)) * 1e-300,
    "huge-1e300": _rng.normal(size=(20, 3)) * 1e300,
    "mixed-scales": np.vstack([_rng.normal(size=(8, 3)) * 1e-300, _rng.normal(size=(8, 3)) * 1e300]),
    "two-points": np.array([(0, 0, 1), (0, 0, -1)], dtype=float),
    "one-point": np.array([(0, 0, 1)], dtype=float),
    "empty": np.zeros((0, 3)),
}
FAMILIES = {**{f"lonlat:{k}": v for k, v in LONLAT.items()}, **{f"xyz:{k}": v for k, v in VECTORS.items()}}


@pytest.mark.slow
@pytest.mark.parametrize("name", list(FAMILIES))
def test_degenerate_families(name):
    pts = FAMILIES[name]
    sd = SphericalDelaunay(pts)
    assert np.array_equal(spherical_delaunay(pts), sd.simplices)
    check_sphere(sd.xyz, sd.simplices, sd.covers_sphere)
    rng = np.random.default_rng(len(name))
    for _ in range(2):
        perm = rng.permutation(len(pts))
        again = SphericalDelaunay(pts[perm])
        assert coordinate_set(again.xyz, again.simplices) == coordinate_set(sd.xyz, sd.simplices)
    if name.startswith("xyz:") and len(pts):
        for e in (-900, 900):                              # exact power-of-two scaling: same answer
            with np.errstate(over="ignore"):
                scaled = np.ldexp(pts, e)
                exact_scale = np.isfinite(scaled).all() and np.array_equal(np.ldexp(scaled, -e), pts)
            if exact_scale:
                assert np.array_equal(spherical_delaunay(scaled), sd.simplices)


@pytest.mark.slow
@pytest.mark.parametrize("name,count,covers", [
    ("lonlat:octahedron", 8, True), ("lonlat:poles-any-longitude", 6, True),
    ("lonlat:equator+poles", 24, True), ("lonlat:equator+north", 8, False),
    ("lonlat:great-circle", 0, False), ("lonlat:wrapped-duplicates", 8, True),
    ("xyz:cube", 12, True), ("xyz:lattice-directions", 48, True), ("xyz:two-points", 0, False),
    ("xyz:same-direction-duplicates", 6, True),
])
def test_degenerate_counts(name, count, covers):
    sd = SphericalDelaunay(FAMILIES[name])
    assert len(sd.simplices) == count and sd.covers_sphere == covers


# ----------------------------------------------------------------------------- known bug
CLUSTER_1E6 = np.vstack([np.c_[10 + _rng.random(8) * 1e-6, 20 + _rng.random(8) * 1e-6],
                         np.c_[_rng.uniform(-180, 180, 8), _rng.uniform(-80, 80, 8)]])


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="known defect: points about 1e-6 degrees apart (~10 cm on Earth) are "
                   "left out of every triangle (reported in SphericalDelaunay.missing): their rounded unit "
                   "vectors fall strictly inside the convex hull of the others, and SphericalDelaunay returns "
                   "the exact hull of the stored vectors")
@pytest.mark.parametrize("pts", [
    # minimal: 4 distinct points in a tiny cap give 1 triangle; point 0 is in none
    _ll([(10.00000027, 20.00000045), (10.00000039, 20.00000047), (10.00000091, 20.00000001),
         (10.00000007, 20.00000042)]),
    CLUSTER_1E6,
], ids=["4-points", "cluster-1e-6-degrees"])
def test_nearly_coincident_points_are_vertices(pts):
    sd = SphericalDelaunay(pts)
    used = set(sd.simplices.ravel().tolist())
    assert used == set(sd.index_map.tolist()), f"points {sorted(set(sd.index_map.tolist()) - used)} in no triangle"


@pytest.mark.slow
def test_points_that_cannot_be_vertices_are_reported_not_dropped_silently():
    """The known limitation above, made visible: every distinct point is in a triangle or in
    ``missing``."""
    for pts in (_ll([(10.00000027, 20.00000045), (10.00000039, 20.00000047), (10.00000091, 20.00000001),
                     (10.00000007, 20.00000042)]), CLUSTER_1E6):
        sd = SphericalDelaunay(pts)
        used = set(sd.simplices.ravel().tolist())
        missing = set(sd.missing.tolist())
        assert missing and not (missing & used)
        assert used | missing == set(sd.index_map.tolist())
