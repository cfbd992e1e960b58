"""Every problem has its C++ reference solutions and a C++ time limit (a structural check; no
compiling, no judging: benchmarks/bench_cpp_solutions.py proves the verdicts, and the judge's
own tests judge the files).

Each ``solutions/<id>/`` holds ``accepted.cpp``, ``wrong_double.cpp``, ``quadratic.cpp`` and
``compile_error.cpp`` with their verdicts in ``expected_cpp.yaml`` (AC; a failing verdict on the
degenerate group; TLE on the group built to stop a quadratic solution; CE), and each problem's
course.yaml names a C++ limit (``time_limits: {cpp: X}``), read by ``Problem.time_limit_for``.

Run: .venv/bin/python -m pytest tests/test_cpp_solutions.py -q
Example: a problem without quadratic.cpp fails with "navmesh: missing quadratic.cpp".
"""
from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from grader import load_problem

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = sorted(p.parent.name for p in (ROOT / "assignments").glob("*/problem.yaml"))
FILES = ("accepted.cpp", "wrong_double.cpp", "quadratic.cpp", "compile_error.cpp")
#: problems built so that a quadratic algorithm passes (small inputs): their quadratic.cpp is AC
#: and another file is the one the C++ limit stops (problem: (file, the group that stops it))
QUADRATIC_PASSES = {"bowyer-watson-timed": "a 30-minute exercise, n <= 250: quadratic Bowyer-Watson is the intended solution"}
TOO_SLOW = {"bowyer-watson-timed": ("too_slow_recheck.cpp", "random")}


def expected(problem: str) -> dict[str, tuple[str, list[str]]]:
    table = yaml.safe_load((ROOT / "solutions" / problem / "expected_cpp.yaml").read_text()) or {}
    return {str(k): (str(v).split()[0], str(v).split()[1:]) for k, v in table.items()}


def test_every_problem_is_listed():
    assert len(PROBLEMS) == 12, PROBLEMS


@pytest.mark.parametrize("problem", PROBLEMS)
def test_problem_has_the_four_cpp_solutions(problem):
    folder = ROOT / "solutions" / problem
    for name in FILES:
        assert (folder / name).is_file(), f"{problem}: missing {name}"
    table = expected(problem)
    assert sorted(table) == sorted(p.name for p in folder.glob("*.cpp")), f"{problem}: expected_cpp.yaml vs files"
    assert table["accepted.cpp"] == ("AC", []), problem
    assert table["compile_error.cpp"][0] == "CE", problem
    wrong, wrong_groups = table["wrong_double.cpp"]
    assert wrong in ("WA", "PE", "RE", "TLE") and "degenerate" in wrong_groups, (problem, wrong, wrong_groups)
    verdict, groups = table["quadratic.cpp"]
    if problem in QUADRATIC_PASSES:
        assert verdict == "AC", (problem, QUADRATIC_PASSES[problem])
        slow, group = TOO_SLOW[problem]
        assert table[slow] == ("TLE", [group]), (problem, table.get(slow))
    else:
        assert verdict == "TLE" and "large" in groups, (problem, verdict, groups)
    present = {g.name for g in load_problem(problem).present_groups}
    for name, (_, failed) in table.items():
        assert set(failed) <= present, (problem, name, failed, present)


@pytest.mark.parametrize("problem", PROBLEMS)
def test_problem_has_a_cpp_time_limit(problem):
    course = yaml.safe_load((ROOT / "assignments" / problem / "course.yaml").read_text())
    limit = (course.get("time_limits") or {}).get("cpp")
    assert isinstance(limit, (int, float)) and 0 < limit <= 600, (problem, course.get("time_limits"))
    p = load_problem(problem)
    assert p.time_limit_for("cpp") == float(limit)
    assert p.time_limit_for("python") == p.time_limit  # the Python limit stays problem.yaml's


def test_the_limit_rule():
    """The rule the benchmark writes the limits with: 5 x the accepted slowest, up to 0.5 s, at least 1 s."""
    import importlib.util
    import sys

    spec = importlib.util.spec_from_file_location("bench_cpp", ROOT / "benchmarks" / "bench_cpp_solutions.py")
    bench = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = bench  # its dataclasses look their module up
    spec.loader.exec_module(bench)
    assert [bench.cpp_time_limit(t) for t in (0.0, 0.05, 0.2, 0.21, 0.3, 0.61, 2.0)] == [1.0, 1.0, 1.0, 1.5, 1.5, 3.5, 10.0]
