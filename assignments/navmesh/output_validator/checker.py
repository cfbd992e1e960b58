"""Checker for `navmesh`: accepts any path from start to goal inside the closed free space whose
length is optimal within a relative tolerance of 1e-9.

Exact where it decides: every point and segment of the received path is tested exactly (Fractions
of the doubles, ``reference_impl/exact/free_space.py``) against the closed free space (inside or on the
boundary, not strictly inside a hole: walls may be touched and followed). The length (``hypot`` per
segment, ``fsum``) must satisfy ``L <= L_ref * (1 + 1e-9)``; ``None`` ("no path") is right exactly
when the reference is ``None`` (start or goal outside the free space). A path has at most
2 + (number of polygon vertices) points: longer answers are rejected before any work on them.

Example:
    >>> room = [[0, 0], [10, 0], [10, 10], [0, 10]]
    >>> check([room, [], [1, 1], [9, 1]], [[1, 1], [9, 1]], [[1.0, 1.0], [9.0, 1.0]])
    (True, 'ok')
"""
from __future__ import annotations

import math

LIBRARY = ("judge_io", "free_space")  # bound as globals by the shared loader

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages
RELATIVE_TOLERANCE = 1e-9
EXPLAIN_MAX_VERTICES = 60  # below this, a failing message shows the whole input


def read_input(text: str) -> list:
    """``[boundary, holes, start, goal]`` from the text format (see the statement)."""
    tok = text.split()
    pos = 0

    def ring():
        nonlocal pos
        n = int(tok[pos])
        pts = [[float(tok[pos + 1 + 2 * i]), float(tok[pos + 2 + 2 * i])] for i in range(n)]
        pos += 1 + 2 * n
        return pts

    boundary = ring()
    h = int(tok[pos])
    pos += 1
    holes = [ring() for _ in range(h)]
    start = [float(tok[pos]), float(tok[pos + 1])]
    goal = [float(tok[pos + 2]), float(tok[pos + 3])]
    return [boundary, holes, start, goal]


def write_input(args: list) -> str:
    boundary, holes, start, goal = args
    return (judge_io.write_points(boundary) + f"{len(holes)}\n"  # noqa: F821
            + "".join(judge_io.write_points(h) for h in holes)  # noqa: F821
            + f"{float(start[0])!r} {float(start[1])!r}\n{float(goal[0])!r} {float(goal[1])!r}\n")


def _limit(args) -> int:
    return 2 + len(args[0]) + sum(len(h) for h in args[1])


def _number(v, where: str) -> float:
    return judge_io.number(v, where)  # noqa: F821 - finite float or PresentationError, never OverflowError


def from_result(value, args: list) -> list[list[float]] | None:
    """A returned list of ``[x, y]`` number pairs, or ``None``."""
    if value is None:
        return None
    if not isinstance(value, (list, tuple)):
        raise PresentationError(f"expected a list of [x, y] points or None, got a {type(value).__name__}")
    if len(value) > _limit(args):
        raise PresentationError(f"a path with {len(value)} points: a shortest path has at most {_limit(args)} "
                                "(start, goal and polygon corners, each once)")
    path = []
    for k, p in enumerate(value):
        if not isinstance(p, (list, tuple)) or len(p) != 2:
            raise PresentationError(f"point {k}: expected [x, y], got {show(p, 60)}")
        path.append([_number(p[0], f"point {k}"), _number(p[1], f"point {k}")])
    return path


