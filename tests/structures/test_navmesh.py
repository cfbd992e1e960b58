"""Tests for reference_impl.structures.navmesh, polygon, funnel: polygons with holes and shortest paths in them.

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

The tests marked ``slow`` (at the end; until issue 9 they were ``test_navmesh_1000.py``;
``-m "not slow"`` leaves them out): navmesh: polygon_triangulation and shortest_path on 1000 random small cases each, and on
degenerate rooms, against independent oracles.

Oracles (nothing shared with the library):

* ``polygon_triangulation``: Triangle ('p', a point inside each hole) gives the same
  triangles on random polygons (general position: the constrained Delaunay
  triangulation is unique); an exact checker on Python integers: every triangle
  strictly counter-clockwise, twice the area sums exactly to the polygon's minus the
  holes', every ring edge is a triangle edge with the free space on its left (rings
  normalised: boundary counter-clockwise, holes clockwise), neighbours -1 exactly
  across ring edges, every other edge locally Delaunay.
* ``shortest_path``: the visibility graph of all polygon vertices plus start and goal,
  solved with networkx Dijkstra.  On random polygons an edge is kept when shapely says
  the polygon covers the closed segment; on the degenerate integer rooms (collinear
  vertices, paths grazing corners, scaled to 1e-300 / 1e300, offset by 1e9) visibility
  is decided exactly with Python integers and Fractions instead (``segment_free``), so
  that the oracle itself cannot be fooled by rounding.  The path must start and end at
  start and goal, bend only at polygon vertices, stay in the closed free space, and be
  as short as the oracle's to 1e-9 (relative); ``None`` exactly when start or goal is
  outside the free space.
* Invalid polygons (repeated vertices, crossings) must raise ``ValueError``; random
  shuffled outlines raise exactly when shapely says the ring is not simple.
"""
from __future__ import annotations

import math
from fractions import Fraction

import networkx as nx
import numpy as np
import pytest
import shapely
import triangle
from hypothesis import given, settings, strategies as st
from shapely.geometry import LinearRing, LineString, Point, Polygon

from exact_oracle import exact, incircle, orient
from grader.problems import load_problem
from reference_impl.structures.funnel import funnel
from reference_impl.structures.navmesh import NavMesh
from reference_impl.structures.polygon import polygon_triangulation
from reference_impl.exact.verify import exact_coordinates, incircle_exact, orient_exact

shortest_path = load_problem("navmesh").generator.shortest_path   # the problem's adapter


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


# =================================================================================================
# slow (was test_navmesh_1000.py): polygon_triangulation and shortest_path, 1000 cases, degenerate rooms
# =================================================================================================
CASES = 1000


# ----------------------------------------------------------------------------- exact helpers


def area2(P, ring) -> int:
    return sum(P[a][0] * P[b][1] - P[b][0] * P[a][1] for a, b in zip(ring, list(ring[1:]) + list(ring[:1])))


def on_closed_segment(a, b, p) -> bool:
    return (orient(a, b, p) == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0])
            and min(a[1], b[1]) <= p[1] <= max(a[1], b[1]))


def where(p, ring) -> int:
    """+1 strictly inside the ring, 0 on it, -1 strictly outside (exact, any number type)."""
    inside = False
    for a, b in zip(ring, ring[1:] + ring[:1]):
        if on_closed_segment(a, b, p):
            return 0
        if (a[1] > p[1]) != (b[1] > p[1]):
            s = orient(a, b, p)
            if (s > 0) == (b[1] > a[1]):
                inside = not inside
    return 1 if inside else -1


def point_free(p, rings) -> bool:
    """p in the closed free space: inside or on the boundary, not strictly inside a hole."""
    return where(p, rings[0]) >= 0 and all(where(p, h) <= 0 for h in rings[1:])


