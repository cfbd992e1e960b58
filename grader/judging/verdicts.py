"""Verdicts and scoring: per-test results, per-group points, the overall verdict.

Example:
    >>> t = TestResult("tiny/1", "tiny", Verdict.AC, 0.01)
    >>> r = JudgeResult("delaunay", "s.py", [t], {"tiny": 20})
    >>> (r.verdict, r.score, r.max_score)
    ('AC', 20, 20)
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field
from enum import Enum
from typing import Any


class Verdict(str, Enum):
    """Fixed verdict names. ``JE`` is only for faults of the judge itself."""

    AC = "AC"  # accepted
    WA = "WA"  # wrong answer
    PE = "PE"  # output of the wrong shape or type
    TLE = "TLE"  # time limit exceeded
    MLE = "MLE"  # memory limit exceeded
    OLE = "OLE"  # output limit exceeded
    RE = "RE"  # run-time error
    CE = "CE"  # syntax or import error, missing entry
    SV = "SV"  # security violation: forbidden import or operation
    JE = "JE"  # judge error
    SKIPPED = "--"  # not run: an earlier test of the same group failed

    def __str__(self) -> str:
        return self.value


DESCRIPTIONS = {
    "AC": "accepted", "WA": "wrong answer", "PE": "presentation error (wrong shape or type)",
    "TLE": "time limit exceeded", "MLE": "memory limit exceeded", "OLE": "output limit exceeded",
    "RE": "run-time error", "CE": "compile error (syntax, import, missing entry)",
    "SV": "security violation (forbidden import or operation)", "JE": "judge error", "--": "skipped",
}


@dataclass
class TestResult:
    """One test's outcome. ``input_preview`` is the failing input for small tests (for students).
    ``message`` is the detail (instructor, reports, public tests); ``hidden_message`` what a student
    may see when the test is hidden (:mod:`grader.judging.hidden_feedback`; empty: the verdict's description).
    ``stderr``: the end of what the submission wrote to stderr in a failing test, kept only by a
    judge that asks for it (``Judge(stderr_lines=...)``, as ``stress`` does); in JSON only when set."""

    __test__ = False  # not a pytest test class

    name: str
    group: str
    verdict: Verdict
    time_s: float = 0.0
    memory_mb: float = 0.0
    message: str = ""
    input_preview: str = ""
    hidden_message: str = ""
    received: Any = field(default=None, repr=False, compare=False)  #: a wrong answer, for reports only
    stderr: str = field(default="", repr=False)
    #: a failing test's answer as the submission gave it, as text (capped; the counterexample
    #: search shows it): not in JSON, not stored
    answer: str = field(default="", repr=False, compare=False)

    def to_json(self) -> dict:
        d = asdict(self)
        d.pop("received")
        d.pop("answer")
        if not self.stderr:
            d.pop("stderr")
        d["verdict"] = str(self.verdict)
        return d

    @classmethod
    def from_json(cls, d: dict) -> "TestResult":
        keys = {"name", "group", "verdict", "time_s", "memory_mb", "message", "input_preview", "hidden_message",
                "stderr"}
        return cls(**{k: v for k, v in d.items() if k in keys and k != "verdict"}, verdict=Verdict(d["verdict"]))


@dataclass
class JudgeResult:
    """All tests of one submission to one problem, with scoring by group."""

    problem: str
    submission: str
    tests: list[TestResult]
    group_points: dict[str, int]
    mode: str = ""
    judge_time_s: float = 0.0
    extra: dict = field(default_factory=dict)
    #: group -> a small input the submission fails (``Counterexample.to_json()``), or None when a
    #: search ran for that group and found none; groups not searched are absent
    #: (:mod:`grader.contest.counterexample`)
    counterexamples: dict[str, dict | None] = field(default_factory=dict)

    @property
    def verdict(self) -> str:
        """The first non-AC (non-skipped) test's verdict, else AC."""
        for t in self.tests:
            if t.verdict not in (Verdict.AC, Verdict.SKIPPED):
                return str(t.verdict)
        return "AC" if self.tests else "JE"

    def group_passed(self, group: str) -> bool:
        ts = [t for t in self.tests if t.group == group]
        return bool(ts) and all(t.verdict == Verdict.AC for t in ts)

    @property
    def score(self) -> int:
        return sum(p for g, p in self.group_points.items() if self.group_passed(g))

    @property
    def max_score(self) -> int:
        return sum(self.group_points.values())

    def to_json(self) -> dict:
        """The ``--json`` object: problem, verdict, score, max_score, tests (name, group, verdict, time_s...)."""
        return {
            "problem": self.problem, "submission": self.submission, "verdict": self.verdict,
            "score": self.score, "max_score": self.max_score, "mode": self.mode,
            "groups": [{"name": g, "points": p, "passed": self.group_passed(g),
                        **({"counterexample": self.counterexamples[g]} if g in self.counterexamples else {})}
                       for g, p in self.group_points.items()],
            "tests": [t.to_json() for t in self.tests], "judge_time_s": round(self.judge_time_s, 3),
            "sandbox": _sandbox_mechanism(), **self.extra,
        }


def _sandbox_mechanism() -> str:
    """Which jail judged (``bwrap+cgroup-v1+seccomp``, ``namespaces+...``, ``rlimits``)."""
    from ..jail import mechanism  # late: verdicts stays importable without the sandbox
    return mechanism()


FAILURES_SHOWN = 12  #: failing tests described below the table (each with its input when small)
MESSAGE_SHOWN = 3000


def format_table(result: JudgeResult) -> str:
    """A readable per-test table (the default output of ``python -m grader judge``)."""
    rows = [("test", "verdict", "time", "memory", "message")]
    for t in result.tests:
        rows.append((t.name, str(t.verdict), f"{t.time_s:.3f}s", f"{t.memory_mb:.0f}MB" if t.memory_mb else "-",
                     t.message.splitlines()[0][:90] if t.message else ""))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    lines = ["  ".join(c.ljust(w) for c, w in zip(r[:4], widths)) + "  " + r[4] for r in rows]
    lines.insert(1, "-" * min(120, sum(widths) + 8 + 20))
    groups = ", ".join(f"{g} {'passed' if result.group_passed(g) else 'failed'} ({p})"
                       for g, p in result.group_points.items())
    lines.append("")
    lines.append(f"{result.problem}: {result.verdict} ({DESCRIPTIONS.get(result.verdict, '')}), "
                 f"score {result.score}/{result.max_score}  [{groups}]")
    bad = [t for t in result.tests if t.verdict not in (Verdict.AC, Verdict.SKIPPED)]
    shown: set[str] = set()
    for k, t in enumerate(bad):
        if len(shown) == FAILURES_SHOWN:
            lines.append(f"... {len(bad) - k} more failing tests (all of them: --json or --report)")
            break
        if t.message in shown and not t.input_preview:  # e.g. a compile error: once is enough
            continue
        shown.add(t.message)
        lines.append(f"{'first failure' if k == 0 else 'also failed'}: {t.name}: {t.message[:MESSAGE_SHOWN]}")
        if t.input_preview:
            lines.append("its input:\n" + t.input_preview.rstrip("\n"))
    lines += counterexample_lines(result)
    return "\n".join(lines)


CX_ANSWER_LINES = 12  #: the table shows this many lines of the answer to a counterexample


def counterexample_lines(result: JudgeResult) -> list[str]:
    """The table's lines about the counterexample search (:mod:`grader.contest.counterexample`):
    the input, the submission's answer, why it is wrong; or that none was found."""
    if not result.counterexamples:
        return []
    found = {g: c for g, c in result.counterexamples.items() if c}
    if not found:
        note = (result.extra.get("counterexample_search") or {}).get("note", "")
        return ["", f"counterexample search: {note or 'no failing input found among small public inputs'}"]
    cx = next(iter(found.values()))
    answer = cx["answer"].rstrip("\n").splitlines() or ["(nothing)"]
    if len(answer) > CX_ANSWER_LINES:
        answer = answer[:CX_ANSWER_LINES] + [f"... ({len(answer) - CX_ANSWER_LINES} more lines)"]
    out = ["", f"a small input your program also gets wrong ({cx['verdict']}, {cx['size']} elements; "
               f"for {', '.join(found)}; found in {cx['seconds']:.1f} s, not a test of the problem):",
           cx["input"].rstrip("\n"), "your answer:", *answer, f"why: {cx['reason'][:MESSAGE_SHOWN]}"]
    if cx.get("certificate"):
        out.append(f"certificate: {json.dumps(cx['certificate'])[:MESSAGE_SHOWN]}")
    return out
