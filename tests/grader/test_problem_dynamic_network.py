"""The `dynamic-network` package: the reference answers equal a brute-force oracle of the strict
Delaunay graph (Fractions, straight from the definition) on random and degenerate sequences; the
accepted solution agrees; the checker accepts exactly the right answers, names the first wrong
one, and turns answers of the wrong shape into presentation errors; each wrong solution is killed
by a test of the group its docstring names.

Run: .venv/bin/python -m pytest tests/grader/test_problem_dynamic_network.py -q
"""
from __future__ import annotations

import importlib.util
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from grader.problems import load_problem

P = load_problem("dynamic-network")
CHK, GEN = P.checker, P.generator
SOLUTIONS = Path(__file__).resolve().parents[2] / "solutions" / "dynamic-network"


def _solution(name: str):
    spec = importlib.util.spec_from_file_location(f"dyn_{name}", SOLUTIONS / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def linked(p, q, others) -> bool:
    """The definition: some circle through p and q has every r strictly outside. Its centre
    c = m + t d runs along the bisector; each r allows an open half-line of t (or all, or none)."""
    m = ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)
    d = (p[1] - q[1], q[0] - p[0])
    lo, hi = None, None
    for r in others:
        # |c - r|^2 > |c - p|^2  <=>  2 c.(r - p) < |r|^2 - |p|^2
        e = (r[0] - p[0], r[1] - p[1])
        a = 2 * (d[0] * e[0] + d[1] * e[1])
        b = r[0] ** 2 + r[1] ** 2 - p[0] ** 2 - p[1] ** 2 - 2 * (m[0] * e[0] + m[1] * e[1])
        if a == 0 and b <= 0:
            return False
        if a > 0:
            hi = b / a if hi is None else min(hi, b / a)
        elif a < 0:
            lo = b / a if lo is None else max(lo, b / a)
    return lo is None or hi is None or lo < hi


def oracle(operations) -> list:
    """Answers straight from the definition, O(n^3) per query with Fractions."""
    pos, alive, out = [], [], []
    for op in operations:
        if op[0] == "join":
            pos.append((Fraction(op[1]), Fraction(op[2])))
            alive.append(True)
            out.append(len(pos) - 1)
        elif op[0] == "count":
            out.append(sum(alive))
        elif not (0 <= op[1] < len(pos) and alive[op[1]]):
            out.append("error")
        elif op[0] == "fail":
            alive[op[1]] = False
            out.append("ok")
        else:
            p = pos[op[1]]
            live = {pos[i] for i, a in enumerate(alive) if a}
            near = {q for q in live if q != p and linked(p, q, live - {p, q})} | {p}
            out.append([i for i, a in enumerate(alive) if a and i != op[1] and pos[i] in near])
    return out


ACCEPTED = _solution("accepted_local")

op_strategy = st.one_of(
    st.tuples(st.just("join"), st.integers(0, 3), st.integers(0, 3)).map(lambda t: [t[0], float(t[1]), float(t[2])]),
    st.tuples(st.just("fail"), st.integers(0, 12)).map(list),
    st.tuples(st.just("neighbors"), st.integers(0, 12)).map(list),
    st.just(["count"]))


@settings(max_examples=120, deadline=None)
@given(st.lists(op_strategy, max_size=40))
def test_reference_and_accepted_equal_the_definition_on_a_small_grid(ops):
    # a 4x4 integer grid: squares, collinear rows, repeated positions are the common case
    want = oracle(ops)
    assert GEN.solve(ops) == want
    assert ACCEPTED.process(ops) == want
    assert CHK.check([ops], CHK.from_result(want, [ops]), want) == (True, "ok")


@pytest.mark.parametrize("case", [
    {"kind": "ring", "r": 5}, {"kind": "network", "points": {"kind": "grid", "w": 4, "h": 3}, "rejoin": 0.3},
    {"kind": "network", "points": {"kind": "cocircular", "r": 5}, "fail": 0.4},
    {"kind": "network", "points": {"kind": "circle", "n": 12}},
    {"kind": "network", "points": {"kind": "collinear", "n": 8}, "fail": 0.3},
    {"kind": "network", "points": {"kind": "duplicates", "n": 8, "repeats": 6}, "rejoin": 0.3},
    {"kind": "network", "points": {"kind": "scaled", "n": 12, "scale": 1e300}, "fail": 0.3},
    {"kind": "network", "points": {"kind": "scaled", "n": 12, "scale": 1e-300}, "fail": 0.3},
    {"kind": "network", "points": {"kind": "uniform", "n": 14, "offset": 1e9}, "fail": 0.3},
    {"kind": "network", "points": {"kind": "grid", "w": 5, "h": 5}, "fail": 0.9}])
