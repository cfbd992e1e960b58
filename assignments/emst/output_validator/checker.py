"""Checker for `emst`: accepts any spanning tree of the n input points of minimum total length.

Exact: the answer must be a spanning tree of all n indices (n - 1 edges, no cycle), and its sorted
list of squared edge lengths, computed exactly from the input doubles (Python integers after one
common power-of-two scaling, ``reference_impl/exact/verify.py``), must equal the reference tree's. Every
minimum spanning tree has the same sorted lengths, and a spanning tree with those lengths has the
minimum total, so this accepts exactly the optimal trees, whatever the ties. The reference's own
edges (each once, in any order) are accepted at once (``reference_impl/exact/edgesets.py``), and
another spanning tree compares only the edges it does not share with the reference's. The grader loads this
file with the shared loader (``grader/checker_runtime.py``); ``export-kattis`` makes it a
self-contained Kattis output validator.

Example:
    >>> check([[[0, 0], [1, 0], [0, 2]]], [[1, 0], [0, 2]], [[0, 1], [0, 2]])
    (True, 'ok')
"""
from __future__ import annotations

import math

LIBRARY = ("judge_io", "verify", "edgesets")  # bound as globals by the shared loader

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages
EXPLAIN_MAX_N = 300  # below this, a wrong tree's message names an edge swap that shortens it


def read_input(text: str) -> list:
    """``[points]`` from ``n`` and ``n`` lines ``x y``."""
    return [judge_io.read_points(text)]  # noqa: F821


def write_input(args: list) -> str:
    return judge_io.write_points(args[0])  # noqa: F821


def _limit(args) -> int:
    return 2 * len(args[0]) + 8  # far above n - 1: rejected at once, before any work on it


def from_result(value, args: list) -> list[list[int]]:
    """A returned list of ``[i, j]`` int pairs."""
    return judge_io.index_rows(value, 2, "edge", _limit(args))  # noqa: F821


def read_output(text: str, args: list) -> list[list[int]]:
    """Program output: ``m``, then ``m`` lines ``i j``."""
    return judge_io.read_index_rows(text, 2, "edge", _limit(args))  # noqa: F821


def write_output(edges: list) -> str:
    return judge_io.write_index_rows(edges)  # noqa: F821


def _find(parent: list[int], i: int) -> int:
    while parent[i] != i:
        parent[i] = parent[parent[i]]
        i = parent[i]
    return i


def _tree_errors(points: list, edges: list) -> str:
    n = len(points)
    if len(edges) != max(n - 1, 0):
        distinct = len({(float(x), float(y)) for x, y in points})
        hint = (" (join each repeated point to a copy of it by a zero-length edge)"
                if len(edges) == distinct - 1 < n - 1 else "")
        return f"a spanning tree of n = {n} points has {max(n - 1, 0)} edges, you gave {len(edges)}{hint}"
    parent = list(range(n))
    for k, (i, j) in enumerate(edges):
        for v in (i, j):
            if not 0 <= v < n:
                return f"edge {k} = [{i}, {j}] uses index {v}, outside 0..{n - 1}"
        if i == j:
            return f"edge {k} = [{i}, {j}] joins a point to itself"
        a, b = _find(parent, i), _find(parent, j)
        if a == b:
            return f"edge {k} = [{i}, {j}] closes a cycle: {i} and {j} are already connected"
        parent[a] = b
    return ""


def _swap_hint(P, edges, expected, length) -> str:
    """An edge of the optimal tree whose cycle in the received tree has a longer edge."""
    adj: dict[int, list[int]] = {}
    for i, j in edges:
        adj.setdefault(i, []).append(j)
        adj.setdefault(j, []).append(i)
    have = {tuple(sorted(e)) for e in edges}
    for c, d in expected:
        if tuple(sorted((c, d))) in have:
            continue
        prev = {c: c}
        stack = [c]
        while stack:
            u = stack.pop()
            for v in adj.get(u, ()):
                if v not in prev:
                    prev[v] = u
                    stack.append(v)
        path, v = [], d
        while v != c:
            path.append((prev[v], v))
            v = prev[v]
        worst = max(path, key=lambda e: length(*e))
        if length(*worst) > length(c, d):
            return (f"; replacing your edge [{min(worst)}, {max(worst)}] by [{min(c, d)}, {max(c, d)}] "
                    "gives a shorter spanning tree")
    return ""


