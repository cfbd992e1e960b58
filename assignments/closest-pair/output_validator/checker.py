"""Checker for `closest-pair`: accepts any pair of distinct indices at the minimum distance (exact).

The squared distance of the received pair, computed exactly from the input doubles (Python
integers after one common power-of-two scaling, ``reference_impl/exact/verify.py``), must equal the
reference pair's. The grader loads this file with the shared loader
(``grader/checker_runtime.py``); ``export-kattis`` makes it a self-contained Kattis output validator.

Example:
    >>> check([[[0, 0], [5, 5], [1, 1], [5, 6]]], [3, 1], [1, 3])
    (True, 'ok')
"""
from __future__ import annotations

import math

LIBRARY = ("judge_io", "verify")  # bound as globals by the shared loader

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages


def read_input(text: str) -> list:
    """``[points]`` from ``n`` and ``n`` lines ``x y``."""
    return [judge_io.read_points(text)]  # noqa: F821


def write_input(args: list) -> str:
    return judge_io.write_points(args[0])  # noqa: F821


def from_result(value, args: list) -> list[int]:
    """A returned ``[i, j]`` (a list, tuple or numpy array of two ints)."""
    if not isinstance(value, list) or len(value) != 2:
        raise PresentationError(f"expected a pair [i, j] of indices, got {show(value, 60)}")
    return [judge_io.as_index(v, "the pair") for v in value]  # noqa: F821


def read_output(text: str, args: list) -> list[int]:
    """Program output: one line ``i j``."""
    lines = [ln for ln in text.split("\n", 3)[:3] if ln.strip()]
    if len(lines) != 1 or len(text.split()) != 2:
        raise PresentationError(f"expected one line 'i j', got {show(text, 60)}")
    return [judge_io.parse_int(t, "the pair", "an integer index") for t in text.split()]  # noqa: F821


def write_output(pair: list) -> str:
    return f"{pair[0]} {pair[1]}\n"


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "outside 0..": "an index is out of range",
    "twice": "the two indices are the same point",
    "floating point": "not a closest pair (compare squared distances exactly)",
}


@judge_io.mistake_kinds(MISTAKES, "not a closest pair")  # noqa: F821 - bound by the loader
def check(args: list, pair: list[int], expected: list[int] | None) -> tuple[bool, str]:
    """Exact check; ``expected`` is a closest pair (the reference answer)."""
    (points,) = args
    n = len(points)
    i, j = pair
    for v in (i, j):
        if not 0 <= v < n:
            return False, f"index {v} is outside 0..{n - 1}"
    if i == j:
        return False, f"[{i}, {j}] is one point twice: the two indices must differ"
    if expected is None:
        return True, "ok (not compared with the minimum)"
    a, b = expected
    # the four points alone, scaled by one common power of two: the squared distances compare exactly
    (pi, pj, pa, pb) = verify.exact_coordinates([points[i], points[j], points[a], points[b]])  # noqa: F821
    if (pi[0] - pj[0]) ** 2 + (pi[1] - pj[1]) ** 2 == (pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2:
        return True, "ok"
    mine = math.hypot(points[i][0] - points[j][0], points[i][1] - points[j][1])
    best = math.hypot(points[a][0] - points[b][0], points[a][1] - points[b][1])
    if mine == best:
        how = (f"both distances round to {mine!r} in floating point, but yours is exactly larger: compare "
               "squared distances exactly (integers or fractions.Fraction), not as floats")
    else:
        how = f"distance {mine!r}, but points {a} and {b} are at distance {best!r}"
    return False, f"points {i} {tuple(points[i])} and {j} {tuple(points[j])} are not a closest pair: {how}"


def draw(axes, args: list, received: list[int], expected: list[int] | None) -> None:
    """Picture for reports: a closest pair (left) and the received pair (right)."""
    (points,) = args
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    n = len(points)
    for ax, pair, title, colour in ((axes[0], expected, "a closest pair", "tab:blue"),
                                    (axes[1], received, "received", "tab:red")):
        ax.scatter(xs, ys, s=10, color="black", zorder=3)
        if pair and all(0 <= v < n for v in pair):
            i, j = pair
            ax.plot([xs[i], xs[j]], [ys[i], ys[j]], color=colour, lw=2, marker="o")
        ax.set_title(f"{title}: {pair}", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
