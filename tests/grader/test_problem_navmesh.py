"""The `navmesh` checker and tests: accepts every shortest path (ties included), rejects each kind
of wrong answer with a message; the reference lengths agree with a brute-force oracle (all-corner
visibility graph with exact segment tests, networkx Dijkstra); the input validator rejects invalid rooms.

Run: .venv/bin/python -m pytest tests/grader/test_problem_navmesh.py -q
"""
from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import networkx as nx
import pytest
import yaml

from grader.problems import load_problem
from reference_impl.exact import free_space

P = load_problem("navmesh")
CHK, GEN = P.checker, P.generator
ROOT = Path(__file__).resolve().parents[2]
ROOM = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]
PILLAR = [[4.0, 4.0], [6.0, 4.0], [6.0, 6.0], [4.0, 6.0]]
_spec = importlib.util.spec_from_file_location(
    "validate_navmesh", ROOT / "assignments/navmesh/input_validators/validate_navmesh/validate_navmesh.py")
VAL = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(VAL)


def oracle_length(boundary, holes, start, goal):
    """Brute force: every corner a node, every pair tested exactly."""
    if not (free_space.point_in_free_space(start, boundary, holes) and free_space.point_in_free_space(goal, boundary, holes)):
        return None
    nodes = [tuple(start), tuple(goal)] + [tuple(p) for r in [boundary] + list(holes) for p in r]
    G = nx.Graph()
    G.add_nodes_from(range(len(nodes)))
    for i in range(len(nodes)):
        for j in range(i + 1, len(nodes)):
            if free_space.segment_in_free_space(nodes[i], nodes[j], boundary, holes):
                G.add_edge(i, j, weight=math.dist(nodes[i], nodes[j]))
    return nx.dijkstra_path_length(G, 0, 1)


COURSE = yaml.safe_load((ROOT / "assignments/navmesh/course.yaml").read_text())


def course_cases(group):
    for k, case in enumerate(next(g for g in COURSE["groups"] if g["name"] == group)["cases"]):
        yield GEN.generate_args(case, COURSE["seed"] + k)


@pytest.mark.parametrize("group", ["tiny", "degenerate"])
def test_reference_lengths_match_brute_force(group):
    for args in course_cases(group):
        ref = GEN.solve(*args)
        want = oracle_length(*args)
        assert (ref is None) == (want is None), args
        if ref is not None:
            assert free_space.path_problem(ref, args[0], args[1]) is None
            assert math.isclose(free_space.path_length(ref), want, rel_tol=1e-12, abs_tol=0), args
            assert CHK.check(args, ref, ref) == (True, "ok")


def test_ties_both_ways_round_a_pillar_are_accepted():
    args = [ROOM, [PILLAR], [1.0, 5.0], [9.0, 5.0]]
    ref = GEN.solve(*args)
    for path in ([[1.0, 5.0], [4.0, 6.0], [6.0, 6.0], [9.0, 5.0]], [[1.0, 5.0], [4.0, 4.0], [6.0, 4.0], [9.0, 5.0]]):
        assert CHK.check(args, CHK.from_result(path, args), ref) == (True, "ok")


def test_start_equal_goal_accepts_one_or_two_points():
    args = [ROOM, [PILLAR], [6.0, 6.0], [6.0, 6.0]]
    ref = GEN.solve(*args)
    assert CHK.check(args, [[6.0, 6.0]], ref)[0] and CHK.check(args, [[6.0, 6.0], [6.0, 6.0]], ref)[0]


def test_wall_following_path_is_accepted_and_open_space_detour_rejected():
    args = [ROOM, [[[4.0, 5.0], [6.0, 5.0], [6.0, 7.0], [4.0, 7.0]]], [0.0, 5.0], [10.0, 5.0]]
    ref = GEN.solve(*args)
    assert CHK.check(args, [[0.0, 5.0], [4.0, 5.0], [6.0, 5.0], [10.0, 5.0]], ref)[0]
    ok, msg = CHK.check(args, [[0.0, 5.0], [4.0, 4.9], [6.0, 4.9], [10.0, 5.0]], ref)
    assert not ok and "length" in msg


