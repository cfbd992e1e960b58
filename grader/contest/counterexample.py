"""A small input the submission gets wrong, for a failing group's feedback: the counterexample search.

When a submission fails a group with a wrong answer (``WA``), an answer of the wrong shape (``PE``)
or a run-time error (``RE``), the judge may look for a small input of its own that the
submission fails too, and show it with the student's answer and the checker's reason: the hidden
input stays hidden, and the student still gets something to debug. The search is
:func:`grader.contest.stress.stress` (same batches, same sandbox and limits, each failure judged
again alone, then shrunk) on **public families only**: the lattice configurations of
:mod:`grader.problems.smallcases` in another order than the ``exhaustive`` group lists them, in
turn with the families of :mod:`grader.problems.families` (small inputs scaled, shifted far out,
nudged by one ulp off a degenerate configuration, nearly flat, beyond a finite super-triangle:
where floating point fails), then :func:`grader.contest.stress.random_case` inputs that grow
with time. Never hidden data: an input
that reads the same as any test of the problem (hidden or sample; compared by
:func:`grader.contest.stress.normalized` text) is never judged, and the result is checked again
before it is returned. A solution that is only slow never gets one (TLE is never a
counterexample), and a correct one costs nothing: nothing is searched unless a group failed.

Budget: ``feedback: {counterexample: true, counterexample_seconds: 10}`` in a problem's
``course.yaml`` (:mod:`grader.judging.feedback_policy`; on, 10 s by default); one search per
submission, shared by all its failing groups. The counterexample goes to every failing group
whose failing verdict is the counterexample's own, or, when none is, to the first group that
failed with WA, PE or RE (``JudgeResult.counterexamples``; ``--json``: a ``counterexample``
object in the group's entry, ``null`` when the search found nothing).

Run:
    python -m grader judge emst solutions/emst/wrong_collinear_sort_x.py --counterexample-seconds 10

Example:
    >>> cx = search("emst", "solutions/emst/wrong_collinear_sort_x.py", seconds=10)  # doctest: +SKIP
    >>> cx.size <= 10, cx.verdict, sorted(cx.to_json())                           # doctest: +SKIP
    (True, 'WA', ['answer', 'certificate', 'input', 'reason', 'seconds', 'size', 'verdict'])
"""
from __future__ import annotations

import random
import time
from dataclasses import dataclass
from pathlib import Path

from ..judging.text import clean
from ..judging.verdicts import JudgeResult, Verdict
from ..problems import Problem, families, load_problem, smallcases
from . import stress as engine

__all__ = ["Counterexample", "search", "attach", "TRIGGERS", "hidden_inputs", "public_first_cases"]

TRIGGERS = frozenset({Verdict.WA, Verdict.PE, Verdict.RE})
"""The failing verdicts that start a search and that a counterexample may have (never TLE)."""
REASON_MAX_CHARS = 1000
INPUT_MAX_CHARS = 20_000
"""A counterexample is at most this long (the search's inputs are far smaller): only tests this
short need comparing, so a problem's large hidden tests are never even read for it."""
RANDOM_BASES = 8
"""Random small cases (:func:`grader.contest.stress.random_case`) whose scaled and shifted copies join the families."""


@dataclass
class Counterexample:
    """A small input the submission fails: ``input`` (the problem's input text), ``answer`` (the
    submission's answer as output text, capped), ``reason`` (the checker's message or the error),
    ``verdict`` (WA, PE or RE), ``certificate`` (an exact proof that the answer is wrong, or
    None), ``seconds`` (the search's wall time) and ``size`` (points; polygon vertices for
    navmesh; operations for dynamic-network)."""

    input: str
    answer: str
    reason: str
    verdict: str
    certificate: dict | None
    seconds: float
    size: int

    def to_json(self) -> dict:
        """JSON-native: ``input, answer, reason, certificate, seconds, verdict, size``."""
        return {"input": self.input, "answer": self.answer, "reason": self.reason, "certificate": self.certificate,
                "seconds": round(self.seconds, 3), "verdict": self.verdict, "size": self.size}


def _certificate(problem_id: str, input_text: str, answer_text: str) -> dict | None:
    """An exact certificate that ``answer_text`` is wrong for ``input_text``
    (:func:`grader.contest.certificate.certify`), or None: for a problem it has no rules for (a
    course's own), an answer it cannot read, or a fault of its own (feedback never crashes a
    grading for want of a certificate)."""
    from .certificate import certify   # its rules load only when a counterexample is found
    try:
        return certify(problem_id, input_text, answer_text)
    except Exception:  # noqa: BLE001 - an unknown problem (ValueError) or a fault: no certificate
        return None


def size_of(case: dict) -> int:
    """The size of a generator case: its operations, else its polygon vertices (boundary and
    holes), else its points.

    >>> size_of({"kind": "points", "points": [[0, 0], [1, 1]]})
    2
    >>> size_of({"kind": "room", "boundary": [[0, 0], [4, 0], [0, 4]], "holes": [[[1, 1], [2, 1], [1, 2]]]})
    6
    """
    return families.size_of(case)


def hidden_inputs(problem: Problem) -> frozenset[str]:
    """The normalized input of every test of ``problem`` (hidden and sample) up to
    :data:`INPUT_MAX_CHARS` long: never a counterexample (a longer input never is one either)."""
    return frozenset(engine.normalized(t.input_text) for t in problem.tests() if len(t.input_text) <= INPUT_MAX_CHARS)


