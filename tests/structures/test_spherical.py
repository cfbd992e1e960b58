"""Spherical Delaunay triangulation against independent oracles.

Run: .venv/bin/python -m pytest tests/structures/test_spherical.py -q

Oracles: ``scipy.spatial.ConvexHull`` on general-position sets (the hull facets
of points on a sphere are the spherical Delaunay triangles), and a brute-force
exact empty-cap check written here with Python integers: no point strictly on
the cap side (outside) of any triangle's plane, every point used, edges paired.
"""
from __future__ import annotations

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
    as_coords = lambda s: {frozenset(map(tuple, s.xyz[t].tolist())) for t in s.simplices}
    assert as_coords(sd2) == as_coords(sd)
