"""Wrong algorithms must not get marks: every wrong approach in solutions/<problem>/expected.yaml
(the original tutorial's mistakes, finite super-triangles, epsilon tests; see the docstring of
each file) is WA on `delaunay` and `bowyer-watson-timed`, and its first failure is in the group
its file names on its ``Killed by:`` line. Two of them passed every test before the cases with a
nearly flat hull triangle and with points at 1e6 were added: for those the test also checks
that exactly that input is what kills them.

Run: .venv/bin/python -m pytest tests/grader/test_wrong_algorithms.py -q
"""
from __future__ import annotations

import re

import pytest

from grader.contest.judge import Judge
from grader.contest.kattis import expected_verdicts
from grader.judging.verdicts import Verdict

from .conftest import REPO

PROBLEMS = ("delaunay", "bowyer-watson-timed")
WRONG = [(p, f) for p in PROBLEMS for f, v in expected_verdicts(p).items() if v == "WA"]
FLAT_HULL = [[0.0, 0.0], [1.0, 1e-12], [2.0, 0.0], [1.0, 1.0]]
AT_1E6 = [[1e6, 1e6], [2e6, 3e6], [4e6, 1e6]]
#: (problem, file) -> the input that is the first to kill it (it passes every test before).
KILLER_INPUT = {
    ("delaunay", "wrong_super_exact.py"): FLAT_HULL,
    ("bowyer-watson-timed", "../delaunay/wrong_super_exact.py"): FLAT_HULL,
    ("bowyer-watson-timed", "../delaunay/wrong_super_float.py"): FLAT_HULL,
    ("delaunay", "wrong_super_1e5.py"): AT_1E6,
    ("bowyer-watson-timed", "../delaunay/wrong_super_1e5.py"): AT_1E6,
}


@pytest.fixture(scope="module")
def judges():
    return {p: Judge(p, stop_at_first_failure=True) for p in PROBLEMS}


def killing_group(path) -> str:
    m = re.search(r"^Killed by: (\w[\w-]*)", path.read_text(), re.M)
    assert m, f"{path.name} must say which group kills it ('Killed by: GROUP')"
    return m.group(1)


def test_the_corpus_covers_each_wrong_approach():
    names = {f.rsplit("/", 1)[-1] for p, f in WRONG}
    assert {"wrong_tutorial.py", "wrong_super_float.py", "wrong_super_exact.py", "wrong_super_1e5.py",
            "wrong_shared_edges.py", "wrong_unoriented.py", "wrong_epsilon.py"} <= names
    for p in PROBLEMS:
        assert {f.rsplit("/", 1)[-1] for q, f in WRONG if q == p} == names, f"{p} misses a wrong approach"


@pytest.mark.parametrize("problem,file", WRONG, ids=[f"{p}/{f.rsplit('/', 1)[-1]}" for p, f in WRONG])
def test_wrong_algorithm_is_killed_by_its_group(problem, file, judges):
    path = (REPO / "solutions" / problem / file).resolve()
    judge = judges[problem]
    result = judge.judge_path(path)
    first = next(t for t in result.tests if t.verdict not in (Verdict.AC, Verdict.SKIPPED))
    assert (first.verdict, first.group) == (Verdict.WA, killing_group(path)), (first.name, first.message[:200])
    assert result.score < result.max_score
    if (problem, file) in KILLER_INPUT:
        k = next(i for i, t in enumerate(judge.tests) if t.name == first.name)
        (points,) = judge.problem.checker.read_input(judge.tests[k].input_text)
        assert sorted(points) == sorted(KILLER_INPUT[(problem, file)]), first.name
