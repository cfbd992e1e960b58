"""Tests for reference_impl.structures.navmesh: polygons with holes, triangulated, and shortest paths in them.

Run:  .venv/bin/python -m pytest tests/structures/test_navmesh.py -q

Oracle: the visibility graph of all polygon vertices plus start and goal, with
an edge wherever shapely says the closed polygon (with holes) covers the
segment, solved by networkx Dijkstra.  Lengths must agree to 1e-9 (relative),
every returned segment must be covered by the polygon, corners must be polygon
vertices.  Also: ``is_visible`` against shapely on integer mazes (exact there),
the funnel (``channel_path``) against the optimum on polygons without holes,
``None`` cases, hand-made mazes and degenerate touching paths.
``polygon_triangulation``: the same triangles as Triangle ('p' with hole
points) on random polygons with holes; exact integer areas; ring orientation;
every invalid polygon (crossing, touching, nested, outside) named in the error.
"""
from __future__ import annotations

import math

import networkx as nx
import numpy as np
import pytest
import shapely
import triangle
from hypothesis import given, settings, strategies as st
from shapely.geometry import LineString, Point, Polygon

from reference_impl.structures.navmesh import NavMesh, funnel, polygon_triangulation, shortest_path
from reference_impl.exact.verify import exact_coordinates, incircle_exact, orient_exact


# ----------------------------------------------------------------------------- oracle
def oracle_length(boundary, holes, start, goal) -> float | None:
    poly = Polygon(boundary, holes)
    if not (poly.covers(Point(start)) and poly.covers(Point(goal))):
        return None
    nodes = [tuple(map(float, p)) for ring in [boundary, *holes] for p in ring] + [tuple(start), tuple(goal)]
    pairs = [(i, j) for i in range(len(nodes)) for j in range(i + 1, len(nodes))]
    lines = shapely.linestrings([[nodes[i], nodes[j]] for i, j in pairs])
    ok = shapely.covers(poly, lines)
    g = nx.Graph()
    g.add_nodes_from(range(len(nodes)))
    for (i, j), good in zip(pairs, ok):
        if good or nodes[i] == nodes[j]:
            g.add_edge(i, j, weight=math.dist(nodes[i], nodes[j]))
    return nx.dijkstra_path_length(g, len(nodes) - 2, len(nodes) - 1)


def path_length(path) -> float:
    return sum(math.dist(a, b) for a, b in zip(path, path[1:]))


def assert_valid_path(boundary, holes, start, goal, path) -> None:
    poly = Polygon(boundary, holes)
    assert path[0] == tuple(map(float, start)) and path[-1] == tuple(map(float, goal))
    vertices = {tuple(map(float, p)) for ring in [boundary, *holes] for p in ring}
    assert all(c in vertices for c in path[1:-1]), "a corner is not a polygon vertex"
    for a, b in zip(path, path[1:]):
        assert poly.covers(LineString([a, b])), f"segment {a}-{b} leaves the free space"


def check_against_oracle(boundary, holes, start, goal) -> None:
    path = shortest_path(boundary, holes, start, goal)
    expect = oracle_length(boundary, holes, start, goal)
    if expect is None:
        assert path is None
        return
    assert path is not None
    assert_valid_path(boundary, holes, start, goal, path)
    assert math.isclose(path_length(path), expect, rel_tol=1e-9, abs_tol=1e-12)


# ----------------------------------------------------------------------------- generators
def star_polygon(rng, k, scale=1.0):
    """Random simple polygon, star-shaped around the origin, radii in [0.7, 1] * scale."""
    ang = (np.arange(k) + rng.uniform(-0.4, 0.4, k)) * 2 * np.pi / k
    r = rng.uniform(0.7, 1.0, k)
    return np.stack([r * np.cos(ang), r * np.sin(ang)], axis=1) * scale


