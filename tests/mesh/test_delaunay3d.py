"""3D Delaunay tetrahedralisation against independent oracles.

Run: .venv/bin/python -m pytest tests/mesh/test_delaunay3d.py -q

Oracles: the exact validity checker ``reference_impl.exact.verify.check_delaunay_3d``
(Python integers; it shares no code with the numba kernel), a brute-force empty-sphere check on small sets,
``scipy.spatial.Delaunay`` (Qhull) on general-position sets, where the
Delaunay tetrahedralisation is unique, and ``scipy.spatial.ConvexHull`` for the
hull volume (its facets are themselves checked exactly), which cross-checks the
exact checker on the degenerate sets.

The tests marked ``slow`` (at the end; until issue 9 they were ``test_delaunay3d_1000.py``;
``-m "not slow"`` leaves them out): delaunay_3d / Delaunay3D: 1000 random small cases and the 3D degenerate families, against
independent oracles.

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
from hypothesis import given, strategies as st
from scipy.spatial import ConvexHull, Delaunay as QhullDelaunay

from reference_impl.mesh.delaunay3d import (Delaunay3D, Mesh, delaunay_3d, hilbert_index_3d,
                                       insertion_order_3d)
from reference_impl.exact.verify import check_delaunay_3d


# ----------------------------------------------------------------------------- exact checker
def int_points(points) -> list[tuple[int, int, int]]:
    """Every coordinate times one common power of two, as Python integers."""
    ratios = [[float(v).as_integer_ratio() for v in p] for p in np.asarray(points, dtype=float)]
    den = max([d for r in ratios for _, d in r], default=1)
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def det3(u, v, w) -> int:
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def orient(a, b, c, d) -> int:
    """Shewchuk's orient3d: det(a - d, b - d, c - d) (positive: d below abc seen CCW)."""
    return det3(sub(a, d), sub(b, d), sub(c, d))


def insphere(a, b, c, d, e) -> int:
    rows = [sub(p, e) for p in (a, b, c, d)]
    lift = [x * x + y * y + z * z for x, y, z in rows]
    cof = [det3(*(rows[j] for j in range(4) if j != i)) for i in range(4)]
    return -lift[0] * cof[0] + lift[1] * cof[1] - lift[2] * cof[2] + lift[3] * cof[3]


def hull_volume6(P: list, points: np.ndarray) -> int:
    """6 x the convex hull volume, exactly, from Qhull's facets (each checked to be supporting)."""
    pts = np.asarray(points, dtype=float)
    pts = np.ldexp(pts, -np.frexp(np.abs(pts).max())[1])
    hull = ConvexHull(pts - pts.min(axis=0))   # Qhull only proposes facets; checked below
    first = tuple(hull.vertices[:4])
    c4 = [sum(P[i][j] for i in first) for j in range(3)]          # 4 x an interior point
    P4 = [(4 * x, 4 * y, 4 * z) for x, y, z in P]
    vol = 0
    for f in hull.simplices:
        a, b, c = (P4[i] for i in f)
        s = [(v > 0) - (v < 0) for v in (orient(a, b, c, q) for q in P4)]
        assert min(s) >= 0 or max(s) <= 0, "Qhull facet is not supporting"
        vol += abs(orient(a, b, c, tuple(c4)))
    return vol // 64


def brute_force_empty(points, tets) -> bool:
    P = int_points(points)
    for t in np.asarray(tets).reshape(-1, 4):
        a, b, c, d = (P[v] for v in t)
        if any(insphere(a, b, c, d, q) > 0 for q in P):
            return False
    return True


def coordinate_set(points, tets) -> set:
    pts = np.asarray(points, dtype=float)
    return {frozenset(map(tuple, pts[t].tolist())) for t in np.asarray(tets).reshape(-1, 4)}


# ----------------------------------------------------------------------------- point sets
def cube_grid(a, b, c):
    return np.array(list(itertools.product(range(a), range(b), range(c))), dtype=float)


def lattice_sphere(r2=121):
    r = int(r2 ** 0.5) + 1
    return np.array([(x, y, z) for x in range(-r, r + 1) for y in range(-r, r + 1)
                     for z in range(-r, r + 1) if x * x + y * y + z * z == r2], dtype=float)


def unit_sphere(n, seed=0):
    p = np.random.default_rng(seed).normal(size=(n, 3))
    return p / np.linalg.norm(p, axis=1, keepdims=True)


