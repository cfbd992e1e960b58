"""delaunay_3d / Delaunay3D: 1000 random small cases and the 3D degenerate families, against
independent oracles.

Run:  .venv/bin/python -m pytest tests/mesh/test_delaunay3d_1000.py -q

Oracles (nothing shared with the library):

* ``scipy.spatial.Delaunay`` (Qhull) on points in general position, where the Delaunay
  tetrahedralisation is unique: the same set of tetrahedra;
* an exact checker written here on Python integers (every float times one common power
  of two).  It needs no convex hull: (1) every tetrahedron positively oriented
  (``orient3d > 0`` in Shewchuk's convention) and made of representatives of the
  distinct points; (2) a face is shared by at most two tetrahedra, and then they lie
  strictly on opposite sides of it; (3) a face with one tetrahedron has every point on
  that tetrahedron's side (or on its plane): it lies on the hull boundary.  Then the
  number of tetrahedra covering a point is the same everywhere inside the hull (it only
  changes across faces, and every face inside the hull is matched), so (4) "the centroid
  of one tetrahedron lies in exactly one" makes it a tiling of the hull; with (5) every
  distinct point a vertex, that is a tetrahedralisation of the points, and with (6) every
  interior face locally Delaunay (in-sphere <= 0), a Delaunay one.  Coplanar input (or
  fewer than 4 distinct points) must give no tetrahedra.  On small sets a brute-force
  empty-sphere check is added, and the neighbours and hull facets are checked too.
* Input-order independence: the same tetrahedra (as coordinates) for a shuffled input.
"""
from __future__ import annotations

import itertools

import numpy as np
import pytest
from scipy.spatial import Delaunay as QhullDelaunay

from reference_impl.mesh.delaunay3d import Delaunay3D, delaunay_3d

CASES = 1000


# ----------------------------------------------------------------------------- exact checker
def exact(points) -> list[tuple[int, int, int]]:
    """Every coordinate times one common power of two, as Python integers."""
    ratios = [[float(v).as_integer_ratio() for v in p] for p in np.asarray(points, dtype=float).reshape(-1, 3)]
    den = max([d for r in ratios for _, d in r], default=1)
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def det3(u, v, w):
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def orient(a, b, c, d) -> int:
    """Sign of det(a - d, b - d, c - d): positive for a positively oriented tetrahedron."""
    s = det3(*[(p[0] - d[0], p[1] - d[1], p[2] - d[2]) for p in (a, b, c)])
    return (s > 0) - (s < 0)


def insphere(a, b, c, d, e) -> int:
    """+1 when e is strictly inside the sphere through the positively oriented a, b, c, d."""
    rows = [(p[0] - e[0], p[1] - e[1], p[2] - e[2]) for p in (a, b, c, d)]
    lift = [x * x + y * y + z * z for x, y, z in rows]
    # 4x4 determinant expanded along the lift column; sign fixed by test_oracle_sanity
    s = -sum((-1) ** i * lift[i] * det3(*(rows[j] for j in range(4) if j != i)) for i in range(4))
    return (s > 0) - (s < 0)


