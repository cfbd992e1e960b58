"""``python -m grader stress`` reports only inputs that fail when judged alone, shows the
program's stderr, and ends on time (grader/contest/stress.py).

The search judges many inputs per sandboxed run (one idle budget, one worker process); every
failure seen there is judged again alone with the problem's per-test limits before it is
reported or accepted while shrinking. An input that is only over the time limit alone is slow,
not wrong: never reported. Each test uses a copy of the ``tiny-delaunay`` fixture (its checker
and generator, the delaunay input validator) with the time limit it needs, and the accepted
Delaunay solution wrapped in the behaviour under test. No test asserts a timing: the one wall
time checked is a bound derived from the limits (``--seconds`` plus one test's wall cap).

Run: .venv/bin/python -m pytest tests/grader/test_stress.py -q -n 0
"""
from __future__ import annotations

import re
import shutil
import time
from pathlib import Path

import pytest
import yaml

from grader.problems import smallcases
from grader.contest import stress as stress_mod
from grader.contest.judge import Judge
from grader.problems import Problem
from grader.judging.runner import wall_limit_for
from grader.judging.submissions import Submission
from grader.judging.verdicts import TestResult, Verdict

from .conftest import FIXTURE_PROBLEM, REPO

ACCEPTED = (REPO / "solutions" / "delaunay" / "accepted_walk.py").read_text()
STARTUP_SLACK = 5.0  #: sandbox start, worker load and the reference's answers on a loaded host


def tiny_problem(tmp_path: Path, time_limit: float = 1, exhaustive: list[dict] | None = None) -> Problem:
    """A copy of the tiny fixture with ``time_limit`` and an ``exhaustive`` group, the cases stress
    tries first (default: delaunay's, every configuration of a few lattice points)."""
    dst = tmp_path / "tiny-stress"
    shutil.copytree(FIXTURE_PROBLEM, dst)
    shutil.copytree(REPO / "assignments" / "delaunay" / "input_validators", dst / "input_validators")
    course = yaml.safe_load((FIXTURE_PROBLEM / "course.yaml").read_text())
    for key in ("checker", "generator"):
        course[key] = str((FIXTURE_PROBLEM / course[key]).resolve())
    cases = smallcases.cases_for("delaunay") if exhaustive is None else exhaustive
    course["groups"] = [{"name": "exhaustive", "points": 100, "cases": cases}]
    (dst / "course.yaml").write_text(yaml.safe_dump(course))
    meta = yaml.safe_load((FIXTURE_PROBLEM / "problem.yaml").read_text())
    meta["limits"]["time_limit"] = time_limit
    (dst / "problem.yaml").write_text(yaml.safe_dump(meta))
    return Problem.load(dst)


def function_solution(tmp_path: Path, body: str, name: str = "mine.py") -> Path:
    """The accepted solution with its ``delaunay`` wrapped: ``body`` runs first (``points`` and
    ``CALLS``, this process's call count, are in scope) and may return an answer of its own."""
    wrapper = ("\n_correct = delaunay\nCALLS = 0\n\ndef delaunay(points):\n    global CALLS\n    CALLS += 1\n"
               + "".join(f"    {line}\n" for line in body.strip().splitlines()) + "    return _correct(points)\n")
    path = tmp_path / name
    path.write_text(ACCEPTED.replace('if __name__ == "__main__":\n    main()\n', "") + wrapper)
    return path


def stdio_solution(tmp_path: Path, body: str, name: str = "mine_stdio.py") -> Path:
    """The accepted solution as a program (no ``delaunay`` entry: stdio mode); ``body`` runs after
    the input is read (``data``: its words) and before the answer is written."""
    src = ACCEPTED.replace("def delaunay(", "def triangulate(").replace("tris = delaunay(pts)", "tris = triangulate(pts)")
    src = src.replace("    n = int(data[0])\n", "    n = int(data[0])\n"
                      + "".join(f"    {line}\n" for line in body.strip().splitlines()))
    assert "def delaunay(" not in src and "triangulate(pts)" in src
    path = tmp_path / name
    path.write_text(src)
    return path


