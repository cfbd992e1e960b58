"""nbgrader feedback of hidden groups holds none of the hidden inputs or answers: hidden tests stay hidden from students.

The feedback a student gets is the autograded notebook's test-cell outputs
(:func:`grader.course.nbgrader_autograde.write_results`; ``generate_feedback`` renders them). Searched
for every number of the hidden ``.in``/``.ans`` files of the tests judged, in decimal (as
written), ``repr``, hex float and ``%.6g`` form (numbers of fewer than 4 characters, and those the
feedback's own frame holds, such as points, are left out: they cannot be told from the frame):

* every checker's failure messages: for each of the twelve problems, the first test of every
  hidden group checked against many wrong answers (the hostile corpus and the reference answer
  perturbed: rows dropped, repeated, reversed, indices out of range, numbers moved);
* submissions judged in the sandbox that raise with their inputs encoded in every way
  (``repr``, hex floats, JSON, base64, a class named after them, their own source file rewritten
  so that the traceback line shows the data) and print them.

Both under every feedback level a hidden group may have (``course.yaml`` ``feedback``,
:mod:`grader.judging.feedback_policy`); a level that shows test data is refused for a hidden group.
"""

from __future__ import annotations

import base64
import functools
import json
import textwrap

import contextlib

import nbformat
import pytest

from grader.judging.checker_attacks import HOSTILE_VALUES
from grader.contest.judge import Judge
from grader.contest.kattis import selection
from grader.course.nbgrader_autograde import group_output, write_results
from grader.problems import REPO, list_problems, load_problem
from grader.judging.feedback_policy import LEVELS, resolve
from grader.judging.submissions import Submission
from grader.judging.verdicts import JudgeResult, TestResult, Verdict

PROBLEMS = sorted(p.id for p in list_problems())
#: problems whose checker details quote coordinates of the test (the others quote small indices and
#: counts, which the search cannot tell from the feedback's frame)
QUOTES_COORDINATES = {"delaunay-3d", "largest-empty-circle", "navmesh", "obstacle-clearance", "voronoi"}


#: every level a hidden group may have
HIDDEN_LEVELS = sorted(name for name, level in LEVELS.items() if level.hidden_ok)

SMALL_LINES = 2000  #: larger tests are left out: messages do not depend on size, and the checks stay quick


@functools.lru_cache(maxsize=None)
def hidden_only(pid: str):
    """``pid`` with the first test of each scored group (the hidden ones) of at most SMALL_LINES lines."""
    p = load_problem(pid)
    chosen = [(g, 1) for g in p.groups if g.name != "sample"]
    q = selection(p, chosen)
    q.__dict__["_tests"] = [t for t in q.tests() if t.input_text.count("\n") <= SMALL_LINES]
    return q


@functools.lru_cache(maxsize=None)
def _needles(pid: str) -> frozenset:
    return frozenset(_numbers(hidden_only(pid)))


def needles(problem) -> frozenset:
    return _needles(problem.id)


def _numbers(problem) -> set[str]:
    """Every number of the hidden tests' .in/.ans, in the forms a message could use."""
    out: set[str] = set()
    for t in problem.tests():
        for tok in (t.input_text + " " + (t.answer_text or "")).split():
            try:
                f = float(tok)
            except ValueError:
                continue
            forms = {tok, repr(f), f.hex(), f"{f:.6g}"}
            if f.is_integer() and abs(f) < 1e18:
                forms.add(str(int(f)))
            out |= {s for s in forms if len(s.lstrip("-")) >= 4}
    return out


def feedback_text(nb) -> str:
    parts = []
    for cell in nb.cells:
        for o in cell.get("outputs", []):
            parts += [o.get("text", ""), o.get("ename", ""), o.get("evalue", ""), *o.get("traceback", [])]
    return "\n".join(parts)


@functools.lru_cache(maxsize=None)
def _notebook_text(pid: str) -> str:
    return (REPO / "assignments" / "source" / pid / f"{pid}.ipynb").read_text()


@contextlib.contextmanager
def policy(problem, level: str):
    """``problem`` with every group at feedback ``level`` (as its course.yaml would set it)."""
    saved = problem.feedback
    problem.feedback = resolve(problem.id, {"hidden": level}, {g.name: g.public for g in problem.groups})
    try:
        yield problem
    finally:
        problem.feedback = saved


def notebook_feedback(problem, result: JudgeResult) -> str:
    """The test-cell outputs of the problem's notebook with ``result`` written in, scored groups only."""
    nb = nbformat.reads(_notebook_text(problem.id), as_version=4)
    scored = {g.name for g in problem.groups if g.points > 0}
    text = feedback_text(write_results(nb, problem, result))
    # the check cell's sample table is public by design; the rest must hold nothing hidden
    groups = [group_output(result, g.name, g.points, problem.feedback_level(g.name))
              for g in problem.groups if g.name in scored]
    return text + "\n" + "\n".join(feedback_text(nbformat.from_dict({"cells": [{"outputs": [o]}]})) for o in groups)


