"""spherical_delaunay: 1000 random small cases and the degenerate families on the sphere,
against independent oracles.

Run:  .venv/bin/python -m pytest tests/structures/test_spherical_1000.py -q

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
from scipy.spatial import ConvexHull

from reference_impl.structures.spherical import SphericalDelaunay, spherical_delaunay

CASES = 1000


# ----------------------------------------------------------------------------- exact checker
def exact(points) -> list[tuple[int, int, int]]:
    ratios = [[float(v).as_integer_ratio() for v in p] for p in np.asarray(points, dtype=float).reshape(-1, 3)]
    den = max([d for r in ratios for _, d in r], default=1)
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def orient(a, b, c, d) -> int:
    """Sign of det(a - d, b - d, c - d): positive when d is below abc seen counter-clockwise."""
    u, v, w = ([p[i] - d[i] for i in range(3)] for p in (a, b, c))
    s = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
         + u[2] * (v[0] * w[1] - v[1] * w[0]))
    return (s > 0) - (s < 0)


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
