"""Fast acceptance of an edge-list answer that is the reference's edge set (stdlib only).

The checkers of ``proximity-network`` (the Gabriel graph: one right answer) and ``emst`` (most
answers are the reference's tree) name this module in ``LIBRARY`` like ``verify``. Their exact
check runs in Python integers; before it, :func:`same_edge_set` asks a cheaper question: is the
received list, read as undirected edges, exactly the reference's set, each edge once? When it is
and the reference's own list passes the checker's edge tests (asked once per test, through
``reference_ok``), the exact check would accept too ("ok"), so the checker returns that without
doing it. Anything else (a different set, a repeat, a reversed duplicate) goes to the exact check,
which decides and writes the message: a fast "no" never reaches a student.

What a test's reference needs (its set of edges, whether it passes) is kept for the next student's
check of the same test (a judge checks every student's answer against the same lists), and used
only while the point list and the reference are the same objects, equal to copies taken then.

Run the doctests: ``python -m pytest --doctest-modules reference_impl/exact/edgesets.py``

>>> same_edge_set([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], [[1, 0], [0, 2]], [[0, 1], [2, 0]], lambda: True)
True
>>> same_edge_set([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], [[1, 0], [0, 1]], [[0, 1], [2, 0]], lambda: True)
False
"""
from __future__ import annotations

from typing import Callable

__all__ = ["edge_keys", "same_edge_set", "remembered"]

#: (id(points), id(reference)) -> (points, reference, copies of both, {kind: data}); bounded by _MAX_ROWS rows
_KEPT: dict = {}
_MAX_ROWS = 4_000_000


def remembered(points: list, reference: list, kind: str, build: Callable[[], object]) -> object:
    """``build()``, kept for the same ``points`` and ``reference`` lists checked again (same objects,
    still equal to the copies taken when it was built); anything but two lists is never kept.

    >>> pts, ref = [[0.0, 0.0]], [[0, 1]]
    >>> remembered(pts, ref, "demo", lambda: 1), remembered(pts, ref, "demo", lambda: 2)
    (1, 1)
    >>> ref.append([1, 2]); remembered(pts, ref, "demo", lambda: 3)
    3
    """
    if type(points) is not list or type(reference) is not list:
        return build()
    key = (id(points), id(reference))
    hit = _KEPT.get(key)
    if not (hit is not None and hit[0] is points and hit[1] is reference and hit[2] == points and hit[3] == reference):
        if sum(len(h[2]) + len(h[3]) for h in _KEPT.values()) + len(points) + len(reference) > _MAX_ROWS:
            _KEPT.clear()
        hit = _KEPT[key] = (points, reference, [list(p) for p in points], [list(e) for e in reference], {})
    kept = hit[4]
    if kind not in kept:
        kept[kind] = build()
    return kept[kind]


def edge_keys(edges) -> set:
    """The undirected edges as ``(smaller, larger)`` pairs (a repeat counts once).

    >>> sorted(edge_keys([[2, 1], [1, 2], [0, 3]]))
    [(0, 3), (1, 2)]
    """
    return {(i, j) if i < j else (j, i) for i, j in edges}


def same_edge_set(points: list, edges: list, reference: list, reference_ok: Callable[[], bool]) -> bool:
    """True only when ``edges`` (rows ``[i, j]`` of ints) hold each edge of ``reference`` exactly
    once, in either order and any order of rows, and ``reference_ok()`` (asked once per test) says
    the reference passes the checker's edge tests; False means "ask the exact check".

    >>> same_edge_set([[0.0, 0.0]] * 3, [[0, 1], [1, 0]], [[0, 1]], lambda: True)   # a repeat
    False
    """
    want, ok = remembered(points, reference, "edges", lambda: (edge_keys(reference), bool(reference_ok())))
    if not ok or len(edges) != len(want):
        return False
    return edge_keys(edges) == want  # as many rows as edges wanted, all of them there: no repeat
