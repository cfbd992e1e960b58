"""The `emst` checker: accepts every minimum spanning tree (ties included), rejects each kind of
wrong answer with a message, exactly; the reference answers agree with networkx on exact weights.

Run: .venv/bin/python -m pytest tests/grader/test_problem_emst.py -q
"""
from __future__ import annotations

import random
from fractions import Fraction

import networkx as nx
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from grader.problems import load_problem

P = load_problem("emst")
CHK, GEN = P.checker, P.generator


def exact_weight(points, i, j):
    (x1, y1), (x2, y2) = points[i], points[j]
    return (Fraction(x1) - Fraction(x2)) ** 2 + (Fraction(y1) - Fraction(y2)) ** 2


def random_mst(points, rng):
    """Kruskal over all pairs with exact lengths and random tie-breaking: a uniformly odd MST."""
    n = len(points)
    pairs = [(exact_weight(points, i, j), rng.random(), i, j) for i in range(n) for j in range(i + 1, n)]
    parent = list(range(n))

    def find(i):
        while parent[i] != i:
            i = parent[i]
        return i

    tree = []
    for _, _, i, j in sorted(pairs):
        a, b = find(i), find(j)
        if a != b:
            parent[a] = b
            tree.append([j, i] if rng.random() < 0.5 else [i, j])
    return tree


def networkx_weight(points):
    """Sorted exact lengths of networkx's MST (weights given as ranks: networkx rounds to float)."""
    w = {(i, j): exact_weight(points, i, j) for i in range(len(points)) for j in range(i)}
    rank = {v: k for k, v in enumerate(sorted(set(w.values())))}
    g = nx.Graph()
    g.add_nodes_from(range(len(points)))
    g.add_weighted_edges_from((i, j, rank[v]) for (i, j), v in w.items())
    return sorted(w[max(i, j), min(i, j)] for i, j in nx.minimum_spanning_tree(g).edges())


@pytest.mark.parametrize("case", [
    {"kind": "grid", "w": 4, "h": 3}, {"kind": "cocircular", "r": 5}, {"kind": "duplicates", "n": 8, "repeats": 6},
    {"kind": "near_ties", "shape": "triangles", "count": 3}, {"kind": "collinear", "n": 7},
    {"kind": "scaled", "n": 12, "scale": 1e300}, {"kind": "scaled", "n": 12, "scale": 1e-300},
    {"kind": "uniform", "n": 15, "offset": 1e9}])
def test_every_tie_variant_is_accepted_and_matches_networkx(case):
    points = GEN.generate(case, 5)
    expected = GEN.solve(points)
    assert sorted(exact_weight(points, i, j) for i, j in expected) == networkx_weight(points)
    rng = random.Random(1)
    for _ in range(8):
        assert CHK.check([points], random_mst(points, rng), expected) == (True, "ok")


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(-4, 4), st.integers(-4, 4)), min_size=1, max_size=9))
def test_reference_is_optimal_on_small_integer_sets(raw):
    points = [[float(x), float(y)] for x, y in raw]
    expected = GEN.solve(points)
    assert len(expected) == len(points) - 1
    assert CHK.check([points], expected, expected)[0]
    if len(points) > 1:
        assert sorted(exact_weight(points, i, j) for i, j in expected) == networkx_weight(points)


TUTORIAL = [[1.0, 1.0], [3.0, 2.0], [5.0, 1.0], [4.0, 4.0]]
BEST = [[0, 1], [1, 2], [1, 3]]


@pytest.mark.parametrize("edges,words", [
    ([[0, 1], [1, 2]], "has 3 edges, you gave 2"),
    ([[0, 1], [1, 2], [1, 3], [2, 3]], "has 3 edges, you gave 4"),
    ([[0, 1], [1, 0], [1, 3]], "closes a cycle"),
    ([[0, 1], [1, 1], [1, 3]], "joins a point to itself"),
    ([[0, 1], [1, 2], [1, 4]], "outside 0..3"),
    ([[0, 1], [1, 2], [2, 3]], "replacing your edge [2, 3] by [1, 3]"),
])
def test_wrong_trees_are_rejected_with_a_reason(edges, words):
    ok, message = CHK.check([TUTORIAL], edges, BEST)
    assert not ok and words in message, message


def test_forgotten_duplicates_get_a_hint():
    points = [[0.0, 0.0], [0.0, 0.0], [1.0, 0.0]]
    ok, message = CHK.check([points], [[0, 2]], GEN.solve(points))
    assert not ok and "zero-length edge" in message


def test_float_near_tie_is_decided_exactly():
    points = GEN.generate({"kind": "near_ties", "shape": "triangles", "count": 1, "shuffle": False}, 0)
    expected = GEN.solve(points)
    assert expected == [[0, 1], [1, 2]]  # C is closer to B (x = 1) by 2**-52 in squared length
    ok, message = CHK.check([points], [[0, 1], [0, 2]], expected)
    assert not ok and "agree in floating point" in message


@pytest.mark.parametrize("value", [None, "0 1", [[0, 1.0]], [[0, True]], [[0, 1, 2]], [(0, 1)], [[0, "1"]],
                                   [[0, 1]] * 20])
def test_results_of_the_wrong_shape_are_presentation_errors(value):
    with pytest.raises(CHK.PresentationError):
        CHK.from_result(value, [TUTORIAL])


@pytest.mark.parametrize("text", ["", "x\n", "2\n0 1\n", "1\n0 1 2\n", "1\n0 a\n", "99\n0 1\n"])
def test_malformed_output_is_a_presentation_error(text):
    with pytest.raises(CHK.PresentationError):
        CHK.read_output(text, [TUTORIAL])


def test_output_format_round_trip():
    assert CHK.read_output(CHK.write_output(BEST), [TUTORIAL]) == BEST
    assert CHK.read_output("0\n", [[[1.0, 2.0]]]) == []
