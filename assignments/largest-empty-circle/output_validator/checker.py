"""Checker for `largest-empty-circle`: the received circle must be empty, centred in the convex
hull, and of optimal radius, each within a stated tolerance (stdlib only).

Two uses, one logic:

* the grader imports this file and calls ``read_input``, ``from_result`` / ``read_output`` and
  ``check`` in its own process (the reference answer never reaches the student's side);
* Kattis / problemtools run the exported copy (``python -m grader export-kattis largest-empty-circle OUT``) as an
  output validator: ``python3 checker.py input answer feedback_dir < team_output`` (exit 42
  accept, 43 reject, the reason in ``feedback_dir/judgemessage.txt``).

Tolerance: with r* the optimal radius and M the largest absolute coordinate, eps = 1e-6 * r* +
1e-14 * M. Accepted: |r - r*| <= eps, every point at distance >= r - eps from the centre, and the
centre at distance <= eps outside every edge of the convex hull (computed exactly, in integers).
Any optimal circle is accepted when several exist.

Example:
    >>> check([[[0, 0], [4, 0], [4, 4], [0, 4]]], [2.0, 2.0, 8 ** 0.5], [2.0, 2.0, 8 ** 0.5])
    (True, 'ok')
    >>> check([[[0, 0], [4, 0], [4, 4], [0, 4]]], [5.0, 2.0, 8 ** 0.5], [2.0, 2.0, 8 ** 0.5])[1][:42]
    'point 1 (4, 0) is strictly inside the circ'
"""
from __future__ import annotations

import math

REL_TOL = 1e-6
ABS_TOL = 1e-14   # times the largest absolute coordinate


LIBRARY = ("judge_io",)  # reference_impl/judge_io.py (points format, PresentationError), bound by the loader

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages


def read_input(text: str) -> list:
    """Parse the input format into the entry function's argument list ``[points]``."""
    return [judge_io.read_points(text)]  # noqa: F821


def write_input(args: list) -> str:
    return judge_io.write_points(args[0])  # noqa: F821


def write_output(circle) -> str:
    x, y, r = circle
    return f"{float(x)!r} {float(y)!r} {float(r)!r}\n"


def _circle(values, where: str) -> list[float]:
    if len(values) != 3:
        raise PresentationError(f"{where} should be 3 numbers [x, y, r], got {len(values)}: {show(values, 60)}")
    out = []
    for name, v in zip("xyr", values):
        out.append(judge_io.number(v, f"{where}: {name}", "a coordinate or the radius"))  # noqa: F821
    if out[2] < 0:
        raise PresentationError(f"{where}: the radius {out[2]!r} is negative")
    return out


def from_result(value, args: list) -> list[float]:
    """Type-check what ``largest_empty_circle`` returned: ``[x, y, r]`` of finite numbers, r >= 0."""
    if not isinstance(value, list):
        raise PresentationError(f"expected [x, y, r], got {type(value).__name__}: {show(value, 60)}")
    return _circle(value, "the returned circle")


def read_output(text: str, args: list) -> list[float]:
    """Parse program output: one line ``x y r``."""
    tok = text.split()
    if len(tok) != 3:
        raise PresentationError(f"expected three numbers 'x y r', got {len(tok)} tokens: {show(text, 60)}",
                                kind="expected three numbers x y r")
    values = [judge_io.parse_float(t, "the printed circle", "three numbers x y r") for t in tok]  # noqa: F821
    return _circle(values, "the printed circle")


def _exact(points: list) -> list[tuple[int, int]]:
    """All coordinates times one power of two, as Python integers (exact)."""
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def convex_hull(points: list) -> list[int]:
    """Indices of the strict convex hull, counter-clockwise (exact; monotone chain).

    >>> convex_hull([[0, 0], [2, 0], [1, 0], [1, 1], [1, 0.5]])
    [0, 1, 3]
    """
    P = _exact(points)
    order = sorted(range(len(P)), key=lambda i: P[i])

    def cross(o, a, b):
        return (P[a][0] - P[o][0]) * (P[b][1] - P[o][1]) - (P[a][1] - P[o][1]) * (P[b][0] - P[o][0])

    def chain(ids):
        out = []
        for i in ids:
            if out and P[out[-1]] == P[i]:
                continue
            while len(out) >= 2 and cross(out[-2], out[-1], i) <= 0:
                out.pop()
            out.append(i)
        return out

    lower, upper = chain(order), chain(order[::-1])
    return lower[:-1] + upper[:-1]


