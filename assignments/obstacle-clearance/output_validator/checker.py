"""Checker for `obstacle-clearance`: the received radius must equal the optimum within tolerance.

Two uses, one logic (stdlib only):

* the grader imports this file and calls ``read_input``, ``from_result`` / ``read_output`` and
  ``check`` in its own process (the reference answer never reaches the student's side);
* Kattis / problemtools run the exported copy (``python -m grader export-kattis obstacle-clearance OUT``) as an
  output validator: ``python3 checker.py input answer feedback_dir < team_output`` (exit 42
  accept, 43 reject, the reason in ``feedback_dir/judgemessage.txt``).

Tolerance: r is accepted when |r - r*| <= 1e-6 * r* + 1e-14 * M, where r* is the optimum and
M the largest absolute coordinate in the input; r* = inf needs r = inf.

Example:
    >>> check([[[0, 0], [2, 0]], [1, 1], [1, -1]], 1.0, 1.0)
    (True, 'ok')
    >>> check([[[0, 0], [2, 0]], [1, 1], [1, -1]], 0.9, 1.0)[0]
    False
"""
from __future__ import annotations

import math

REL_TOL = 1e-6
ABS_TOL = 1e-14   # times the largest absolute coordinate


LIBRARY = ("judge_io",)  # reference_impl/judge_io.py (points format, PresentationError), bound by the loader

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages


def read_input(text: str) -> list:
    """Parse the input format into the entry function's arguments ``[points, start, goal]``."""
    tok = text.split()
    n = int(tok[0])
    vals = [float(t) for t in tok[1:2 * n + 5]]
    points = [[vals[2 * i], vals[2 * i + 1]] for i in range(n)]
    return [points, vals[2 * n:2 * n + 2], vals[2 * n + 2:2 * n + 4]]


def write_input(args: list) -> str:
    points, start, goal = args
    return judge_io.write_points(points) + f"{start[0]!r} {start[1]!r}\n{goal[0]!r} {goal[1]!r}\n"  # noqa: F821


def write_output(r: float) -> str:
    return f"{float(r)!r}\n"


def _radius(v, where: str) -> float:
    if type(v) not in (int, float):
        raise PresentationError(f"{where} should be a number (float), got {type(v).__name__}: {show(v, 60)}",
                                kind="the radius is not a number")
    try:
        r = float(v)
    except OverflowError:  # an int of hundreds of digits
        raise PresentationError(f"{where}: the integer is too large for a float", kind="the radius is too large") from None
    if math.isnan(r) or r < 0:
        raise PresentationError(f"{where} should be a non-negative number or inf, got {r!r}")
    return r


def from_result(value, args: list) -> float:
    """Type-check what ``max_clearance`` returned: an int or float (``inf`` allowed), not a bool."""
    return _radius(value, "the returned radius")


def read_output(text: str, args: list) -> float:
    """Parse program output: one number (``inf`` when there is no obstacle)."""
    tok = text.split()
    if len(tok) != 1:
        raise PresentationError(f"expected one number, got {len(tok)} tokens: {show(text, 60)}")
    value = judge_io.parse_float(tok[0], "the printed radius")  # noqa: F821
    return _radius(value, "the printed radius")


def tolerance(args: list, expected: float) -> float:
    """The allowed absolute error for this test (see the module docstring)."""
    points, start, goal = args
    big = max([abs(c) for p in [*points, start, goal] for c in p] + [0.0])
    return REL_TOL * expected + ABS_TOL * big


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "no obstacle": "with no obstacle the radius is infinite",
    "too large": "the radius is too large",
    "too small": "the radius is too small",
}


@judge_io.mistake_kinds(MISTAKES, "the radius is wrong")  # noqa: F821 - bound by the loader
def check(args: list, r: float, expected: float) -> tuple[bool, str]:
    """Compare with the reference radius (the only possible way to judge an optimum here)."""
    if math.isinf(expected) or math.isinf(r):
        if r == expected:
            return True, "ok"
        return False, f"radius {r!r}, expected {expected!r}" + (" (there is no obstacle)" if math.isinf(expected) else "")
    tol = tolerance(args, expected)
    if abs(r - expected) <= tol:
        return True, "ok"
    hint = ("too large: no path keeps that clearance" if r > expected
            else "too small: a disk of a larger radius can still get through")
    return False, f"radius {r!r} is {hint} (expected {expected!r}, tolerance {tol:.3g})"


def draw(axes, args: list, received: float, expected: float) -> None:
    """Picture for reports: obstacles, start and goal with a disk of the expected radius (left)
    and of the received one (right). ``axes`` is a pair of matplotlib Axes."""
    from matplotlib.patches import Circle

    points, start, goal = args
    for ax, r, title, colour in ((axes[0], expected, "expected", "tab:blue"),
                                 (axes[1], received, "received", "tab:red")):
        ax.scatter([p[0] for p in points], [p[1] for p in points], s=12, color="black", zorder=3)
        for (x, y), label in ((start, "start"), (goal, "goal")):
            ax.plot([x], [y], marker="*", color=colour, ms=10)
            ax.annotate(label, (x, y), fontsize=7, xytext=(4, 4), textcoords="offset points")
            if r is not None and math.isfinite(r) and r > 0:
                ax.add_patch(Circle((x, y), r, fill=False, color=colour, lw=1))
        ax.set_title(f"{title}: r = {r!r}", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")

