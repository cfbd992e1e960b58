"""Hostile answers for checkers: the rule every checker keeps, and a fixed corpus that tests it.

The rule (``python -m grader validate`` checks it on every problem, and
``tests/grader/test_checker_fuzz.py`` checks it with hypothesis on all twelve checkers and their
exported Kattis validators): ``from_result``, ``read_output`` and ``check`` raise nothing but
``PresentationError`` (or the checker's own ``WrongAnswer``, a wrong answer found before any real
check) on **any** input, and ``check`` returns ``(bool, str)``. What a submission returns or prints
is untrusted: unicode digits (``'²'.isdigit()`` is true, ``int('²')`` raises), integers of
thousands of digits, integers where floats go (``float(10**400)`` overflows), NaN and infinities,
bools, strings and bytes, deep nesting, enormous lengths.

The corpus here is deterministic: leaves (:data:`HOSTILE_VALUES`, :data:`HOSTILE_TOKENS`) put in
place of every position of the reference answer, in its JSON form and in its text form, and whole
values and texts on their own.

Example:
    >>> from grader.problems import load_problem
    >>> p = load_problem("closest-pair")
    >>> rule_violations(p.checker, *sample_data(p)[0])
    []
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Callable, Iterator

from . import checker_runtime


def _deep(levels: int) -> list:
    v: list = []
    for _ in range(levels):
        v = [v]
    return v


#: values a function-mode reply can carry (any JSON, plus what a buggy caller might pass)
HOSTILE_VALUES: tuple = (
    None, True, False, 0, -1, 2 ** 63, -(2 ** 63) - 1, 10 ** 400, -(10 ** 400), 10 ** 4000, 1.5, -0.0,
    float("nan"), float("inf"), float("-inf"), 1e308, 5e-324, "", "0", "²", "١٢", "1" * 5000, "nan",
    b"\x00\xff", [], [[]], [None], [True, False], {}, {"0": 1}, _deep(200), [0] * 100_000,
)

#: tokens a program can print where a number is read
HOSTILE_TOKENS: tuple = (
    "²", "³", "١", "٣", "𝟙", "1_0", "0x10", "1" * 5000, "1" * 401, "-" + "9" * 401, "1e400", "-1e400",
    "nan", "inf", "-inf", "+0", "-0", "1.", ".5", "١.٥", "1e", "e5", "--1", "\x00", "\u200b1", "NaN", "Infinity",
    "9" * 31, "9" * 4301,
)

#: whole outputs
HOSTILE_TEXTS: tuple = (
    "", "\n", " \n\n ", "²\n", "5" * 5000 + "\n", "1\n" + "1" * 401 + " 0 0\n", "nan nan nan\n",
    "0\n" * 10, "\x00", "\ufeff1\n0 1 2\n", "-1\n", "1\n²",
)


def sample_data(problem) -> list[tuple[list, Any]]:
    """``(args, expected)`` of each committed sample (``data/sample/*.in`` with its ``.ans``)."""
    chk = problem.checker
    out = []
    for f in sorted(Path(problem.path, "data", "sample").glob("*.in")):
        args = chk.read_input(f.read_text())
        ans = f.with_suffix(".ans")
        out.append((args, checker_runtime.read_answer(chk, ans.read_text(), args) if ans.is_file() else None))
    return out


def _positions(value: Any, path: tuple = ()) -> Iterator[tuple]:
    yield path
    if isinstance(value, list):
        for k, v in enumerate(value[:6]):
            yield from _positions(v, path + (k,))


def _replace(value: Any, path: tuple, leaf: Any) -> Any:
    if not path:
        return leaf
    out = list(value)
    out[path[0]] = _replace(value[path[0]], path[1:], leaf)
    return out


def hostile_results(expected: Any) -> Iterator[Any]:
    """Whole hostile values, then the reference answer (as JSON data) with each of its first
    positions replaced by each hostile value, then padded far beyond any correct size."""
    yield from HOSTILE_VALUES
    base = json.loads(json.dumps(expected, allow_nan=True))
    for path in _positions(base):
        for leaf in HOSTILE_VALUES:
            yield _replace(base, path, leaf)
    if isinstance(base, list) and base:
        yield base * 2000
        yield [base[0]] * 20_000


def hostile_outputs(text: str) -> Iterator[str]:
    """Whole hostile texts, then the reference output with each of its first tokens replaced by
    each hostile token, then with lines repeated."""
    yield from HOSTILE_TEXTS
    tokens = text.split(" ")
    lines = text.split("\n")
    for k in range(min(len(tokens), 8)):
        for tok in HOSTILE_TOKENS:
            yield " ".join(tokens[:k] + [tok + tokens[k][len(tokens[k].rstrip()):]] + tokens[k + 1:])
    first = text.split()[0] if text.split() else ""
    for tok in HOSTILE_TOKENS:
        yield tok + text[len(first):]
    yield "\n".join(lines[:1] + lines[1:] * 50)


def _allowed(chk) -> tuple:
    return (chk.PresentationError,) + ((chk.WrongAnswer,) if isinstance(getattr(chk, "WrongAnswer", None), type) else ())


def _call(fn: Callable, *args) -> tuple[str, Any]:
    try:
        return "ok", fn(*args)
    except BaseException as exc:  # noqa: BLE001 - the point is to see every exception
        if isinstance(exc, KeyboardInterrupt):
            raise
        return "raised", exc


def check_one(chk, args: list, expected: Any, how: str, received: Any) -> str:
    """'' when the checker keeps the rule on ``received`` (a returned value for ``how ==
    "from_result"``, an output text for ``"read_output"``), else what it did wrong."""
    parse = chk.from_result if how == "from_result" else chk.read_output
    status, answer = _call(parse, received, args)
    if status == "raised":
        if isinstance(answer, _allowed(chk)):
            return ""
        return f"{how} raised {type(answer).__name__}: {str(answer)[:100]} on {_preview(received)}"
    status, verdict = _call(chk.check, args, answer, expected)
    if status == "raised":
        return f"check raised {type(verdict).__name__}: {str(verdict)[:100]} after {how} of {_preview(received)}"
    if not (isinstance(verdict, tuple) and len(verdict) == 2 and isinstance(verdict[0], bool)
            and isinstance(verdict[1], str)):
        return f"check returned {type(verdict).__name__}, not (bool, str), on {_preview(received)}"
    return ""


def _preview(v: Any) -> str:
    from .text import clean
    try:
        return clean(repr(v)[:80], 100)
    except Exception:  # noqa: BLE001 - e.g. a 5000-digit int
        return f"<{type(v).__name__}>"


def rule_violations(chk, args: list, expected: Any, limit: int = 5) -> list[str]:
    """Up to ``limit`` ways the checker breaks the rule on the fixed corpus (empty: it keeps it)."""
    found: list[str] = []
    text = chk.write_output(expected) if expected is not None else ""
    for how, values in (("from_result", hostile_results(expected)), ("read_output", hostile_outputs(text))):
        for v in values:
            problem = check_one(chk, args, expected, how, v)
            if problem and problem not in found:
                found.append(problem)
                if len(found) >= limit:
                    return found
    return found