def _exact(points: list, expected) -> list:
    """``verify.exact_coordinates(points)``, kept for the next student's check of the same test."""
    return edgesets.remembered(points, expected, "exact", lambda: verify.exact_coordinates(points))  # noqa: F821


def _lengths_agree_off_common(points: list, edges: list, expected: list) -> bool:
    """True only when the sorted exact squared lengths of ``edges`` equal ``expected``'s (False: ask
    the full comparison, which writes the message). Both are lists of distinct edges, so the edges
    they share cancel: it compares only the edges in one and not the other."""
    got, want = edgesets.edge_keys(edges), edgesets.edge_keys(expected)  # noqa: F821
    if len(got) != len(edges) or len(want) != len(expected):
        return False  # a repeated edge: the full comparison decides
    mine, theirs = got - want, want - got
    if len(mine) != len(theirs):
        return False
    P = _exact(points, expected)

    def length(e) -> int:
        (ax, ay), (bx, by) = P[e[0]], P[e[1]]
        return (ax - bx) ** 2 + (ay - by) ** 2

    return sorted(map(length, mine)) == sorted(map(length, theirs))


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "edges, you gave": "the number of edges is not n minus one",
    "outside 0..": "an edge uses an index out of range",
    "to itself": "an edge joins a point to itself",
    "cycle": "the edges contain a cycle",
    "not exactly": "not a minimum spanning tree (compare lengths exactly)",
}


@judge_io.mistake_kinds(MISTAKES, "not a minimum spanning tree")  # noqa: F821 - bound by the loader
def check(args: list, edges: list[list[int]], expected: list[list[int]] | None) -> tuple[bool, str]:
    """Exact check; ``expected`` is a minimum spanning tree (the reference answer)."""
    (points,) = args
    if expected is not None and edgesets.same_edge_set(  # noqa: F821 - the reference's tree, each edge once
            points, edges, expected, lambda: not _tree_errors(points, expected)):
        return True, "ok"
    problem = _tree_errors(points, edges)
    if problem:
        return False, problem
    if expected is None:
        return True, "ok (a spanning tree; not compared with an optimum)"
    if _lengths_agree_off_common(points, edges, expected):
        return True, "ok"
    P = _exact(points, expected)

    def length(i: int, j: int) -> int:
        return (P[i][0] - P[j][0]) ** 2 + (P[i][1] - P[j][1]) ** 2

    got = sorted(length(i, j) for i, j in edges)
    best = sorted(length(i, j) for i, j in expected)
    if got == best:
        return True, "ok"

    def total(es) -> float:
        return math.fsum(math.hypot(points[i][0] - points[j][0], points[i][1] - points[j][1]) for i, j in es)

    k = next(k for k, (a, b) in enumerate(zip(got, best)) if a != b)
    mine, opt = total(edges), total(expected)
    if mine == opt:
        how = (f"the total lengths agree in floating point ({mine!r}) but not exactly: compare lengths "
               "exactly (squared lengths as integers or fractions.Fraction), not as floats")
    else:
        how = f"your total length is {mine!r}, the minimum is {opt!r}"
    message = (f"a spanning tree, but not a minimum one: {how}; sorted by length, your edge number {k} "
               f"is {'longer' if got[k] > best[k] else 'shorter'} than in an optimal tree")
    if len(points) <= EXPLAIN_MAX_N:
        message += _swap_hint(P, edges, expected, length)
    return False, message


def draw(axes, args: list, received: list[list[int]], expected: list[list[int]] | None) -> None:
    """Picture for reports: an optimal tree (left) and the received edges (right)."""
    judge_io.draw_edges(axes, args[0], received, expected, "an optimal tree")  # noqa: F821