def check_3d(points, tets, neighbors=None, hull=None, brute=False) -> None:
    P = exact(points)
    first: dict = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    distinct = sorted(set(rep))
    T = [tuple(t) for t in np.asarray(tets).reshape(-1, 4).tolist()]
    o = distinct[0] if distinct else None
    solid = any(orient(P[o], P[i], P[j], P[k]) != 0 for i, j, k in itertools.combinations(distinct[1:], 3))
    if not solid:
        assert T == [], "coplanar input (or fewer than 4 distinct points) must give no tetrahedra"
        return
    assert T, "no tetrahedra for a solid point set"
    for t in T:
        assert all(rep[v] == v for v in t), f"tetrahedron {t} uses a duplicate index"
        assert orient(*(P[v] for v in t)) > 0, f"tetrahedron {t} is not positively oriented"
    faces: dict = {}
    for ti, t in enumerate(T):
        for k in range(4):
            faces.setdefault(tuple(sorted(t[:k] + t[k + 1:])), []).append((ti, t[k]))
    boundary = set()
    for f, side in faces.items():
        a, b, c = (P[v] for v in f)
        assert len(side) <= 2, f"face {f} is shared by {len(side)} tetrahedra"
        if len(side) == 2:
            (t0, x), (t1, y) = side
            sx, sy = orient(a, b, c, P[x]), orient(a, b, c, P[y])
            assert sx * sy < 0, f"the two tetrahedra on face {f} overlap"
            tet = (a, b, c, P[x]) if sx > 0 else (a, c, b, P[x])
            assert insphere(*tet, P[y]) <= 0, f"face {f} is not locally Delaunay"
        else:
            sx = orient(a, b, c, P[side[0][1]])
            assert all(orient(a, b, c, P[q]) * sx >= 0 for q in distinct), f"boundary face {f} is not on the hull"
            boundary.add(f)
    c4 = tuple(sum(P[v][i] for v in T[0]) for i in range(3))           # 4 x the centroid of T[0]
    P4 = [(4 * x, 4 * y, 4 * z) for x, y, z in P]
    holding = 0
    for t in T:
        q = [P4[v] for v in t]
        if all(orient(*(c4 if j == k else q[j] for j in range(4))) >= 0 for k in range(4)):
            holding += 1
    assert holding == 1, f"{holding} tetrahedra cover one point: not a tiling"
    assert {v for t in T for v in t} == set(distinct), "a point is not a vertex"
    if brute:
        for t in T:
            assert all(insphere(*(P[v] for v in t), P[q]) <= 0 for q in distinct), f"{t} has a point inside"
    if neighbors is not None:
        N = np.asarray(neighbors).tolist()
        for ti, t in enumerate(T):
            for k in range(4):
                f = tuple(sorted(t[:k] + t[k + 1:]))
                other = [s for s, _ in faces[f] if s != ti]
                assert N[ti][k] == (other[0] if other else -1), f"neighbour {ti},{k}"
    if hull is not None:
        H = np.asarray(hull).reshape(-1, 3).tolist()
        assert sorted(tuple(sorted(h)) for h in H) == sorted(boundary), "hull facets"
        for a, b, c in H:     # counter-clockwise seen from outside: every point below
            assert all(orient(P[a], P[b], P[c], P[q]) >= 0 for q in distinct)


def coordinate_set(points, tets) -> set:
    pts = np.asarray(points, dtype=float)
    return {frozenset(map(tuple, pts[t].tolist())) for t in np.asarray(tets).reshape(-1, 4)}


def test_oracle_sanity():
    """The hand-written predicates have the conventions the checker assumes, and it rejects
    broken answers."""
    a, b, c, d = (0, 0, 0), (4, 0, 0), (0, 4, 0), (0, 0, 4)
    assert orient(a, d, c, b) > 0 and orient(a, b, c, d) < 0
    # circumsphere: centre (2, 2, 2), through the origin and (4, 4, 4)
    assert insphere(a, d, c, b, (1, 1, 1)) > 0 and insphere(a, d, c, b, (4, 4, 4)) == 0
    assert insphere(a, d, c, b, (5, 4, 4)) < 0
    cube = np.array(list(itertools.product((0, 1), repeat=3)), dtype=float)   # index 4x + 2y + z
    good = delaunay_3d(cube)
    check_3d(cube, good, brute=True)
    for bad in (good[1:], good[:, [1, 0, 2, 3]], np.vstack([good, good[:1]])):
        with pytest.raises(AssertionError):
            check_3d(cube, bad)
    five = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.875, 0.875, 0.875]])
    two = [(0, 3, 2, 1), (4, 1, 2, 3)]                 # a tiling through face 1-2-3, not Delaunay
    with pytest.raises(AssertionError, match="locally Delaunay"):
        check_3d(five, two)

    def positive(tets):
        P = exact(cube)
        return [t if orient(*(P[v] for v in t)) > 0 else (t[1], t[0], t[2], t[3]) for t in tets]

    # the two 5-tetrahedra splits of the cube (central tetrahedron on the even or the odd
    # corners) share no face: stacked, every local test passes and only the tiling test fails
    even = positive([(1, 0, 3, 5), (2, 0, 3, 6), (4, 0, 5, 6), (7, 3, 5, 6), (0, 3, 5, 6)])
    odd = positive([(0, 1, 2, 4), (3, 1, 2, 7), (5, 1, 4, 7), (6, 2, 4, 7), (1, 2, 4, 7)])
    check_3d(cube, even, brute=True)
    check_3d(cube, odd, brute=True)
    with pytest.raises(AssertionError, match="not a tiling"):
        check_3d(cube, even + odd)


