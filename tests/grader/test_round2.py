"""The second round of the shortcut zoo: ``stress``'s random families reach the four shortcuts
that the lattice configurations miss, are deterministic from the seed and valid inputs.

The zoo files themselves (killed by their scored group, found by ``stress`` within 60 s) are
checked by tests/grader/test_zoo.py through ``expected.yaml``; here the families are checked in
this process, without the sandbox: each wrong solution disagrees with its problem's accepted one
on a fair share of :func:`grader.contest.stress.random_case`'s inputs.

Run: .venv/bin/python -m pytest tests/grader/test_round2.py -q -n 0

Example (one family case):
    random_case("closest-pair", random.Random(1), 10)  ->  {"kind": "points", "points": [...], ...}
"""
from __future__ import annotations

import importlib.util
import math
import random

import pytest

from grader.contest.stress import _test, random_case
from grader.problems import load_problem

from .conftest import REPO


def _module(problem: str, file: str):
    spec = importlib.util.spec_from_file_location(f"_round2_{problem}_{file[:-3]}".replace("-", "_"),
                                                  REPO / "solutions" / problem / file)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _cases(problem: str, count: int, seed: int = 7) -> list[dict]:
    rng = random.Random(seed)
    return [random_case(problem, rng, 2 + k % 12) for k in range(count)]


@pytest.mark.parametrize("problem", ["closest-pair", "emst", "navmesh", "obstacle-clearance"])
def test_random_cases_are_deterministic_from_the_seed(problem):
    assert _cases(problem, 60, seed=3) == _cases(problem, 60, seed=3)
    assert _cases(problem, 60, seed=3) != _cases(problem, 60, seed=4)


def test_navmesh_families_are_valid_inputs():
    """Rotated rings, dips of 2**-40 and U-shaped rooms all pass the input validator."""
    problem = load_problem("navmesh")
    cases = _cases("navmesh", 80)
    dips = [c for c in cases if any(isinstance(v, float) and v != round(v * 4) / 4 for p in c["boundary"] for v in p)
            or any(isinstance(v, float) and v != round(v * 4) / 4 for h in c["holes"] for p in h for v in p)]
    assert len(dips) >= 5
    assert all(_test(problem, c, "t") is not None for c in cases)


def _length(path):
    return None if path is None else math.fsum(math.dist(a, b) for a, b in zip(path, path[1:]))


def _disagree(problem: str, good, bad, count: int = 240) -> int:
    """How many of ``count`` random cases get a different answer from ``bad`` than from ``good``."""
    n = 0
    for c in _cases(problem, count):
        if problem == "closest-pair":
            P = c["points"]

            def d(ij):
                return (P[ij[0]][0] - P[ij[1]][0]) ** 2 + (P[ij[0]][1] - P[ij[1]][1]) ** 2
            n += d(good(P)) != d(bad(P))
        elif problem == "obstacle-clearance":
            a, b = good(c["points"], c["start"], c["goal"]), bad(c["points"], c["start"], c["goal"])
            n += not math.isclose(a, b, rel_tol=1e-9)
        else:
            args = (c["boundary"], c["holes"], c["start"], c["goal"])
            a, b = _length(good(*args)), _length(bad(*args))
            n += (a is None) != (b is None) or (a is not None and not math.isclose(a, b, rel_tol=1e-9))
    return n


@pytest.mark.parametrize("problem,good,bad,entry", [
    ("closest-pair", "accepted_sweep.py", "wrong_window7.py", "closest_pair"),
    ("navmesh", "accepted_visibility.py", "wrong_first_corner.py", "shortest_path"),
    ("navmesh", "accepted_visibility.py", "wrong_reflex_epsilon.py", "shortest_path"),
    ("obstacle-clearance", "accepted_delaunay.py", "wrong_triangle_corners.py", "max_clearance"),
], ids=["window7", "first_corner", "reflex_epsilon", "triangle_corners"])
def test_random_families_reach_the_round2_shortcuts(problem, good, bad, entry):
    """At least 2% of the random inputs tell each shortcut from the accepted solution (a batch
    of ``stress`` judges 48): the uniform lattice points alone reach none of them."""
    wrong = _disagree(problem, getattr(_module(problem, good), entry), getattr(_module(problem, bad), entry))
    assert wrong >= 5, f"{bad}: only {wrong} of 240 random inputs show the shortcut"