def test_degenerate_sequences_against_the_definition(case):
    (ops,) = GEN.generate_args(case, 7)
    want = oracle(ops)
    assert GEN.solve(ops) == want
    assert ACCEPTED.process(ops) == want


SQUARE = [["join", 0.0, 0.0], ["join", 1.0, 0.0], ["join", 1.0, 1.0], ["join", 0.0, 1.0], ["neighbors", 0],
          ["join", 0.0, 0.0], ["neighbors", 4], ["fail", 9], ["count"]]
SQUARE_ANS = [0, 1, 2, 3, [1, 3], 4, [0, 1, 3], "error", 5]


def test_the_square_has_no_diagonal_and_coincident_nodes_are_linked():
    assert GEN.solve(SQUARE) == SQUARE_ANS == oracle(SQUARE)


@pytest.mark.parametrize("k,bad,words", [
    (4, [1, 2, 3], "extra: [2], missing: []"),          # the tie diagonal
    (6, [1, 3], "extra: [], missing: [0]"),              # forgets the coincident node
    (4, [3, 1], "must be sorted increasing"),
    (4, [1, 1, 3], "must be sorted increasing, each once"),
    (4, "error", "expected [1, 3], got 'error'"),
    (5, 5, "operation 'join 0.0 0.0'"),
    (7, "ok", "expected 'error', got 'ok'"),
    (8, 4, "operation 'count'"),
])
def test_wrong_answers_are_rejected_naming_the_operation(k, bad, words):
    answers = list(SQUARE_ANS)
    answers[k] = bad
    ok, message = CHK.check([SQUARE], answers, SQUARE_ANS)
    assert not ok and f"answer {k} " in message and words in message, message
    assert "operations: join 0.0 0.0; join 1.0 0.0" in message  # short sequences are quoted


@pytest.mark.parametrize("k,value", [(0, 0.0), (0, True), (0, "0"), (4, [1, 3.0]), (4, [1, False]),
                                     (4, "none"), (4, (1, 3)), (4, list(range(5))), (7, "OK"), (7, None),
                                     (8, "5")])
def test_results_of_the_wrong_type_are_presentation_errors(k, value):
    answers = list(SQUARE_ANS)
    answers[k] = value
    with pytest.raises(CHK.PresentationError):
        CHK.from_result(answers, [SQUARE])


@pytest.mark.parametrize("value", [None, "0 1 2", SQUARE_ANS[:-1], SQUARE_ANS + [1]])
def test_answer_lists_of_the_wrong_shape_are_presentation_errors(value):
    with pytest.raises(CHK.PresentationError):
        CHK.from_result(value, [SQUARE])


def test_text_round_trips_and_malformed_output():
    assert CHK.read_input(CHK.write_input([SQUARE])) == [SQUARE]
    text = CHK.write_output(SQUARE_ANS)
    assert text.splitlines()[4] == "2 1 3" and CHK.read_output(text, [SQUARE]) == SQUARE_ANS
    for bad in (text.replace("2 1 3", "3 1 3"), text.replace("2 1 3", "2 1"), text + "7\n",
                text.replace("error", "err"), text.replace("\n4\n", "\nfour\n"), ""):
        with pytest.raises(CHK.PresentationError):
            CHK.read_output(bad, [SQUARE])


def test_the_input_validator_accepts_the_samples_and_rejects_malformed_lines():
    spec = importlib.util.spec_from_file_location(
        "dyn_validator", P.path / "input_validators" / "validate_operations" / "validate_operations.py")
    val = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(val)
    assert val.validate(CHK.write_input([SQUARE])) == []
    for bad in ("1\njoin 1 nan\n", "1\nfail -1\n", "1\ncount 3\n", "2\ncount\n", "1\nleave 0\n", "1\njoin 1  2\n"):
        assert val.validate(bad), bad


@pytest.mark.parametrize("name,group", [("wrong_tie_diagonals", "degenerate"), ("wrong_coincident", "degenerate")])
def test_each_wrong_solution_is_killed_by_its_group_and_passes_the_tiny_one(name, group):
    wrong = _solution(name)
    results = {}
    for test in P.tests():
        if test.group in ("tiny", group) and len(test.input_text) < 4000:  # the small ones: the wrong ones are slow
            args = P.parse_args(test)
            ok, _ = CHK.check(args, CHK.from_result(wrong.process(*args), args), P.read_answer(test, args))
            results.setdefault(test.group, []).append(ok)
    assert all(results["tiny"]) and not all(results[group]), results
