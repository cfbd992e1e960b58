"""Problem packages load, validate, generate deterministic tests, and reject bad input clearly.

Run: .venv/bin/python -m pytest tests/grader/test_problems.py -q
"""
from __future__ import annotations

import pytest

from grader.problems import list_problems, load_problem


def test_both_problems_are_listed_and_valid():
    ids = [p.id for p in list_problems()]
    assert {"delaunay", "bowyer-watson-timed"} <= set(ids)
    for pid in ("delaunay", "bowyer-watson-timed"):
        p = load_problem(pid)
        assert p.validate() == []
        assert p.entry in ("delaunay", "bowyer_watson")
        assert "reference_impl" in p.forbidden and "grader" in p.forbidden and "scipy.spatial" in p.forbidden
        assert sum(g.points for g in p.groups) == 100


def test_input_validator_accepts_every_test():
    assert load_problem("bowyer-watson-timed").validate_inputs() == []


def test_generator_is_seeded_and_covers_the_tutorial():
    gen = load_problem("delaunay").generator
    assert gen.generate({"kind": "uniform", "n": 5}, 3) == gen.generate({"kind": "uniform", "n": 5}, 3)
    assert gen.generate({"kind": "tutorial", "shuffle": False}, 0) == [[1.0, 1.0], [3.0, 2.0], [5.0, 1.0], [4.0, 4.0]]
    with pytest.raises(ValueError, match="unknown case kind"):
        gen.generate({"kind": "spiral"}, 0)


def test_hidden_groups_hold_the_degenerate_cases():
    p = load_problem("delaunay")
    kinds = {c["kind"] for g in p.groups for c in g.cases}
    assert {"tutorial", "grid", "cocircular", "collinear", "duplicates", "scaled"} <= kinds
    scales = {c.get("scale") for g in p.groups for c in g.cases}
    assert 1e-300 in scales and 1e300 in scales


def test_unknown_problem_is_a_clear_error():
    with pytest.raises(ValueError, match="unknown problem 'nope'.*delaunay"):
        load_problem("nope")


def test_checker_types_results_strictly():
    chk = load_problem("delaunay").checker
    assert chk.from_result([[0, 1, 2]], None) == [[0, 1, 2]]
    for bad in ([[0.0, 1, 2]], [[0, 1]], "012", [[True, 1, 2]], None):
        with pytest.raises(chk.PresentationError):
            chk.from_result(bad, None)
    with pytest.raises(chk.PresentationError):
        chk.read_output("2\n0 1 2\n", None)
