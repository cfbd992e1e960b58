"""Stdlib-only helpers the problem checkers share: the points text format and strict typing of answers.

Checkers name this module in ``LIBRARY = ("judge_io", ...)`` and get it as the global ``judge_io``
(see ``grader/checker_runtime.py``); it never imports numpy, so a checker starts fast and its
Kattis copy runs anywhere. Everything a submission sends is untrusted: the readers here accept only
the exact shape asked for and raise ``PresentationError`` (verdict PE) with a message a student
can act on, and they stop at ``max_rows`` rows before doing any work on them.

Run the doctests: python -m pytest reference_impl/judge_io.py

>>> read_points("2\\n0 0.5\\n-1 2e-300\\n")
[[0.0, 0.5], [-1.0, 2e-300]]
>>> index_rows([[0, 1], [2, 1]], 2, "edge", max_rows=5)
[[0, 1], [2, 1]]
>>> read_index_rows("1\\n0 1\\n", 2, "edge", max_rows=5)
[[0, 1]]
"""
import itertools
import math
import re

__all__ = ["PresentationError", "Mistake", "mistake", "mistake_kinds", "show", "number", "parse_int", "parse_float", "read_points",
           "write_points", "as_index", "index_rows", "read_index_rows", "write_index_rows", "draw_edges"]

#: the longest integer token a reader parses (an index or a count never needs more)
MAX_INT_DIGITS = 30
#: the longest number token a reader parses (``repr`` of a double has at most 24 characters)
MAX_FLOAT_CHARS = 400
_INT = re.compile(r"[+-]?[0-9]+")
_FLOAT = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?|[+-]?(?:inf|infinity|nan)", re.I)


class PresentationError(Exception):
    """The answer has the wrong shape or type (verdict PE), as opposed to a wrong answer.

    ``kind`` is what a student may see when the test is hidden: the kind of mistake, with no
    number, index or size of the test in it (``str(exc)`` is the detail).

    >>> PresentationError("point 3: 'x' is a str, not a number", kind="a coordinate is not a number").kind
    'a coordinate is not a number'
    """

    def __init__(self, message: str = "", kind: str = "") -> None:
        super().__init__(message)
        self.kind = kind


class Mistake(str):
    """A checker's failure message in two parts: the text is the detail (for the instructor and for
    public tests), ``kind`` what a student may see for a hidden test (no numbers, indices or sizes).

    >>> m = mistake("the triangles are not Delaunay", "triangle 3 has point 7 inside its circumcircle")
    >>> (str(m), m.kind)
    ('triangle 3 has point 7 inside its circumcircle', 'the triangles are not Delaunay')
    """

    kind: str = ""


def mistake(kind: str, detail: str) -> Mistake:
    """The failure message ``detail`` tagged with the hidden-test ``kind`` (see :class:`Mistake`)."""
    m = Mistake(detail)
    m.kind = kind
    return m


def mistake_kinds(table: dict, default: str):
    """Decorator for a checker's ``check``: a failure message that is not already a
    :class:`Mistake` gets the kind of the first ``table`` key (a substring) it contains, else
    ``default``. Kinds hold no number of the test (the grader drops any kind with a digit).

    >>> @mistake_kinds({"outside": "an index is out of range"}, "the answer is wrong")
    ... def check(args, answer, expected):
    ...     return False, "index 7 is outside 0..3"
    >>> check(None, None, None)[1].kind
    'an index is out of range'
    """
    def wrap(check):
        def checked(args, answer, expected):
            ok, message = check(args, answer, expected)
            if ok or isinstance(message, Mistake):
                return ok, message
            kind = next((k for key, k in table.items() if key in message), default)
            return ok, mistake(kind, message)
        checked.__name__, checked.__doc__, checked.__wrapped__ = check.__name__, check.__doc__, check
        return checked
    return wrap


