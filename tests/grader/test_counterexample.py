"""The counterexample search of a failing submission (grader/contest/counterexample.py).

A submission that fails a group with WA, PE or RE gets a small input of the grader's own that it
fails too (public families only, shrunk), with its answer and the checker's reason, in the CLI
table and in ``--json``; an accepted or only-slow submission costs no search at all; the input is
never a test's input (even when that is the only failing one); the ``feedback:`` keys are checked;
a C++ submission goes through the same path, compiled once. Verdicts only, no timings.

Run: .venv/bin/python -m pytest tests/grader/test_counterexample.py -q -n 0
"""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
import yaml

from grader import cli
from grader.contest import counterexample as cx_mod
from grader.contest import judge as judge_mod
from grader.contest import stress as stress_mod
from grader.contest.judge import Judge
from grader.judging import compile as compile_mod
from grader.judging.verdicts import format_table
from grader.problems import Problem, load_problem

from .conftest import REPO
from .test_stress import function_solution, tiny_problem

SOLUTIONS = REPO / "solutions"


def _no_search(monkeypatch) -> list:
    """Make any search fail the test loudly; returns the list of calls (must stay empty)."""
    calls: list = []

    def refuse(*args, **kw):
        calls.append(args)
        raise AssertionError("a search ran")
    monkeypatch.setattr(cx_mod, "search", refuse)
    return calls


def _cli(monkeypatch, capsys, problem: Problem, *argv: str) -> tuple[int, str]:
    monkeypatch.setattr(judge_mod, "load_problem", lambda pid: problem)
    code = cli.main(["judge", problem.id, *argv])
    return code, capsys.readouterr().out


def test_a_wrong_solution_gets_a_small_counterexample_in_the_json_and_the_table():
    problem = load_problem("closest-pair")
    path = SOLUTIONS / "closest-pair" / "wrong_x_neighbours.py"
    result = Judge(problem, hide=[str(path.parent)]).judge_path(path, follow_links=True)
    assert result.verdict == "WA"
    found = cx_mod.attach(result, problem, path, seconds=60)
    assert found is not None and found.verdict == "WA" and 2 <= found.size <= 10, found
    assert found.answer.strip() and found.reason and found.input.split()[0] == str(found.size)
    groups = result.to_json()["groups"]
    with_cx = [g for g in groups if g.get("counterexample")]
    assert with_cx and all(not g["passed"] for g in with_cx)
    assert {"input", "answer", "reason", "certificate", "seconds", "verdict", "size"} <= set(with_cx[0]["counterexample"])
    json.dumps(result.to_json())  # JSON-native
    # the certificate is exact and the student's helper recomputes it from input and answer
    cert = with_cx[0]["counterexample"]["certificate"]
    assert cert is not None and cert["kind"] == "closer-pair", cert
    from grader import check_certificate
    assert "closer" in check_certificate(with_cx[0]["counterexample"], draw=False)
    assert stress_mod.normalized(found.input) not in {stress_mod.normalized(t.input_text) for t in problem.tests()}
    table = format_table(result)
    assert "a small input your program also gets wrong" in table and found.input.rstrip("\n") in table
    assert "your answer:" in table and found.reason.splitlines()[0][:60] in table


def test_the_cli_flag_puts_a_counterexample_in_json_and_0_turns_it_off(tmp_path, monkeypatch, capsys):
    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": [[0, 0], [4, 0], [0, 4], [4, 4]],
                                                  "shuffle": False}])
    path = function_solution(tmp_path, "if len(points) >= 3:\n    return [[0, 1, 2]] * 2")
    code, out = _cli(monkeypatch, capsys, problem, str(path), "--json", "--counterexample-seconds", "30")
    assert code == 1
    group = json.loads(out)["groups"][0]
    cx = group["counterexample"]
    assert cx["verdict"] == "WA" and cx["size"] == 3, cx  # shrunk to the smallest that fails
    assert stress_mod.normalized(cx["input"]) != stress_mod.normalized(problem.tests()[0].input_text)
    calls = _no_search(monkeypatch)
    code, out = _cli(monkeypatch, capsys, problem, str(path), "--json", "--counterexample-seconds", "0")
    assert code == 1 and "counterexample" not in json.loads(out)["groups"][0] and calls == []


