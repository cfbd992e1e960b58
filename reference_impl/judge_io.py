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
import math

__all__ = ["PresentationError", "read_points", "write_points", "as_index", "index_rows", "read_index_rows",
           "write_index_rows", "draw_edges"]


class PresentationError(Exception):
    """The answer has the wrong shape or type (verdict PE), as opposed to a wrong answer."""


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
        raise PresentationError(f"{where}: index {v!r} is a float{hint}")
    raise PresentationError(f"{where}: index {str(v)[:40]!r} is a {type(v).__name__}, not an int")


def index_rows(value, width: int, what: str, max_rows: int) -> list:
    """A returned list of ``width``-tuples of ints (function mode), at most ``max_rows`` of them.

    >>> index_rows([], 2, "edge", max_rows=0)
    []
    """
    if not isinstance(value, list):
        raise PresentationError(f"expected a list of {what}s, got {type(value).__name__}: {str(value)[:60]}")
    if len(value) > max_rows:
        raise PresentationError(f"{len(value)} {what}s is more than any correct answer has (at most {max_rows})")
    out = []
    for k, row in enumerate(value):
        if not isinstance(row, list) or len(row) != width:
            raise PresentationError(f"{what} {k} should be {width} indices, got {str(row)[:60]}")
        out.append([as_index(v, f"{what} {k}") for v in row])
    return out


def read_index_rows(text: str, width: int, what: str, max_rows: int) -> list:
    """Program output: a line ``m``, then ``m`` lines of ``width`` integers.

    >>> read_index_rows("0\\n", 2, "edge", max_rows=3)
    []
    """
    lines = text.split("\n")
    if not lines[0].strip():
        raise PresentationError(f"empty output: expected the number of {what}s on the first line")
    try:
        m = int(lines[0].strip())
    except ValueError:
        raise PresentationError(f"first line should be the number of {what}s, got {lines[0][:60]!r}") from None
    if not 0 <= m <= max_rows:
        raise PresentationError(f"announced {m} {what}s: a correct answer has between 0 and {max_rows}")
    body = [ln for ln in lines[1:] if ln.strip()]  # the text is bounded by the output limit
    if len(body) != m:
        raise PresentationError(f"announced {m} {what}s but {len(body)} lines follow")
    out = []
    for k, ln in enumerate(body):
        parts = ln.split()
        if len(parts) != width:
            raise PresentationError(f"line {k + 2}: expected {width} integers, got {ln[:60]!r}")
        try:
            out.append([int(p) for p in parts])
        except ValueError:
            raise PresentationError(f"line {k + 2}: indices must be integers, got {ln[:60]!r}") from None
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