def show(value, limit: int = 60) -> str:
    """A short, safe preview of any value a submission sent, for messages: never raises and does
    work bounded by ``limit`` (deep nesting, huge ints, long strings, foreign objects).

    >>> show([[1, 2.5], "x" * 100, 10 ** 500], 40)
    "[[1, 2.5], 'xxxxxxxxxxxxxxxxxxxxxxxxx..."
    >>> show([[[[[[0]]]]]])
    '[[[[...]]]]'
    """
    out: list = []
    budget = [limit + 1]

    def put(text: str) -> None:
        out.append(text[:max(budget[0], 0)])
        budget[0] -= len(text)

    def walk(v, depth: int) -> None:
        if budget[0] <= 0:
            return
        t = type(v)
        if t in (list, tuple):
            if depth >= 3:
                put("[...]")
                return
            put("[" if t is list else "(")
            for k, item in enumerate(v):
                if budget[0] <= 0:
                    return
                if k:
                    put(", ")
                walk(item, depth + 1)
            put("]" if t is list else ")")
        elif t is int:
            put(repr(v) if v.bit_length() <= 256 else f"<an int of {v.bit_length()} bits>")
        elif t in (float, bool) or v is None:
            put(repr(v))
        elif t is str:
            put(repr(v[:limit + 2]))
        elif t in (bytes, bytearray):
            put(repr(bytes(v[:limit + 2])))
        else:
            put(f"<{t.__name__[:40]}>")

    try:
        walk(value, 0)
    except Exception:  # noqa: BLE001 - a preview never fails
        return f"<{type(value).__name__[:40]}>"
    text = "".join(out)
    return text if len(text) <= limit else text[:limit - 3] + "..."


def number(v, where: str, what: str = "a coordinate") -> float:
    """A JSON number ``v`` (int or float, not a bool) as a finite float; else ``PresentationError``.

    >>> number(3, "x")
    3.0
    >>> try:
    ...     number(10 ** 400, "x")
    ... except PresentationError as exc:
    ...     print(exc, "/", exc.kind)
    x: the integer is too large for a float / a coordinate is not finite
    """
    if type(v) not in (int, float):
        raise PresentationError(f"{where}: {show(v, 40)} is a {type(v).__name__}, not a number",
                                kind=f"{what} is not a number")
    try:
        x = float(v)
    except OverflowError:
        raise PresentationError(f"{where}: the integer is too large for a float", kind=f"{what} is not finite") from None
    if not math.isfinite(x):
        raise PresentationError(f"{where}: {x!r} is not finite", kind=f"{what} is not finite")
    return x


def parse_int(token: str, where: str, what: str = "an integer") -> int:
    """An ASCII decimal integer token of at most ``MAX_INT_DIGITS`` digits; else ``PresentationError``
    (``'²'``, ``'١'``, ``'1_0'``, 5000 digits are all refused, never a crash).

    >>> parse_int("-12", "line 1")
    -12
    """
    if len(token) > MAX_INT_DIGITS + 1 or not _INT.fullmatch(token):
        raise PresentationError(f"{where}: expected {what}, got {show(token, 40)}", kind=f"expected {what}")
    return int(token)


def parse_float(token: str, where: str, what: str = "a number") -> float:
    """An ASCII decimal number token (``inf``/``nan`` spelled out allowed: callers decide), at most
    ``MAX_FLOAT_CHARS`` long; else ``PresentationError``. Too large a value reads as ``inf``.

    >>> parse_float("1e400", "x"), parse_float("-0.5", "x")
    (inf, -0.5)
    """
    if len(token) > MAX_FLOAT_CHARS or not _FLOAT.fullmatch(token):
        raise PresentationError(f"{where}: expected {what}, got {show(token, 40)}", kind=f"expected {what}")
    return float(token)


def read_points(text: str) -> list:
    """Parse ``n`` then ``n`` lines ``x y`` (test inputs: trusted, checked by the input validator).

    >>> read_points("1\\n3 4\\n")
    [[3.0, 4.0]]
    """
    tok = text.split()
    n = int(tok[0])
    return [[float(tok[1 + 2 * i]), float(tok[2 + 2 * i])] for i in range(n)]


def write_points(points) -> str:
    """Inverse of :func:`read_points`; ``repr`` keeps every double exactly.

    >>> write_points([[0.1, 2.0]])
    '1\\n0.1 2.0\\n'
    """
    return f"{len(points)}\n" + "".join(f"{float(x)!r} {float(y)!r}\n" for x, y in points)


