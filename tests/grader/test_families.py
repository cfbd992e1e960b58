"""The public families of the counterexample search (grader/problems/families.py) and what they find.

The families are valid inputs of every problem (its input validators accept them), at most 10
points (vertices, operations) each, and the same for the same seed; the search built on them finds
a float-predicate mistake and a finite super-triangle within the default budget (asserted: found,
never a time); a function's ``None`` answer is shown as the problem's output text; a C++ file
judged and then searched is compiled once.

Run: .venv/bin/python -m pytest tests/grader/test_families.py -q -p no:cacheprovider
Example: .venv/bin/python -m pytest tests/grader/test_families.py -q -k valid
"""
from __future__ import annotations

import math
import random

import pytest

from grader.contest import counterexample as cx_mod
from grader.contest import stress as stress_mod
from grader.contest.judge import Judge
from grader.problems import families, load_problem
from grader.problems.families import MAX_SIZE, scaled, shifted, size_of

from .conftest import REPO

PROBLEMS = ("delaunay", "bowyer-watson-timed", "emst", "proximity-network", "closest-pair", "largest-empty-circle",
            "edge-flip", "voronoi", "obstacle-clearance", "delaunay-3d", "navmesh", "dynamic-network")
ZOO = REPO / "tests" / "grader" / "fixtures" / "cx_zoo"


def _valid(problem, case: dict) -> bool:
    return stress_mod._valid(problem, problem.checker.write_input(problem.generate_args(case, 0)))


def _bases(problem, seed: int) -> list[dict]:
    """The search's random bases that are valid inputs (a random case may not be: three collinear
    points for largest-empty-circle; the search skips those, and their transforms, unjudged)."""
    rng = random.Random(seed)
    cases = [stress_mod.random_case(problem.id, rng, 6) for _ in range(cx_mod.RANDOM_BASES)]
    return [c for c in cases if _valid(problem, c)]


@pytest.mark.parametrize("pid", PROBLEMS)
def test_the_families_are_valid_small_and_deterministic(pid):
    problem = load_problem(pid)
    cases = families.families(pid, 3, _bases(problem, 3))
    assert len(cases) >= 20 and all(size_of(c) <= MAX_SIZE for c in cases)
    assert cases == families.families(pid, 3, _bases(problem, 3))
    assert cases != families.families(pid, 4, _bases(problem, 4))
    refused = [c for c in cases if not _valid(problem, c)]
    assert not refused, refused[:3]
    # the search's first inputs: families in turn with the (reversed) lattice, deterministic too
    first = cx_mod.public_first_cases(problem, 3)
    assert first == cx_mod.public_first_cases(problem, 3) and first[0] == cases[0]


def test_the_families_reach_the_extremes_exactly():
    coords = [x for c in families.families("delaunay", 1) for p in c["points"] for x in p]
    assert max(abs(x) for x in coords) > 1e300 and 0 < min(abs(x) for x in coords if x) < 1e-300
    assert any(x == 1e15 for x in coords) and any(x == math.nextafter(2.0, 3.0) for x in coords)
    case = {"kind": "points", "points": [[1, 2], [0.5, 3]], "box": [0, 0, 4, 4], "start": [0.5, 0.5]}
    back = scaled(scaled(case, 2.0 ** 1000), 2.0 ** -1000)
    assert back["points"] == [[1, 2], [0.5, 3]] and back["box"] == [0, 0, 4, 4] and back["start"] == [0.5, 0.5]
    assert shifted(case, 1e15)["points"][1] == [1e15 + 0.5, 1e15 + 3]
    ops = {"kind": "ops", "operations": [["join", 1.0, 2.0], ["neighbors", 0]]}
    assert scaled(ops, 2.0)["operations"] == [["join", 2.0, 4.0], ["neighbors", 0]]
    for bad in (0, -1.0, math.inf, math.nan, "2"):
        with pytest.raises(ValueError, match="scale factor"):
            scaled(case, bad)
    with pytest.raises(ValueError, match="offset"):
        shifted(case, math.inf)
    assert families.families("not-a-problem", 1) == []


@pytest.mark.parametrize("pid,path", [
    ("delaunay", ZOO / "delaunay" / "float_coordinates.py"),          # a float in-circle test
    ("delaunay", REPO / "solutions" / "delaunay" / "wrong_super_1e5.py"),  # a super-triangle of +-1e5
    ("closest-pair", REPO / "solutions" / "closest-pair" / "wrong_double.cpp"),  # double distances (C++)
])
def test_float_and_super_triangle_mistakes_get_a_counterexample(pid, path):
    """Each of these passes every lattice configuration; the families find it (generous budget)."""
    found = cx_mod.search(pid, path, seconds=60)
    assert found is not None and found.verdict == "WA" and found.size <= MAX_SIZE, found
    assert found.certificate is not None and found.certificate["kind"] != "differs", found.certificate


def test_a_none_answer_is_shown_as_the_problems_output_text():
    """navmesh's "no path" is the function's None: shown as the output "0", not the JSON null."""
    judge = Judge(load_problem("navmesh"))
    assert judge._answer_text(None, None, function_mode=True) == "0\n"
    assert judge._answer_text([[0, 0]], [[0.0, 0.0]], function_mode=True) == "1\n0.0 0.0\n"
    delaunay = Judge(load_problem("delaunay"))   # a None its write_output cannot write: JSON
    assert delaunay._answer_text(None, None, function_mode=True) == "null"