# ----------------------------------------------------------------------------- 1000 random cases
def test_1000_random_cases_match_qhull_and_exact_checker():
    rng = np.random.default_rng(31337)
    for case in range(CASES):
        n = int(rng.integers(5, 16))
        pts = rng.random((n, 3)) if case % 2 else rng.normal(size=(n, 3))
        pts = pts * 10.0 ** int(rng.integers(-3, 4))
        d = Delaunay3D(pts)
        assert np.array_equal(delaunay_3d(pts), d.simplices)
        check_3d(pts, d.simplices, d.neighbors, d.hull_facets)
        ours = {tuple(sorted(t)) for t in d.simplices.tolist()}
        qhull = {tuple(sorted(t)) for t in QhullDelaunay(pts).simplices.tolist()}
        assert ours == qhull, f"case {case}: differs from Qhull"


def test_1000_random_integer_sets_exact_checker():
    """Tiny integer sets: coplanar, cospherical, collinear, duplicates: every kind of tie."""
    rng = np.random.default_rng(4)
    flat = 0
    for case in range(CASES):
        n = int(rng.integers(1, 16))
        hi = rng.integers(1, 4, size=3)
        pts = np.c_[rng.integers(0, hi[0] + 1, n), rng.integers(0, hi[1] + 1, n),
                    rng.integers(0, hi[2] + 1, n)].astype(float)
        if case % 5 == 0:
            pts[:, 2] = pts[:, 0] + 2 * pts[:, 1]          # all on one slanted plane
        d = Delaunay3D(pts)
        flat += d.flat
        check_3d(pts, d.simplices, d.neighbors, d.hull_facets, brute=True)
        perm = rng.permutation(n)
        assert coordinate_set(pts[perm], delaunay_3d(pts[perm])) == coordinate_set(pts, d.simplices)
    assert 100 < flat < CASES - 300                       # both flat and solid sets occurred


# ----------------------------------------------------------------------------- degenerate families
def cube_grid(a, b, c):
    return np.array(list(itertools.product(range(a), range(b), range(c))), dtype=float)


def lattice_sphere(r2):
    r = int(r2 ** 0.5) + 1
    return np.array([(x, y, z) for x in range(-r, r + 1) for y in range(-r, r + 1)
                     for z in range(-r, r + 1) if x * x + y * y + z * z == r2], dtype=float)


def unit_sphere(n, seed):
    p = np.random.default_rng(seed).normal(size=(n, 3))
    return p / np.linalg.norm(p, axis=1, keepdims=True)