def segment_free(p, q, rings) -> bool:
    """Exactly: the closed segment p-q lies in the closed free space."""
    if p == q:
        return point_free(p, rings)
    d = (q[0] - p[0], q[1] - p[1])
    dd = d[0] * d[0] + d[1] * d[1]
    ts = {Fraction(0), Fraction(1)}
    lo, hi = (min(p[0], q[0]), min(p[1], q[1])), (max(p[0], q[0]), max(p[1], q[1]))
    for ring in rings:
        side = [orient(p, q, a) for a in ring]
        for i, a in enumerate(ring):
            j = (i + 1) % len(ring)
            if side[i] * side[j] < 0 and orient(a, ring[j], p) * orient(a, ring[j], q) < 0:
                return False                                   # a proper crossing
            if side[i] == 0 and lo[0] <= a[0] <= hi[0] and lo[1] <= a[1] <= hi[1]:
                ts.add(Fraction((a[0] - p[0]) * d[0] + (a[1] - p[1]) * d[1], dd))
    ts = sorted(ts)
    # between two consecutive vertices on it the open piece meets no wall, or runs along one
    for t0, t1 in zip(ts, ts[1:]):
        t = (t0 + t1) / 2
        if not point_free((p[0] + t * d[0], p[1] + t * d[1]), rings):
            return False
    return True


# ----------------------------------------------------------------------------- oracles
def shapely_oracle(boundary, holes, start, goal) -> float | None:
    poly = Polygon(boundary, holes)
    if not (poly.covers(Point(start)) and poly.covers(Point(goal))):
        return None
    nodes = [tuple(map(float, p)) for ring in [boundary, *holes] for p in ring] + [tuple(start), tuple(goal)]
    pairs = [(i, j) for i in range(len(nodes)) for j in range(i + 1, len(nodes))]
    ok = shapely.covers(poly, shapely.linestrings([[nodes[i], nodes[j]] for i, j in pairs]))
    g = nx.Graph()
    g.add_nodes_from(range(len(nodes)))
    g.add_weighted_edges_from((i, j, math.dist(nodes[i], nodes[j])) for (i, j), good in zip(pairs, ok)
                              if good or nodes[i] == nodes[j])
    return nx.dijkstra_path_length(g, len(nodes) - 2, len(nodes) - 1)


class ExactRoom:
    """A polygon with holes whose vertex-to-vertex visibility is decided exactly once."""

    def __init__(self, boundary, holes) -> None:
        self.boundary, self.holes = boundary, holes
        self.floats = [tuple(map(float, p)) for ring in [boundary, *holes] for p in ring]
        self.graph = nx.Graph()
        self.graph.add_nodes_from(range(len(self.floats)))
        self._visibility_done = False

    def exact_all(self, extra):
        """Exact integer coordinates of the vertices plus the extra points (common scaling)."""
        E = exact(self.floats + [tuple(map(float, p)) for p in extra])
        sizes = np.cumsum([0] + [len(r) for r in [self.boundary, *self.holes]])
        rings = [E[a:b] for a, b in zip(sizes[:-1], sizes[1:])]
        return E, rings

    def length(self, start, goal) -> float | None:
        E, rings = self.exact_all([start, goal])
        n = len(self.floats)
        s, g = E[n], E[n + 1]
        if not (point_free(s, rings) and point_free(g, rings)):
            return None
        if not self._visibility_done:            # vertex-vertex visibility, once per room
            for i in range(n):
                for j in range(i + 1, n):
                    if segment_free(E[i], E[j], rings):
                        self.graph.add_edge(i, j, weight=math.dist(self.floats[i], self.floats[j]))
            self._visibility_done = True
        g2 = self.graph.copy()
        nodes = self.floats + [tuple(map(float, start)), tuple(map(float, goal))]
        for k in (n, n + 1):
            for i in range(n):
                if segment_free(E[k], E[i], rings):
                    g2.add_edge(k, i, weight=math.dist(nodes[k], nodes[i]))
        if segment_free(s, g, rings):
            g2.add_edge(n, n + 1, weight=math.dist(nodes[n], nodes[n + 1]))
        return nx.dijkstra_path_length(g2, n, n + 1)

    def assert_valid(self, start, goal, path) -> None:
        assert path[0] == tuple(map(float, start)) and path[-1] == tuple(map(float, goal))
        assert all(c in set(self.floats) for c in path[1:-1]), "a corner is not a polygon vertex"
        E, rings = self.exact_all(path)
        m = len(self.floats)
        for a, b in zip(E[m:], E[m + 1:]):
            assert segment_free(a, b, rings), "a path segment leaves the free space"


