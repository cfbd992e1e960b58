"""reference_impl.exact.free_space (exact, stdlib-only point/segment/path tests in a polygon with holes)
against an independent oracle: ``NavMesh.is_visible``, which walks segments through the
constrained triangulation with the adaptive predicates (no code shared).

Run: .venv/bin/python -m pytest tests/exact/test_free_space.py -q
"""
from __future__ import annotations

import numpy as np
import pytest

from grader.problems import load_problem
from reference_impl import NavMesh
from reference_impl.exact.free_space import path_length, path_problem, point_in_free_space, segment_in_free_space

shortest_path = load_problem("navmesh").generator.shortest_path   # the problem's adapter

ROOM = [(0, 0), (12, 0), (12, 8), (7, 8), (7, 5), (5, 5), (5, 8), (0, 8)]          # a notch in the top wall
HOLES = [[(2, 2), (4, 2), (4, 4), (2, 4)], [(8, 1), (10, 1), (9, 3)], [(8, 4), (10, 4), (10, 6), (8, 6)]]


def candidates(rng, k):
    """Random points plus every polygon vertex and edge midpoint: the grazing cases."""
    verts = [p for ring in [ROOM] + HOLES for p in ring]
    mids = [((a[0] + b[0]) / 2, (a[1] + b[1]) / 2) for ring in [ROOM] + HOLES
            for a, b in zip(ring, ring[1:] + ring[:1])]
    rand = [tuple(v) for v in np.round(rng.uniform(-1, 13, (k, 2)) * 2) / 2]   # half-integer grid: many ties
    return verts + mids + rand


@pytest.mark.parametrize("scale", [1.0, 2.0 ** -900, 2.0 ** 900])
def test_segments_agree_with_the_navmesh_walk(scale):
    rng = np.random.default_rng(1)
    pts = candidates(rng, 40)
    room = [(x * scale, y * scale) for x, y in ROOM]
    holes = [[(x * scale, y * scale) for x, y in h] for h in HOLES]
    nav = NavMesh(room, holes)
    agree = tested = 0
    for i in range(len(pts)):
        for j in rng.choice(len(pts), 12, replace=False):
            p = (pts[i][0] * scale, pts[i][1] * scale)
            q = (pts[j][0] * scale, pts[j][1] * scale)
            ours = segment_in_free_space(p, q, room, holes)
            assert ours == nav.is_visible(p, q), (p, q, ours)
            tested += 1
            agree += ours
    assert tested > 500 and 0 < agree < tested            # both answers occur


def test_points_agree_with_locate():
    nav = NavMesh(ROOM, HOLES)
    for p in candidates(np.random.default_rng(2), 300):
        assert point_in_free_space(p, ROOM, HOLES) == (nav.locate(p) >= 0), p


def test_library_shortest_paths_stay_in_the_free_space():
    rng = np.random.default_rng(3)
    pts = [p for p in candidates(rng, 60) if point_in_free_space(p, ROOM, HOLES)]
    for _ in range(60):
        s, g = (pts[k] for k in rng.choice(len(pts), 2, replace=False))
        path = shortest_path(ROOM, HOLES, s, g)
        assert path is not None and path_problem(path, ROOM, HOLES) is None, (s, g, path)
        assert path_length(path) >= np.hypot(g[0] - s[0], g[1] - s[1]) * (1 - 1e-12)


def test_messages_name_the_first_bad_piece():
    assert path_problem([(1, 1), (5, 5)], ROOM, HOLES) == (
        "segment 0 from (1, 1) to (5, 5) leaves the free space (it crosses a wall or passes through a hole)")
    assert path_problem([(1, 1), (3, 3)], ROOM, HOLES) == "point 1 (3, 3) is outside the free space"
    assert path_problem([(1, 1), (2, 2), (4, 2), (11, 2)], ROOM, HOLES) is not None   # through the triangle
    assert path_problem([(1, 1), (2, 2), (4, 2), (4, 1), (11, 0.5)], ROOM, HOLES) is None
