"""Every reference submission in solutions/<problem>/ gets the verdict listed in its expected.yaml,
and every C++ one the verdict of its expected_cpp.yaml (``file: VERDICT [group ...]``, the groups
being exactly the ones it fails), judged by the real judge: compiled once in the compile jail, run
in the run jail; a failing one stops at its first failure, which must be in one of its groups (it
is judged on every test of those groups and the first three of each other group).

Run: .venv/bin/python -m pytest tests/grader/test_solutions.py -q
"""
from __future__ import annotations


import pytest
import yaml

from grader.contest.judge import Judge
from grader.contest.kattis import expected_verdicts, selection
from grader.problems import list_problems, load_problem
from grader.judging.verdicts import Verdict

from .conftest import REPO

PROBLEMS = [p.id for p in list_problems()]
CASES = [(p, f, v) for p in PROBLEMS for f, v in expected_verdicts(p).items()]




def _cpp_cases() -> list[tuple[str, str, str, list[str]]]:
    cases = []
    for p in PROBLEMS:
        f = REPO / "solutions" / p / "expected_cpp.yaml"
        if f.is_file():
            for name, value in (yaml.safe_load(f.read_text()) or {}).items():
                verdict, *groups = str(value).split()
                cases.append((p, name, verdict, groups))
    return cases


CPP_CASES = _cpp_cases()
#: tests judged of each group a failing C++ solution passes (it runs every test of the groups it fails)
PASSED_SAMPLE = 3


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


@pytest.mark.parametrize("problem,file,verdict,groups", CPP_CASES, ids=[f"{p}/{f}" for p, f, _, _ in CPP_CASES])
def test_cpp_solution_verdict(problem, file, verdict, groups, judges):
    key = (problem, "cpp", verdict != "AC", tuple(groups))
    if key not in judges:
        p = load_problem(problem)  # judged under the problem's own C++ limit (course.yaml time_limits)
        assert "cpp" in p.time_limits, f"{problem}: course.yaml names no C++ time limit"
        if verdict != "AC" and groups:
            # CI time: the groups it must fail run in full (up to the first failure); of the groups
            # it passes, the first PASSED_SAMPLE tests (the benchmark runs every test of them)
            p = selection(p, [(g, None if g.name in groups else PASSED_SAMPLE) for g in p.present_groups])
        judges[key] = Judge(p, stop_at_first_failure=verdict != "AC")
    result = judges[key].judge_path(REPO / "solutions" / problem / file, follow_links=True)
    failed = [t for t in result.tests if t.verdict not in (Verdict.AC, Verdict.SKIPPED)]
    assert result.verdict == verdict, [(t.name, str(t.verdict), t.message[:200]) for t in failed[:3]]
    assert Verdict.JE not in [t.verdict for t in result.tests]
    if verdict == "AC":
        assert result.score == result.max_score == 100
    elif groups:
        assert failed[0].group in groups, (failed[0].name, groups)
