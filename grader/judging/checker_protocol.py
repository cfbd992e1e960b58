"""The checker protocol, checked in full: what ``python -m grader validate PROBLEM`` asks of a checker.

A checker is ``assignments/<id>/output_validator/checker.py``, stdlib-only, loaded by
:func:`grader.judging.checker_runtime.load_checker`. It defines (``args`` is the entry function's argument
list, ``answer`` the checker's own parsed form of an answer):

| name | contract |
| --- | --- |
| ``read_input(text) -> args`` | parse the problem's text input format |
| ``write_input(args) -> text`` | inverse of ``read_input`` (the generator's cases are written with it) |
| ``from_result(value, args) -> answer`` | type-check what the entry function returned (JSON data) |
| ``read_output(text, args) -> answer`` | parse a program's stdout (stdio mode, Kattis) |
| ``write_output(answer) -> text`` | inverse of ``read_output`` (``.ans`` files are written with it) |
| ``check(args, answer, expected) -> (bool, message)`` | the verdict; ``expected`` is the reference answer or ``None`` |
| ``PresentationError`` | an ``Exception`` subclass raised by ``from_result``/``read_output`` for a wrong shape or type |
| ``LIBRARY`` (optional) | tuple of stdlib-only modules ``reference_impl/<name>.py`` bound as globals (optional imports allowed) |
| ``read_answer(text, args)`` (optional) | parse an ``.ans`` text when it is not in the output format |
| ``draw(axes, args, received, expected)`` (optional) | picture for the HTML report on a pair of Axes |
| ``from_arrays(rows, args) -> answer`` (optional) | a long float answer sent as a binary frame (``frames``): as ``from_result(rows.tolist(), args)`` |

It must not define its own ``__main__`` entry: ``export-kattis`` appends the shared one. The checks
here: the names and signatures; stdlib-only imports (checker and library, ``draw`` excepted); on
every test ``read_input(write_input(args)) == args``, ``read_output(write_output(answer)) ==
answer`` for the reference answer, which ``check`` accepts, also after a JSON round trip through
``from_result`` (and, with ``from_arrays``, as a binary frame); ``draw`` runs on the first test; and on every committed sample the rule of
:mod:`grader.judging.checker_attacks` holds: ``from_result``, ``read_output`` and ``check`` raise nothing but
``PresentationError`` (or ``WrongAnswer``) on a fixed corpus of hostile answers.

Example:
    >>> from grader.problems import load_problem
    >>> validate_checker(load_problem("delaunay"), tests=load_problem("delaunay").tests()[:1])
    []
"""

from __future__ import annotations

import ast
import inspect
import json
import sys
from typing import Any, Sequence

from . import checker_attacks
from . import checker_runtime
from . import frames
from . import hidden_feedback

REQUIRED = {"read_input": 1, "write_input": 1, "from_result": 2, "read_output": 2, "write_output": 1, "check": 3}
OPTIONAL = {"read_answer": 2, "draw": 4, "from_arrays": 2}
STDLIB = set(sys.stdlib_module_names) | {"__future__"}


def _takes(fn: Any, n: int) -> bool:
    try:
        inspect.signature(fn).bind(*range(n))
        return True
    except (TypeError, ValueError):
        return False