def read_output(text: str, args: list) -> list[list[float]] | None:
    """Program output: ``k``, then ``k`` lines ``x y``; ``k = 0`` means no path (None)."""
    tok = text.split()
    if not tok:
        raise PresentationError("empty output: expected the number of path points k (0 for no path)")
    k = judge_io.parse_int(tok[0], "the first token", "the number of points k")  # noqa: F821
    if k < 0 or k > _limit(args):
        raise PresentationError(f"k = {k}: a shortest path has between 1 and {_limit(args)} points (0 for no path)")
    if len(tok) != 1 + 2 * k:
        raise PresentationError(f"expected {2 * k} coordinates after k = {k}, got {len(tok) - 1} tokens")
    if k == 0:
        return None
    path = []
    for i in range(k):
        p = [judge_io.parse_float(tok[1 + 2 * i], f"point {i}"), judge_io.parse_float(tok[2 + 2 * i], f"point {i}")]  # noqa: F821
        if not all(math.isfinite(c) for c in p):
            raise PresentationError(f"point {i}: coordinates must be finite", kind="a coordinate is not finite")
        path.append(p)
    return path


def write_output(path) -> str:
    if path is None:
        return "0\n"
    return f"{len(path)}\n" + "".join(f"{float(x)!r} {float(y)!r}\n" for x, y in path)


def _where(args) -> str:
    boundary, holes, start, goal = args
    if _limit(args) - 2 > EXPLAIN_MAX_VERTICES:
        return ""
    return f" (boundary {boundary}, holes {holes}, start {start}, goal {goal})"


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "the answer is None": "start or goal is outside the free space: the answer is None",
    "you answered None": "a path exists, but the answer is None",
    "empty": "the path is empty",
    "starts at": "the path does not start at start",
    "ends at": "the path does not end at goal",
    "outside the free space": "a path point is outside the free space",
    "leaves the free space": "a segment leaves the free space",
    "the shortest has length": "the path is longer than the shortest",
}


@judge_io.mistake_kinds(MISTAKES, "the path is wrong")  # noqa: F821 - bound by the loader
def check(args: list, path, expected) -> tuple[bool, str]:
    """``expected`` is a shortest path or None (the reference answer)."""
    boundary, holes, start, goal = args
    if expected is None:
        if path is None:
            return True, "ok"
        return False, "start or goal lies outside the free space: the answer is None (0 in text mode)" + _where(args)
    if path is None:
        return False, ("you answered None, but start and goal both lie in the closed free space (points on a "
                       "wall count as inside) and a path exists" + _where(args))
    s, g = [float(c) for c in start], [float(c) for c in goal]
    if not path:
        return False, "the path is empty: it must start at start and end at goal"
    if path[0] != s:
        return False, f"the path starts at {path[0]}, not at start {s}"
    if path[-1] != g:
        return False, f"the path ends at {path[-1]}, not at goal {g}"
    problem = free_space.path_problem(path, boundary, holes)  # noqa: F821
    if problem:
        return False, problem + _where(args)
    mine, best = free_space.path_length(path), free_space.path_length(expected)  # noqa: F821
    if mine > best * (1 + RELATIVE_TOLERANCE):
        return False, (f"your path (inside the free space) has length {mine!r}, the shortest has length {best!r}"
                       f"; a shortest path bends only at polygon corners{_where(args)}")
    return True, "ok"


def draw(axes, args: list, received, expected) -> None:
    """Picture for reports: the room with the shortest path (left) and the received path (right)."""
    boundary, holes, start, goal = args
    for ax, path, title in zip(axes, (expected, received), ("a shortest path", "received")):
        for ring, colour in [(boundary, "black")] + [(h, "grey") for h in holes]:
            xs, ys = zip(*(list(ring) + [ring[0]]))
            ax.fill(xs, ys, color=colour if colour == "grey" else "none", alpha=0.5 if colour == "grey" else 1)
            ax.plot(xs, ys, color=colour, lw=1)
        if path:
            ax.plot([p[0] for p in path], [p[1] for p in path], color="tab:red", lw=2, marker="o", ms=3)
        ax.scatter([start[0], goal[0]], [start[1], goal[1]], color="tab:blue", zorder=3)
        ax.set_title(title if path is not None else f"{title}: None", fontsize=9)
        ax.set_aspect("equal")