def convex_holes(rng, count, scale=1.0):
    """Up to 9 disjoint convex holes around the points (0.3 i, 0.3 j), i, j in -1..1; returns holes, centres."""
    cells = rng.permutation(9)[:count]
    holes, centres = [], []
    for c in cells:
        cx, cy = 0.3 * (c % 3 - 1), 0.3 * (c // 3 - 1)
        m = int(rng.integers(3, 7))
        ang = np.sort(rng.uniform(0, 2 * np.pi, m))
        if np.max(np.diff(np.concatenate([ang, [ang[0] + 2 * np.pi]]))) > 0.9 * np.pi:
            ang = np.arange(m) * 2 * np.pi / m + ang[0]    # keep the centre inside the hole
        r = rng.uniform(0.05, 0.1, m)
        holes.append(np.stack([cx + r * np.cos(ang), cy + r * np.sin(ang)], axis=1) * scale)
        centres.append((cx * scale, cy * scale))
    return holes, centres


def triangle_set(tris) -> set:
    return {frozenset(t) for t in np.asarray(tris).tolist()}


def float_area(pt) -> float:
    a, b, c = (pt.points[pt.simplices[:, k]] for k in range(3))
    return float(np.sum((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))) / 2


def area2_int(P, ring) -> int:
    return sum(P[a][0] * P[b][1] - P[b][0] * P[a][1] for a, b in zip(ring, list(ring[1:]) + [ring[0]]))


def free_point(rng, poly: Polygon, integer=False):
    x0, y0, x1, y1 = poly.bounds
    while True:
        p = (rng.uniform(x0, x1), rng.uniform(y0, y1))
        if integer:
            p = (float(round(p[0])), float(round(p[1])))
        if poly.covers(Point(p)):
            return p


# serpentine corridor: teeth from the left wall (y 3..4) and the right wall (y 6..7)
SERPENT = [(0, 0), (10, 0), (10, 6), (2, 6), (2, 7), (10, 7), (10, 10), (0, 10), (0, 4), (8, 4), (8, 3), (0, 3)]
SERPENT_HOLES = [[(4, 1), (5, 1), (5, 2), (4, 2)], [(5, 8), (6, 8), (6, 9), (5, 9)]]


# ----------------------------------------------------------------------------- against the oracle
@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), k=st.integers(8, 40), h=st.integers(0, 6))
def test_random_polygons_match_visibility_graph(seed, k, h):
    rng = np.random.default_rng(seed)
    boundary = star_polygon(rng, k)
    holes, _ = convex_holes(rng, h)
    poly = Polygon(boundary, holes)
    for _ in range(3):
        check_against_oracle(boundary, holes, free_point(rng, poly), free_point(rng, poly))


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_serpentine_maze_integer_points(seed):
    """Integer start/goal: on walls, at corners, collinear with walls (degenerate on purpose)."""
    rng = np.random.default_rng(seed)
    poly = Polygon(SERPENT, SERPENT_HOLES)
    for _ in range(4):
        check_against_oracle(SERPENT, SERPENT_HOLES, free_point(rng, poly, True), free_point(rng, poly, True))


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(1, 3))
def test_pillar_grid_collinear_corners(seed, n):
    """Square pillars on a grid: paths graze rows of collinear corners, start/goal often on walls."""
    rng = np.random.default_rng(seed)
    size = 3 * n + 1
    room = [(0, 0), (size, 0), (size, size), (0, size)]
    pillars = [[(3 * i + 1, 3 * j + 1), (3 * i + 3, 3 * j + 1), (3 * i + 3, 3 * j + 3), (3 * i + 1, 3 * j + 3)]
               for i in range(n) for j in range(n) if rng.random() < 0.8]
    poly = Polygon(room, pillars)
    for _ in range(4):
        check_against_oracle(room, pillars, free_point(rng, poly, True), free_point(rng, poly, True))


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), k=st.integers(12, 40))
def test_funnel_is_optimal_without_holes(seed, k):
    rng = np.random.default_rng(seed)
    boundary = star_polygon(rng, k)
    poly = Polygon(boundary)
    nav = NavMesh(boundary)
    corners = [tuple(map(float, p)) for p in boundary]
    for _ in range(4):
        s, g = (corners[rng.integers(k)] if rng.random() < 0.3 else free_point(rng, poly) for _ in "sg")
        quick = nav.channel_path(s, g)
        assert_valid_path(boundary, [], s, g, quick)
        assert math.isclose(path_length(quick), path_length(nav.shortest_path(s, g)), rel_tol=1e-9)


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_is_visible_matches_shapely_on_integer_maze(seed):
    rng = np.random.default_rng(seed)
    nav = NavMesh(SERPENT, SERPENT_HOLES)
    poly = Polygon(SERPENT, SERPENT_HOLES)
    corners = [tuple(map(float, p)) for p in SERPENT] + [tuple(map(float, p)) for h in SERPENT_HOLES for p in h]
    for _ in range(30):
        a = corners[rng.integers(len(corners))] if rng.random() < 0.4 else free_point(rng, poly, True)
        b = corners[rng.integers(len(corners))] if rng.random() < 0.4 else free_point(rng, poly, True)
        assert nav.is_visible(a, b) == poly.covers(LineString([a, b])), (a, b)


