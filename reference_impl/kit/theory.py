"""Players for the theory lesson (13): one constrained segment inserted step by step, and one 3D
cavity turned around.

Run the examples:  python -m pytest reference_impl/kit/theory.py

They are players built on the teaching code: ``segment_player`` plays
``teaching.segment.insert_segment`` (the crossed triangles found one by one, the two cavities, each
new triangle with its empty circle), ``cavity_player`` turns the boundary of one 3D insertion's
cavity (``teaching.cavity3d.cavity_3d``) around its vertical axis (a ``Player3D``: the browser draws it
and turns it), and ``flip_angle_player`` shows
the six angles each of Lawson's flips (``teaching.theory.lawson``) takes away and puts back;
``star_player`` shows each insertion's new triangles (the new point's star) and their running mean.

>>> pts = [(0, 0), (2, -1), (4, 0), (2.5, 1), (2, 3), (1.5, 1.2)]
>>> p = segment_player(pts, 1, 4)
>>> [f.phase for f in p.steps]
['start', 'cross', 'cross', 'cavity', 'new', 'new', 'done']
>>> p.index = 3; print(p.caption.value.split(": ", 1)[1])
delete the 2 crossed triangles: two cavities remain, left of the segment (vertices 1, 5, 4) and right of it (vertices 1, 3, 4)
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from reference_impl.mesh.delaunay import Delaunay
from reference_impl.teaching.bowyer_watson import INFINITE, Step, bowyer_watson
from reference_impl.teaching.cavity3d import Cavity3D
from reference_impl.teaching.segment import SegmentInsertion, insert_segment
from reference_impl.teaching.theory import angle_vector, lawson
from reference_impl.validate import as_points

from .canvas3d import Player3D
from .player import StepPlayer
from .render import COLORS, draw_circumcircle, draw_edges, draw_points, draw_triangles, fill_triangles, fit_bounds

__all__ = ["SegmentFrame", "segment_frames", "segment_player", "cavity_player", "flip_angle_player",
           "star_player", "SEGMENT_PSEUDOCODE"]

SEGMENT_PSEUDOCODE = [
    ("start", "insert segment a-b into a (Delaunay) triangulation"),
    ("cross", "walk from a towards b: collect every triangle the segment crosses"),
    ("cavity", "delete them: one polygon left of a-b, one right of it, a-b an edge of both"),
    ("new", "in each polygon: the vertex c with no polygon vertex inside circle(a, b, c) makes "
            "triangle (a, b, c); repeat on the two smaller polygons cut off by a-c and c-b"),
    ("done", "the segment is an edge; every other edge is locally Delaunay"),
]


@dataclass(frozen=True)
class SegmentFrame:
    """One picture of a segment insertion: its phase and how far it has got (``count``)."""

    phase: str
    count: int


def segment_frames(points, a: int, b: int, triangles=None) -> tuple[np.ndarray, SegmentInsertion, list[SegmentFrame]]:
    """(points, the insertion, its frames); ``triangles`` default: the Delaunay triangulation.

    >>> _, ins, frames = segment_frames([(0, 0), (1, 0), (0, 1)], 0, 1)
    >>> [f.phase for f in frames]
    ['start', 'done']
    """
    P = as_points(points)
    T = Delaunay(P).simplices if triangles is None else triangles
    ins = insert_segment(P, T, a, b)
    frames = [SegmentFrame("start", 0)]
    frames += [SegmentFrame("cross", k + 1) for k in range(len(ins.crossed))]
    if ins.crossed:
        frames.append(SegmentFrame("cavity", 0))
    frames += [SegmentFrame("new", k + 1) for k in range(len(ins.new))]
    frames.append(SegmentFrame("done", 0))
    return P, ins, frames


def segment_player(points, a: int, b: int, triangles=None, *, title: str = "inserting a segment",
                   **kwargs: Any) -> StepPlayer:
    """A ``StepPlayer`` through the insertion of segment a-b (see ``segment_frames``).

    >>> p = segment_player([(0, 0), (2, -1), (4, 0), (2, 1)], 0, 2)     # crosses edge 1-3
    >>> p.index = len(p.steps) - 1; print(p.caption.value.split(": ", 1)[1])
    done: 2 triangles out, 2 in (2 triangles, as before)
    """
    P, ins, frames = segment_frames(points, a, b, triangles)
    bounds = kwargs.pop("bounds", None) or fit_bounds(P)
    crossed_set = set(ins.crossed)
    kept = [t for t in ins.before.tolist() if _canon(t) not in crossed_set]

    def draw(ax, f: SegmentFrame, _k: int) -> None:
        ax.set_xlim(bounds[0], bounds[2])
        ax.set_ylim(bounds[1], bounds[3])
        if f.phase in ("start", "cross"):
            fill_triangles(ax, P, ins.crossed[:f.count], color=COLORS["bad"])
            draw_triangles(ax, P, ins.before)
        elif f.phase in ("cavity", "new"):
            draw_triangles(ax, P, kept)
            made = ins.new[:f.count]
            fill_triangles(ax, P, made, color=COLORS["new"])
            draw_triangles(ax, P, made)
            for side in (ins.left, ins.right):
                ring = [ins.a] + side + [ins.b]
                draw_edges(ax, P, list(zip(ring, ring[1:])), color=COLORS["bad"], linewidth=2)
            if f.phase == "new":
                draw_circumcircle(ax, *P[list(ins.new[f.count - 1])])
        else:
            draw_triangles(ax, P, ins.triangles)
        draw_edges(ax, P, [(ins.a, ins.b)], color=COLORS["flip"], linewidth=3,
                   linestyle="--" if f.phase in ("start", "cross") else "-")
        draw_points(ax, P, labels=len(P) <= 30)

    def describe(f: SegmentFrame) -> str:
        if f.phase == "start":
            return (f"segment {ins.a}-{ins.b} (orange, dashed) must become an edge; "
                    + (f"it crosses {len(ins.crossed)} triangles" if ins.crossed else "it already is one"))
        if f.phase == "cross":
            return f"crossed triangle {f.count} of {len(ins.crossed)}: {ins.crossed[f.count - 1]}"
        if f.phase == "cavity":
            left = ", ".join(map(str, [ins.a] + ins.left + [ins.b]))
            right = ", ".join(map(str, [ins.a] + ins.right + [ins.b]))
            return (f"delete the {len(ins.crossed)} crossed triangles: two cavities remain, left of the "
                    f"segment (vertices {left}) and right of it (vertices {right})")
        if f.phase == "new":
            return (f"new triangle {f.count} of {len(ins.new)}: {ins.new[f.count - 1]}; its dashed circle "
                    "holds no other vertex of its polygon")
        return (f"done: {len(ins.crossed)} triangles out, {len(ins.new)} in "
                f"({len(ins.triangles)} triangles, as before)")

    return StepPlayer(frames, draw, phases=lambda f: f.phase, pseudocode=SEGMENT_PSEUDOCODE, title=title,
                      describe=describe, bounds=bounds, **kwargs)


def _canon(t) -> tuple[int, int, int]:
    a, b, c = (int(v) for v in t)
    if a < b and a < c:
        return (a, b, c)
    return (b, c, a) if b < c else (c, a, b)


def cavity_player(points, cavity: Cavity3D, *, turns: int = 12, title: str = "one 3D cavity, turning",
                  **kwargs: Any) -> Player3D:
    """Turn the cavity's boundary faces (and the new point, red) around the vertical axis.

    Each step turns it by another 180 / ``turns`` degrees; the browser draws the faces back to
    front, half transparent, so the point is seen inside its cavity, and a drag or the arrow keys
    turn it further (``canvas3d.Player3D``).

    >>> from reference_impl.teaching.cavity3d import cavity_3d
    >>> pts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (0.2, 0.2, 0.2)]
    >>> p = cavity_player(pts, cavity_3d(pts, [(0, 2, 1, 3)], 4), turns=3)
    >>> print(p.caption.value.split(": ", 1)[1])
    turned 0 degrees: 1 tetrahedron bad, 4 boundary faces on 4 vertices, 4 tetrahedra new
    """
    P = as_points(points, dim=3)
    faces = np.asarray(cavity.boundary, dtype=np.int64).reshape(-1, 3)
    used = sorted({int(v) for v in faces.ravel()})
    shown = used + [int(cavity.q)]                      # only the cavity's vertices and q are drawn
    local = {v: k for k, v in enumerate(shown)}
    F = np.vectorize(local.__getitem__, otypes=[np.int64])(faces) if len(faces) else faces
    edges = sorted({tuple(sorted((int(t[i]), int(t[(i + 1) % 3])))) for t in F.tolist() for i in range(3)})
    angles = list(np.linspace(0, np.pi, max(1, int(turns)), endpoint=False))

    def tets(k: int) -> str:
        return f"{k} {'tetrahedron' if k == 1 else 'tetrahedra'}"

    def describe(angle: float) -> str:
        return (f"turned {np.degrees(angle):.0f} degrees: {tets(len(cavity.bad))} bad, "
                f"{len(faces)} boundary faces on {len(used)} vertices, {tets(len(cavity.new))} new")

    return Player3D(P[shown], faces=F, edges=edges, marks=[len(shown) - 1], angles=angles, describe=describe,
                    title=title, depth_colors=False, interval=kwargs.pop("interval", 400),
                    face_color=COLORS["bad"], face_alpha=0.25, edge_color=COLORS["edge"], lw=0.7,
                    point_color=COLORS["point"], mark_color=COLORS["new_point"], **kwargs)


@dataclass(frozen=True, eq=False)
class FlipAngles:
    """One flip of a Lawson run: the triangulation before and after, the two triangles it removes
    and the two it makes, and their six angles (degrees, sorted) each."""

    before: np.ndarray
    after: np.ndarray
    old: list
    new: list
    old_angles: np.ndarray
    new_angles: np.ndarray


def flip_angle_player(points, triangles, *, title: str = "each flip's six angles", **kwargs: Any) -> StepPlayer:
    """Step through Lawson's flips from ``triangles``, two frames a flip: the quadrilateral before
    (its two triangles red) and after (green), with the six angles of each in the caption.

    >>> p = flip_angle_player([(0, 0), (4, 0), (4, 1), (0, 3)], [(0, 1, 3), (1, 2, 3)])
    >>> flip, phase = p.steps[0]; len(p.steps), phase, bool(flip.old_angles.min() < flip.new_angles.min())
    (2, 'before', True)
    """
    P = as_points(points)
    states = lawson(P, triangles)
    flips = []
    for before, after in zip(states, states[1:]):
        b, a = {tuple(t) for t in before.tolist()}, {tuple(t) for t in after.tolist()}
        old, new = sorted(b - a), sorted(a - b)
        flips.append(FlipAngles(before, after, old, new, np.degrees(angle_vector(P, old)),
                                np.degrees(angle_vector(P, new))))
    if not flips:
        raise ValueError("the triangulation is already Delaunay: there is no flip to show")
    frames = [(f, phase) for f in flips for phase in ("before", "after")]
    bounds = kwargs.pop("bounds", None) or fit_bounds(P)

    def draw(ax, frame, _k: int) -> None:
        f, phase = frame
        ax.set_xlim(bounds[0], bounds[2])
        ax.set_ylim(bounds[1], bounds[3])
        shown, pair = (f.before, f.old) if phase == "before" else (f.after, f.new)
        fill_triangles(ax, P, pair, color=COLORS["bad"] if phase == "before" else COLORS["new"])
        draw_triangles(ax, P, shown)
        draw_points(ax, P, labels=len(P) <= 30)

    def describe(frame) -> str:
        f, phase = frame
        k = next(i for i, g in enumerate(flips, start=1) if g is f)
        six = ", ".join(f"{v:.1f}" for v in (f.old_angles if phase == "before" else f.new_angles))
        if phase == "before":
            return f"flip {k} of {len(flips)}: triangles {f.old[0]} and {f.old[1]}; their angles {six} degrees"
        return (f"after flip {k}: triangles {f.new[0]} and {f.new[1]}; their angles {six} degrees: the smallest "
                f"went from {f.old_angles[0]:.1f} to {f.new_angles[0]:.1f}")

    return StepPlayer(frames, draw, describe=describe, bounds=bounds, title=title, **kwargs)


def star_player(points, order=None, *, title: str = "each insertion's new triangles", **kwargs: Any) -> StepPlayer:
    """One frame per insertion (from the third point): the triangulation after it, the new point's
    star in green, and the count of created triangles (ghosts included) with the mean so far.

    ``order``: a permutation of the point indices (default: as given).

    >>> p = star_player([(0, 0), (1, 0), (0, 1), (0.9, 0.8)])
    >>> p.index = 1; print(p.caption.value.split(": ", 1)[1])
    point 3 creates 4 triangles (2 real, 2 ghosts outside hull edges); mean so far 3.50 (bound on the mean: 6)
    """
    P = as_points(points)
    order = np.arange(len(P)) if order is None else np.asarray(order, dtype=np.int64)
    if sorted(order.tolist()) != list(range(len(P))):
        raise ValueError(f"order must be a permutation of 0..{len(P) - 1}")
    steps: list[Step] = []
    bowyer_watson(P[order], trace=steps, locate="walk", order="input")
    steps = steps[2:]
    if not steps:
        raise ValueError("fewer than three points off one line: nothing is inserted")
    counts = np.array([len(s.new) for s in steps])
    means = np.cumsum(counts) / np.arange(1, len(counts) + 1)
    bounds = kwargs.pop("bounds", None) or fit_bounds(P)
    Q = P[order]

    def draw(ax, k: int, _i: int) -> None:
        s = steps[k]
        ax.set_xlim(bounds[0], bounds[2])
        ax.set_ylim(bounds[1], bounds[3])
        real = [t for t in s.new if INFINITE not in t]
        fill_triangles(ax, Q, real, color=COLORS["new"])
        draw_triangles(ax, Q, s.triangles)
        ghosts = [(t[0], t[1]) for t in s.new if INFINITE in t and INFINITE not in (t[0], t[1])]
        draw_edges(ax, Q, ghosts, color=COLORS["hull"], linewidth=2.5, linestyle=":")
        inserted = sorted({v for t in s.triangles.tolist() for v in t} | {s.index})
        draw_points(ax, Q[inserted])
        draw_points(ax, Q[[s.index]], color=COLORS["new_point"], size=60)

    def describe(k: int) -> str:
        s = steps[k]
        ghosts = sum(INFINITE in t for t in s.new)
        return (f"point {int(order[s.index])} creates {len(s.new)} triangles ({len(s.new) - ghosts} real, "
                f"{ghosts} ghosts outside hull edges); mean so far {means[k]:.2f} (bound on the mean: 6)")

    return StepPlayer(list(range(len(steps))), draw, describe=describe, bounds=bounds, title=title, **kwargs)

