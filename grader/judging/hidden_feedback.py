"""What a student may see of a hidden test: the kind of mistake, never the test's data.

A test result carries two messages. ``message`` is the detail (the checker's full text, the
student's exception and prints) for the instructor, reports and public (sample) tests.
``hidden_message`` is built here from parts that cannot carry the hidden input or answer:

* ``WA``/``PE``: the checker's *kind* of mistake (``judge_io.mistake(kind, detail)`` or
  ``PresentationError(detail, kind=...)``), kept only when it holds no digit; otherwise the
  verdict's description alone;
* ``RE``: the exception's type when it is a built-in one (a class of the student's own could be
  named after the data), and the line numbers in their own code (at most the length of their
  source, so no number of the test fits in them); never the exception's text, the source line
  (the file in the sandbox is writable), or what the test printed;
* ``SV``: "a forbidden import or operation" and the line; every other verdict: its description.

Example:
    >>> for_checker("WA", "triangle 3 is not Delaunay")
    'wrong answer'
    >>> for_run("RE", "ValueError: 0.1234 is hidden", ("line 4, in delaunay: raise ValueError(x)",), 10)
    'run-time error: ValueError at line 4 of your code'
"""

from __future__ import annotations

import builtins
import re

from .verdicts import DESCRIPTIONS

_KIND_MAX = 120
_LINE = re.compile(r"\bline (\d{1,6})\b")


def safe_kind(kind: object) -> str:
    """``kind`` when it is short printable text without digits, else ``''``.

    >>> safe_kind("the triangles do not cover the hull"), safe_kind("point 7 is outside")
    ('the triangles do not cover the hull', '')
    """
    if not isinstance(kind, str) or len(kind) > _KIND_MAX or not kind.isprintable():
        return ""
    return "" if any(c.isdigit() for c in kind) else kind


def for_checker(verdict: str, message: object) -> str:
    """The hidden-test text of a checker's verdict: its description and the message's kind, if any."""
    base = DESCRIPTIONS.get(verdict, verdict).split(" (")[0]
    kind = safe_kind(getattr(message, "kind", ""))
    return f"{base}: {kind}" if kind else base


def _builtin_exception(name: str) -> bool:
    cls = getattr(builtins, name, None)
    return isinstance(cls, type) and issubclass(cls, BaseException)


def own_lines(where: tuple[str, ...] | list[str], message: str, source_lines: int) -> list[int]:
    """Line numbers of the student's own code named in a traceback or violation report, each at
    most ``source_lines`` (the length of the submission)."""
    found = []
    for text in [*where, message]:
        for m in _LINE.finditer(text):
            n = int(m.group(1))
            if 1 <= n <= source_lines and n not in found:
                found.append(n)
    return found[-3:]


def for_run(verdict: str, message: str, where: tuple[str, ...] | list[str], source_lines: int) -> str:
    """The hidden-test text of a verdict from running the submission (RE, SV, TLE, ...)."""
    base = DESCRIPTIONS.get(verdict, verdict)
    if verdict not in ("RE", "SV", "MLE"):
        return base
    lines = own_lines(where, message, source_lines)
    at = (" at line " + ", ".join(map(str, lines)) + " of your code") if lines else ""
    if verdict == "SV":
        return f"security violation: a forbidden import or operation{at}"
    name = message.split(":", 1)[0].strip() if ":" in message else ""
    if verdict == "MLE":
        return base + at
    kind = name if re.fullmatch(r"[A-Za-z_]\w{0,60}", name) and _builtin_exception(name) else (
        "an exception of your own class" if name else "")
    return f"run-time error: {kind}{at}".rstrip(": ") if kind or at else "run-time error"
