"""Certificates of wrong answers (grader/contest/certificate.py) and the counterexample zoo.

Each problem gets a small hand-made wrong answer; its certificate's claim is checked here
independently (exact circumcentres, brute force with Fractions, networkx, scipy), a right answer
gets none, ``check_certificate`` recomputes, rejects a tampered certificate and draws (Agg). The
zoo test judges every file of tests/grader/fixtures/cx_zoo: it passes its samples and loses points.

Run: .venv/bin/python -m pytest tests/grader/test_certificate.py -q -p no:cacheprovider
"""
from __future__ import annotations

import copy
import json
import math
import sys
from fractions import Fraction
from pathlib import Path

import pytest

from grader.contest.certificate import check_certificate, certify
from grader.problems import load_problem

ZOO = sorted((Path(__file__).parent / "fixtures" / "cx_zoo").glob("*/*.py"))


def text(problem: str, args: list, value) -> tuple[str, str]:
    ck = load_problem(problem).checker
    return ck.write_input(args), ck.write_output(value)


def circumcentre(a, b, c):
    (ax, ay), (bx, by), (cx, cy) = [tuple(map(Fraction, p)) for p in (a, b, c)]
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    ux = ((ax ** 2 + ay ** 2) * (by - cy) + (bx ** 2 + by ** 2) * (cy - ay) + (cx ** 2 + cy ** 2) * (ay - by)) / d
    uy = ((ax ** 2 + ay ** 2) * (cx - bx) + (bx ** 2 + by ** 2) * (ax - cx) + (cx ** 2 + cy ** 2) * (bx - ax)) / d
    return ux, uy


def d2(p, q) -> Fraction:
    return sum((Fraction(x) - Fraction(y)) ** 2 for x, y in zip(p, q))


POINTS4 = [[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 3.0]]


@pytest.mark.parametrize("problem", ["delaunay", "bowyer-watson-timed"])
def test_a_point_inside_a_circumcircle_is_checked_by_an_exact_circumcentre(problem):
    inp, ans = text(problem, [POINTS4], [[0, 1, 3], [1, 2, 3]])
    c = certify(problem, inp, ans)
    assert c["kind"] == "point-in-circumcircle" and c["problem"] == problem
    t, p = c["triangle"], c["point"]
    centre = circumcentre(*(POINTS4[v] for v in t))
    assert d2(POINTS4[p], centre) < d2(POINTS4[t[0]], centre)
    assert Fraction(c["incircle"]) > 0
    json.dumps(c)  # JSON-native
    right = [[0, 1, 2], [0, 2, 3]]
    assert certify(problem, inp, text(problem, [POINTS4], right)[1]) is None


def test_triangulation_defects():
    square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [1.0, 2.0]]
    inp, _ = text("delaunay", [square], [])
    clockwise = certify("delaunay", inp, text("delaunay", [square], [[0, 3, 1]])[1])
    assert clockwise["kind"] == "not-counter-clockwise" and Fraction(clockwise["orient2d"]) < 0
    half = certify("delaunay", inp, text("delaunay", [square], [[0, 1, 4]])[1])
    assert half["kind"] in ("hull-edge-uncovered", "point-in-circumcircle")
    if half["kind"] == "hull-edge-uncovered":
        u, v = half["edge"]
        assert all((Fraction(square[v][0]) - square[u][0]) * (Fraction(p[1]) - square[u][1])
                   - (Fraction(square[v][1]) - square[u][1]) * (Fraction(p[0]) - square[u][0]) >= 0 for p in square)
    empty = certify("delaunay", inp, "0\n")
    assert empty["kind"] == "hull-edge-uncovered"


def test_edge_flip_replays_the_flips_first():
    inp, ans = text("edge-flip", [POINTS4, [[0, 1, 3], [1, 2, 3]]], [])
    c = certify("edge-flip", inp, ans)
    assert c["kind"] == "point-in-circumcircle" and c["after_flips"] == 0
    bad = certify("edge-flip", inp, text("edge-flip", [POINTS4, [[0, 1, 3], [1, 2, 3]]], [[0, 1]])[1])
    assert bad["kind"] == "illegal-flip" and "hull edge" in bad["claim"]
    assert certify("edge-flip", inp, text("edge-flip", [POINTS4, [[0, 1, 3], [1, 2, 3]]], [[1, 3]])[1]) is None


