"""The answers of every `exhaustive` test agree with brute-force oracles written here, independent of
reference_impl: exact Fractions on the lattice points (all pairs, all triples, clipping by every
bisector), and scipy's convex hull for the 3D volumes. Problems whose checker decides alone
(edge-flip: every flip and the final triangulation are checked exactly) or whose brute force would
repeat the reference's algorithm (navmesh, obstacle-clearance) are covered by their checker and by
tests/grader/test_problem_*.py.

Run: .venv/bin/python -m pytest tests/grader/test_exhaustive_oracles.py -q -n 0
"""
from __future__ import annotations

import itertools
import math
from fractions import Fraction as F

import pytest

from grader.problems import load_problem


def exhaustive(problem_id: str, exact: bool = True):
    """(args, reference answer) of each test of the problem's exhaustive group; with ``exact``
    the points (the first argument) as tuples of Fractions."""
    p = load_problem(problem_id)
    for t in p.tests():
        if t.group == "exhaustive":
            args = p.checker.read_input(t.input_text)
            first = [tuple(F(c) for c in q) for q in args[0]] if exact else args[0]
            yield [first, *args[1:]], p.read_answer(t, args)


def cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def sq(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b))


def distinct(points):
    first: dict = {}
    return [i for i, p in enumerate(points) if first.setdefault(tuple(p), i) == i]


def hull(points):
    """Convex hull vertices, counter-clockwise, without collinear ones (monotone chain)."""
    pts = sorted(set(map(tuple, points)))
    if len(pts) < 3:
        return pts
    out = []
    for seq in (pts, pts[::-1]):
        part = []
        for p in seq:
            while len(part) >= 2 and cross(part[-2], part[-1], p) <= 0:
                part.pop()
            part.append(p)
        out += part[:-1]
    return out


def area2(poly):
    return sum(a[0] * b[1] - a[1] * b[0] for a, b in zip(poly, poly[1:] + poly[:1]))


def on_hull_boundary(points, h):
    return sum(any(cross(a, b, p) == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0])
                   and min(a[1], b[1]) <= p[1] <= max(a[1], b[1]) for a, b in zip(h, h[1:] + h[:1]))
               for p in set(map(tuple, points)))


def incircle(a, b, c, d):
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    (ax, ay), (bx, by), (cx, cy) = rows
    return ((ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
            + (cx * cx + cy * cy) * (ax * by - bx * ay))


@pytest.mark.parametrize("problem", ["delaunay", "bowyer-watson-timed"])
def test_delaunay_answers_are_empty_circle_triangulations(problem):
    for (points,), tris in exhaustive(problem):
        h = hull(points)
        if len(h) < 3:
            assert tris == [], points
            continue
        P = [tuple(points[i]) for i in distinct(points)]
        assert len(tris) == 2 * len(P) - 2 - on_hull_boundary(P, h), (points, tris)
        assert sum(cross(*(points[v] for v in t)) for t in tris) == area2(h), (points, tris)
        for t in tris:
            a, b, c = (points[v] for v in t)
            assert cross(a, b, c) > 0 and all(incircle(a, b, c, d) <= 0 for d in P), (points, t)


def test_delaunay_3d_answers_are_empty_sphere_tetrahedralisations():
    from scipy.spatial import ConvexHull

    def det3(u, v, w):
        return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
                + u[2] * (v[0] * w[1] - v[1] * w[0]))

    for (points,), tets in exhaustive("delaunay-3d"):
        P = [tuple(points[i]) for i in distinct(points)]
        flat = all(det3(*[[x - y for x, y in zip(q, P[0])] for q in (a, b, c)]) == 0
                   for a, b, c in itertools.combinations(P[1:], 3))
        if flat:
            assert tets == [], points
            continue
        volume = 0
        for t in tets:
            a, b, c, d = (points[v] for v in t)
            rows = [[x - y for x, y in zip(q, d)] for q in (a, b, c)]
            vol = det3(*rows)
            assert vol != 0, (points, t)
            volume += abs(vol) / 6
            assert not any(_insphere_strict(a, b, c, d, e) for e in P if e not in (a, b, c, d)), (points, t)
        assert math.isclose(float(volume), ConvexHull([list(map(float, p)) for p in P]).volume, rel_tol=1e-12)


def _insphere_strict(a, b, c, d, e) -> bool:
    """Whether e is strictly inside the sphere through a, b, c, d (exact: the centre solved by
    Cramer's rule in Fractions)."""
    rows = [[q[k] - a[k] for k in range(3)] for q in (b, c, d)]
    rhs = [sum(x * x for x in r) / 2 for r in rows]

    def det(m):
        return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))

    D = det(rows)
    centre = [det([[rhs[i] if j == k else rows[i][j] for j in range(3)] for i in range(3)]) / D for k in range(3)]
    centre = [centre[k] + a[k] for k in range(3)]
    return sq(e, centre) < sq(a, centre)


def test_emst_answers_have_the_brute_force_tree_lengths():
    for (points,), edges in exhaustive("emst"):
        n = len(points)
        parent = list(range(n))

        def find(i):
            while parent[i] != i:
                i = parent[i]
            return i

        best = []
        for i, j in sorted(itertools.combinations(range(n), 2), key=lambda e: sq(points[e[0]], points[e[1]])):
            if find(i) != find(j):
                parent[find(i)] = find(j)
                best.append(sq(points[i], points[j]))
        assert sorted(sq(points[i], points[j]) for i, j in edges) == best, (points, edges)


