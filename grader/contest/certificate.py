"""Exact certificates that a wrong answer is wrong, and ``check_certificate`` for students.

A counterexample (a small input a submission gets wrong) comes with a *certificate*: a short fact,
decided with exact arithmetic, that shows the submission's answer is wrong. For the Delaunay
problems it is a triangle of the answer and an input point strictly inside its circumcircle (or
the defect that stops the answer from being a triangulation); for the minimum spanning tree a
cheaper edge than the heaviest one on the tree path between its ends; for the closest pair a
closer pair; and so on (:data:`KINDS` lists every kind, per problem). A certificate is plain JSON:
point indices, input coordinates as the floats they are (JSON keeps a double exactly), and every
computed value as an exact rational ``"p/q"`` (or ``"p"``) string, never a rounded float.

``certify(problem, input_text, answer_text)`` builds one (``None`` when the answer is right or
cannot be read: then the checker's message says why); ``check_certificate(counterexample)``
recomputes it from the input and the answer, checks that it matches and draws it.

Run (prints the certificate as JSON):
    python -m grader.contest.certificate closest-pair input.txt answer.txt

Example:
    >>> c = certify("closest-pair", "3\\n0 0\\n5 0\\n0 1\\n", "0 1\\n")
    >>> c["kind"], c["closer"], c["distance2"]
    ('closer-pair', [0, 2], {'answer': '25', 'closer': '1'})
"""
from __future__ import annotations

import json
import sys
from fractions import Fraction
from typing import Any, Callable

from ..judging.checker_runtime import read_answer
from . import certificate_rules as rules

KINDS = rules.KINDS


def _problem(problem_id: str):
    from ..problems import list_problems, load_problem

    if not isinstance(problem_id, str) or not problem_id:
        raise ValueError(f"problem must be a problem id (a string), not {problem_id!r}")
    try:
        return load_problem(problem_id)
    except Exception:
        known = ", ".join(p.id for p in list_problems())
        raise ValueError(f"unknown problem {problem_id!r}: known problems are {known}") from None


def _reference(problem, args: list):
    """The reference answer in the checker's form (None when the reference refuses the input)."""
    try:
        text = problem.checker.write_output(problem.generator.solve(*args))
        return read_answer(problem.checker, text, args)
    except Exception:
        return None


_UNREADABLE = object()


def _read_answer(checker, answer_text: str, args: list):
    """The answer in the checker's form: the output text format, else the entry function's return
    value as JSON (``null`` for None); ``_UNREADABLE`` when it is neither."""
    try:
        return checker.read_output(answer_text, args)
    except Exception:
        pass
    try:
        return checker.from_result(json.loads(answer_text), args)
    except Exception:
        return _UNREADABLE


def certify(problem_id: str, input_text: str, answer_text: str) -> dict | None:
    """An exact certificate that ``answer_text`` is a wrong answer to ``input_text``, or None.

    ``problem_id`` names the problem (unknown -> ValueError); both texts are in the problem's
    text formats (the statement's input and output; the answer may also be the entry function's
    return value as JSON, e.g. ``null``). None when the checker accepts the answer, or
    when the answer cannot be read at all (the checker's message then says what is wrong with it).
    The certificate is JSON-native: ``problem``, ``kind`` (see :data:`KINDS`), ``claim`` (one
    sentence in plain words) and the indices and exact values the claim is about.

    >>> certify("closest-pair", "3\\n0 0\\n5 0\\n0 1\\n", "0 2\\n") is None
    True
    """
    problem = _problem(problem_id)
    checker = problem.checker
    if not isinstance(input_text, str) or not isinstance(answer_text, str):
        raise ValueError("input_text and answer_text must be strings (the problem's text formats)")
    try:
        args = checker.read_input(input_text)
    except Exception as e:
        raise ValueError(f"the input is not a {problem_id} input: {type(e).__name__}: {e}") from None
    answer = _read_answer(checker, answer_text, args)
    if answer is _UNREADABLE:
        return None
    expected = _reference(problem, args)
    try:
        ok, reason = checker.check(args, answer, expected)
    except Exception as e:  # a checker's WrongAnswer: a verdict, not a crash
        ok, reason = False, str(e)
    if ok:
        return None
    build: Callable[..., dict] = rules.BUILDERS[problem.id]
    cert = build(args, answer, expected, reason)
    return {"problem": problem.id, **cert}


