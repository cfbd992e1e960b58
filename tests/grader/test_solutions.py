"""Every reference submission in solutions/<problem>/ gets the verdict listed in its expected.yaml.

Run: .venv/bin/python -m pytest tests/grader/test_solutions.py -q
"""
from __future__ import annotations

import pytest

from grader.contest.judge import Judge
from grader.contest.kattis import expected_verdicts
from grader.problems import list_problems
from grader.judging.verdicts import Verdict

from .conftest import REPO

PROBLEMS = [p.id for p in list_problems()]
CASES = [(p, f, v) for p in PROBLEMS for f, v in expected_verdicts(p).items()]


@pytest.fixture(scope="module")
def judges():
    return {}


@pytest.mark.parametrize("problem,file,verdict", CASES, ids=[f"{p}/{f}" for p, f, _ in CASES])
def test_solution_verdict(problem, file, verdict, judges):
    # a failing solution stops at its first failure (as Kattis does): the verdict is the same
    key = (problem, verdict != "AC")
    judge = judges.setdefault(key, Judge(problem, stop_at_first_failure=verdict != "AC"))
    result = judge.judge_path(REPO / "solutions" / problem / file, follow_links=True)
    assert result.verdict == verdict, [(t.name, str(t.verdict), t.message[:120]) for t in result.tests]
    assert Verdict.JE not in [t.verdict for t in result.tests]
    if verdict == "AC":
        assert result.score == result.max_score == 100


@pytest.mark.parametrize("problem", PROBLEMS)
def test_every_problem_has_accepted_wrong_and_slow(problem):
    expected = expected_verdicts(problem)
    assert {"AC", "WA", "TLE"} <= set(expected.values()), expected
    for name in expected:
        assert (REPO / "solutions" / problem / name).exists(), name


def test_accepted_delaunay_implements_bowyer_watson_itself():
    src = (REPO / "solutions" / "delaunay" / "accepted_walk.py").read_text()
    assert "reference_impl" not in src.replace("reference_impl`", "") or "import reference_impl" not in src
    assert "cavity" in src
