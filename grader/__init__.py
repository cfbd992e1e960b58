"""The course judge: sandboxed, contest-grade grading of student code (``python -m grader``).

Public API:

* :func:`load_problem`, :func:`list_problems` - problem packages under ``assignments/``;
* :class:`Judge`, :func:`judge_file` - judge a submission, get a :class:`JudgeResult`;
* :class:`Verdict` - AC, WA, PE, TLE, MLE, OLE, RE, CE, SV, JE;
* :func:`check_certificate` - recompute a counterexample's exact certificate and draw it.

Example:
    >>> from grader import judge_file
    >>> judge_file("delaunay", "solutions/delaunay/accepted_walk.py").verdict   # doctest: +SKIP
    'AC'
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # the names below are imported on first use: ``import grader`` stays light
    from .contest.judge import Judge, judge_file
    from .judging.verdicts import JudgeResult, TestResult, Verdict
    from .problems import Problem, list_problems, load_problem
    from .contest.certificate import check_certificate

_WHERE = {"Judge": ".contest.judge", "judge_file": ".contest.judge", "Problem": ".problems",
          "list_problems": ".problems", "load_problem": ".problems", "JudgeResult": ".judging.verdicts",
          "TestResult": ".judging.verdicts", "Verdict": ".judging.verdicts",
          "check_certificate": ".contest.certificate"}

__all__ = ["Judge", "judge_file", "Problem", "list_problems", "load_problem", "JudgeResult", "TestResult", "Verdict",
           "check_certificate"]


def __getattr__(name: str) -> Any:
    """The public names, imported when first used (a command that lists problems never loads the jail)."""
    if name not in _WHERE:
        raise AttributeError(f"module 'grader' has no attribute {name!r}")
    value = getattr(importlib.import_module(_WHERE[name], __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