_rng = np.random.default_rng(2024)
DEGENERATE = {
    "grid-3x3x3": cube_grid(3, 3, 3),
    "grid-2x3x4": cube_grid(2, 3, 4),
    "grid-4x4x2": cube_grid(4, 4, 2),
    "lattice-sphere-9": lattice_sphere(9),
    "lattice-sphere-9+centre": np.vstack([lattice_sphere(9), [[0.0, 0.0, 0.0]]]),
    "lattice-sphere-3": lattice_sphere(3),                 # the cube's corners
    "octahedron+centre": np.array([(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1),
                                   (0, 0, 0)], dtype=float),
    "unit-sphere": unit_sphere(40, 1),
    "unit-sphere+centre": np.vstack([unit_sphere(40, 2), [[0.0, 0.0, 0.0]]]),
    "coplanar-layers": np.vstack([np.c_[_rng.random((15, 2)), np.full(15, z)] for z in (0.0, 1.0, 3.0)]),
    "grid-layers": np.vstack([cube_grid(4, 4, 1) + [0, 0, z] for z in (0, 1, 3)]),
    "collinear+2": np.vstack([np.c_[np.arange(10.0), np.zeros(10), np.zeros(10)], [[0, 1, 0], [3, 0, 2]]]),
    "collinear-runs": np.vstack([np.c_[np.arange(6.0), np.arange(6.0) * 2, np.arange(6.0) * 3],
                                 np.c_[np.arange(6.0), np.zeros(6), 5 - np.arange(6.0)], [[1, 7, 0]]]),
    "skew-lines": np.array([(t, 0, 0) for t in range(12)] + [(0, t, 1) for t in range(12)], dtype=float),
    "moment-curve": np.array([(t, t * t, t ** 3) for t in range(-8, 9)], dtype=float),
    "duplicates": np.vstack([cube_grid(2, 2, 3)] * 3),
    "random-duplicates": np.vstack([_rng.random((20, 3))] * 2)[_rng.permutation(40)[:35]],
    "clusters": np.vstack([_rng.random((15, 3)) * 1e-6, _rng.random((15, 3)) * 1e6 - 5e5, _rng.random((15, 3)) + 3]),
    "grid-clusters": np.vstack([cube_grid(2, 2, 2) * 1e-6, cube_grid(2, 2, 2) * 1e6, cube_grid(2, 2, 2) + 5]),
    "tiny-1e-300": _rng.random((40, 3)) * 1e-300,
    "huge-1e300": _rng.random((40, 3)) * 1e300,
    "grid-1e-300": cube_grid(3, 3, 3) * 1e-300,
    "grid-1e300": cube_grid(3, 3, 3) * 1e300,
    "mixed-1e-300-1e300": np.vstack([cube_grid(2, 2, 2) * 1e-300, cube_grid(2, 2, 2) * 1e300]),
    "offset-1e9-grid": cube_grid(3, 3, 3) + 1e9,
    "offset-1e9-half-grid": cube_grid(3, 3, 3) * 0.5 + 1e9,
    "offset-1e9-micro": cube_grid(3, 3, 3) * 1e-6 + 1e9,     # rounded: nearly degenerate
    "offset-1e9-random": _rng.random((40, 3)) + 1e9,
    "offset-1e9-sphere": lattice_sphere(9) + 1e9,
    # flat: no tetrahedra
    "empty": np.zeros((0, 3)),
    "one": np.array([[1.0, 2.0, 3.0]]),
    "three": np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]]),
    "all-same": np.ones((6, 3)),
    "collinear": np.c_[np.arange(8.0), 2 * np.arange(8.0), -np.arange(8.0)],
    "coplanar-grid": cube_grid(5, 5, 1),
    "slanted-plane-duplicates": np.vstack([[(x, y, x + 2 * y) for x in range(4) for y in range(4)]] * 2).astype(float),
    "coplanar-1e9": cube_grid(4, 4, 1)[:, [0, 2, 1]] + 1e9,
}


@pytest.mark.parametrize("name", list(DEGENERATE))
def test_degenerate_families(name):
    pts = DEGENERATE[name]
    d = Delaunay3D(pts)
    assert np.array_equal(delaunay_3d(pts), d.simplices)
    check_3d(pts, d.simplices, d.neighbors, d.hull_facets, brute=len(pts) <= 60)
    rng = np.random.default_rng(len(name))
    for _ in range(2):
        perm = rng.permutation(len(pts))
        assert coordinate_set(pts[perm], delaunay_3d(pts[perm])) == coordinate_set(pts, d.simplices)
    if np.abs(pts).max(initial=0) < 1e290 and np.abs(pts[pts != 0]).min(initial=1) > 1e-290:
        scaled = np.ldexp(pts, 8)          # the insertion order (a hash of the bits) changes
        check_3d(scaled, delaunay_3d(scaled))
