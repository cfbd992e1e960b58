"""Checker for `edge-flip`: replays the submitted flips exactly and checks the result is Delaunay.

The grader imports this file and calls ``read_input``, ``from_result`` / ``read_output`` and
``check`` in its own process; ``python -m grader export-kattis edge-flip OUT`` turns it into a
self-contained Kattis output validator (``checker.py input answer feedback_dir < team_output``).

Each flip ``[a, b]`` must be, at its turn, an interior edge of the current triangulation (two
triangles ``a b c`` and ``b a d`` on its sides) that is *not locally Delaunay*: ``d`` strictly
inside the circumcircle of ``a b c`` (then the quadrilateral is strictly convex; this is checked
too). The edge is replaced by ``c d``. After the last flip the triangulation must be Delaunay
(``verify.check_delaunay``). Every decision is exact (``verify``'s predicates: a float filter with a proven
error bound, Python integers where it cannot decide). A valid answer is accepted by a faster pass
first (``flip_replay.accepts``: the flips' topology replayed alone, in compiled code on a long
answer when numba is there, then every flip's predicates decided at once); whatever it does not
accept is replayed here flip by flip, which gives the verdict and the message.

Example:
    >>> check([[[0, 0], [4, 0], [4, 1], [0, 3]], [[0, 1, 3], [1, 2, 3]]], [[1, 3]], None)
    (True, 'ok')
    >>> check([[[0, 0], [4, 0], [4, 1], [0, 3]], [[0, 1, 3], [1, 2, 3]]], [], None)[0]
    False
"""
from __future__ import annotations

from itertools import chain

LIBRARY = ("judge_io", "verify", "bulk", "flip_replay")  # bound as globals by the shared loader
SMALL = 16                        # triangulations up to this many points are quoted in messages

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages


def read_input(text: str) -> list:
    """Parse ``n m``, n lines ``x y``, m lines ``i j k`` into ``[points, triangles]``."""
    tok = text.split()
    n, m = int(tok[0]), int(tok[1])
    points = [[float(tok[2 + 2 * i]), float(tok[3 + 2 * i])] for i in range(n)]
    base = 2 + 2 * n
    triangles = [[int(tok[base + 3 * k]), int(tok[base + 3 * k + 1]), int(tok[base + 3 * k + 2])] for k in range(m)]
    return [points, triangles]


def write_input(args: list) -> str:
    points, triangles = args
    return (f"{len(points)} {len(triangles)}\n" + "".join(f"{float(x)!r} {float(y)!r}\n" for x, y in points)
            + "".join(f"{a} {b} {c}\n" for a, b, c in triangles))


def write_output(flips: list) -> str:
    return judge_io.write_index_rows(flips)  # noqa: F821


def max_flips(n: int) -> int:
    """No flip sequence of this problem is longer than the number of point pairs: an edge that a
    Delaunay flip removes can never come back (each flip lowers the lifted surface).

    >>> max_flips(4)
    6
    """
    return n * (n - 1) // 2


def _limit(args) -> int:
    return max_flips(len(args[0])) if args is not None else 10 ** 12


def from_result(value, args: list) -> list[list[int]]:
    """Type-check what the entry function returned (JSON data): a list of [a, b] int pairs."""
    if (type(value) is list and 0 < len(value) <= _limit(args) and set(map(type, value)) == {list}
            and set(map(len, value)) == {2} and set(map(type, chain.from_iterable(value))) == {int}):
        return value  # the common case, checked in C loops (the checker never changes the rows)
    return judge_io.index_rows(value, 2, "flip", _limit(args))  # noqa: F821


def read_output(text: str, args: list | None) -> list[list[int]]:
    """Parse program output: f, then f lines 'a b'."""
    return judge_io.read_index_rows(text, 2, "flip", _limit(args))  # noqa: F821


def _where(flips, s: int) -> str:
    """``flip s = [a, b]`` as submitted (formatted only when a message quotes it)."""
    return f"flip {s} = [{flips[s][0]}, {flips[s][1]}]"