@pytest.fixture
def run_stress(monkeypatch, capsys):
    """``run_stress(problem, path, seconds)``: the ``stress`` command on a problem of this test (not
    one under ``assignments/``): its exit status and output."""
    def run(problem: Problem, path: Path, seconds: float) -> tuple[int, str]:
        monkeypatch.setattr(stress_mod, "load_problem", lambda pid: problem)
        code = stress_mod.main(problem.id, str(path), seconds)
        return code, capsys.readouterr().out
    return run


def test_a_correct_function_that_sleeps_in_every_call_is_never_reported(tmp_path, run_stress):
    """1.2 s of sleep a call is under the per-test idle limit (2 s with a 2 s limit), but a batch of
    48 such calls spends the batch's idle budget (22 s): the call that finds it spent is TLE in the
    batch, answers in 1.2 s alone, and is a fluke, not a counterexample."""
    problem = tiny_problem(tmp_path, time_limit=2)
    code, out = run_stress(problem, function_solution(tmp_path, "import time\ntime.sleep(1.2)"), 30)
    assert code == 0 and out.startswith("no failing input found in "), out
    # 19 calls of 1.2 s spend the idle budget of one batch: by then a batch saw a TLE that was no failure alone
    tried = int(re.search(r"\((\d+) inputs judged\)", out).group(1))
    assert tried < 19 or "did not happen again when the input was judged alone" in out or "slow, not wrong" in out, out


def test_a_correct_program_that_sleeps_is_never_reported_and_the_command_exits_0(tmp_path, run_stress):
    problem = tiny_problem(tmp_path, time_limit=2)
    code, out = run_stress(problem, stdio_solution(tmp_path, "import time\ntime.sleep(1.2)"), 4)
    assert code == 0 and out.startswith("no failing input found in "), out


def test_a_failure_that_depends_on_earlier_calls_in_the_process_is_not_reported(tmp_path, run_stress):
    """Batching-dependent state: from its 4th call in one process it answers a bogus triangle. Judged
    alone every input is a first call and correct: flukes, counted in the output."""
    problem = tiny_problem(tmp_path)
    path = function_solution(tmp_path, "if CALLS > 3:\n    return [[0, 0, 0]]")
    code, out = run_stress(problem, path, 5)
    assert code == 0, out
    assert out.startswith("no failing input found in "), out
    assert "did not happen again when the input was judged alone" in out, out


def test_an_input_only_slow_alone_is_not_a_counterexample(tmp_path, run_stress):
    """Over the time limit on 3+ points even alone: slow, not wrong; said in a note, exit 0."""
    problem = tiny_problem(tmp_path)
    path = function_solution(tmp_path, "if len(points) >= 3:\n    import time\n    time.sleep(3)")
    code, out = run_stress(problem, path, 6)
    assert code == 0, out
    assert out.startswith("no failing input found in "), out
    assert "slow, not wrong" in out, out


@pytest.mark.parametrize("mode", ["stdio", "function"])
def test_a_crash_is_reported_with_the_end_of_its_stderr_made_safe(tmp_path, run_stress, mode):
    problem = tiny_problem(tmp_path)
    if mode == "stdio":
        crash = ("if n >= 3:\n    for k in range(30):\n        print(f'trace line {k}', file=sys.stderr)\n"
                 "    print('\\x1b[31mboom\\x1b[0m: 3 points are too many', file=sys.stderr)\n    sys.exit(1)")
        path = stdio_solution(tmp_path, crash)
    else:
        crash = ("if len(points) >= 3:\n    import sys\n    print('\\x1b[31mboom\\x1b[0m: 3 points are too many', "
                 "file=sys.stderr)\n    raise ValueError('gave up')")
        path = function_solution(tmp_path, crash)
    code, out = run_stress(problem, path, 30)
    assert code == 1, out
    assert out.startswith("RE on this input"), out
    assert "--- its stderr (last lines) ---\n" in out, out
    report = out.split("--- its stderr (last lines) ---\n", 1)[1]
    assert "\\x1b[31mboom\\x1b[0m: 3 points are too many" in report and "\x1b" not in out, out
    if mode == "stdio":   # the last lines only
        assert "trace line 29" in report and "trace line 0\n" not in report, report


