"""laplacian_smooth and mesh_quality: 1000 random small meshes each and the degenerate
families, against oracles written here.

Run:  .venv/bin/python -m pytest tests/structures/test_flips_1000.py -q

Oracles (nothing shared with the library):

* ``mesh_quality``: per triangle, the squared side lengths as exact ``Fraction``s, the
  angles from the law of cosines (cos A = (b^2 + c^2 - a^2) / 2bc, with cos^2 A formed
  exactly and only its square root and arccos in floating point), the radius ratio
  R / 2r = abc (a + b + c) / 16 K^2 with 16 K^2 formed exactly, the edge ratio from the
  exact squared lengths; the counts from a plain edge count (an edge in one triangle is
  a boundary edge, in two an interior edge), "below 30 degrees" and "obtuse" decided
  exactly (cos^2 A > 3/4 with cos A > 0; b^2 + c^2 - a^2 < 0).
* ``laplacian_smooth``: a networkx graph of the mesh edges; boundary vertices are the
  ends of edges used by one triangle; every free vertex moves to the plain average of
  its neighbours' previous positions (Jacobi), all at once; with the guard, while some
  triangle is inverted (exact orientation <= 0 with Fractions), the vertices of the
  inverted triangles that moved are put back.  Also checked directly: boundary, fixed
  and unused vertices do not move (bit for bit), and no triangle is inverted.
"""
from __future__ import annotations

import math
from collections import Counter
from fractions import Fraction

import networkx as nx
import numpy as np
import pytest

import pointsets
from reference_impl import Delaunay
from reference_impl.structures.flips import laplacian_smooth, mesh_quality

CASES = 1000


# ----------------------------------------------------------------------------- oracles
def frac(p):
    return (Fraction(float(p[0])), Fraction(float(p[1])))


def sq(p, q) -> Fraction:
    return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2


def cross(a, b, c) -> Fraction:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def triangle_quality(A, B, C) -> dict:
    """Angles (degrees), exact flags, radius ratio and edge ratio of one triangle (exact inputs)."""
    a2, b2, c2 = sq(B, C), sq(C, A), sq(A, B)          # sides opposite A, B, C
    angles, below30, obtuse = [], 0, False
    for opp, s1, s2 in ((a2, b2, c2), (b2, c2, a2), (c2, a2, b2)):
        num = s1 + s2 - opp                            # = 2 s1' s2' cos(angle)
        cos2 = num * num / (4 * s1 * s2)
        cos = math.sqrt(float(cos2)) * (1 if num >= 0 else -1)
        angles.append(math.degrees(math.acos(min(1.0, cos))))
        below30 += num > 0 and cos2 > Fraction(3, 4)   # cos > sqrt(3) / 2
        obtuse |= num < 0
    m = max(a2, b2, c2)
    u, v, w = float(a2 / m), float(b2 / m), float(c2 / m)
    k16 = 4 * cross(A, B, C) ** 2 / (m * m)            # 16 K^2 / m^2
    ratio = math.sqrt(u * v * w) * (math.sqrt(u) + math.sqrt(v) + math.sqrt(w)) / float(k16)
    edge = math.sqrt(float(m / min(a2, b2, c2)))
    return {"angles": angles, "below30": below30, "obtuse": obtuse, "ratio": ratio, "edge": edge}


def quality_oracle(points, tris) -> dict:
    F = [frac(p) for p in np.asarray(points, dtype=float)]
    per = [triangle_quality(*(F[v] for v in t)) for t in np.asarray(tris).tolist()]
    angles = [a for q in per for a in q["angles"]]
    edges = Counter(frozenset((t[i], t[(i + 1) % 3])) for t in np.asarray(tris).tolist() for i in range(3))
    return {
        "min_angle": min(angles), "max_angle": max(angles),
        "mean_min_angle": sum(min(q["angles"]) for q in per) / len(per),
        "radius_ratio_max": max(q["ratio"] for q in per),
        "radius_ratio_mean": sum(q["ratio"] for q in per) / len(per),
        "edge_ratio_max": max(q["edge"] for q in per),
        "triangles": len(per),
        "vertices": len({v for t in np.asarray(tris).tolist() for v in t}),
        "interior_edges": sum(1 for c in edges.values() if c == 2),
        "boundary_edges": sum(1 for c in edges.values() if c == 1),
        "angles_below_30": sum(q["below30"] for q in per),
        "obtuse_triangles": sum(q["obtuse"] for q in per),
    }