def test_delaunay_3d_point_inside_a_circumsphere():
    pts = [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 4.0], [1.0, 1.0, 1.0]]
    inp, ans = text("delaunay-3d", [pts], [[0, 1, 2, 3]])
    c = certify("delaunay-3d", inp, ans)
    assert c["kind"] == "point-in-circumsphere" and c["point"] == 4
    centre = (2, 2, 2)  # equidistant from the four corners: radius^2 12
    assert all(d2(pts[v], centre) == 12 for v in c["tetrahedron"]) and d2(pts[4], centre) < 12


def test_emst_cheaper_edge_against_networkx():
    nx = pytest.importorskip("networkx")
    pts = [[0.0, 0.0], [1.0, 0.0], [5.0, 0.0], [0.0, 1.0], [5.0, 2.0]]
    tree = [[0, 1], [1, 2], [2, 3], [2, 4]]
    inp, ans = text("emst", [pts], tree)
    c = certify("emst", inp, ans)
    assert c["kind"] == "cheaper-edge"
    (a, b), (u, v) = c["edge"], c["heaviest"]
    assert d2(pts[a], pts[b]) < d2(pts[u], pts[v]) and [u, v] in [list(e) for e in tree] + [[y, x] for x, y in tree]
    g = nx.Graph()
    for i in range(len(pts)):
        for j in range(i + 1, len(pts)):
            g.add_edge(i, j, weight=math.dist(pts[i], pts[j]))
    best = sum(d["weight"] for *_, d in nx.minimum_spanning_tree(g).edges(data=True))
    swapped = [e for e in tree if sorted(e) != sorted((u, v))] + [[a, b]]
    assert sum(math.dist(pts[i], pts[j]) for i, j in swapped) < sum(math.dist(pts[i], pts[j]) for i, j in tree)
    assert best < sum(math.dist(pts[i], pts[j]) for i, j in tree)
    cycle = certify("emst", inp, text("emst", [pts], [[0, 1], [1, 3], [3, 0], [2, 4]])[1])
    assert cycle is None or cycle["kind"] in ("cycle", "not-spanning", "differs")


def test_closest_pair_brute_force():
    pts = [[0.0, 0.0], [5.0, 0.0], [0.5, 0.25], [9.0, 9.0]]
    inp, ans = text("closest-pair", [pts], [0, 1])
    c = certify("closest-pair", inp, ans)
    a, b = c["closer"]
    assert c["kind"] == "closer-pair" and d2(pts[a], pts[b]) < d2(pts[0], pts[1])
    assert Fraction(c["distance2"]["closer"]) == d2(pts[a], pts[b])
    assert certify("closest-pair", inp, text("closest-pair", [pts], [0, 2])[1]) is None


def test_largest_empty_circle_point_inside_and_a_larger_circle():
    sq = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]
    inp, ans = text("largest-empty-circle", [sq], [0.5, 0.5, 2.0])
    c = certify("largest-empty-circle", inp, ans)
    assert c["kind"] == "point-in-circle" and d2(sq[c["point"]], (0.5, 0.5)) < 4
    small = certify("largest-empty-circle", inp, text("largest-empty-circle", [sq], [2.0, 2.0, 1.0])[1])
    assert small["kind"] == "larger-empty-circle"
    centre = [Fraction(v) for v in small["centre"]]
    assert centre == [2, 2] and Fraction(small["radius2"]) == 8
    assert all(d2(p, centre) >= 8 for p in sq)
    assert certify("largest-empty-circle", inp, text("largest-empty-circle", [sq], [2.0, 2.0, 8 ** 0.5])[1]) is None