def test_the_deadline_holds_while_shrinking_and_the_smallest_confirmed_input_is_printed(tmp_path, run_stress):
    """A 38-point failing input found at once (it fails when 6 points of the x axis are all in it),
    but every input under 30 points takes 1 s: shrinking it to those 6 points takes about 110 such
    calls, far longer than --seconds, so the search stops at the deadline and prints the smallest
    input confirmed so far (exit 1), within --seconds plus one test's wall cap (and start-up slack)."""
    special = [[2 * i + 1, 0] for i in range(6)]
    pts = [[i, (i * 17) % 37 + 1] for i in range(1, 33)]
    for j, p in enumerate(special):
        pts.insert(j * len(pts) // len(special) + 2, p)
    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": pts, "shuffle": False}])
    body = ("if all([2.0 * i + 1, 0.0] in points for i in range(6)):\n    return [[0, 0, 0]]\n"
            "if len(points) < 30:\n    import time\n    time.sleep(1.0)")
    path = function_solution(tmp_path, body)
    seconds = 4
    t0 = time.monotonic()
    code, out = run_stress(problem, path, seconds)
    elapsed = time.monotonic() - t0
    assert elapsed < seconds + wall_limit_for(problem.time_limit) + STARTUP_SLACK, (elapsed, out)
    assert code == 1, out
    assert "the time ran out while shrinking" in out, out
    assert len(problem.tests()) == 1   # stress judged its own inputs on a copy: the problem keeps its test
    printed = out.split(":\n\n", 1)[1].split("\n\n", 1)[0].splitlines()
    assert all(f"{x:.1f} {y:.1f}" in printed for x, y in special) and int(printed[0]) <= len(pts), out


def test_a_judge_starts_no_test_after_its_deadline(tmp_path):
    """The hook stress cuts its batches with: tests not started by the deadline are skipped."""
    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": [[0, 0], [1, 0], [0, 1]],
                                                  "shuffle": False}])
    judge = Judge(problem)
    result = judge.judge(Submission.from_path(function_solution(tmp_path, "")), deadline=time.monotonic())
    assert [str(t.verdict) for t in result.tests] == ["--"], result.tests
    assert "time given ran out" in result.tests[0].message


def test_the_json_of_a_result_has_stderr_only_when_it_was_kept():
    plain = TestResult("t/1", "t", Verdict.RE, message="boom")
    assert "stderr" not in plain.to_json()          # judge --json and the results store as before
    kept = TestResult("t/1", "t", Verdict.RE, message="boom", stderr="Traceback ...")
    assert kept.to_json()["stderr"] == "Traceback ..." and TestResult.from_json(kept.to_json()) == kept


def test_a_judge_given_other_tests_sends_their_inputs_not_the_old_ones(tmp_path):
    """The judge encodes a test's arguments once and keeps the encoding with its test: after
    ``use_tests`` (each stress batch) or a hand-made swap of ``judge.tests``, the child gets the new
    inputs (a stale encoding judged every batch on the first batch's inputs)."""
    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": [[0, 0], [1, 0], [0, 1]], "shuffle": False}])
    judge = Judge(problem)
    first = judge._args_json(0)
    other = [stress_mod._test(problem, {"kind": "points", "points": [[0, 0], [5, 0], [0, 5], [5, 5]]}, "other/1")]
    judge.use_tests(other)
    assert judge._args_json(0) != first and "5.0" in judge._args_json(0)
    judge.tests = [problem.tests()[0]]               # by hand, without use_tests
    judge._args, judge._answers = [None], [None]
    assert judge._args_json(0) == first