#: id(points) -> (points, a copy of its rows, its convex_hull): a judge checks every student's circle
#: against the same point list, whose exact hull is the check's dearest part; bounded by _HULLS_MAX points
_HULLS: dict = {}
_HULLS_MAX = 2_000_000


def _hull_of(points) -> list[int]:
    """:func:`convex_hull` of ``points``, kept for the same list checked again (the same object,
    still equal to the copy taken then)."""
    if type(points) is not list:
        return convex_hull(points)
    hit = _HULLS.get(id(points))
    if hit is not None and hit[0] is points and hit[1] == points:
        return hit[2]
    hull = convex_hull(points)
    if sum(len(h[1]) for h in _HULLS.values()) + len(points) > _HULLS_MAX:
        _HULLS.clear()
    _HULLS[id(points)] = (points, [list(p) for p in points], hull)
    return hull


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "strictly inside the circle": "a point lies strictly inside the circle",
    "outside the convex hull": "the centre is outside the convex hull",
    "not the largest": "the radius is too small",
    "larger than the optimum": "the radius is too large",
}


@judge_io.mistake_kinds(MISTAKES, "the circle is wrong")  # noqa: F821 - bound by the loader
def check(args: list, circle: list[float], expected: list[float]) -> tuple[bool, str]:
    """Emptiness, centre in the hull and optimality (see the module docstring)."""
    (points,) = args
    x, y, r = circle
    r_opt = expected[2]
    big = max(abs(c) for p in points for c in p)
    k = math.frexp(big)[1] if big > 0 else 0           # work at unit scale: no overflow at 1e300

    def s(v: float) -> float:
        try:
            return math.ldexp(v, -k)
        except OverflowError:                           # a far-away answer at a tiny scale
            return math.copysign(math.inf, v)

    X, Y, R, ROPT = s(x), s(y), s(r), s(r_opt)
    eps = REL_TOL * ROPT + ABS_TOL * s(big)
    if not (math.isfinite(X) and math.isfinite(Y)):
        return False, f"the centre ({x!r}, {y!r}) is far outside the convex hull"
    for i, (px, py) in enumerate(points):
        d = math.hypot(s(px) - X, s(py) - Y)
        if d < R - eps:
            return False, (f"point {i} ({px!r}, {py!r}) is strictly inside the circle: its distance to the "
                           f"centre is {d * 2.0 ** k!r} < r = {r!r}")
    hull = _hull_of(points)
    for a, b in zip(hull, hull[1:] + hull[:1]):
        ax, ay, bx, by = s(points[a][0]), s(points[a][1]), s(points[b][0]), s(points[b][1])
        length = math.hypot(bx - ax, by - ay)
        if length == 0.0:          # an edge far below the tolerance at this scale
            continue
        out = -((bx - ax) * (Y - ay) - (by - ay) * (X - ax)) / length
        if not out <= eps:
            return False, (f"the centre ({x!r}, {y!r}) is outside the convex hull: {out * 2.0 ** k:.3g} beyond its "
                           f"edge from point {a} to point {b}")
    if R < ROPT - eps:
        return False, f"radius {r!r} is not the largest: a circle of radius {r_opt!r} exists (tolerance {eps * 2.0 ** k:.3g})"
    if R > ROPT + eps:
        return False, f"radius {r!r} is larger than the optimum {r_opt!r}: such a circle cannot be empty"
    return True, "ok"


def draw(axes, args: list, received: list[float], expected: list[float]) -> None:
    """Picture for reports: the points and their hull with the expected circle (left) and the
    received one (right). ``axes`` is a pair of matplotlib Axes."""
    from matplotlib.patches import Circle

    (points,) = args
    hull = convex_hull(points)
    for ax, c, title, colour in ((axes[0], expected, "expected (one optimal answer)", "tab:blue"),
                                 (axes[1], received, "received", "tab:red")):
        cyc = hull + hull[:1]
        ax.plot([points[i][0] for i in cyc], [points[i][1] for i in cyc], color="0.7", lw=0.8)
        ax.scatter([p[0] for p in points], [p[1] for p in points], s=10, color="black", zorder=3)
        if c is not None:
            ax.add_patch(Circle((c[0], c[1]), c[2], fill=False, color=colour, lw=1.2))
            ax.plot([c[0]], [c[1]], marker="+", color=colour)
            ax.set_title(f"{title}: r = {c[2]:.6g}", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")