def as_index(v, where: str) -> int:
    """``v`` if it is an int (not a bool, not a float); else ``PresentationError`` saying why.

    >>> as_index(3, "edge 0")
    3
    """
    if type(v) is int:
        return v
    if type(v) is float:
        hint = " (not a number)" if math.isnan(v) else " (use integer indices: dtype=int)"
        raise PresentationError(f"{where}: index {v!r} is a float{hint}", kind="an index is a float, not an int")
    raise PresentationError(f"{where}: index {show(v, 40)} is a {type(v).__name__}, not an int",
                            kind="an index is not an int")


def index_rows(value, width: int, what: str, max_rows: int) -> list:
    """A returned list of ``width``-tuples of ints (function mode), at most ``max_rows`` of them.

    >>> index_rows([], 2, "edge", max_rows=0)
    []
    """
    if not isinstance(value, list):
        raise PresentationError(f"expected a list of {what}s, got {type(value).__name__}: {show(value)}",
                                kind=f"expected a list of {what}s")
    if len(value) > max_rows:
        raise PresentationError(f"{len(value)} {what}s is more than any correct answer has (at most {max_rows})",
                                kind=f"more {what}s than any correct answer has")
    if value and set(map(type, value)) == {list} and set(map(len, value)) == {width}:  # fast path, C loops
        if set(map(type, itertools.chain.from_iterable(value))) == {int}:
            return value  # exactly lists of ints: used as it is (a copy would only feed the garbage collector)
    out = []
    for k, row in enumerate(value):
        if not isinstance(row, list) or len(row) != width:
            raise PresentationError(f"{what} {k} should be {width} indices, got {show(row)}",
                                    kind=f"a {what} has the wrong number of indices")
        out.append([as_index(v, f"{what} {k}") for v in row])
    return out


def read_index_rows(text: str, width: int, what: str, max_rows: int) -> list:
    """Program output: a line ``m``, then ``m`` lines of ``width`` integers.

    >>> read_index_rows("0\\n", 2, "edge", max_rows=3)
    []
    """
    lines = text.split("\n")
    if not lines[0].strip():
        raise PresentationError(f"empty output: expected the number of {what}s on the first line",
                                kind="the output is empty")
    m = parse_int(lines[0].strip(), "the first line", f"the number of {what}s")
    if not 0 <= m <= max_rows:
        raise PresentationError(f"announced {m} {what}s: a correct answer has between 0 and {max_rows}",
                                kind=f"the announced number of {what}s is impossible")
    body = [ln for ln in lines[1:] if ln.strip()]  # the text is bounded by the output limit
    if len(body) != m:
        raise PresentationError(f"announced {m} {what}s but {len(body)} lines follow",
                                kind=f"the number of lines differs from the announced number of {what}s")
    out = []
    for k, ln in enumerate(body):
        parts = ln.split()
        if len(parts) != width:
            raise PresentationError(f"line {k + 2}: expected {width} integers, got {show(ln)}",
                                    kind="a line has the wrong number of integers")
        out.append([parse_int(p, f"line {k + 2}", "an integer index") for p in parts])
    return out


def write_index_rows(rows) -> str:
    """Inverse of :func:`read_index_rows`.

    >>> write_index_rows([[0, 1], [1, 2]])
    '2\\n0 1\\n1 2\\n'
    """
    return f"{len(rows)}\n" + "".join(" ".join(str(int(v)) for v in row) + "\n" for row in rows)


def draw_edges(axes, points, received, expected, expected_title: str) -> None:
    """Report picture for graph answers: ``expected`` edges on ``axes[0]``, ``received`` on
    ``axes[1]`` (a pair of matplotlib Axes; nothing is imported here), indices shown up to 30 points."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    n = len(points)
    for ax, edges, title, colour in ((axes[0], expected or [], expected_title, "tab:blue"),
                                     (axes[1], received or [], "received", "tab:red")):
        for i, j in edges:
            if 0 <= i < n and 0 <= j < n:
                ax.plot([xs[i], xs[j]], [ys[i], ys[j]], color=colour, lw=1.0)
        ax.scatter(xs, ys, s=12, color="black", zorder=3)
        if n <= 30:
            for i, (x, y) in enumerate(points):
                ax.annotate(str(i), (x, y), fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.set_title(f"{title}: {len(edges)} edges", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