def test_an_accepted_solution_and_an_only_slow_one_get_no_search(tmp_path, monkeypatch, capsys):
    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": [[0, 0], [2, 0], [0, 2]],
                                                  "shuffle": False}])
    calls = _no_search(monkeypatch)
    code, out = _cli(monkeypatch, capsys, problem, str(function_solution(tmp_path, "pass")), "--json")
    assert code == 0 and "counterexample" not in out
    slow = function_solution(tmp_path, "import time\ntime.sleep(3)", name="slow.py")
    code, out = _cli(monkeypatch, capsys, problem, str(slow), "--json")
    assert code == 1 and json.loads(out)["verdict"] == "TLE" and "counterexample" not in out
    assert calls == []


def test_the_accepted_and_slow_solutions_of_the_course_cost_no_search(monkeypatch):
    problem = load_problem("closest-pair")
    calls = _no_search(monkeypatch)
    for name in ("slow_brute_force.py",):
        path = SOLUTIONS / "closest-pair" / name
        result = Judge(problem, hide=[str(path.parent)]).judge_path(path, follow_links=True)
        assert result.verdict in ("AC", "TLE"), result.verdict
        assert cx_mod.attach(result, problem, path, seconds=10) is None
        assert result.counterexamples == {} and "counterexample_search" not in result.extra
    assert calls == []


def test_a_failing_input_that_is_a_test_input_is_never_a_counterexample(tmp_path):
    """The submission fails only on one input, which is the problem's test: the search must drop it
    (never judged) and find nothing; without the exclusion the same search reports it."""
    case = {"kind": "points", "points": [[0, 0], [2, 0], [0, 2]], "shuffle": False}
    problem = tiny_problem(tmp_path, exhaustive=[case])
    path = function_solution(tmp_path, "if points == [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]]:\n    return []")
    result = Judge(problem, hide=[str(tmp_path)]).judge_path(path, follow_links=True)
    assert result.verdict == "WA"
    plain = stress_mod.stress(problem, path, 20, first=[case])
    assert plain is not None and stress_mod.normalized(plain.input_text) == stress_mod.normalized(problem.tests()[0].input_text)
    stats = stress_mod.Stats()
    hidden = cx_mod.hidden_inputs(problem)
    found = stress_mod.stress(problem, path, 4, first=[case], exclude=hidden, verdicts=cx_mod.TRIGGERS, stats=stats)
    assert found is None and stats.excluded >= 1
    assert cx_mod.attach(result, problem, path, seconds=4) is None
    assert result.counterexamples == {"exhaustive": None} and result.extra["counterexample_search"]["found"] is False
    assert "no failing input found" in format_table(result)


def _with_feedback(tmp_path: Path, feedback) -> Path:
    dst = tmp_path / "fb"
    problem = tiny_problem(tmp_path)
    shutil.copytree(problem.path, dst)
    course = yaml.safe_load((dst / "course.yaml").read_text())
    course["feedback"] = feedback
    (dst / "course.yaml").write_text(yaml.safe_dump(course))
    return dst


@pytest.mark.parametrize("feedback,message", [
    ({"counterexample": "yes"}, "counterexample must be true or false"),
    ({"counterexample_seconds": -1}, "counterexample_seconds must be a number"),
    ({"counterexample_seconds": "10"}, "counterexample_seconds must be a number"),
    ({"counterexample_seconds": True}, "counterexample_seconds must be a number"),
    ({"counterexample_seconds": 1e9}, "counterexample_seconds must be a number"),
    ({"counterexamples": True}, "takes hidden, public, groups, counterexample, counterexample_seconds"),
])
def test_feedback_schema_errors_name_the_problem(tmp_path, feedback, message):
    with pytest.raises(ValueError, match=message) as err:
        Problem.load(_with_feedback(tmp_path, feedback))
    assert "'fb'" in str(err.value)


def test_feedback_schema_values(tmp_path):
    assert Problem.load(_with_feedback(tmp_path / "a", None)).counterexample_seconds == 10.0
    assert Problem.load(_with_feedback(tmp_path / "b", {"counterexample": False})).counterexample_seconds == 0.0
    p = Problem.load(_with_feedback(tmp_path / "c", {"counterexample_seconds": 2.5, "hidden": "verdict"}))
    assert p.counterexample_seconds == 2.5 and p.feedback_level("exhaustive") == "verdict"


WRONG_CPP = r"""
#include <cstdio>
int main() {
    int n = 0;
    if (std::scanf("%d", &n) != 1) return 1;
    if (n >= 3) std::printf("2\n0 1 2\n0 1 2\n"); else std::printf("0\n");
    return 0;
}
"""