def check_path_shapely(boundary, holes, start, goal) -> bool:
    """Compare with the shapely oracle; return True when a path was expected."""
    path = shortest_path(boundary, holes, start, goal)
    expect = shapely_oracle(boundary, holes, start, goal)
    if expect is None:
        assert path is None, (start, goal)
        return False
    assert path is not None, (start, goal)
    assert path[0] == tuple(map(float, start)) and path[-1] == tuple(map(float, goal))
    vertices = {tuple(map(float, p)) for ring in [boundary, *holes] for p in ring}
    assert all(c in vertices for c in path[1:-1]), "a corner is not a polygon vertex"
    poly = Polygon(boundary, holes)
    if len(path) > 1:
        assert shapely.covers(poly, shapely.linestrings([[a, b] for a, b in zip(path, path[1:])])).all()
    assert math.isclose(path_length(path), expect, rel_tol=1e-9, abs_tol=1e-12), (path, expect)
    return True


def check_triangulation(boundary, holes, pt) -> None:
    """Exact checks of polygon_triangulation's answer (see the module docstring)."""
    rings_in = [np.asarray(boundary, dtype=float)] + [np.asarray(h, dtype=float) for h in holes]
    P = exact(pt.points)
    T = pt.simplices.tolist()
    for t in T:
        assert orient(*(P[v] for v in t)) > 0, f"triangle {t} is not strictly counter-clockwise"
    R = [r.tolist() for r in pt.rings]
    assert area2(P, R[0]) > 0 and all(area2(P, r) < 0 for r in R[1:]), "ring orientation"
    sizes = np.cumsum([0] + [len(r) for r in rings_in])
    for r, (a, b) in zip(R, zip(sizes[:-1], sizes[1:])):      # the rings are the input rings
        assert sorted(r) == list(range(a, b))
    total = sum(area2(P, t) for t in T)
    assert total == area2(P, R[0]) + sum(area2(P, r) for r in R[1:]), "area of the triangles"
    apex = {}
    for t in T:
        for k in range(3):
            e = (t[(k + 1) % 3], t[(k + 2) % 3])
            assert e not in apex, "overlapping triangles"
            apex[e] = t[k]
    walls = set()
    for r in R:
        for u, v in zip(r, r[1:] + r[:1]):
            assert (u, v) in apex and (v, u) not in apex, f"ring edge {u}->{v}"
            walls.add((u, v))
    N = pt.neighbors.tolist()
    for i, t in enumerate(T):
        for k in range(3):
            u, v = t[(k + 1) % 3], t[(k + 2) % 3]
            assert (N[i][k] < 0) == ((u, v) in walls)
            if N[i][k] >= 0:
                assert set(T[N[i][k]]) == {u, v, apex[(v, u)]}
                assert incircle(P[u], P[v], P[t[k]], P[apex[(v, u)]]) <= 0, f"edge {u}-{v} not Delaunay"


# ----------------------------------------------------------------------------- random polygons
def random_polygon(rng):
    """A star-shaped boundary (4-10 vertices, radii 0.3-1) and 0-2 small convex holes."""
    k = int(rng.integers(4, 11))
    ang = (np.arange(k) + rng.uniform(-0.4, 0.4, k)) * 2 * np.pi / k
    r = rng.uniform(0.3, 1.0, k)
    boundary = np.stack([r * np.cos(ang), r * np.sin(ang)], axis=1)
    if rng.random() < 0.5:
        boundary = boundary[::-1]
    room = Polygon(boundary)
    holes, centres = [], []
    for _ in range(int(rng.integers(0, 3))):
        for _attempt in range(10):
            m = int(rng.integers(3, 5))
            c = rng.uniform(-0.6, 0.6, 2)
            a = np.sort(rng.uniform(0, 2 * np.pi, m)) if m == 4 else np.arange(3) * 2 * np.pi / 3 + rng.uniform(0, 7)
            if m == 4 and np.max(np.diff(np.r_[a, a[0] + 2 * np.pi])) > 0.9 * np.pi:
                a = np.arange(4) * np.pi / 2 + a[0]
            h = c + np.stack([np.cos(a), np.sin(a)], axis=1) * rng.uniform(0.05, 0.2)
            hp = Polygon(h)
            if room.contains(hp.buffer(1e-3)) and all(Polygon(o).distance(hp) > 1e-3 for o in holes):
                if rng.random() < 0.5:
                    h = h[::-1]
                holes.append(h)
                centres.append(h.mean(axis=0))
                break
    return boundary, holes, centres


