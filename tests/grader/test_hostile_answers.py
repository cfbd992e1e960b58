"""Issue 23's attacks on the checkers, through the real sandbox: each gets its verdict (PE, WA,
TLE), never JE, and a checker that runs away costs a TLE, not the grader.

* counts written with a superscript digit or 5000 digits (``isdigit()`` true, ``int()`` raises);
* a forged reply carrying a 401-digit integer where a coordinate or radius goes
  (``float()``/``math.isfinite`` overflow);
* navmesh's padded path: 2592 points on ``large/01`` (about five minutes of exact checking before;
  the walls' bounding boxes are now compared first), on the shortest path (AC) and off it (WA);
* a checker stuck in a loop: TLE from the check's own CPU budget.
"""

from __future__ import annotations

import shutil
import textwrap

import pytest

from grader.contest.judge import Judge
from grader.contest.kattis import selection
from grader.problems import Problem, load_problem
from grader.judging.submissions import Submission
from grader.judging.verdicts import Verdict

from .conftest import REPO

#: a forged function-mode reply: the submission's own answer to the call in progress (id 1)
FORGE = """
import json, os, time
def _forge(value):
    fd = json.loads(open("/proc/self/cmdline", "rb").read().split(b"\\0")[4])["ctl_out"]
    os.write(fd, json.dumps({{"id": 1, "ok": value}}).encode() + b"\\n")
    time.sleep(30)
def {entry}(*args):
    _forge({value})
"""

STDIO = """
import sys
sys.stdin.read()
sys.stdout.write({text})
"""


def first_of(pid: str, group: str) -> Problem:
    """``pid`` with one test: the first of ``group``."""
    p = load_problem(pid)
    return selection(p, [(next(g for g in p.groups if g.name == group), 1)])


def judge_source(problem: Problem, source: str, **judge_attrs):
    judge = Judge(problem)
    for k, v in judge_attrs.items():
        setattr(judge, k, v)
    return judge.judge(Submission.from_source(textwrap.dedent(source), "attack.py"), "attack.py")


def verdicts(result) -> list[str]:
    return [str(t.verdict) for t in result.tests]


@pytest.mark.parametrize("pid", ["delaunay", "bowyer-watson-timed"])
@pytest.mark.parametrize("text", ["'\\u00b2\\n0 1 2\\n'", "'5' * 5000 + '\\n'", "'\\u0661\\n0 1 2\\n'"])
def test_crafted_counts_are_pe(pid, text):
    result = judge_source(first_of(pid, "tiny" if pid == "delaunay" else load_problem(pid).groups[1].name),
                          STDIO.format(text=text))
    assert verdicts(result) == ["PE"], [t.message for t in result.tests]


@pytest.mark.parametrize("pid,entry,value", [
    ("largest-empty-circle", "largest_empty_circle", "[10 ** 401, 0.0, 1.0]"),
    ("largest-empty-circle", "largest_empty_circle", "[0.0, 0.0, -(10 ** 401)]"),
    ("obstacle-clearance", "max_clearance", "10 ** 401"),
    ("voronoi", "voronoi_cells", "[[[10 ** 401, 0.0], [1.0, 0.0], [0.0, 1.0]]] * len(args[0])"),
    ("navmesh", "shortest_path", "[args[2], [10 ** 401, 0.0], args[3]]"),
    ("delaunay", "delaunay", "[[10 ** 401, 1, 2]]"),
    ("closest-pair", "closest_pair", "[10 ** 401, 0]"),
    ("dynamic-network", "process", "[10 ** 401] * len(args[0])"),
])
def test_forged_replies_with_huge_integers_are_pe_or_wa(pid, entry, value):
    group = next(g.name for g in load_problem(pid).groups if g.points > 0)
    result = judge_source(first_of(pid, group), FORGE.format(entry=entry, value=value))
    assert verdicts(result)[0] in ("PE", "WA"), [t.message for t in result.tests]


@pytest.mark.parametrize("text", ["'1\\n' + '1' * 401 + ' 0\\n'", "'\\u00b3\\n'", "'2\\n' + '9' * 5000 + ' 0\\n0 0\\n'"])
def test_navmesh_crafted_text_is_pe(text):
    result = judge_source(first_of("navmesh", "tiny"), STDIO.format(text=text))
    assert verdicts(result) == ["PE"], [t.message for t in result.tests]


PADDED = (REPO / "solutions/navmesh/accepted_visibility.py").read_text() + """

_shortest = shortest_path


def shortest_path(boundary, holes, start, goal):
    path = _shortest(boundary, holes, start, goal)
    a, b = path[0], path[1]
    limit = 2 + len(boundary) + sum(len(h) for h in holes)
    k = limit - len(path)
    off = OFF
    pad = [[a[0] + (b[0] - a[0]) * i / (k + 1) + off * (-1) ** i,
            a[1] + (b[1] - a[1]) * i / (k + 1) + off * (-1) ** i] for i in range(1, k + 1)]
    return [list(a)] + pad + [list(p) for p in path[1:]]
"""


@pytest.mark.parametrize("off,verdict", [("0.0", "AC"), ("1e-3", "WA")])
def test_navmesh_padded_path_is_checked_in_bounded_time(off, verdict):
    """A path of 2 + (number of vertices) points on large/01: the largest a checker accepts. On the
    shortest path it is a correct answer; zigzagging 1e-3 beside it, a longer one. Either way a verdict, and
    within the check's CPU budget (a TLE from the budget would fail this test)."""
    result = judge_source(first_of("navmesh", "large"), PADDED.replace("OFF", off))
    assert verdicts(result) == [verdict], [t.message[:300] for t in result.tests]


def test_a_runaway_checker_costs_a_tle_not_the_grader(tmp_path):
    """A checker bug (here: an endless loop in check) is stopped by the check's CPU budget."""
    dest = tmp_path / "loop"
    shutil.copytree(REPO / "tests/grader/fixtures/tiny-delaunay", dest)
    checker = REPO / "assignments/delaunay/output_validator/checker.py"
    looping = dest / "checker.py"
    looping.write_text(checker.read_text().replace("    (points,) = args\n", "    (points,) = args\n    while True:\n        pass\n", 1))
    shutil.copytree(REPO / "reference_impl", tmp_path / "reference_impl", ignore=shutil.ignore_patterns("__pycache__"))
    course = (dest / "course.yaml").read_text()
    course = course.replace("checker: ../../../../assignments/delaunay/output_validator/checker.py", f"checker: {looping}")
    course = course.replace("generator: ../../../../", f"generator: {REPO}/")
    (dest / "course.yaml").write_text(course)
    problem = Problem.load(dest)
    accepted = (REPO / "solutions/delaunay/accepted_walk.py").read_text()
    result = judge_source(problem, accepted, check_cpu_s=1.0)
    assert result.tests[0].verdict == Verdict.TLE, [(str(t.verdict), t.message[:200]) for t in result.tests]
    assert {t.verdict for t in result.tests[1:]} <= {Verdict.SKIPPED}
    assert "grader's CPU time" in result.tests[0].message
    assert result.tests[0].hidden_message == "time limit exceeded: checking the answer took too long"
