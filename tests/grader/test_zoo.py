"""The exhaustive group and the shortcut zoo: every problem has the scored `exhaustive` group
(grader/problems/smallcases.py, committed in course.yaml and current); every wrong solution that
expected.yaml names with a killing group (``WA exhaustive``) fails a test of that scored group;
and ``python -m grader stress`` finds each zoo solution's bug in seconds and prints a small input,
while it finds nothing against an accepted solution.

Run: .venv/bin/python -m pytest tests/grader/test_zoo.py -q -n 0
"""
from __future__ import annotations

import pytest

from grader import cli
from grader.problems import smallcases
from grader.contest.judge import Judge
from grader.contest.kattis import expected_verdicts, killing_groups
from grader.problems import list_problems
from grader.contest.stress import candidates, stress
from grader.judging.verdicts import Verdict

from .conftest import REPO

LOADED = {p.id: p for p in list_problems()}
PROBLEMS = list(LOADED)
ZOO = [(p, f, g) for p in PROBLEMS for f, g in killing_groups(p).items()]
IDS = [f"{p}/{f.rsplit('/', 1)[-1]}" for p, f, _ in ZOO]


def test_exhaustive_cases_in_course_yaml_are_current():
    assert smallcases.main(["--check"]) == 0


@pytest.mark.parametrize("problem", PROBLEMS)
def test_every_problem_has_a_scored_exhaustive_group_and_a_zoo(problem):
    group = next(g for g in LOADED[problem].groups if g.name == "exhaustive")
    assert group.points > 0
    assert len(group.cases) >= len(smallcases.cases_for(problem)) >= 12
    assert any(q == problem for q, _, _ in ZOO), "no zoo solution names the group that kills it"


def test_lattice_configurations_are_complete_up_to_symmetry():
    configs = smallcases.lattice_configs(repeats=False)
    # orbits of the 3x3 grid's subsets under its 8 symmetries, by size 1..5 (Burnside)
    assert [sum(len(c) == n for c in configs) for n in range(1, 6)] == [3, 8, 16, 23, 23]
    assert len(smallcases.lattice_configs(dim=3, size=2, max_n=8, repeats=False)) == 21
    lists = smallcases.point_lists()
    assert [[0, 0], [0, 2], [0, 1]] in lists and [[2, 0], [0, 0], [1, 0]] in lists   # lines, not in order
    assert [[0, 0], [0, 0]] in lists                            # n = 2 with a repeat
    rings = {tuple(map(tuple, c["boundary"])) for c in smallcases.cases_for("navmesh")}
    assert ((0, 0), (4, 0), (4, 4), (0, 4)) in rings and ((0, 4), (4, 4), (4, 0), (0, 0)) in rings


def test_shrink_candidates_drop_runs_then_single_elements():
    case = {"kind": "points", "points": [[0, 0], [1, 0], [2, 0], [3, 0]]}
    assert [len(c["points"]) for c in candidates(case)] == [2, 2, 3, 3, 3, 3]
    assert [c["points"] for c in candidates(case)][2] == [[1, 0], [2, 0], [3, 0]]


@pytest.fixture(scope="module")
def judges():
    return {}


@pytest.mark.parametrize("problem,file,group", ZOO, ids=IDS)
def test_zoo_solution_fails_its_scored_group(problem, file, group, judges):
    assert expected_verdicts(problem)[file] == "WA"
    judge = judges.get(problem)
    if judge is None:
        judge = judges[problem] = Judge(problem, stop_at_first_failure=True)
    points = judge.problem.group_points[group]
    assert points > 0, f"{group} is not a scored group"
    all_tests = judge.tests
    judge.use_tests([t for t in all_tests if t.group == group])
    try:
        result = judge.judge_path(REPO / "solutions" / problem / file, follow_links=True)
    finally:
        judge.use_tests(all_tests)
    verdicts = [t.verdict for t in result.tests]
    assert Verdict.JE not in verdicts
    assert Verdict.WA in verdicts, f"{file} passes every test of {group}"


@pytest.mark.parametrize("problem,file,group", ZOO, ids=IDS)
def test_stress_finds_the_zoo_bug_and_shrinks_it(problem, file, group):
    failure = stress(problem, REPO / "solutions" / problem / file, seconds=60)
    assert failure is not None, f"stress found no failing input for {file}"
    assert failure.verdict in ("WA", "PE", "RE"), failure
    lines = failure.input_text.strip().splitlines()
    limit = 40 if problem in ("navmesh", "dynamic-network", "obstacle-clearance") else 8
    assert len(lines) <= WINDOW_LINES.get(file, limit), lines


#: zoo solutions whose smallest failing input is larger than most: a window of 7 in sorted order
#: misses the closest pair only with 7 points between them (n = 9: 10 lines), and a shrunk input
#: has no point it can lose and still fail
WINDOW_LINES = {"wrong_window7.py": 10}


def test_stress_command_exit_status(capsys):
    assert cli.main(["stress", "emst", str(REPO / "solutions/emst/wrong_collinear_sort_x.py"), "--seconds", "30"]) == 1
    out = capsys.readouterr().out
    assert out.startswith("WA on this input") and "0.0 1.0" in out, out   # the vertical line, shrunk
    assert cli.main(["stress", "closest-pair", str(REPO / "solutions/closest-pair/accepted_sweep.py"),
                     "--seconds", "3"]) == 0
    assert "no failing input found" in capsys.readouterr().out
    assert cli.main(["stress", "nope", "x.py"]) == 2
