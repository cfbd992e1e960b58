"""The course judge: sandboxed, contest-grade grading of student code (``python -m grader``).

Public API:

* :func:`load_problem`, :func:`list_problems` - problem packages under ``assignments/``;
* :class:`Judge`, :func:`judge_file` - judge a submission, get a :class:`JudgeResult`;
* :class:`Verdict` - AC, WA, PE, TLE, MLE, OLE, RE, CE, SV, JE.

Example:
    >>> from grader import judge_file
    >>> judge_file("delaunay", "solutions/delaunay/accepted_walk.py").verdict   # doctest: +SKIP
    'AC'
"""

from .contest.judge import Judge, judge_file
from .problems import Problem, list_problems, load_problem
from .judging.verdicts import JudgeResult, TestResult, Verdict

__all__ = ["Judge", "judge_file", "Problem", "list_problems", "load_problem", "JudgeResult", "TestResult", "Verdict"]