# ----------------------------------------------------------------------------- hand-made cases
def test_serpentine_path_goes_round_both_teeth():
    path = shortest_path(SERPENT, [], (1, 1), (9, 9))
    assert path == [(1.0, 1.0), (8.0, 3.0), (8.0, 4.0), (2.0, 6.0), (2.0, 7.0), (9.0, 9.0)]


def test_path_along_a_wall_and_through_collinear_corners():
    room = [(0, 0), (4, 0), (4, 4), (0, 4)]
    holes = [[(1, 1), (3, 1), (3, 2), (1, 2)]]
    # the straight segment runs along the hole's bottom edge: touching is allowed
    assert shortest_path(room, holes, (0, 1), (4, 1)) == [(0.0, 1.0), (4.0, 1.0)]
    # from one hole corner to the opposite one: around the hole, two equal ways
    path = shortest_path(room, holes, (1, 1), (3, 2))
    assert math.isclose(path_length(path), 3.0)


def test_start_and_goal_on_walls_and_vertices():
    check_against_oracle(SERPENT, SERPENT_HOLES, (8, 3), (2, 7))      # reflex corners
    check_against_oracle(SERPENT, SERPENT_HOLES, (5, 0), (6, 10))      # on the outer walls
    check_against_oracle(SERPENT, SERPENT_HOLES, (4, 1.5), (10, 10))   # on a hole edge, at a corner
    check_against_oracle(SERPENT, SERPENT_HOLES, (0, 3), (0, 4))       # the two tips of a tooth


def test_none_cases():
    room = [(0, 0), (10, 0), (10, 10), (0, 10)]
    holes = [[(4, 4), (6, 4), (6, 6), (4, 6)]]
    assert shortest_path(room, holes, (5, 5), (1, 1)) is None          # start inside a hole
    assert shortest_path(room, holes, (1, 1), (5, 5)) is None          # goal inside a hole
    assert shortest_path(room, holes, (11, 1), (1, 1)) is None         # start outside
    assert shortest_path(SERPENT, [], (1, 1), (5, 3.5)) is None        # goal inside a tooth
    assert shortest_path(room, holes, (4, 5), (1, 1)) is not None      # on the hole's boundary


def test_start_equals_goal():
    assert shortest_path(SERPENT, [], (3, 3), (3, 3)) == [(3.0, 3.0)]
    assert shortest_path(SERPENT, [], (8, 4), (8, 4)) == [(8.0, 4.0)]
    assert shortest_path(SERPENT, [], (5, 3.5), (5, 3.5)) is None


def test_hole_orientation_and_closing_vertex_do_not_matter():
    holes_cw = [h[::-1] for h in SERPENT_HOLES]
    closed = SERPENT[::-1] + [SERPENT[-1]]
    a = shortest_path(SERPENT, SERPENT_HOLES, (1, 1), (9, 9))
    b = shortest_path(closed, holes_cw, (1, 1), (9, 9))
    assert a == b


@pytest.mark.parametrize("scale", [1e-300, 1e-3, 1e150, 1e300])
def test_scale_invariance(scale):
    """The same corners at any scale (every decision is exact; only lengths are rounded)."""
    sc = lambda pts: [(x * scale, y * scale) for x, y in pts]  # noqa: E731
    base = shortest_path(SERPENT, SERPENT_HOLES, (1, 1), (9, 9.5))
    path = shortest_path(sc(SERPENT), [sc(h) for h in SERPENT_HOLES], (scale, scale), (9 * scale, 9.5 * scale))
    assert path == sc(base)


def test_bad_input_raises():
    with pytest.raises(ValueError, match="start"):
        shortest_path(SERPENT, [], (math.nan, 1), (1, 1))
    with pytest.raises(ValueError, match="crosses"):
        shortest_path([(0, 0), (2, 0), (0, 2), (2, 2)], [], (0.5, 0.2), (1, 0.5))
    with pytest.raises(ValueError, match="outside the boundary"):
        shortest_path(SERPENT, [[(20, 20), (21, 20), (21, 21)]], (1, 1), (2, 2))