def layers(n, k, seed=0):
    rng = np.random.default_rng(seed)
    return np.vstack([np.c_[rng.random((n, 2)), np.full(n, float(z))] for z in range(k)])


DEGENERATE = {
    "grid-6x6x6": cube_grid(6, 6, 6),
    "grid-3x4x5": cube_grid(3, 4, 5),
    "lattice-sphere": lattice_sphere(),
    "lattice-sphere+centre": np.vstack([lattice_sphere(), [[0.0, 0.0, 0.0]]]),
    "unit-sphere": unit_sphere(300),
    "coplanar-layers": layers(60, 4),
    "grid-layers": np.vstack([cube_grid(5, 5, 1) + [0, 0, z] for z in (0, 1, 3)]),
    "moment-curve": np.array([(t, t * t, t ** 3) for t in range(-20, 21)], dtype=float),
    "skew-lines": np.array([(t, 0, 0) for t in range(40)] + [(0, t, 1) for t in range(40)],
                           dtype=float),
    "duplicates": np.vstack([cube_grid(3, 3, 3)] * 3),
    "tiny-1e-300": np.random.default_rng(2).random((150, 3)) * 1e-300,
    "huge-1e300": np.random.default_rng(3).random((150, 3)) * 1e300,
    "mixed-1e-300-1e300": np.vstack([cube_grid(3, 3, 3) * 1e-300, cube_grid(2, 2, 2) * 1e300]),
    "offset-1e9": 1e9 + cube_grid(4, 4, 4) * 1e-6,
    "extreme-1.7e308": np.random.default_rng(4).uniform(-1, 1, (60, 3)) * 1.7e308,
}


# ----------------------------------------------------------------------------- tests
@pytest.mark.parametrize("n,seed", [(50, 0), (400, 1), (2000, 2)])
def test_matches_qhull_in_general_position(n, seed):
    pts = np.random.default_rng(seed).random((n, 3))
    ours = {tuple(sorted(t)) for t in delaunay_3d(pts).tolist()}
    qhull = {tuple(sorted(t)) for t in QhullDelaunay(pts).simplices.tolist()}
    assert ours == qhull


@pytest.mark.parametrize("n,seed", [(30, 4), (700, 5)])
def test_valid_on_random_sets(n, seed):
    pts = np.random.default_rng(seed).normal(size=(n, 3))
    d = Delaunay3D(pts)
    assert check_delaunay_3d(pts, d.simplices) == (True, "ok")
    if n <= 30:
        assert brute_force_empty(pts, d.simplices)


@pytest.mark.parametrize("name", sorted(DEGENERATE))
def test_valid_on_degenerate_sets(name):
    pts = DEGENERATE[name]
    d = Delaunay3D(pts)
    ok, msg = check_delaunay_3d(pts, d.simplices)
    assert ok, msg
    if len(pts) <= 60:
        assert brute_force_empty(pts, d.simplices)
    assert d.stats["fallback_scans"] == 0
    if len(d.simplices):   # an independent oracle for the tiling: total volume == Qhull's hull volume
        P = int_points(pts)
        assert sum(orient(*(P[v] for v in t)) for t in d.simplices) == hull_volume6(P, pts)


def test_checker_rejects_broken_answers():
    """The checker must fail on wrong answers, or the tests above prove nothing."""
    pts = cube_grid(3, 3, 3)
    tets = Delaunay3D(pts).simplices
    assert check_delaunay_3d(pts, tets)[0]
    assert not check_delaunay_3d(pts, tets[1:])[0]                          # a hole
    assert check_delaunay_3d(pts, tets[:, [1, 0, 2, 3]])[0]                 # either orientation is fine
    flat = np.vstack([tets[1:], [[0, 1, 2, 2]]])
    assert "flat" in check_delaunay_3d(pts, flat)[1]                         # a zero-volume tetrahedron
    assert not check_delaunay_3d(pts, np.vstack([tets, tets[:1]]))[0]       # an overlap
    five = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.875, 0.875, 0.875]])
    # point 4 is inside the sphere through 0..3: the Delaunay answer is the three tetrahedra
    # around edge 0-4; the two-tetrahedra split through face (1, 2, 3) is a valid
    # triangulation but not Delaunay, so it must be rejected
    good = Delaunay3D(five).simplices
    assert check_delaunay_3d(five, good)[0] and len(good) == 3
    bad = [(0, 1, 2, 3), (4, 1, 2, 3)]
    bad = [t if orient(*(int_points(five)[v] for v in t)) > 0 else (t[1], t[0], t[2], t[3])
           for t in bad]
    ok, msg = check_delaunay_3d(five, bad)
    assert not ok and "Delaunay" in msg
    assert not brute_force_empty(five, bad)
    assert not check_delaunay_3d(five, good[:1])[0]                         # a point left out