def test_voronoi_vertex_nearer_another_site():
    args = [[[0.0, 0.0], [2.0, 0.0]], [-1.0, -1.0, 3.0, 1.0]]
    box = [[-1.0, -1.0], [3.0, -1.0], [3.0, 1.0], [-1.0, 1.0]]
    inp, ans = text("voronoi", args, [box, [[1.0, -1.0], [3.0, -1.0], [3.0, 1.0], [1.0, 1.0]]])
    c = certify("voronoi", inp, ans)
    assert c["kind"] == "vertex-nearer-other-site" and c["cell"] == 0
    v, j = c["vertex"], c["point"]
    assert d2(v, args[0][j]) < d2(v, args[0][0])


def test_proximity_network_extra_and_missing_edges():
    pts = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.5]]
    inp, ans = text("proximity-network", [pts], [[0, 1], [0, 2], [1, 2]])
    c = certify("proximity-network", inp, ans)
    (i, j), r = c["edge"], c["point"]
    assert c["kind"] == "not-gabriel-edge"
    assert sum((Fraction(pts[r][k]) - pts[i][k]) * (Fraction(pts[r][k]) - pts[j][k]) for k in range(2)) <= 0
    miss = certify("proximity-network", inp, text("proximity-network", [pts], [[0, 2]])[1])
    assert miss["kind"] == "missing-gabriel-edge" and miss["edge"] == [1, 2]


def test_obstacle_dynamic_and_navmesh():
    inp, ans = text("obstacle-clearance", [[[0.0, 0.0], [4.0, 0.0]], [2.0, 3.0], [2.0, -3.0]], 3.7)
    c = certify("obstacle-clearance", inp, ans)
    assert c["kind"] == "obstacle-too-close" and Fraction(c["distance2"]) < Fraction(c["radius2"])
    ops = [["join", 0.0, 0.0], ["join", 1.0, 0.0], ["neighbors", 0], ["count"]]
    inp, ans = text("dynamic-network", [ops], [0, 1, [1], 3])
    c = certify("dynamic-network", inp, ans)
    assert c["kind"] == "first-wrong-answer" and c["operation"] == 3 and c["expected"] == 2
    nav = load_problem("navmesh")
    test = nav.tests()[0]
    args = nav.checker.read_input(test.input_text)
    if nav.generator.solve(*args) is not None:
        c = certify("navmesh", test.input_text, nav.checker.write_output(None))
        assert c["kind"] == "path-exists" and c["path"][0] == [float(v) for v in args[2]]
    room = [[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]], [[[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]]],
            [0.5, 2.0], [3.5, 2.0]]
    inp, ans = text("navmesh", room, [[0.5, 2.0], [3.5, 2.0]])
    through = certify("navmesh", inp, ans)
    assert through["kind"] == "path-leaves-free-space"
    detour = [[0.5, 2.0], [0.5, 0.5], [3.5, 0.5], [3.5, 2.0]]
    longer = certify("navmesh", inp, text("navmesh", room, detour)[1])
    assert longer["kind"] == "shorter-path"
    assert sum(math.dist(p, q) for p, q in zip(longer["path"], longer["path"][1:])) < 1.5 + 3 + 1.5


def test_bad_arguments_and_unreadable_answers():
    with pytest.raises(ValueError, match="unknown problem 'nope'"):
        certify("nope", "1\n0 0\n", "0\n")
    assert certify("closest-pair", "2\n0 0\n1 1\n", "zero one\n") is None


def test_check_certificate_recomputes_rejects_tampering_and_draws():
    import matplotlib

    matplotlib.use("Agg")
    inp, ans = text("delaunay", [POINTS4], [[0, 1, 3], [1, 2, 3]])
    cx = {"input": inp, "answer": ans, "reason": "x", "certificate": certify("delaunay", inp, ans)}
    verdict = check_certificate(cx, draw=True)
    assert verdict.startswith("checked exactly (delaunay, point-in-circumcircle)")
    forged = copy.deepcopy(cx)
    forged["certificate"]["point"] = 0
    with pytest.raises(AssertionError, match="'point'"):
        check_certificate(forged, draw=False)
    lie = copy.deepcopy(cx)
    lie["answer"] = text("delaunay", [POINTS4], [[0, 1, 2], [0, 2, 3]])[1]
    with pytest.raises(AssertionError, match="not wrong"):
        check_certificate(lie, draw=False)
    with pytest.raises(ValueError, match="no certificate"):
        check_certificate({**cx, "certificate": None}, draw=False)