def replay(points, triangles, flips) -> tuple[list | None, str]:
    """Apply the flips one by one; ``(final triangles, "ok")`` or ``(None, what is wrong)``.

    >>> replay([[0, 0], [4, 0], [4, 1], [0, 3]], [[0, 1, 3], [1, 2, 3]], [[1, 3]])[0]
    [[2, 3, 0], [0, 1, 2]]
    """
    P, rep, orient, incircle = verify.indexed_predicates(points)  # noqa: F821 - exact, on indices
    n = len(P)
    opp = {}                              # directed edge (u, v) -> w of the CCW triangle (u, v, w)
    for a, b, c in triangles:
        a, b, c = rep[a], rep[b], rep[c]
        opp[(a, b)], opp[(b, c)], opp[(c, a)] = c, a, b
    for s, (a, b) in enumerate(flips):
        if not (0 <= a < n and 0 <= b < n):
            return None, f"{_where(flips, s)}: index outside 0..{n - 1}"
        a, b = rep[a], rep[b]
        c, d = opp.get((a, b)), opp.get((b, a))
        if c is None and d is None:
            return None, f"{_where(flips, s)} is not an edge of the current triangulation (after {s} flips)"
        if c is None or d is None:
            return None, f"{_where(flips, s)} is a convex hull edge: only interior edges can be flipped"
        if incircle(a, b, c, d) <= 0:
            tie = "on" if incircle(a, b, c, d) == 0 else "outside"
            return None, (f"{_where(flips, s)} is already locally Delaunay (point {d} is {tie} the circumcircle of "
                          f"triangle {a} {b} {c}): only illegal edges may be flipped")
        if orient(c, d, b) <= 0 or orient(d, c, a) <= 0:   # cannot happen if illegal
            return None, f"{_where(flips, s)}: its quadrilateral {a} {d} {b} {c} is not strictly convex"
        for e in ((a, b), (b, c), (c, a), (b, a), (a, d), (d, b)):
            del opp[e]
        opp[(c, a)], opp[(a, d)], opp[(d, c)] = d, c, a       # triangle (c, a, d)
        opp[(d, b)], opp[(b, c)], opp[(c, d)] = c, d, b       # triangle (d, b, c)
    seen, final = set(), []
    for (u, v), w in opp.items():
        key = frozenset((u, v, w))
        if key not in seen:
            seen.add(key)
            final.append([u, v, w])
    return final, "ok"


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "index outside": "a flip uses an index out of range",
    "not an edge": "a flip is not an edge of the current triangulation",
    "convex hull edge": "a flip is of a convex hull edge",
    "already locally Delaunay": "a flipped edge was already locally Delaunay",
    "strictly convex": "a flip of a non-convex quadrilateral",
    "not Delaunay": "the final triangulation is not Delaunay",
}


@judge_io.mistake_kinds(MISTAKES, "the flips are wrong")  # noqa: F821 - bound by the loader
def check(args: list, flips: list[list[int]], expected: list[list[int]] | None) -> tuple[bool, str]:
    """Replay and check; ``expected`` (the reference flips) only improves the message."""
    points, triangles = args
    if flip_replay.accepts(points, triangles, flips, verify, bulk):  # noqa: F821 - a fast pass that only accepts
        return True, "ok"
    final, message = replay(points, triangles, flips)
    if final is not None:
        ok, why = verify.check_delaunay(points, final, bulk)  # noqa: F821
        if ok:
            return True, "ok"
        message = f"after your {len(flips)} flips the triangulation is not Delaunay: {why}"
        if expected is not None:
            message += f" (Lawson's algorithm needs {len(expected)} flips here)"
    if len(points) <= SMALL:
        message += f"; points: {points}; starting triangles: {triangles}"
    return False, message


def draw(axes, args: list, received: list[list[int]], expected: list[list[int]] | None) -> None:
    """Picture for reports: the starting triangulation with the expected (left) and the received
    (right) flipped edges highlighted. ``axes`` is a pair of matplotlib Axes."""
    points, triangles = args
    for ax, flips, title, colour in ((axes[0], expected or [], "reference flips", "tab:blue"),
                                     (axes[1], received or [], "your flips", "tab:red")):
        for t in triangles:
            cyc = [t[0], t[1], t[2], t[0]]
            ax.plot([points[v][0] for v in cyc], [points[v][1] for v in cyc], color="0.7", lw=0.6)
        for a, b in flips:
            if 0 <= a < len(points) and 0 <= b < len(points):
                ax.plot([points[a][0], points[b][0]], [points[a][1], points[b][1]], color=colour, lw=1.2)
        ax.scatter([p[0] for p in points], [p[1] for p in points], s=8, color="black", zorder=3)
        ax.set_title(f"{title}: {len(flips)} edges flipped (drawn on the start)", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