def public_first_cases(problem: Problem, seed: int = 1) -> list[dict]:
    """The first inputs to try, public code only, deterministic given ``seed``: the families of
    :mod:`grader.problems.families` (small inputs scaled, shifted, nudged by one ulp, nearly flat
    or far out, and transforms of :data:`RANDOM_BASES` random small cases) taken in turn with the
    lattice configurations of :mod:`grader.problems.smallcases`, each with its points in the
    reverse order so that they are not the ``exhaustive`` group's tests (so neither kind of
    mistake waits for the other); none for a problem neither module knows."""
    try:
        cases = smallcases.cases_for(problem.id)
    except ValueError:
        cases = []
    lattice = [{**c, "points": c["points"][::-1]} if isinstance(c.get("points"), list) else c for c in cases]
    rng = random.Random(seed)
    bases = [engine.random_case(problem.id, rng, 6) for _ in range(RANDOM_BASES)] if lattice else []
    return families.interleave(families.families(problem.id, seed, bases), lattice)


def search(problem: Problem | str, path: str | Path, seconds: float = 10.0, seed: int = 1, *,
           trusted: bool | None = None, build_from=None, build_store: str | None = None) -> Counterexample | None:
    """A small input (public families only, shrunk) that the submission at ``path`` fails with WA,
    PE or RE, found within ``seconds`` (plus one test's limits), or None. Never the input of a
    test of the problem. ``ValueError`` when the problem has no generator (its reference
    answers) or ``path`` is not a file. ``trusted``: as :class:`grader.contest.judge.Judge`'s.
    ``build_from``: a judge that kept its build of ``path`` (a C++ file is then not compiled
    again; see :func:`grader.contest.stress.stress`); ``build_store``: a folder where a judge of
    another process left its build (:meth:`grader.contest.judge.Judge.store_build`). A compile is
    not part of ``seconds``."""
    problem = load_problem(problem) if isinstance(problem, str) else problem
    if not seconds > 0:
        raise ValueError(f"counterexample search: seconds must be positive, got {seconds!r}")
    if problem.generator_path is None or not problem.generator_path.is_file():
        raise ValueError(f"problem {problem.id!r}: no counterexample search in this copy of the problem: it has no "
                         "reference answers (the generator stays with the instructor)")
    t0 = time.monotonic()
    hidden = hidden_inputs(problem)
    failure = engine.stress(problem, path, seconds, seed=seed, first=public_first_cases(problem, seed),
                            exclude=hidden, verdicts=TRIGGERS, max_chars=INPUT_MAX_CHARS, trusted=trusted,
                            build_from=build_from, build_store=build_store)
    if (failure is None or len(failure.input_text) > INPUT_MAX_CHARS
            or engine.normalized(failure.input_text) in hidden):
        return None  # the engine never judges a test's input: the second check is a guard
    return Counterexample(
        input=failure.input_text, answer=failure.answer, reason=clean(failure.message, REASON_MAX_CHARS, newlines=True),
        verdict=failure.verdict, certificate=_certificate(problem.id, failure.input_text, failure.answer),
        seconds=time.monotonic() - t0, size=size_of(failure.case))


def failing_groups(result: JudgeResult) -> dict[str, str]:
    """group -> its failing verdict, for the groups that failed with WA, PE or RE (in order)."""
    out: dict[str, str] = {}
    for t in result.tests:
        if t.group not in out and t.verdict not in (Verdict.AC, Verdict.SKIPPED):
            out[t.group] = str(t.verdict)
    return {g: v for g, v in out.items() if Verdict(v) in TRIGGERS}


def attach(result: JudgeResult, problem: Problem, path: str | Path, seconds: float | None = None,
           seed: int = 1, *, trusted: bool | None = None, build_from=None,
           build_store: str | None = None) -> Counterexample | None:
    """Search once for ``result``'s submission when a group failed with WA, PE or RE, and put the
    counterexample on the failing groups (see the module's docstring); nothing when none failed
    so or the budget is 0. ``seconds``: the budget (default: the problem's ``course.yaml``).
    ``result.extra["counterexample_search"]`` says what the search did (found or not, its
    seconds, or why none ran). ``build_from``: the judge that judged ``result`` with
    :attr:`~grader.contest.judge.Judge.keep_build` set: its build is reused, not compiled again;
    ``build_store``: the folder where the judge left it (:meth:`~grader.contest.judge.Judge.store_build`)."""
    budget = problem.counterexample_seconds if seconds is None else seconds
    groups = failing_groups(result)
    if not groups or budget <= 0:
        return None
    t0 = time.monotonic()
    try:
        cx = search(problem, path, budget, seed, trusted=trusted, build_from=build_from, build_store=build_store)
    except ValueError as exc:  # no reference answers in this copy of the problem, a vanished file
        result.extra["counterexample_search"] = {"found": False, "seconds": 0.0, "note": str(exc)}
        result.counterexamples.update({g: None for g in groups})
        return None
    spent = round(time.monotonic() - t0, 3)
    note = "" if cx is not None else f"no failing input found among small public inputs in {spent:g} s"
    result.extra["counterexample_search"] = {"found": cx is not None, "seconds": spent,
                                             **({"note": note} if note else {})}
    if cx is None:
        result.counterexamples.update({g: None for g in groups})
        return None
    same = [g for g, v in groups.items() if v == cx.verdict] or [next(iter(groups))]
    result.counterexamples.update({g: cx.to_json() for g in same})
    return cx