def test_a_cpp_wrong_solution_goes_through_the_same_path_compiled_once(tmp_path, monkeypatch, capsys):
    """A C++ program (stdio mode) that repeats a triangle on 3+ points: the judge compiles it once
    and hands the build to the search, which finds the 3-point input; the answer is its output."""
    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": [[0, 0], [4, 0], [0, 4], [4, 4]],
                                                  "shuffle": False}])
    path = tmp_path / "wrong.cpp"
    path.write_text(WRONG_CPP)
    builds = []
    real = compile_mod.compile_source

    def counted(*args, **kw):
        builds.append(1)
        return real(*args, **kw)
    monkeypatch.setattr(judge_mod, "compile_source", counted)
    code, out = _cli(monkeypatch, capsys, problem, str(path), "--json", "--counterexample-seconds", "60")
    assert code == 1 and len(builds) == 1, (builds, out[-2000:])  # the judging's build serves the search
    cx = json.loads(out)["groups"][0]["counterexample"]
    assert cx["verdict"] == "WA" and cx["size"] == 3 and cx["answer"] == "2\n0 1 2\n0 1 2\n", cx


def test_size_counts_points_vertices_and_operations():
    assert cx_mod.size_of({"kind": "ops", "operations": [["count"]] * 4}) == 4
    assert cx_mod.size_of({"kind": "points", "points": [[0, 0]] * 3, "start": [0, 0]}) == 3


def _search_after_scores(problem_id, student, sha, file, db_path, *rest):
    """``search_one``, checking first that every student's score is stored (runs in a pool worker)."""
    from grader.classroom.store import ResultStore

    store = ResultStore(db_path)
    try:
        status = {s["student"]: s["status"] for s in store.submissions(problem_id)}
    finally:
        store.close()
    assert status == {"ada": "done", "bob": "done"}, status
    return _REAL_SEARCH_ONE(problem_id, student, sha, file, db_path, *rest)


_REAL_SEARCH_ONE = None  #: the real ``search_one``, set by the test before the workers are forked


def test_class_grading_stores_every_score_then_searches_the_failing_ones(tmp_path, monkeypatch):
    global _REAL_SEARCH_ONE
    from grader.classroom import class_counterexamples, classgrade
    from grader.classroom.store import ResultStore

    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": [[0, 0], [4, 0], [0, 4], [4, 4]],
                                                  "shuffle": False}])
    for mod in (classgrade, class_counterexamples, judge_mod):
        monkeypatch.setattr(mod, "load_problem", lambda pid: problem)
    subs = tmp_path / "subs"
    for student, body in (("ada", "pass"), ("bob", "if len(points) >= 3:\n    return [[0, 1, 2]] * 2")):
        (subs / student).mkdir(parents=True)
        function_solution(subs / student, body)
    _REAL_SEARCH_ONE = class_counterexamples.search_one
    monkeypatch.setattr(class_counterexamples, "search_one", _search_after_scores)
    db = tmp_path / "results.sqlite"
    out = classgrade.grade_class(problem.id, subs, db, progress=False, counterexample_seconds=30)
    assert {s["student"]: s["verdict"] for s in out} == {"ada": "AC", "bob": "WA"}
    store = ResultStore(db)
    try:
        latest = store.latest(problem.id)
        assert store.counterexamples("ada", problem.id, latest["ada"]["sha"]) is None  # accepted: no search
        groups, search = store.counterexamples("bob", problem.id, latest["bob"]["sha"])
        assert search["found"] and groups["exhaustive"]["size"] == 3, (groups, search)
        assert store.counterexample_seconds(problem.id)[0] == 1
        assert class_counterexamples.pending(store, problem) == []  # a rerun of grade searches nothing again
    finally:
        store.close()