@pytest.mark.slow
def test_1000_random_polygon_triangulations_match_triangle():
    rng = np.random.default_rng(1234)
    for case in range(CASES):
        boundary, holes, centres = random_polygon(rng)
        pt = polygon_triangulation(boundary, holes)
        assert np.array_equal(pt.points, np.vstack([boundary, *holes]))
        check_triangulation(boundary, holes, pt)
        rings = [boundary] + holes
        sizes = np.cumsum([0] + [len(r) for r in rings])
        segs = np.concatenate([np.stack([np.arange(a, b), np.roll(np.arange(a, b), -1)], 1)
                               for a, b in zip(sizes[:-1], sizes[1:])])
        data = {"vertices": np.vstack(rings), "segments": segs}
        if centres:
            data["holes"] = np.array(centres)
        ref = triangle.triangulate(data, "p")
        assert len(ref["vertices"]) == len(pt.points), f"case {case}: Triangle added a point"
        assert {frozenset(t) for t in pt.simplices.tolist()} == \
            {frozenset(t) for t in ref["triangles"].tolist()}, f"case {case}"


@pytest.mark.slow
def test_1000_random_invalid_outlines_raise():
    """Shuffled outlines raise exactly when they are not simple; a repeated vertex always raises."""
    rng = np.random.default_rng(99)
    raised = 0
    for case in range(CASES):
        boundary, holes, _ = random_polygon(rng)
        if case % 2:
            i = int(rng.integers(0, len(boundary)))
            j = (i + int(rng.integers(2, len(boundary) - 1))) % len(boundary)   # not a neighbour
            bad = np.insert(boundary, j + 1 if j > i else j, boundary[i], axis=0)
            if rng.random() < 0.5 and holes:            # or a hole vertex repeats a vertex of another ring
                h = holes[0].copy()
                h[0] = boundary[i] if rng.random() < 0.5 else (holes[1][0] if len(holes) > 1 else boundary[i])
                with pytest.raises(ValueError):
                    polygon_triangulation(boundary, [h] + holes[1:])
                continue
            with pytest.raises(ValueError, match="repeats"):
                polygon_triangulation(bad, holes)
            with pytest.raises(ValueError, match="repeats"):
                shortest_path(bad, holes, (0, 0), (0.1, 0.1))
            raised += 1
        else:
            shuffled = boundary[rng.permutation(len(boundary))]
            simple = LinearRing(shuffled).is_simple
            if simple:
                check_triangulation(shuffled, [], polygon_triangulation(shuffled, []))
            else:
                raised += 1
                with pytest.raises(ValueError, match="not simple"):
                    polygon_triangulation(shuffled, [])
    assert raised > CASES // 4


@pytest.mark.slow
def test_1000_random_shortest_paths_match_visibility_graph():
    rng = np.random.default_rng(4321)
    found = 0
    for case in range(CASES):
        boundary, holes, _ = random_polygon(rng)
        vertices = np.vstack([boundary, *holes])
        poly = Polygon(boundary, holes)

        def pick():
            u = rng.random()
            if u < 0.25:                                   # a polygon vertex (a reflex corner, often)
                return tuple(vertices[rng.integers(len(vertices))].tolist())
            for _ in range(50 if u < 0.85 else 1):         # mostly in the free space
                p = tuple(rng.uniform(-1.0, 1.0, 2).tolist())
                if poly.covers(Point(p)):
                    break
            return p

        found += check_path_shapely(boundary, holes, pick(), pick())
    assert CASES // 2 < found < CASES - 50                # paths and None both occur


# ----------------------------------------------------------------------------- degenerate rooms
def _square(x, y, s=1):
    return [(x, y), (x + s, y), (x + s, y + s), (x, y + s)]


GRID_ROOM = ([(x, 0) for x in range(7)] + [(6, y) for y in range(1, 5)]
             + [(x, 4) for x in range(5, -1, -1)] + [(0, y) for y in range(3, 0, -1)],
             [_square(1, 1), [(3, 1), (4, 1), (5, 1), (5, 2), (4, 2), (3, 2)], _square(2, 3 - 0.5, 1)[:2]
              + [(3, 3), (2.5, 3), (2, 3)]])
SERPENT_WITH_HOLES = (SERPENT, SERPENT_HOLES)   # SERPENT_HOLES: the squares at (4, 1) and (5, 8)
PILLARS = ([(0, 0), (7, 0), (7, 7), (0, 7)],
           [_square(2 * i + 1, 2 * j + 1) for i in range(3) for j in range(3) if (i, j) != (1, 1)])