def test_funnel_directly():
    # a straight channel: no corner
    assert funnel((0, 0), (3, 0), [((1, 1), (1, -1)), ((2, 1), (2, -1))]) == [(0, 0), (3, 0)]
    # a bend to the left around (2, 1)
    portals = [((1, 1), (1, -1)), ((2, 1), (2, -1)), ((2, 1), (3, 2))]
    assert funnel((0, 0), (2, 3), portals) == [(0, 0), (2, 1), (2, 3)]


def test_large_polygon_with_many_holes():
    """About 1000 boundary vertices and 30 holes: a valid path no longer than the funnel's."""
    rng = np.random.default_rng(5)
    k = 1000
    ang = (np.arange(k) + rng.uniform(-0.4, 0.4, k)) * 2 * np.pi / k
    r = rng.uniform(0.85, 1.0, k)
    boundary = np.stack([r * np.cos(ang), r * np.sin(ang)], axis=1)
    holes = []
    for i in range(6):
        for j in range(5):
            cx, cy = -0.5 + 0.2 * i, -0.4 + 0.2 * j
            a = np.arange(6) * np.pi / 3 + rng.uniform(0, 1)
            holes.append(np.stack([cx + 0.06 * np.cos(a), cy + 0.06 * np.sin(a)], axis=1))
    nav = NavMesh(boundary, holes)
    s, g = (-0.7, -0.05), (0.72, 0.03)
    path = nav.shortest_path(s, g)
    assert_valid_path(boundary, holes, s, g, path)
    assert path_length(path) <= path_length(nav.channel_path(s, g)) * (1 + 1e-12)
    assert path_length(path) > math.dist(s, g)


# ----------------------------------------------------------------------------- polygon_triangulation
@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), k=st.integers(12, 60), h=st.integers(0, 6))
def test_polygon_with_holes_matches_triangle(seed, k, h):
    rng = np.random.default_rng(seed)
    boundary = star_polygon(rng, k)
    holes, centres = convex_holes(rng, h)
    pt = polygon_triangulation(boundary, holes)
    rings = [boundary] + holes
    sizes = np.cumsum([0] + [len(r) for r in rings])
    segs = np.concatenate([np.stack([np.arange(a, b), np.roll(np.arange(a, b), -1)], 1)
                           for a, b in zip(sizes[:-1], sizes[1:])])
    data = {"vertices": np.vstack(rings), "segments": segs}
    if centres:
        data["holes"] = np.array(centres)
    ref = triangle.triangulate(data, "p")
    assert len(ref["vertices"]) == len(pt.points)
    assert triangle_set(pt.simplices) == triangle_set(ref["triangles"])
    # every boundary/hole edge is an edge with exactly one free triangle beside it
    P = exact_coordinates(pt.points)
    directed = {(t[k], t[(k + 1) % 3]) for t in pt.simplices.tolist() for k in range(3)}
    for r, ring in enumerate(pt.rings):
        for u, v in zip(ring, np.roll(ring, -1)):
            assert (u, v) in directed and (v, u) not in directed
        assert (area2_int(P, ring.tolist()) > 0) == (r == 0)


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), k=st.integers(12, 40), h=st.integers(0, 5),
       flip=st.booleans())
def test_integer_polygon_area_is_exact(seed, k, h, flip):
    rng = np.random.default_rng(seed)
    boundary = np.round(star_polygon(rng, k, 1000))
    holes = [np.round(x) for x in convex_holes(rng, h, 1000)[0]]
    if flip:                                   # any orientation is accepted
        boundary = boundary[::-1]
        holes = [x[::-1] for x in holes]
    pt = polygon_triangulation(boundary, holes)
    P = [tuple(int(c) for c in p) for p in pt.points]
    tri_area = sum(area2_int(P, list(t)) for t in pt.simplices.tolist())
    expect = abs(area2_int(P, list(range(len(boundary))))) - sum(
        abs(area2_int(P, r.tolist())) for r in pt.rings[1:])
    assert tri_area == expect
    assert all(area2_int(P, list(t)) > 0 for t in pt.simplices.tolist())
    # constrained Delaunay: every edge between two kept triangles is locally Delaunay
    for t, nb in zip(pt.simplices.tolist(), pt.neighbors.tolist()):
        for k, o in enumerate(nb):
            if o >= 0:
                x = (set(pt.simplices[o].tolist()) - set(t)).pop()
                assert incircle_exact(*(P[v] for v in t), P[x]) <= 0