def test_class_grading_compiles_a_failing_cpp_submission_once_for_its_search(tmp_path, monkeypatch):
    """The judge (a pool worker) leaves the binary of a failing C++ submission in the grader's
    private folder; its search (another worker, after every score) takes it instead of compiling
    again; the folder is gone afterwards. Compiles are counted in a file (workers are processes)."""
    from grader.classroom import class_counterexamples, classgrade

    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": [[0, 0], [4, 0], [0, 4], [4, 4]],
                                                  "shuffle": False}])
    for mod in (classgrade, class_counterexamples, judge_mod):
        monkeypatch.setattr(mod, "load_problem", lambda pid: problem)
    subs, log = tmp_path / "subs", tmp_path / "compiles.log"
    (subs / "carl").mkdir(parents=True)
    (subs / "carl" / "wrong.cpp").write_text(WRONG_CPP)
    real = compile_mod.compile_source

    def counted(*args, **kw):
        with open(log, "a") as f:
            f.write("compile\n")
        return real(*args, **kw)
    monkeypatch.setattr(judge_mod, "compile_source", counted)
    folders = []
    real_folder = classgrade._builds_folder
    monkeypatch.setattr(classgrade, "_builds_folder", lambda *a: folders.append(real_folder(*a)) or folders[-1])
    out = classgrade.grade_class(problem.id, subs, tmp_path / "results.sqlite", progress=False,
                                 counterexample_seconds=60)
    assert [s["verdict"] for s in out] == ["WA"], out
    from grader.classroom.store import ResultStore
    store = ResultStore(tmp_path / "results.sqlite")
    try:
        groups, search = store.counterexamples("carl", problem.id, store.latest(problem.id)["carl"]["sha"])
    finally:
        store.close()
    assert search["found"] and groups["exhaustive"]["answer"] == "2\n0 1 2\n0 1 2\n", (groups, search)
    assert log.read_text().count("compile") == 1, "the search compiled the submission again"
    assert len(folders) == 1 and folders[0] and not Path(folders[0]).exists()


def test_the_sample_check_shows_a_counterexample_only_when_a_sample_failed(tmp_path, monkeypatch):
    from grader.contest import sample_check

    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": [[0, 0], [4, 0], [0, 4], [4, 4]],
                                                  "shuffle": False}])
    monkeypatch.setattr(sample_check, "load_problem", lambda pid: problem)
    good = function_solution(tmp_path, "pass")
    calls = _no_search(monkeypatch)
    result = Judge(problem, hide=[str(tmp_path)], trusted=True).judge_path(good)
    assert result.verdict == "AC" and sample_check.search_samples(problem.id, result, good) == "" and calls == []
    monkeypatch.undo()
    monkeypatch.setattr(sample_check, "load_problem", lambda pid: problem)
    bad = function_solution(tmp_path, "if len(points) >= 3:\n    return [[0, 1, 2]] * 2", name="bad.py")
    result = Judge(problem, hide=[str(tmp_path)], trusted=True).judge_path(bad)
    html_text = sample_check.search_samples(problem.id, result, bad, seconds=30)
    assert "a small input your code also gets wrong (WA, 3 elements" in html_text and "your answer:" in html_text


def test_the_sample_check_compiles_a_cpp_file_once(tmp_path, monkeypatch):
    """``judge_samples`` keeps its build and ``search_samples`` hands it to the search."""
    from grader.contest import sample_check

    problem = tiny_problem(tmp_path, exhaustive=[{"kind": "points", "points": [[0, 0], [4, 0], [0, 4], [4, 4]],
                                                  "shuffle": False}])
    monkeypatch.setattr(sample_check, "load_problem", lambda pid: problem)
    monkeypatch.setattr(sample_check, "sample_problem", lambda p: p)  # its tests stand for samples
    path = tmp_path / "wrong.cpp"
    path.write_text(WRONG_CPP)
    builds = []
    real = compile_mod.compile_source
    monkeypatch.setattr(judge_mod, "compile_source", lambda *a, **k: builds.append(1) or real(*a, **k))
    result, _ = sample_check.judge_samples(problem.id, path)
    assert result.verdict == "WA", format_table(result)
    html_text = sample_check.search_samples(problem.id, result, path, seconds=60)
    assert "a small input your code also gets wrong (WA, 3 elements" in html_text, html_text
    assert len(builds) == 1 and sample_check._kept == {}, builds


def test_a_copy_of_the_problem_without_reference_answers_says_why_there_is_none(tmp_path):
    import dataclasses

    from grader.judging.verdicts import JudgeResult, TestResult, Verdict

    problem = dataclasses.replace(tiny_problem(tmp_path), generator_path=None)
    result = JudgeResult(problem.id, "x.py", [TestResult("exhaustive/1", "exhaustive", Verdict.WA)],
                         problem.group_points)
    assert cx_mod.attach(result, problem, function_solution(tmp_path, "pass"), seconds=5) is None
    assert "no reference answers" in result.extra["counterexample_search"]["note"]
    assert "no reference answers" in format_table(result)