@pytest.mark.slow
@pytest.mark.parametrize("path", ZOO, ids=[f"{p.parent.name}/{p.stem}" for p in ZOO])
def test_zoo_file_passes_its_samples_and_loses_points(path):
    from grader.contest.judge import Judge
    from grader.judging.submissions import Submission

    result = Judge(path.parent.name, stop_at_first_failure=True).judge(Submission.from_path(path), name=path.name)
    assert path.read_text().startswith('"""A plausible wrong solution')
    samples = [t for t in result.tests if t.group == "sample"]
    assert samples and all(t.verdict.name == "AC" for t in samples)
    failed = [t for t in result.tests if t.verdict.name not in ("AC", "SKIPPED")]
    assert failed and failed[0].verdict.name in ("WA", "PE", "RE"), [(t.name, t.verdict.name) for t in failed]


def test_zoo_has_thirty_files_and_two_per_problem():
    assert len(ZOO) >= 30
    problems = {p.id for p in __import__("grader").list_problems()}
    for problem in problems:
        assert sum(p.parent.name == problem for p in ZOO) >= 2, problem


def test_counterexample_benchmark_counts_and_formats_with_a_fake_search():
    import importlib.util
    import io
    from types import SimpleNamespace

    spec = importlib.util.spec_from_file_location("bench_cx", Path(__file__).parents[2] / "benchmarks" / "bench_counterexamples.py")
    bench = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = bench
    spec.loader.exec_module(bench)
    rows = [bench.Row("emst", "a.py", "wrong"), bench.Row("emst", "b.py", "zoo"), bench.Row("emst", "c.py", "zoo"),
            bench.Row("delaunay", "d.py", "zoo"), bench.Row("emst", "ok.py", "control")]
    found = {"a.py": 4, "b.py": 12, "d.py": 3}

    def search(problem, path, seconds):
        n = found.get(path)
        return None if n is None else SimpleNamespace(size=n, verdict="WA", certificate=None, input="i", answer="a")

    bench.run(rows, 1.0, search, lambda p, i, a: {"kind": "differs" if p == "delaunay" else "cheaper-edge"},
              out=io.StringIO())
    s = bench.summarize(rows)
    assert s["problems"]["emst"] | {"seconds": None} == {"files": 3, "found": 2, "small": 1, "certified": 2, "seconds": None}
    assert s["total"]["small"] == 2 and s["total"]["files"] == 4 and s["controls"] == {"files": 1, "found": 0, "which": []}
    text = bench.report(s)
    assert "found with <= 10 points within the budget: 2/4 = 50%" in text
    assert "1 searched, 0 found (expected 0)" in text
    subjects = bench.subjects(["emst"])
    assert {r.group for r in subjects} == {"wrong", "zoo", "control"}
    assert any(r.path.endswith("wrong_double.cpp") and r.group == "wrong" for r in subjects)


def test_an_answer_given_as_the_entry_functions_json_is_read_too():
    inp, _ = text("closest-pair", [[[0.0, 0.0], [5.0, 0.0], [0.0, 1.0]]], [0, 1])
    assert certify("closest-pair", inp, "[0, 1]")["closer"] == [0, 2]
    room = [[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]], [], [4.0, 3.0], [4.0, 3.0]]
    c = certify("navmesh", text("navmesh", room, None)[0], "null")
    assert c["kind"] == "path-exists" and c["path"] == [[4.0, 3.0]]


@pytest.mark.slow
def test_a_found_counterexample_gets_a_certificate_that_checks():
    from grader.contest.counterexample import search

    cx = search("emst", "solutions/emst/wrong_collinear_sort_x.py", seconds=20)
    assert cx is not None and cx.size <= 10
    cert = certify("emst", cx.input, cx.answer)
    assert cert["kind"] == "cheaper-edge"
    verdict = check_certificate({**cx.to_json(), "certificate": cert}, draw=False, problem="emst")
    assert verdict.startswith("checked exactly (emst, cheaper-edge)")