L_ROOM = ([(0, 0), (2, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4), (0, 2)], [[(1, 1), (1, 2), (0.5, 1.5)]])
COMB = ([(0, 0), (9, 0), (9, 3), (8, 3), (8, 1), (7, 1), (7, 3), (6, 3), (6, 1), (5, 1), (5, 3), (4, 3), (4, 1),
         (3, 1), (3, 3), (0, 3)], [])
ROOMS = {"grid-room": GRID_ROOM, "serpent": SERPENT_WITH_HOLES, "pillars": PILLARS, "L-room": L_ROOM, "comb": COMB}
TRANSFORMS = {
    "plain": lambda p: p,
    "x1e-300": lambda p: p * 1e-300,
    "x1e300": lambda p: p * 1e300,
    "+1e9": lambda p: p + 1e9,
    "x0.5+1e9": lambda p: p * 0.5 + 1e9,
}


@pytest.mark.slow
@pytest.mark.parametrize("tname", list(TRANSFORMS))
@pytest.mark.parametrize("rname", list(ROOMS))
def test_degenerate_rooms(rname, tname):
    f = TRANSFORMS[tname]
    b0, h0 = ROOMS[rname]
    boundary = f(np.array(b0, dtype=float))
    holes = [f(np.array(h, dtype=float)) for h in h0]
    pt = polygon_triangulation(boundary, holes)
    check_triangulation(boundary, holes, pt)
    room = ExactRoom(boundary, holes)
    xs, ys = np.array([p[0] for p in b0]), np.array([p[1] for p in b0])
    rng = np.random.default_rng(len(rname) * 31 + len(tname))
    corners = [tuple(p) for ring in [b0, *h0] for p in ring]
    for _ in range(12):
        pts = []
        for _ in range(2):                 # integer points: on walls, at corners, in holes, outside
            if rng.random() < 0.3:
                pts.append(corners[rng.integers(len(corners))])
            else:
                pts.append((float(rng.integers(xs.min() - 1, xs.max() + 2)),
                            float(rng.integers(ys.min() - 1, ys.max() + 2))))
        s, g = (tuple(f(np.array(p, dtype=float)).tolist()) for p in pts)
        path = shortest_path(boundary, holes, s, g)
        expect = room.length(s, g)
        if expect is None:
            assert path is None, (s, g)
            continue
        assert path is not None, (s, g)
        room.assert_valid(s, g, path)
        assert math.isclose(path_length(path), expect, rel_tol=1e-9), (s, g, path, expect)


@pytest.mark.slow
@pytest.mark.parametrize("boundary, holes, message", [
    ([(0, 0), (4, 0), (4, 4), (2, 2), (0, 4), (2, 2)], [], "repeats"),
    ([(0, 0), (2, 0), (4, 0), (4, 4), (2, 0), (0, 4)], [], "repeats"),
    ([(x, 0) for x in range(5)] + [(4, 4), (0, 4)], [[(1, 1), (2, 1), (1, 1.5), (2, 1)]], "repeats|crosses|lies on"),
    ([(0, 0), (4, 0), (4, 4), (0, 4)], [[(4, 4), (3, 3), (3, 2)]], "repeats"),
    ([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (2, 1), (2, 2)], [(2, 2), (3, 2), (3, 3)]], "repeats"),
    ([(0, 0), (4, 0), (4, 4), (0, 4)], [[(2, 0), (3, 1), (1, 1)]], "lies on|repeats"),
    ([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (3, 1), (3, 3), (1, 3)], [(2, 2), (2.5, 2), (2, 2.5)]], "inside"),
    ([(0, 0), (1, 0), (2, 0), (3, 0)], [], "zero area"),
])
@pytest.mark.parametrize("tname", ["plain", "x1e-300", "x1e300", "+1e9"])
def test_invalid_polygons_raise_transformed(boundary, holes, message, tname):
    f = TRANSFORMS[tname]
    b = f(np.array(boundary, dtype=float))
    hs = [f(np.array(h, dtype=float)) for h in holes]
    with pytest.raises(ValueError, match=message):
        polygon_triangulation(b, hs)
    with pytest.raises(ValueError, match=message):
        shortest_path(b, hs, tuple(b[0]), tuple(b[1]))