def test_closest_pair_answers_are_at_the_brute_force_distance():
    for (points,), (i, j) in exhaustive("closest-pair"):
        assert i != j and sq(points[i], points[j]) == min(sq(a, b) for a, b in itertools.combinations(points, 2))


def test_proximity_network_answers_are_the_brute_force_gabriel_graph():
    for (points,), edges in exhaustive("proximity-network"):
        reps = distinct(points)
        want = sorted([i, j] for i, j in itertools.combinations(reps, 2)
                      if all(sq(points[k], points[i]) + sq(points[k], points[j]) > sq(points[i], points[j])
                             for k in reps if k not in (i, j)))
        assert sorted(map(list, edges)) == want, (points, edges)


def test_largest_empty_circle_radius_is_the_brute_force_maximum():
    for (points,), (x, y, r) in exhaustive("largest-empty-circle"):
        h = hull(points)
        P = list(set(map(tuple, points)))
        cands = []
        for a, b, c in itertools.combinations(P, 3):
            d = 2 * cross(a, b, c)
            if d:
                ux = ((a[0] ** 2 + a[1] ** 2) * (b[1] - c[1]) + (b[0] ** 2 + b[1] ** 2) * (c[1] - a[1])
                      + (c[0] ** 2 + c[1] ** 2) * (a[1] - b[1])) / d
                uy = ((a[0] ** 2 + a[1] ** 2) * (c[0] - b[0]) + (b[0] ** 2 + b[1] ** 2) * (a[0] - c[0])
                      + (c[0] ** 2 + c[1] ** 2) * (b[0] - a[0])) / d
                cands.append((ux, uy))
        for p, q in itertools.combinations(P, 2):          # bisector of p, q crossing a hull edge
            for a, b in zip(h, h[1:] + h[:1]):
                # a + s (b - a) equidistant from p and q: linear in s
                fa = sq(a, p) - sq(a, q)
                fb = sq(b, p) - sq(b, q)
                if fa != fb:
                    s = fa / (fa - fb)
                    if 0 <= s <= 1:
                        cands.append((a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])))
        inside = [c for c in cands if all(cross(a, b, c) >= 0 for a, b in zip(h, h[1:] + h[:1]))]
        best = max(min(sq(c, p) for p in P) for c in inside)
        assert math.isclose(r, math.sqrt(best), rel_tol=1e-9), (points, r, best)


def clip(poly, p, q):
    """The part of ``poly`` closer to p than to q (exact)."""
    def f(v):
        return sq(v, q) - sq(v, p)     # >= 0: on p's side

    out = []
    for a, b in zip(poly, poly[1:] + poly[:1]):
        fa, fb = f(a), f(b)
        if fa >= 0:
            out.append(a)
        if (fa > 0 > fb) or (fa < 0 < fb):
            s = fa / (fa - fb)
            out.append((a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])))
    return out


def test_voronoi_cells_have_the_brute_force_areas():
    for (points, box), cells in exhaustive("voronoi"):
        x0, y0, x1, y1 = (F(v) for v in box)
        P = [tuple(p) for p in points]
        for i, p in enumerate(P):
            poly = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
            for q in set(P) - {p}:
                poly = clip(poly, p, q)
            want = float(area2(poly)) / 2 if len(poly) >= 3 else 0.0
            got = area2([tuple(map(F, v)) for v in cells[i]]) / 2 if len(cells[i]) >= 3 else 0
            assert math.isclose(float(got), want, abs_tol=1e-12), (points, box, i)


def strict_neighbours(pos, live, u):
    """Ids linked to u in the strict Delaunay graph of the live nodes (brute force, exact): the
    centres equidistant from P(u) and Q that are strictly closer to both than to every other
    position form a segment of positive length."""
    P = pos[u]
    places = {pos[v] for v in live}
    out = {v for v in live if v != u and pos[v] == P}
    for Q in places - {P}:
        m = ((P[0] + Q[0]) / 2, (P[1] + Q[1]) / 2)
        d = (P[1] - Q[1], Q[0] - P[0])
        lo, hi, ok = -math.inf, math.inf, True
        for R in places - {P, Q}:
            a = sq(m, R) - sq(m, P)
            b = 2 * (d[0] * (P[0] - R[0]) + d[1] * (P[1] - R[1]))
            if b == 0:
                ok = ok and a > 0
            elif b > 0:
                lo = max(lo, -a / b)
            else:
                hi = min(hi, -a / b)
        if ok and lo < hi:
            out |= {v for v in live if pos[v] == Q}
    return sorted(out)


def test_dynamic_network_answers_are_the_brute_force_strict_delaunay_graph():
    for (operations,), answers in exhaustive("dynamic-network", exact=False):
        pos, live, want = [], set(), []
        for op in operations:
            if op[0] == "join":
                pos.append((F(op[1]), F(op[2])))
                live.add(len(pos) - 1)
                want.append(len(pos) - 1)
            elif op[0] == "fail":
                want.append("ok" if op[1] in live else "error")
                live.discard(op[1])
            elif op[0] == "neighbors":
                want.append(strict_neighbours(pos, live, op[1]) if op[1] in live else "error")
            else:
                want.append(len(live))
        assert answers == want