def test_rectangle_with_collinear_vertices_and_square_hole():
    boundary = [(0, 0), (1, 0), (2, 0), (3, 0), (3, 1), (3, 2), (3, 3), (2, 3), (1, 3), (0, 3), (0, 2), (0, 1)]
    hole = [(1, 1), (1.5, 1), (2, 1), (2, 2), (1, 2)]            # collinear vertex on a hole edge
    pt = polygon_triangulation(boundary, [hole])
    P = exact_coordinates(pt.points)
    assert sum(orient_exact(*(P[v] for v in t)) for t in pt.simplices.tolist()) == len(pt.simplices)
    area = float_area(pt)
    assert area == 8.0
    # 17 vertices, no interior points: triangles = n + 2 * holes - 2
    assert len(pt.simplices) == len(pt.points) + 2 * 1 - 2


def test_grid_room_with_axis_aligned_walls():
    """A 4x4 room with two 1x1 pillars; boundary closed with a repeated first vertex."""
    boundary = [(0, 0), (4, 0), (4, 4), (0, 4), (0, 0)]
    holes = [[(1, 1), (2, 1), (2, 2), (1, 2)], [(3, 2), (3, 3), (2, 3), (2, 2.5)]]
    pt = polygon_triangulation(boundary, holes)
    assert len(pt.points) == 12 and pt.rings[0].tolist() == [0, 1, 2, 3]
    area = float_area(pt)
    assert area == 16 - 1 - 0.75
    # neighbours: -1 exactly across the 4 + 4 + 4 ring edges
    assert int((pt.neighbors < 0).sum()) == 12


def test_orientation_is_normalised():
    pt1 = polygon_triangulation([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (2, 1), (2, 2)]])
    pt2 = polygon_triangulation([(0, 4), (4, 4), (4, 0), (0, 0)], [[(2, 2), (2, 1), (1, 1)]])
    assert pt1.rings[0].tolist() == [0, 1, 2, 3] and pt1.rings[1].tolist() == [6, 5, 4]
    assert pt2.rings[0].tolist() == [3, 2, 1, 0] and pt2.rings[1].tolist() == [4, 5, 6]
    key = lambda pt: {frozenset(map(tuple, pt.points[t].tolist())) for t in pt.simplices}  # noqa: E731
    assert key(pt1) == key(pt2)


SQUARE = [(0, 0), (10, 0), (10, 10), (0, 10)]


@pytest.mark.parametrize("boundary, holes, message", [
    ([(0, 0), (2, 0), (0, 2), (2, 2)], [], "boundary edge 3 .* crosses boundary edge 1"),
    (SQUARE, [[(20, 20), (21, 20), (21, 21)]], "hole 0 lies outside the boundary"),
    (SQUARE, [[(1, 1), (9, 1), (9, 9), (1, 9)], [(4, 4), (5, 4), (5, 5)]], "hole 1 lies inside hole 0"),
    (SQUARE, [[(4, 4), (5, 4), (5, 5)], [(1, 1), (9, 1), (9, 9), (1, 9)]], "hole 0 lies inside hole 1"),
    (SQUARE, [[(1, 1), (5, 1), (5, 5)], [(4, 2), (8, 2), (8, 8)]], "hole 1 edge .* crosses hole 0 edge"),
    (SQUARE, [[(5, 0), (6, 1), (4, 1)]], "hole 0 vertex 0 .* repeats|lies on"),
    (SQUARE, [[(5, 0.0), (6, 1), (4, 1)]], "lies on boundary edge 0"),
    (SQUARE, [[(10, 10), (9, 9), (9, 8)]], "repeats boundary vertex 2"),
    ([(0, 0), (4, 0), (2, 0), (2, 2)], [], "lies on"),                  # spike folding back
    ([(0, 0), (1, 1), (2, 2)], [], "zero area"),
    ([(0, 0), (1, 1), (0, 0)], [], "at least 3"),
    (SQUARE, [[(1, 1), (2, math.nan), (2, 2)]], r"holes\[0\]"),
    ([(0, 0), (4, 0), (4, 4), (2, 2), (0, 4), (2, 2)], [], "repeats"),   # touches itself at a vertex
])
def test_invalid_polygons_raise(boundary, holes, message):
    with pytest.raises(ValueError, match=message):
        polygon_triangulation(boundary, holes)