def _as_dict(counterexample: Any) -> dict:
    if hasattr(counterexample, "to_json"):
        counterexample = counterexample.to_json()
    if not isinstance(counterexample, dict):
        raise ValueError("check_certificate needs a counterexample: a dict with 'input', 'answer' and "
                         f"'certificate' (the judge's JSON), not {type(counterexample).__name__}")
    missing = [k for k in ("input", "answer", "certificate") if k not in counterexample]
    if missing:
        raise ValueError(f"the counterexample has no {', '.join(repr(k) for k in missing)}")
    return counterexample


def check_certificate(counterexample: Any, draw: bool = True, problem: str | None = None) -> str:
    """Recompute a counterexample's certificate exactly, check it, draw it; a one-line verdict.

    ``counterexample`` is the judge's ``counterexample`` object (from ``--json``, the report or
    ``Counterexample.to_json()``): ``input``, ``answer`` and ``certificate``. The certificate is
    recomputed from the input and the answer with exact rational arithmetic; a certificate that
    does not match raises AssertionError naming the first field that differs. With ``draw`` the
    input, the answer and the witness (the circle and the point inside it, the cheaper edge, the
    closer pair...) are drawn with matplotlib.

    >>> cx = {"input": "3\\n0 0\\n5 0\\n0 1\\n", "answer": "0 1\\n",
    ...       "certificate": certify("closest-pair", "3\\n0 0\\n5 0\\n0 1\\n", "0 1\\n")}
    >>> check_certificate(cx, draw=False)
    'checked exactly (closest-pair, closer-pair): points 0 and 2 are closer (squared distance 1) than your points 0 and 1 (squared distance 25).'
    """
    cx = _as_dict(counterexample)
    given = cx["certificate"]
    if not isinstance(given, dict) or "kind" not in given:
        raise ValueError("this counterexample has no certificate to check (the search found the input, "
                         "but no exact certificate was made for it)")
    problem_id = problem or given.get("problem") or cx.get("problem")
    if not problem_id:
        raise ValueError("the certificate does not name its problem: pass problem='...'")
    again = certify(problem_id, cx["input"], cx["answer"])
    if again is None:
        raise AssertionError("recomputed: the answer is not wrong (or cannot be read): the certificate is false")
    for key in sorted(set(again) | set(given)):
        if again.get(key) != given.get(key):
            raise AssertionError(f"the certificate does not match: its {key!r} is {given.get(key)!r}, "
                                 f"recomputed exactly it is {again.get(key)!r}")
    if draw:
        _draw(problem_id, cx, again)
    return f"checked exactly ({problem_id}, {again['kind']}): {again['claim']}"


def _draw(problem_id: str, cx: dict, cert: dict):
    """The checker's picture of the input and the answer, the witness on top (returns the figure)."""
    import matplotlib.pyplot as plt

    problem = _problem(problem_id)
    checker = problem.checker
    args = checker.read_input(cx["input"])
    answer = _read_answer(checker, cx["answer"], args)
    fig, axes = plt.subplots(figsize=(6, 6))
    try:
        checker.draw(axes, args, answer, _reference(problem, args))
    except Exception:  # a picture of the witness alone is still worth having
        pass
    rules.overlay(axes, problem.id, args, cert)
    axes.set_title(f"{cert['kind']}: {cert['claim']}", fontsize=8, wrap=True)
    return fig


def main(argv: list[str] | None = None) -> int:
    """``python -m grader.contest.certificate PROBLEM INPUT ANSWER``: print the certificate."""
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 3:
        print(__doc__.split("\n\n")[3].strip(), file=sys.stderr)
        return 2
    problem_id, inp, ans = argv
    with open(inp) as f, open(ans) as g:
        cert = certify(problem_id, f.read(), g.read())
    print(json.dumps(cert, indent=2))
    return 0 if cert is not None else 1


def exact(value: str) -> Fraction:
    """A certificate's exact value (``"p/q"``, ``"p"``) as a Fraction: ``exact("-3/4") == Fraction(-3, 4)``."""
    return Fraction(value)


if __name__ == "__main__":
    raise SystemExit(main())