def foreign_imports(source: str, filename: str, allow_in: Sequence[str] = ("draw",)) -> list[str]:
    """Imported top-level modules that are not in the standard library (relative imports included),
    skipping the bodies of the functions named in ``allow_in`` and optional imports (numpy in
    ``reference_impl/exact/bulk.py``): a ``try`` whose
    handler catches ``ImportError`` (the module works without them, as an exported validator must).

    >>> foreign_imports("import math\\nimport numpy as np\\n", "x.py")
    ['numpy']
    >>> foreign_imports("try:\\n    import numpy\\nexcept ImportError:\\n    numpy = None\\n", "x.py")
    []
    """
    tree = ast.parse(source, filename)
    skip = {id(n) for f in ast.walk(tree) if isinstance(f, ast.FunctionDef) and f.name in allow_in for n in ast.walk(f)}
    skip |= {id(n) for t in ast.walk(tree) if isinstance(t, ast.Try) and any(
             h.type is not None and "ImportError" in ast.unparse(h.type) for h in t.handlers)
             for stmt in t.body for n in ast.walk(stmt)}
    found = []
    for node in ast.walk(tree):
        if id(node) in skip:
            continue
        if isinstance(node, ast.Import):
            found += [a.name.split(".")[0] for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            found.append("." * node.level + (node.module or "").split(".")[0])
    return [m for m in dict.fromkeys(found) if m not in STDLIB]


def _interface_errors(problem) -> list[str]:
    errors = []
    source = problem.checker_path.read_text()
    bad = foreign_imports(source, str(problem.checker_path))
    if bad:
        errors.append(f"checker imports {', '.join(bad)}: checkers are stdlib-only (name library modules in LIBRARY)")
    try:
        names = checker_runtime.library_names(source, str(problem.checker_path))
    except (ValueError, SyntaxError) as exc:
        return errors + [str(exc)]
    for name in names:
        try:
            f = checker_runtime.library_file(name)
        except ValueError as exc:
            errors.append(f"LIBRARY names {name!r}: {exc}")
            continue
        if foreign_imports(f.read_text(), str(f), allow_in=()):
            errors.append(f"LIBRARY module {name!r} imports {', '.join(foreign_imports(f.read_text(), str(f), ()))}: "
                          "library modules for checkers must be stdlib-only")
    if any(isinstance(n, ast.If) and "__name__" in ast.unparse(n.test) for n in ast.parse(source).body):
        errors.append("checker defines its own __main__ entry: export-kattis appends the shared one")
    if errors:  # loading would fail or import what it must not
        return errors
    chk = problem.checker
    for name, n in {**REQUIRED, **OPTIONAL}.items():
        fn = getattr(chk, name, None)
        if fn is None:
            if name in REQUIRED:
                errors.append(f"checker lacks {name}()")
        elif not callable(fn) or not _takes(fn, n):
            errors.append(f"checker's {name} must be callable with {n} positional argument(s)")
    pe = getattr(chk, "PresentationError", None)
    if not (isinstance(pe, type) and issubclass(pe, Exception)):
        errors.append("checker lacks PresentationError (an Exception subclass)")
    for kind in dict(getattr(chk, "MISTAKES", None) or {}).values():
        if hidden_feedback.safe_kind(kind) != kind:
            errors.append(f"MISTAKES kind {kind!r} would be dropped from hidden feedback: short text, no digits")
    return errors


def _test_errors(problem, test) -> list[str]:
    chk = problem.checker
    where = f"{test.name}:"
    args = chk.read_input(test.input_text)
    if not isinstance(args, list):
        return [f"{where} read_input must return the entry function's argument list, got {type(args).__name__}"]
    again = chk.read_input(chk.write_input(args))
    if again != args:
        return [f"{where} read_input(write_input(args)) != args"]
    if not test.answer_text:
        return [f"{where} has no answer (.ans)"]
    expected = checker_runtime.read_answer(chk, test.answer_text, args)
    if chk.read_output(chk.write_output(expected), args) != expected:
        return [f"{where} read_output(write_output(answer)) != answer for the reference answer"]
    verdict = chk.check(args, expected, expected)
    if not (isinstance(verdict, tuple) and len(verdict) == 2 and isinstance(verdict[0], bool)
            and isinstance(verdict[1], str)):
        return [f"{where} check must return (bool, message), got {verdict!r:.80}"]
    if not verdict[0]:
        return [f"{where} the reference answer is rejected: {verdict[1][:200]}"]
    as_json = json.loads(json.dumps(expected, allow_nan=True))
    ok, message = chk.check(args, chk.from_result(as_json, args), expected)
    if not ok:
        return [f"{where} the reference answer, returned as JSON data, is rejected: {message[:200]}"]
    frame = frames.frame_of(as_json) if callable(getattr(chk, "from_arrays", None)) else None
    if frame is not None:
        ok, message = chk.check(args, chk.from_arrays(frames.decode(frame), args), expected)
        if not ok:
            return [f"{where} the reference answer, returned as a binary frame (from_arrays), is rejected: {message[:200]}"]
    return []


def _draw_errors(problem, test) -> list[str]:
    draw = getattr(problem.checker, "draw", None)
    if draw is None:
        return []
    try:
        import matplotlib
    except ImportError:  # the report cannot draw either; nothing to check
        return []
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    chk = problem.checker
    args = chk.read_input(test.input_text)
    expected = checker_runtime.read_answer(chk, test.answer_text, args)
    fig, axes = plt.subplots(1, 2)
    try:
        draw(axes, args, expected, expected)
    finally:
        plt.close(fig)
    return []


def validate_checker(problem, tests: Sequence | None = None) -> list[str]:
    """Every way ``problem``'s checker breaks the protocol (empty when it keeps it)."""
    if not problem.checker_path.is_file():
        return []  # reported by Problem.validate
    try:
        errors = _interface_errors(problem)
    except Exception as exc:  # noqa: BLE001 - a broken checker is a finding, not a crash
        return [f"checker does not load: {type(exc).__name__}: {exc}"]
    if errors:
        return errors
    tests = problem.tests() if tests is None else tests
    for test in tests:
        try:
            errors += _test_errors(problem, test)
        except Exception as exc:  # noqa: BLE001
            errors.append(f"{test.name}: {type(exc).__name__}: {exc}")
    if not errors:
        try:
            for args, expected in checker_attacks.sample_data(problem):
                errors += [f"hostile answer: {e}" for e in checker_attacks.rule_violations(problem.checker, args, expected)]
        except Exception as exc:  # noqa: BLE001
            errors.append(f"the hostile-answer corpus could not run: {type(exc).__name__}: {exc}")
    if tests and not errors:
        try:
            errors += _draw_errors(problem, tests[0])
        except Exception as exc:  # noqa: BLE001
            errors.append(f"draw failed on {tests[0].name}: {type(exc).__name__}: {exc}")
    return errors