def assert_quality(points, tris) -> None:
    got = mesh_quality(points, tris)
    want = quality_oracle(points, tris)
    assert set(got) == set(want)
    for key in ("triangles", "vertices", "interior_edges", "boundary_edges", "angles_below_30",
                "obtuse_triangles"):
        assert got[key] == want[key], (key, got[key], want[key])
    for key in ("min_angle", "max_angle", "mean_min_angle"):
        assert math.isclose(got[key], want[key], rel_tol=1e-12, abs_tol=1e-7), (key, got[key], want[key])
    if want["radius_ratio_max"] > 1e12:
        # a needle: its float area (a difference of near-equal products) has lost most digits
        assert got["radius_ratio_max"] > 1e10, (got["radius_ratio_max"], want["radius_ratio_max"])
        assert got["radius_ratio_mean"] >= got["radius_ratio_max"] / want["triangles"]
    else:
        # the float area of a thin triangle loses about eps * ratio of relative accuracy
        tol = max(1e-9, 1e-13 * want["radius_ratio_max"])
        for key in ("radius_ratio_max", "radius_ratio_mean"):
            assert math.isclose(got[key], want[key], rel_tol=tol), (key, got[key], want[key])
    assert math.isclose(got["edge_ratio_max"], want["edge_ratio_max"], rel_tol=1e-12)


def smooth_oracle(points, tris, iterations=1, fixed=(), guard=True):
    """(new points as float pairs, number of vertices the guard put back)."""
    X = [tuple(map(float, p)) for p in np.asarray(points, dtype=float)]
    T = [tuple(t) for t in np.asarray(tris).tolist()]
    g = nx.Graph()
    uses = Counter()
    for t in T:
        for i in range(3):
            g.add_edge(t[i], t[(i + 1) % 3])
            uses[frozenset((t[i], t[(i + 1) % 3]))] += 1
    boundary = {v for e, c in uses.items() if c == 1 for v in e}
    free = set(g.nodes) - boundary - set(int(v) for v in fixed)
    reverted = 0
    for _ in range(iterations):
        new = list(X)
        for v in free:
            nb = list(g.neighbors(v))
            new[v] = (math.fsum(X[u][0] for u in nb) / len(nb), math.fsum(X[u][1] for u in nb) / len(nb))
        if guard:
            moved = set(free)
            while True:
                bad = [t for t in T if cross(*(frac(new[v]) for v in t)) <= 0]
                if not bad:
                    break
                back = {v for t in bad for v in t} & moved
                assert back, "an inverted triangle with no moved vertex"
                for v in back:
                    new[v] = X[v]
                moved -= back
                reverted += len(back)
        X = new
    return np.array(X, dtype=float).reshape(-1, 2), free, reverted


def assert_smooth(points, tris, iterations=1, fixed=None, guard=True) -> int:
    pts = np.asarray(points, dtype=float)
    got = laplacian_smooth(pts, tris, iterations, fixed=fixed, guard=guard)
    want, free, reverted = smooth_oracle(pts, tris, iterations, () if fixed is None else fixed, guard)
    still = np.setdiff1d(np.arange(len(pts)), sorted(free))
    assert np.array_equal(got[still], pts[still]), "a boundary, fixed or unused vertex moved"
    scale = np.abs(pts).max()
    assert np.allclose(got, want, rtol=0, atol=8 * np.spacing(scale)), np.abs(got - want).max()
    if guard:
        for t in np.asarray(tris).tolist():
            assert cross(*(frac(got[v]) for v in t)) > 0, f"triangle {t} inverted"
    return reverted


