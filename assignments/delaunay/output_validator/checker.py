"""Checker for the Delaunay problems: accepts any valid Delaunay triangulation (exact arithmetic).

Two uses, one logic:

* the grader imports this file and calls ``read_input``, ``from_result`` / ``read_output`` and
  ``check`` in its own process (answers never reach the student's side);
* Kattis / problemtools run the exported copy (``python -m grader export-kattis delaunay OUT``) as an
  output validator: ``python3 checker.py input answer feedback_dir < team_output`` (exit 42
  accept, 43 reject, the reason in ``feedback_dir/judgemessage.txt``).

The exact test itself is ``reference_impl.exact.verify.check_delaunay`` (Python integers), and the
text formats and strict typing are ``reference_impl.judge_io``'s, both named in ``LIBRARY``: the
shared loader (``grader/checker_runtime.py``) binds it without importing the rest
of ``reference_impl`` (which would pull in numba), and ``export-kattis`` embeds it together with
the Kattis entry point.

Example:
    >>> check([[[0, 0], [1, 0], [0, 1]]], [[0, 1, 2]], None)
    (True, 'ok')
"""
from __future__ import annotations

import itertools

LIBRARY = ("judge_io", "verify", "bulk")  # reference_impl/<name>.py, bound as globals by the shared loader

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages


class WrongAnswer(Exception):
    """The answer is wrong before any triangle is looked at (verdict WA): too many triangles."""


def read_input(text: str) -> list:
    """Parse the input format into the entry function's argument list ``[points]``."""
    return [judge_io.read_points(text)]  # noqa: F821


def write_input(args: list) -> str:
    return judge_io.write_points(args[0])  # noqa: F821


def write_output(triangles: list) -> str:
    return judge_io.write_index_rows(triangles)  # noqa: F821


def _limit(args) -> int:
    """Any triangulation of n points has fewer than 2n triangles: more is rejected at once."""
    return 2 * len(args[0]) + 8 if args else 1 << 62


def _at_most(m: int, args) -> None:
    """Reject over 2n triangles for n points before looking at any of them (WA), so a forged huge
    answer costs nothing beyond reading it (bounded by the output limit). A triangulation has at
    most 2n - 5; a count up to 2n gets the full check and its message."""
    if args:
        n = len(args[0])
        if m > 2 * n:
            raise WrongAnswer(f"{m} triangles for {n} points: a triangulation of n points has at most "
                              f"2n - 5 triangles")


def from_result(value, args: list) -> list[list[int]]:
    """Type-check what the entry function returned (JSON data): a list of [i, j, k] int triples."""
    if isinstance(value, list):
        _at_most(len(value), args)
    return judge_io.index_rows(value, 3, "triangle", _limit(args))  # noqa: F821


def read_output(text: str, args: list) -> list[list[int]]:
    """Parse program output: m, then m lines 'i j k'."""
    first = text.lstrip().split("\n", 1)[0].strip()
    try:
        announced = judge_io.parse_int(first, "the first line")  # noqa: F821 - ASCII digits, bounded length
    except PresentationError:
        announced = None  # read_index_rows says what is wrong with it
    if announced is not None:
        _at_most(announced, args)
    return judge_io.read_index_rows(text, 3, "triangle", _limit(args))  # noqa: F821


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "outside 0..": "a triangle uses an index out of range",
    "counter-clockwise": "a triangle is not counter-clockwise",
    "collinear": "triangles given for collinear points",
    "overlap": "triangles overlap",
    "convex hull": "the triangles do not cover the convex hull exactly",
    "not a vertex": "a point is not a vertex of any triangle",
    "not Delaunay": "an edge is not Delaunay",
    "circumcircle": "a point lies inside a circumcircle",
}


@judge_io.mistake_kinds(MISTAKES, "not a valid Delaunay triangulation")  # noqa: F821 - bound by the loader
def check(args: list, triangles: list[list[int]], expected: list[list[int]] | None) -> tuple[bool, str]:
    """Exact check; ``expected`` (the reference answer) only improves the message."""
    (points,) = args
    n = len(points)
    ok, message = verify.check_delaunay(points, triangles, bulk)  # noqa: F821 - bound by the loader
    if ok:  # then every index is in range
        return True, "ok"
    flat = itertools.chain.from_iterable
    if triangles and (min(flat(triangles)) < 0 or max(flat(triangles)) >= n):  # then name the first one out of range
        for k, t in enumerate(triangles):
            bad = [v for v in t if not 0 <= v < n]
            if bad:
                return False, f"triangle {k} = {t} uses index {bad[0]}, outside 0..{n - 1}"
    if expected is not None and len(expected) != len(triangles):
        message += f" (a valid answer has {len(expected)} triangles, you gave {len(triangles)})"
    return ok, message


def draw(axes, args: list, received: list[list[int]], expected: list[list[int]] | None) -> None:
    """Picture for reports: expected triangulation (left) and the received one (right).

    ``axes`` is a pair of matplotlib Axes; only the grader's HTML report calls this.
    """
    (points,) = args
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    for ax, tris, title, colour in ((axes[0], expected or [], "expected (one valid answer)", "tab:blue"),
                                    (axes[1], received or [], "received", "tab:red")):
        for t in tris:
            if all(0 <= v < len(points) for v in t):
                cyc = [t[0], t[1], t[2], t[0]]
                ax.plot([xs[v] for v in cyc], [ys[v] for v in cyc], color=colour, lw=0.8)
        ax.scatter(xs, ys, s=12, color="black", zorder=3)
        if len(points) <= 30:
            for i, (x, y) in enumerate(points):
                ax.annotate(str(i), (x, y), fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.set_title(f"{title}: {len(tris)} triangles", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
