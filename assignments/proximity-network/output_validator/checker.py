"""Checker for `proximity-network`: accepts exactly the Gabriel graph (exact arithmetic).

Points i and j (distinct positions) are linked when no other point lies in the *closed* disc
with diameter ij, that is (r - i) . (r - j) > 0 for every other point r. The graph is unique, so
the received edge set (either endpoint order, any edge order) must equal the reference's, with
repeated points named by their smallest index. A wrong answer's message names a missing edge, or an
extra edge together with a point inside (or on) its disc, found with exact integer arithmetic
(``reference_impl/exact/verify.py`` scaling). The reference's edges, each once in any order, are
accepted at once (``reference_impl/exact/edgesets.py``); anything else gets the full check. The grader loads this file with the shared loader
(``grader/checker_runtime.py``); ``export-kattis`` makes it a self-contained Kattis output validator.

Example:
    >>> check([[[0, 0], [1, 0], [1, 1], [0, 1]]], [[1, 0], [1, 2], [2, 3], [0, 3]], [[0, 1], [0, 3], [1, 2], [2, 3]])
    (True, 'ok')
"""
from __future__ import annotations

LIBRARY = ("judge_io", "verify", "edgesets")  # bound as globals by the shared loader

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages


def read_input(text: str) -> list:
    """``[points]`` from ``n`` and ``n`` lines ``x y``."""
    return [judge_io.read_points(text)]  # noqa: F821


def write_input(args: list) -> str:
    return judge_io.write_points(args[0])  # noqa: F821


def _limit(args) -> int:
    return 3 * len(args[0]) + 8  # a planar graph has fewer than 3n edges: more is rejected at once


def from_result(value, args: list) -> list[list[int]]:
    """A returned list of ``[i, j]`` int pairs."""
    return judge_io.index_rows(value, 2, "edge", _limit(args))  # noqa: F821


def read_output(text: str, args: list) -> list[list[int]]:
    """Program output: ``m``, then ``m`` lines ``i j``."""
    return judge_io.read_index_rows(text, 2, "edge", _limit(args))  # noqa: F821


def write_output(edges: list) -> str:
    return judge_io.write_index_rows(edges)  # noqa: F821


def _edge_errors(points: list, edges: list) -> tuple[str, set, list, dict]:
    """The first problem of the edge list on its own ("" if none), its edges as ``(min, max)``
    pairs, the exact points and each position's smallest index."""
    n = len(points)
    P = verify.exact_coordinates(points)  # noqa: F821
    first: dict = {}
    for k, p in enumerate(P):
        first.setdefault(p, k)
    seen: set = set()
    for k, (i, j) in enumerate(edges):
        for v in (i, j):
            if not 0 <= v < n:
                return f"edge {k} = [{i}, {j}] uses index {v}, outside 0..{n - 1}", seen, P, first
            if first[P[v]] != v:
                return (f"edge {k} = [{i}, {j}]: point {v} repeats point {first[P[v]]}; "
                        f"name repeated points by their smallest index ({first[P[v]]})"), seen, P, first
        if i == j:
            return f"edge {k} = [{i}, {j}] joins a point to itself", seen, P, first
        e = (min(i, j), max(i, j))
        if e in seen:
            return f"edge {k} = [{i}, {j}] is listed twice", seen, P, first
        seen.add(e)
    return "", seen, P, first


def _witness(P: list, i: int, j: int, first: dict) -> int | None:
    """A point (smallest index of its position) in the closed disc with diameter ij, or None."""
    (xi, yi), (xj, yj) = P[i], P[j]
    for r, (x, y) in enumerate(P):
        if first[P[r]] == r and r != i and r != j and (x - xi) * (x - xj) + (y - yi) * (y - yj) <= 0:
            return r
    return None


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "outside 0..": "an edge uses an index out of range",
    "repeats point": "a repeated point is not named by its smallest index",
    "to itself": "an edge joins a point to itself",
    "listed twice": "an edge is listed twice",
    "is not a Gabriel edge": "an edge is not a Gabriel edge",
    "missing the Gabriel edge": "a Gabriel edge is missing",
}


@judge_io.mistake_kinds(MISTAKES, "not the Gabriel graph")  # noqa: F821 - bound by the loader
def check(args: list, edges: list[list[int]], expected: list[list[int]] | None) -> tuple[bool, str]:
    """Exact check; ``expected`` is the Gabriel graph (the reference answer)."""
    (points,) = args
    if expected is not None and edgesets.same_edge_set(  # noqa: F821 - the reference's edges, each once
            points, edges, expected, lambda: not _edge_errors(points, expected)[0]):
        return True, "ok"
    problem, seen, P, first = _edge_errors(points, edges)
    if problem:
        return False, problem
    if expected is None:
        return True, "ok (not compared with the Gabriel graph)"
    want = {(min(i, j), max(i, j)) for i, j in expected}
    if seen == want:
        return True, "ok"
    extra, missing = sorted(seen - want), sorted(want - seen)
    counts = f"you gave {len(seen)} edges, the Gabriel graph has {len(want)}"
    if extra:
        i, j = extra[0]
        r = _witness(P, i, j, first)
        where = "on the boundary of" if r is not None and _on_circle(P, i, j, r) else "inside"
        why = f": point {r} lies {where} the closed disc with diameter {i}-{j}" if r is not None else ""
        return False, f"[{i}, {j}] is not a Gabriel edge{why} ({counts}; {len(extra)} extra, {len(missing)} missing)"
    i, j = missing[0]
    return False, (f"missing the Gabriel edge [{i}, {j}]: no other point lies in the closed disc with "
                   f"diameter {i}-{j} ({counts}; {len(missing)} missing)")


def _on_circle(P: list, i: int, j: int, r: int) -> bool:
    (xi, yi), (xj, yj), (x, y) = P[i], P[j], P[r]
    return (x - xi) * (x - xj) + (y - yi) * (y - yj) == 0


def draw(axes, args: list, received: list[list[int]], expected: list[list[int]] | None) -> None:
    """Picture for reports: the Gabriel graph (left) and the received edges (right)."""
    judge_io.draw_edges(axes, args[0], received, expected, "the Gabriel graph")  # noqa: F821