def leaks(problem, feedback: str, frame: str) -> list[str]:
    return sorted(n for n in needles(problem) if n in feedback and n not in frame)


def frame_of(problem, result: JudgeResult) -> str:
    """The feedback of the same tests with every message blank: the numbers the frame itself holds."""
    blank = [TestResult(t.name, t.group, t.verdict, t.time_s, t.memory_mb) for t in result.tests]
    return notebook_feedback(problem, JudgeResult(problem.id, "x", blank, problem.group_points))


def perturbed(answer) -> list:
    """Wrong answers near the reference one."""
    data = json.loads(json.dumps(answer, allow_nan=True))
    out = []
    if isinstance(data, list) and data:
        out += [data[:-1], data + data[:1], data[::-1][:1] + data[1:], [data[0]] * len(data)]
        if isinstance(data[0], list):
            out.append([row[::-1] for row in data])
            out.append([[10 ** 6] + row[1:] if row else row for row in data])
            out.append([[(v * 1.001 + 1e-3 if type(v) is float else v) for v in row] for row in data])
            out.append([[(v + 1 if type(v) is int else v) for v in row] for row in data])
        else:
            out.append([(v * 1.001 + 1e-3 if type(v) is float else v) for v in data])
            out.append([(v + 1 if type(v) is int else v) for v in data])
    elif type(data) is float:
        out += [data * 1.001 + 1e-3, data / 2, 0.0]
    elif data is None:
        out.append([[0.0, 0.0]])
    return out


@pytest.mark.parametrize("pid", PROBLEMS)
def test_checker_failure_messages_never_reach_hidden_feedback(pid):
    problem = hidden_only(pid)
    judge = Judge(problem)
    results = []
    for k, test in enumerate(problem.tests()):
        args, expected = judge._test_data(k)
        for value in [*perturbed(expected), *HOSTILE_VALUES[:20]]:
            r = TestResult(test.name, test.group, Verdict.JE)
            judge._check(r, value, args, expected, function_mode=True)
            if r.verdict != Verdict.AC:
                results.append(r)
    assert {str(r.verdict) for r in results} >= {"WA", "PE"} or pid == "dynamic-network", "the answers must fail"
    if pid in QUOTES_COORDINATES:  # the details quote the test, so the search below would find a leak
        assert any(leaks(problem, r.message, "") for r in results), [r.message[:100] for r in results[:5]]
    # one result per test and message: each is put in its group's cell in turn, at every level
    for level in HIDDEN_LEVELS:
        with policy(problem, level):
            for r in results:
                result = JudgeResult(problem.id, "x", [r], problem.group_points)
                feedback = notebook_feedback(problem, result)
                assert leaks(problem, feedback, frame_of(problem, result)) == [], (level, r.message[:200],
                                                                                   r.hidden_message)


LEAKY = '''
import base64, json, sys

def {entry}(*args):
    data = json.dumps(args)
    flat = []
    def walk(v):
        if isinstance(v, (list, tuple)):
            for w in v:
                walk(w)
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            flat.append(float(v))
    walk(args)
    print("my input:", data[:1500], [x.hex() for x in flat[:40]])
    print(base64.b64encode(data.encode()).decode()[:500], file=sys.stderr)
    MODE
'''

MODES = {
    "repr": 'raise ValueError(repr(args)[:1800])',
    "hex": 'raise RuntimeError(" ".join(x.hex() for x in flat[:60]))',
    "json": 'raise KeyError(data[:1800])',
    "class_name": 'raise type("E_" + "_".join(str(abs(int(x * 1000))) for x in flat[:12]), (Exception,), {})("x")',
    "own_source": '''import os
    with open(os.path.basename(__file__) if "__file__" in globals() else "attack.py", "w") as f:
        f.write("\\n".join([repr(flat[:20])] * 40))
    raise ValueError("see the line")''',
    "wrong_answer_with_prints": 'return []',
}


@pytest.mark.parametrize("pid,entry", [("delaunay", "delaunay"), ("largest-empty-circle", "largest_empty_circle"),
                                       ("navmesh", "shortest_path")])
@pytest.mark.parametrize("mode", sorted(MODES))
def test_submission_that_encodes_its_inputs_leaks_nothing(pid, entry, mode):
    problem = hidden_only(pid)
    source = textwrap.dedent(LEAKY).replace("{entry}", entry).replace("MODE", MODES[mode])
    result = Judge(problem).judge(Submission.from_source(source, "attack.py"), "attack.py")
    failing = [t for t in result.tests if t.verdict not in (Verdict.AC, Verdict.SKIPPED)]
    assert failing and Verdict.JE not in {t.verdict for t in result.tests}, [t.message[:200] for t in result.tests]
    if mode != "wrong_answer_with_prints":
        assert failing[0].verdict == Verdict.RE, failing[0].message[:300]
        assert "your own class" in failing[0].hidden_message or mode != "class_name"
    # the detail has the data (so the test would see a leak), the hidden feedback does not
    assert leaks(problem, "\n".join(t.message for t in failing), "") != [] or mode == "class_name"
    for level in HIDDEN_LEVELS:
        with policy(problem, level):
            feedback = notebook_feedback(problem, result)
            assert leaks(problem, feedback, frame_of(problem, result)) == [], (level, feedback[:2000])


