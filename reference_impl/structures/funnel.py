"""The funnel algorithm: the taut path through a channel of portals (exact orientation tests).

``funnel(start, goal, portals)`` pulls a string from start to goal through the
portals (the edges a channel of triangles crosses, each as ``(left, right)``
seen walking towards the goal): the "simple stupid funnel" of the game
industry's navigation meshes, with the exact ``orient2d`` for every test.
``navmesh.NavMesh.channel_path`` feeds it the channel that A* finds.

Run the doctests:  python -m pytest reference_impl/structures/funnel.py

>>> funnel((0, 0), (4, 0), [((1, 1), (1, -1)), ((3, 1), (3, -1))])     # nothing in the way
[(0, 0), (4, 0)]
"""
from __future__ import annotations

from typing import Sequence

from reference_impl.exact.predicates import orient2d

__all__ = ["funnel"]

Point = tuple[float, float]

_RIGHT, _LEFT = 0, 1
_SIGN = (1, -1)               # the right side narrows towards the left: orientation >= 0


def funnel(start: Point, goal: Point, portals: Sequence[tuple[Point, Point]]) -> list[Point]:
    """String pulling through a channel ("simple stupid funnel", exact orientation tests).

    ``portals`` are the edges crossed in order, each as ``(left, right)`` seen
    walking from start to goal.  Returns the taut path ``[start, ..., goal]``
    inside the channel: the funnel (apex, left ray, right ray) narrows portal by
    portal; when one side would cross the other, the crossed side's point is a
    corner of the path and becomes the new apex.  A side whose point is the
    apex itself (a portal ending at the apex) constrains nothing.  The two
    sides are one rule mirrored: the right side first, then the left.

    >>> funnel((0, 0), (4, 0), [((1, 1), (1, -1)), ((3, 3), (3, 0.5))])
    [(0, 0), (3, 0.5), (4, 0)]
    """
    gates = [(start, start)] + list(portals) + [(goal, goal)]
    path = [start]
    apex, apex_i = start, 0
    end, end_i = [start, start], [0, 0]               # the funnel's right and left points
    i = 1
    while i < len(gates):
        new = (gates[i][1], gates[i][0])              # (right, left) of this portal
        for side in (_RIGHT, _LEFT):
            s, other = _SIGN[side], 1 - side
            if s * orient2d(apex, end[side], new[side]) < 0:
                continue                              # this side widens: keep it
            if apex in (end[_RIGHT], end[_LEFT]) or s * orient2d(apex, end[other], new[side]) < 0:
                end[side], end_i[side] = new[side], i     # narrows
            else:                                     # crosses the other side: a corner there
                path.append(end[other])
                apex, apex_i = end[other], end_i[other]
                end[side], end_i[side] = apex, apex_i
                i = apex_i + 1
                break
        else:
            i += 1
    if path[-1] != goal:
        path.append(goal)
    return path
