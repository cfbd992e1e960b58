"""HTML reports: the caption holds the whole message, tests that did not run show "-", the
picture highlights what the message names, the drawing is bounded for a forged huge answer.

Run: .venv/bin/python -m pytest tests/grader/test_report.py -q
"""
from __future__ import annotations

import base64
import re

from grader.contest import report
from grader.problems import Problem
from grader.judging.verdicts import JudgeResult, TestResult, Verdict

from .conftest import FIXTURE_PROBLEM

PROBLEM = Problem.load(FIXTURE_PROBLEM)
FIRST = PROBLEM.tests()[0]  # tiny/1-tutorial: 4 points


def _result(received, message: str) -> JudgeResult:
    bad = TestResult(FIRST.name, "tiny", Verdict.WA, 0.01, 31.0, message)
    bad.received = received
    skipped = TestResult("tiny/02", "tiny", Verdict.SKIPPED, message="an earlier test of this group failed")
    return JudgeResult(PROBLEM.id, "x.py", [bad, skipped], PROBLEM.group_points, mode="function")


def _png(page: str) -> bytes:
    return base64.b64decode(re.search(r"base64,([A-Za-z0-9+/=]+)", page).group(1))


def test_caption_keeps_the_whole_message():
    msg = ("triangle 0 = (0, 2, 1) is clockwise; triangles must be counter-clockwise "
           "(a valid answer has 3 triangles, you gave 1)")
    text = report.caption("tiny/1-tutorial", msg)
    assert text.replace("\n", " ").endswith("you gave 1)") and "\n" in text


def test_skipped_tests_show_a_dash_not_memory_zero():
    page = report.render(_result([[0, 2, 1]], "triangle 0 = (0, 2, 1) is clockwise"), PROBLEM)
    row = re.search(r"<tr class='bad'><td>tiny/02</td>(.*?)</tr>", page).group(1)
    assert "<td>-</td><td>-</td>" in row and "<td>0</td>" not in row


def test_message_names_are_parsed_and_highlighted():
    assert report.parse_hint("edge 1-3 is not Delaunay: point 2 is strictly inside", []) == \
        {"triangles": [], "edges": [[1, 3]], "points": [2]}
    assert report.parse_hint("triangle 1 is degenerate", [[0, 1, 2], [1, 2, 3]])["triangles"] == [[1, 2, 3]]
    plain = _png(report.render(_result([[0, 1, 3]], "the answer is wrong"), PROBLEM))
    marked = _png(report.render(_result([[0, 1, 3]], "triangle 0 = (0, 1, 3) is not Delaunay"), PROBLEM))
    assert plain != marked  # the highlight changes the picture


def test_checker_hint_protocol_is_optional(monkeypatch):
    calls = []
    monkeypatch.setattr(PROBLEM.checker, "hint", lambda m, a, r: calls.append(m) or {"points": [1]}, raising=False)
    report.render(_result([[0, 1, 3]], "whatever the checker says"), PROBLEM)
    assert calls == ["whatever the checker says"]
    monkeypatch.setattr(PROBLEM.checker, "hint", lambda m, a, r: 1 / 0, raising=False)  # a broken hint is ignored
    assert "data:image/png" in report.render(_result([[0, 1, 3]], "x"), PROBLEM)


def test_a_forged_huge_answer_is_drawn_bounded(monkeypatch):
    drawn = []
    real = PROBLEM.checker.draw
    monkeypatch.setattr(PROBLEM.checker, "draw", lambda ax, a, r, e: drawn.append(len(r)) or real(ax, a, r, e))
    huge = [[0, 1, 2]] * 2_000_000
    page = report.render(_result(huge, "the directed edge 0->1 is used by 2000000 triangles"), PROBLEM)
    assert drawn == [report.MAX_DRAW_ITEMS] and "data:image/png" in page
    assert len(page) < 1_000_000 and f"{2_000_000 - report.MAX_DRAW_ITEMS:,} elements of the received answer not drawn" in page


def test_first_failing_test_is_the_judges_first_failure_and_columns_follow_group_order():
    """The heading names the first failure in the judge's order (a TLE here), not a later WA
    that has a stored answer; index columns sort by the problem's group order, not alphabetically."""
    from grader.problems import load_problem

    p = load_problem("delaunay")
    tests = [TestResult("tiny/01", "tiny", Verdict.AC, 0.1, 1, ""),
             TestResult("degenerate/03", "degenerate", Verdict.TLE, 6.0, 1, "time limit"),
             TestResult("medium/01", "medium", Verdict.WA, 0.1, 1, "wrong", received=[[0, 1, 2]])]
    page = report.render(JudgeResult(p.id, "x.py", tests, p.group_points), p)
    assert "First failing test: degenerate/03 (TLE)" in page and "First failing test: medium/01" not in page
    order = [g.name for g in p.groups]
    names = sorted(["tiny/02", "degenerate/01", "sample/01", "large/01", "exhaustive/01"], key=report._test_order(p.id))
    assert [n.split("/")[0] for n in names] == [g for g in order if g in {n.split("/")[0] for n in names}]