def test_grid_counts_and_volume():
    pts = cube_grid(4, 4, 4)
    d = Delaunay3D(pts)
    vol6 = sum(orient(*(int_points(pts)[v] for v in t)) for t in d.simplices)
    assert vol6 == 6 * 27
    assert len(d.hull_facets) == 6 * 9 * 2     # each 3x3 square face split into 18 triangles


def test_positive_orientation_and_neighbours():
    pts = np.random.default_rng(9).random((300, 3))
    d = Delaunay3D(pts)
    P = int_points(pts)
    S, N = d.simplices, d.neighbors
    hull = {tuple(sorted(f)) for f in d.hull_facets.tolist()}
    assert (N < 0).sum() == len(hull)
    for t in range(len(S)):
        assert orient(*(P[v] for v in S[t])) > 0
        for k in range(4):
            face = set(S[t].tolist()) - {S[t, k]}
            o = N[t, k]
            if o < 0:
                assert tuple(sorted(face)) in hull
            else:
                assert face <= set(S[o].tolist()) and t in N[o].tolist()


def test_hull_facets_face_outward():
    pts = np.vstack([cube_grid(3, 3, 3), np.random.default_rng(1).random((40, 3)) * 2])
    d = Delaunay3D(pts)
    P = int_points(pts)
    for a, b, c in d.hull_facets:
        s = [orient(P[a], P[b], P[c], q) for q in P]
        assert min(s) >= 0 and max(s) > 0      # every point below (inside) a CCW-from-outside facet
    assert len(d.hull_facets) == 6 * 2 * 4     # the 3x3x3 grid's faces, two triangles per square


@given(st.lists(st.tuples(st.integers(0, 3), st.integers(0, 3), st.integers(0, 2)),
                min_size=1, max_size=30), st.randoms(use_true_random=False))
def test_hypothesis_small_integer_sets(raw, rnd):
    """Heavily degenerate sets (coplanar, cospherical, duplicates): valid, empty spheres, and
    the same tetrahedra (as coordinates) for a shuffled input."""
    pts = np.array(raw, dtype=float)
    d = Delaunay3D(pts)
    ok, msg = check_delaunay_3d(pts, d.simplices)
    assert ok, msg
    assert brute_force_empty(pts, d.simplices)
    perm = list(range(len(pts)))
    rnd.shuffle(perm)
    d2 = Delaunay3D(pts[perm])
    assert coordinate_set(pts[perm], d2.simplices) == coordinate_set(pts, d.simplices)


@pytest.mark.parametrize("name", ["grid-6x6x6", "lattice-sphere+centre", "duplicates"])
def test_input_order_does_not_matter(name):
    pts = DEGENERATE[name]
    base = coordinate_set(pts, delaunay_3d(pts))
    for seed in range(3):
        perm = np.random.default_rng(seed).permutation(len(pts))
        assert coordinate_set(pts[perm], delaunay_3d(pts[perm])) == base


def test_power_of_two_scaling_gives_identical_output():
    pts = DEGENERATE["lattice-sphere+centre"]
    base = delaunay_3d(pts)
    for e in (-1000, -500, 500, 1000):
        assert np.array_equal(delaunay_3d(np.ldexp(pts, e)), base)


def test_duplicates_are_merged():
    pts = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 0, 0], [0, 0, 0], [1, 1, 1]],
                   dtype=float)
    d = Delaunay3D(pts)
    assert d.index_map.tolist() == [0, 1, 2, 3, 1, 0, 6]
    assert set(d.simplices.ravel().tolist()) == {0, 1, 2, 3, 6}
    assert check_delaunay_3d(pts, d.simplices)[0]