# ----------------------------------------------------------------------------- random meshes
def random_mesh(rng):
    """Delaunay triangles of 4-15 points, some removed (non-convex meshes, unused vertices)."""
    n = int(rng.integers(4, 16))
    kind = rng.integers(0, 3)
    pts = rng.random((n, 2))
    if kind == 1:                                   # a star: a centre and a jagged ring
        ang = np.sort(rng.uniform(0, 2 * np.pi, n - 1))
        r = rng.uniform(0.2, 1.0, n - 1)
        pts = np.vstack([[0.0, 0.0], np.c_[r * np.cos(ang), r * np.sin(ang)]])
    pts = pts * 10.0 ** int(rng.integers(-3, 4)) + (1e6 if rng.random() < 0.1 else 0.0)
    tris = Delaunay(pts).simplices
    if kind == 1:                                   # the fan around the centre, not Delaunay
        k = n - 1
        tris = np.array([(0, 1 + i, 1 + (i + 1) % k) for i in range(k)])
        P = [frac(p) for p in pts]
        tris = np.array([t for t in tris.tolist() if cross(*(P[v] for v in t)) > 0]).reshape(-1, 3)
    elif kind == 2 and len(tris) > 2:
        tris = tris[rng.permutation(len(tris))[: max(1, len(tris) - int(rng.integers(1, len(tris) // 2 + 1)))]]
    return pts, tris


def test_1000_random_meshes_mesh_quality():
    rng = np.random.default_rng(55)
    done = 0
    for _ in range(CASES):
        pts, tris = random_mesh(rng)
        if len(tris) == 0:
            continue
        assert_quality(pts, tris)
        done += 1
    assert done > 0.95 * CASES


def test_1000_random_meshes_laplacian_smooth():
    rng = np.random.default_rng(56)
    reverted = unguarded = 0
    for _ in range(CASES):
        pts, tris = random_mesh(rng)
        if len(tris) == 0:
            continue
        iterations = int(rng.integers(1, 4))
        fixed = rng.choice(len(pts), int(rng.integers(1, 3)), replace=False) if rng.random() < 0.3 else None
        guard = rng.random() < 0.85
        unguarded += not guard
        reverted += assert_smooth(pts, tris, iterations, fixed, guard)
    assert reverted > 20 and unguarded > 50             # the guard had work to do


# ----------------------------------------------------------------------------- degenerate families
def _mesh(pts):
    return Delaunay(pts).simplices


FAMILIES = [(name, pts) for name, pts in pointsets.degenerate_sets()] + [
    ("grid+1e9", pointsets.grid(6) + 1e9),
    ("grid*0.5+1e9", pointsets.grid(6) * 0.5 + 1e9),
    ("integer-right-triangles", np.array([(0, 0), (2, 1), (1, 3), (3, 4), (4, 2), (-1, 2)], dtype=float)),
    ("rotated-squares", np.array([(3 * i - 4 * j, 4 * i + 3 * j) for i in range(4) for j in range(4)], dtype=float)),
]


@pytest.mark.parametrize("name,pts", FAMILIES, ids=[f[0] for f in FAMILIES])
def test_degenerate_families(name, pts):
    tris = _mesh(pts)
    assert_quality(pts, tris)
    for iterations in (1, 3):
        assert_smooth(pts, tris, iterations)
    assert_smooth(pts, tris, 2, fixed=np.arange(0, len(pts), 3))
    assert_smooth(pts, tris, 1, guard=False)
    # perturbed interior (a non-Delaunay, non-uniform mesh on the same triangles)
    rng = np.random.default_rng(len(name))
    span = np.ptp(pts, axis=0).max()
    noisy = pts + rng.uniform(-0.02, 0.02, pts.shape) * span / np.sqrt(len(pts))
    P = [frac(p) for p in noisy]
    if all(cross(*(P[v] for v in t)) > 0 for t in tris.tolist()):
        assert_quality(noisy, tris)
        assert_smooth(noisy, tris, 2)