@pytest.mark.parametrize("path, words", [
    ([[1.0, 5.0], [9.0, 5.0]], "leaves the free space"),
    ([[1.0, 5.0], [5.0, 5.0], [9.0, 5.0]], "outside the free space"),
    ([[1.0, 5.0], [4.0, 6.0], [6.0, 6.0]], "not at goal"),
    ([[1.5, 5.0], [4.0, 6.0], [6.0, 6.0], [9.0, 5.0]], "not at start"),
    ([[1.0, 5.0], [1.0, 9.0], [9.0, 9.0], [9.0, 5.0]], "length"),
    (None, "None"),
])
def test_wrong_paths_are_rejected_with_a_reason(path, words):
    args = [ROOM, [PILLAR], [1.0, 5.0], [9.0, 5.0]]
    ok, msg = CHK.check(args, path, GEN.solve(*args))
    assert not ok and words in msg


def test_a_path_when_there_is_none_is_rejected():
    args = [ROOM, [PILLAR], [5.0, 5.0], [9.0, 5.0]]
    assert GEN.solve(*args) is None
    assert not CHK.check(args, [[5.0, 5.0], [9.0, 5.0]], None)[0]
    assert CHK.check(args, None, None) == (True, "ok")


@pytest.mark.parametrize("value", [[[1, 2, 3]], "path", [[1.0, float("nan")]], [["a", 1]], [[0.0, 0.0]] * 11, 5])
def test_bad_shapes_are_presentation_errors(value):
    with pytest.raises(CHK.PresentationError):
        CHK.from_result(value, [ROOM, [PILLAR], [1.0, 5.0], [9.0, 5.0]])


@pytest.mark.parametrize("text", ["", "x\n", "2\n1 1\n", "11\n" + "0 0\n" * 11, "1\n1 nan\n", "-1\n"])
def test_bad_outputs_are_presentation_errors(text):
    with pytest.raises(CHK.PresentationError):
        CHK.read_output(text, [ROOM, [PILLAR], [1.0, 5.0], [9.0, 5.0]])


def test_exact_at_extreme_scales():
    for e in (-900, 900):
        s = 2.0 ** e
        args = [[[x * s, y * s] for x, y in ROOM], [[[x * s, y * s] for x, y in PILLAR]], [s, 5 * s], [9 * s, 5 * s]]
        ref = GEN.solve(*args)
        assert CHK.check(args, ref, ref)[0]
        assert not CHK.check(args, [args[2], args[3]], ref)[0]      # through the pillar, at any scale


@pytest.mark.parametrize("holes, words", [
    ([[[4, 4], [6, 4], [6, 6], [4, 6]], [[5, 5], [7, 5], [7, 7]]], "touch or cross"),   # overlapping holes
    ([[[8, 8], [12, 8], [12, 9]]], "touch or cross"),                                    # sticks out
    ([[[10, 5], [9, 4], [9, 6]]], "touch or cross"),                                      # touches the boundary
    ([[[20, 20], [21, 20], [21, 21]]], "not inside"),
    ([[[2, 2], [8, 2], [8, 8], [2, 8]], [[4, 4], [5, 4], [5, 5]]], "inside hole"),
    ([[[4, 4], [6, 6], [6, 4], [4, 6]]], "touch or cross"),                               # a bow tie
])
def test_validator_rejects_invalid_rooms(holes, words):
    text = GEN.write_input([ROOM, holes, [1, 1], [2, 2]])
    problems = VAL.validate(text)
    assert problems and words in problems[0]


def test_validator_accepts_every_course_case():
    for group in ("tiny", "degenerate", "medium"):
        for args in course_cases(group):
            assert VAL.validate(GEN.write_input(args)) == []