@pytest.mark.parametrize("pts", [
    [], [(1.0, 2.0, 3.0)], [(0, 0, 0)] * 5, [(0, 0, 0), (1, 1, 1), (2, 2, 2), (5, 5, 5)],
    [(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(x, y, 0) for x in range(5) for y in range(5)],
    [(x, y, x + 2 * y) for x in range(4) for y in range(4)] * 2])
def test_flat_input_gives_no_tetrahedra(pts):
    d = Delaunay3D(pts)
    assert d.flat and d.simplices.shape == (0, 4) and d.neighbors.shape == (0, 4)
    assert d.hull_facets.shape == (0, 3)
    assert d.find_simplex((0.1, 0.1, 0.1)) == -1
    imap = d.index_map
    arr = np.asarray(pts, dtype=float).reshape(-1, 3)
    for i in range(len(arr)):
        assert imap[i] <= i and np.array_equal(arr[imap[i]], arr[i])
        assert imap[i] == min(j for j in range(len(arr)) if np.array_equal(arr[j], arr[i]))


@pytest.mark.parametrize("bad", [[(0, 0)], [(0, 0, float("nan"))], [(0, 0, float("inf"))],
                                 "points", [("a", "b", "c")], [[1, 2, 3], [4, 5]]])
def test_bad_input_raises(bad):
    with pytest.raises(ValueError):
        Delaunay3D(bad)


def test_find_simplex():
    rng = np.random.default_rng(11)
    pts = rng.random((400, 3))
    d = Delaunay3D(pts)
    q = np.vstack([rng.random((300, 3)) * 1.4 - 0.2, pts[:20], (pts[:10] + pts[10:20]) / 2])
    found = d.find_simplex(q)
    P = int_points(np.vstack([pts, q]))
    Q = P[len(pts):]
    for i, t in enumerate(found.tolist()):
        if t >= 0:
            a, b, c, e = (P[v] for v in d.simplices[t])
            tet = (a, b, c, e)
            for k in range(4):   # q on the inner side (or on) of every face
                rest = [tet[j] for j in range(4) if j != k]
                assert orient(*rest, Q[i]) * orient(*rest, tet[k]) >= 0
        else:
            assert any(orient(P[a], P[b], P[c], Q[i]) < 0 for a, b, c in d.hull_facets)
    assert (found[300:] >= 0).all()
    assert isinstance(d.find_simplex((0.5, 0.5, 0.5)), int)


def test_arrays_grow_when_needed():
    """Large cavities and O(n^2) outputs: the kernel asks for room and resumes."""
    sphere = unit_sphere(1500, seed=4)
    coords = np.vstack([sphere, [[0.0, 0.0, 0.0]]])          # centre last: its cavity is everything
    m = Mesh(coords)
    simp, _, _, _ = m.extract()
    assert len(m.bad) > 1024                                   # the cavity arrays grew
    assert len(simp) and (simp == 1500).any(axis=1).sum() == len(ConvexHull(sphere).simplices)
    curve = DEGENERATE["skew-lines"]
    m2 = Mesh(curve[insertion_order_3d(curve)])
    assert len(m2.mark) > 7 * len(curve) + 64                  # the tetrahedron arrays grew
    assert check_delaunay_3d(curve, delaunay_3d(curve))[0]


def test_kernel_face_table_matches_the_predicates():
    from reference_impl.mesh import kernel3d as _mesh3d
    from reference_impl.exact.predicates3d import FACES
    assert _mesh3d._F.tolist() == [list(f) for f in FACES]


def test_hilbert_curve_is_continuous():
    bits = 3
    cells = list(itertools.product(range(8), repeat=3))
    keys = [hilbert_index_3d(x, y, z, bits) for x, y, z in cells]
    assert sorted(keys) == list(range(512))
    path = [c for _, c in sorted(zip(keys, cells))]
    assert all(sum(abs(a - b) for a, b in zip(p, q)) == 1 for p, q in zip(path, path[1:]))


def test_insertion_order_depends_only_on_the_set():
    pts = np.vstack([cube_grid(4, 4, 4), unit_sphere(100)])
    base = pts[insertion_order_3d(pts)]
    perm = np.random.default_rng(0).permutation(len(pts))
    assert np.array_equal(pts[perm][insertion_order_3d(pts[perm])], base)


# =================================================================================================
# slow: 1000 random small cases and the 3D degenerate families (was test_delaunay3d_1000.py)
# =================================================================================================
CASES = 1000


# ----------------------------------------------------------------------------- exact checker
def exact(points) -> list[tuple[int, int, int]]:
    """Every coordinate times one common power of two, as Python integers."""
    ratios = [[float(v).as_integer_ratio() for v in p] for p in np.asarray(points, dtype=float).reshape(-1, 3)]
    den = max([d for r in ratios for _, d in r], default=1)
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def orient_sign(a, b, c, d) -> int:
    """Sign of det(a - d, b - d, c - d): positive for a positively oriented tetrahedron."""
    s = orient(a, b, c, d)
    return (s > 0) - (s < 0)


def insphere_sign(a, b, c, d, e) -> int:
    """+1 when e is strictly inside the sphere through the positively oriented a, b, c, d
    (the sign convention is checked by test_oracle_sanity)."""
    s = insphere(a, b, c, d, e)
    return (s > 0) - (s < 0)


def check_3d(points, tets, neighbors=None, hull=None, brute=False) -> None:
    P = exact(points)
    first: dict = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    distinct = sorted(set(rep))
    T = [tuple(t) for t in np.asarray(tets).reshape(-1, 4).tolist()]
    o = distinct[0] if distinct else None
    solid = any(orient_sign(P[o], P[i], P[j], P[k]) != 0 for i, j, k in itertools.combinations(distinct[1:], 3))
    if not solid:
        assert T == [], "coplanar input (or fewer than 4 distinct points) must give no tetrahedra"
        return
    assert T, "no tetrahedra for a solid point set"
    for t in T:
        assert all(rep[v] == v for v in t), f"tetrahedron {t} uses a duplicate index"
        assert orient_sign(*(P[v] for v in t)) > 0, f"tetrahedron {t} is not positively oriented"
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
            sx, sy = orient_sign(a, b, c, P[x]), orient_sign(a, b, c, P[y])
            assert sx * sy < 0, f"the two tetrahedra on face {f} overlap"
            tet = (a, b, c, P[x]) if sx > 0 else (a, c, b, P[x])
            assert insphere_sign(*tet, P[y]) <= 0, f"face {f} is not locally Delaunay"
        else:
            sx = orient_sign(a, b, c, P[side[0][1]])
            assert all(orient_sign(a, b, c, P[q]) * sx >= 0 for q in distinct), f"boundary face {f} is not on the hull"
            boundary.add(f)
    c4 = tuple(sum(P[v][i] for v in T[0]) for i in range(3))           # 4 x the centroid of T[0]
    P4 = [(4 * x, 4 * y, 4 * z) for x, y, z in P]
    holding = 0
    for t in T:
        q = [P4[v] for v in t]
        if all(orient_sign(*(c4 if j == k else q[j] for j in range(4))) >= 0 for k in range(4)):
            holding += 1
    assert holding == 1, f"{holding} tetrahedra cover one point: not a tiling"
    assert {v for t in T for v in t} == set(distinct), "a point is not a vertex"
    if brute:
        for t in T:
            assert all(insphere_sign(*(P[v] for v in t), P[q]) <= 0 for q in distinct), f"{t} has a point inside"
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
            assert all(orient_sign(P[a], P[b], P[c], P[q]) >= 0 for q in distinct)


@pytest.mark.slow
def test_oracle_sanity():
    """The hand-written predicates have the conventions the checker assumes, and it rejects
    broken answers."""
    a, b, c, d = (0, 0, 0), (4, 0, 0), (0, 4, 0), (0, 0, 4)
    assert orient_sign(a, d, c, b) > 0 and orient_sign(a, b, c, d) < 0
    # circumsphere: centre (2, 2, 2), through the origin and (4, 4, 4)
    assert insphere_sign(a, d, c, b, (1, 1, 1)) > 0 and insphere_sign(a, d, c, b, (4, 4, 4)) == 0
    assert insphere_sign(a, d, c, b, (5, 4, 4)) < 0
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
        return [t if orient_sign(*(P[v] for v in t)) > 0 else (t[1], t[0], t[2], t[3]) for t in tets]

    # the two 5-tetrahedra splits of the cube (central tetrahedron on the even or the odd
    # corners) share no face: stacked, every local test passes and only the tiling test fails
    even = positive([(1, 0, 3, 5), (2, 0, 3, 6), (4, 0, 5, 6), (7, 3, 5, 6), (0, 3, 5, 6)])
    odd = positive([(0, 1, 2, 4), (3, 1, 2, 7), (5, 1, 4, 7), (6, 2, 4, 7), (1, 2, 4, 7)])
    check_3d(cube, even, brute=True)
    check_3d(cube, odd, brute=True)
    with pytest.raises(AssertionError, match="not a tiling"):
        check_3d(cube, even + odd)


# ----------------------------------------------------------------------------- 1000 random cases
@pytest.mark.slow
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


@pytest.mark.slow
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


_rng = np.random.default_rng(2024)
SMALL_DEGENERATE = {
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


@pytest.mark.slow
@pytest.mark.parametrize("name", list(SMALL_DEGENERATE))
def test_degenerate_families(name):
    pts = SMALL_DEGENERATE[name]
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