def test_levels_that_show_data_are_refused_on_hidden_groups():
    groups = {g.name: g.public for g in load_problem("delaunay").groups}
    shows_data = [name for name, level in LEVELS.items() if not level.hidden_ok]
    assert shows_data
    for level in shows_data:
        with pytest.raises(ValueError, match="shows test data: group 'large' is hidden"):
            resolve("delaunay", {"groups": {"large": level}}, groups)
        with pytest.raises(ValueError, match="shows test data"):
            resolve("delaunay", {"hidden": level}, groups)
    with pytest.raises(ValueError, match="unknown level 'everything'"):
        resolve("delaunay", {"public": "everything"}, groups)
    with pytest.raises(ValueError, match="unknown group"):
        resolve("delaunay", {"groups": {"nope": "verdict"}}, groups)


def test_levels_on_a_public_group_and_a_hidden_one():
    """``input`` puts the failing sample's input in the check cell; ``verdict`` drops the messages."""
    problem = load_problem("delaunay")
    sample = next(t for t in problem.tests() if t.group == "sample")
    hidden = next(g for g in problem.groups if g.points > 0)
    bad = TestResult(sample.name, "sample", Verdict.WA, 0.1, 1.0, "triangle 0 is not Delaunay", sample.input_text[:200])
    hid = TestResult(f"{hidden.name}/01", hidden.name, Verdict.WA, 0.1, 1.0, "point (0.25, 3.5) is inside",
                     "", "a point lies inside a triangle's circumcircle")
    result = JudgeResult(problem.id, "x", [bad, hid], problem.group_points)
    texts = {}
    for raw in ({}, {"public": "input"}, {"public": "verdict", "hidden": "verdict"}):
        problem.feedback = resolve(problem.id, raw, {g.name: g.public for g in problem.groups})
        texts[str(raw)] = notebook_feedback(problem, result)
    default, shown, terse = texts.values()
    first_line = sample.input_text.splitlines()[1]
    assert "triangle 0 is not Delaunay" in default and first_line not in default.split("samples, as judged")[1]
    assert "input:" in shown and first_line in shown
    assert "a point lies inside" in default and "a point lies inside" not in terse
    assert "triangle 0 is not Delaunay" not in terse and "0.25" not in default + shown + terse


def test_needles_include_every_form():
    p = hidden_only("largest-empty-circle")
    x = float(p.tests()[0].input_text.split()[1])
    assert {repr(x), x.hex()} <= needles(p) | {repr(x)[:3]}
    assert base64  # the encodings above are the submission's, not the test's



@pytest.mark.parametrize("pid,entry", [("delaunay", "delaunay"), ("largest-empty-circle", "largest_empty_circle"),
                                       ("navmesh", "shortest_path")])
def test_a_counterexample_in_the_feedback_and_the_json_leaks_nothing(pid, entry, tmp_path):
    """The counterexample search's input, answer and reason (grader/contest/counterexample.py) are
    the grader's own small input: the feedback and ``--json`` with them hold no number of the
    hidden tests, and the input is none of the problem's tests."""
    from grader.contest.counterexample import attach, hidden_inputs
    from grader.contest.stress import normalized

    problem = hidden_only(pid)
    path = tmp_path / "attack.py"
    path.write_text(textwrap.dedent(LEAKY).replace("{entry}", entry).replace("MODE", MODES["repr"]))
    result = Judge(problem, hide=[str(tmp_path)]).judge_path(path)
    full = load_problem(pid)
    found = attach(result, full, path, seconds=20)
    assert found is not None and found.verdict == "RE", result.extra
    assert normalized(found.input) not in hidden_inputs(full)
    # the counterexample's own numbers (the submission prints them as hex, repr, ...) are its to show
    own = " ".join(form for tok in found.input.split() for form in _forms(tok))
    # the search's wall time is the grader's own measurement: "seconds": 10.614 once matched a
    # hidden number's first digits ("0.61"), so it is left out of the text searched for leaks
    groups = result.to_json()["groups"]
    for g in groups:
        if g.get("counterexample"):
            g["counterexample"] = {k: v for k, v in g["counterexample"].items() if k != "seconds"}
    assert leaks(problem, json.dumps(groups), own) == []
    for level in HIDDEN_LEVELS:
        with policy(problem, level):
            feedback = notebook_feedback(problem, result)
            assert "a small input your code also gets wrong" in feedback
            assert leaks(problem, feedback, frame_of(problem, result) + own) == [], (level, feedback[:2000])


def _forms(tok: str) -> set[str]:
    """The forms of one number a message could use (as :func:`_numbers` lists them)."""
    try:
        f = float(tok)
    except ValueError:
        return set()
    forms = {tok, repr(f), f.hex(), f"{f:.6g}", json.dumps(f)}
    if f.is_integer() and abs(f) < 1e18:
        forms.add(str(int(f)))
    return forms
