"""The step player: play, pause, slide, step back and forth through any recorded algorithm.

Run the examples:  python -m pytest reference_impl/kit/player.py

``StepPlayer(steps, draw)`` shows one picture per step: ``draw(ax, step, index)``
draws step ``index`` on a matplotlib Axes.  With ``pseudocode`` (a list of
``(key, text)`` lines) and ``phases`` (a function step -> key), the line of the
pseudocode that the current step executes is highlighted.  Two ready-made
players: ``StepPlayer.bowyer_watson(points)`` (every insertion in four phases:
locate, bad triangles, cavity boundary, new triangles, then the answer without the ghost
triangles, the pseudocode's last line) and
``StepPlayer.lawson(points)`` (Lawson's edge flips, one at a time).

>>> p = StepPlayer.bowyer_watson([(1, 1), (3, 2), (5, 1), (4, 4)])
>>> len(p.steps), p.index
(11, 0)
>>> p.next.click(); p.next.click(); p.index
2
>>> p.current_line
'locate'
>>> print(p.caption.value.split("<br>")[0])
<b>step 3/11</b>: insert point 2 at (5, 1): it lies outside the current hull (only ghost triangles contain it)
>>> "image/png" in p._repr_mimebundle_()
True
>>> p.handle_gesture({"kind": "step", "by": 1}); p.index      # the right arrow on the focused picture
3
>>> p.image.announce.split(":")[0]           # what a screen reader says
'step 4/11'

Without a mouse: Tab reaches play, previous, next and the slider (whose arrow keys move it); the
picture itself takes the focus too, and then the left / right arrow keys step (Shift: 5 steps),
Home and End go to the first and last step, Space plays and pauses (``canvas.PLAYER_KEYS``).  The caption is said by a
live region as the steps change.
"""
from __future__ import annotations

import html
from dataclasses import dataclass
from typing import Any, Callable, Sequence

import ipywidgets as widgets
import numpy as np

from reference_impl.teaching.bowyer_watson import INFINITE, Step, bowyer_watson
from reference_impl.mesh.delaunay import Delaunay
from reference_impl.structures.flips import apply_flips, lawson_flip
from reference_impl.validate import as_points
from reference_impl.exact.predicates import orient2d

from .render import (COLORS, Canvas, draw_circumcircle, draw_edges, draw_points, draw_triangles,
                     filmstrip, fill_triangles, fit_bounds)
from .canvas import SceneView
from .scene import axes_scene
from .widget import KitWidget, button

__all__ = ["StepPlayer", "PickAndStep", "BWFrame", "FlipFrame", "BOWYER_WATSON_PSEUDOCODE", "LAWSON_PSEUDOCODE",
           "bowyer_watson_frames", "lawson_frames", "scrambled_triangulation"]

BOWYER_WATSON_PSEUDOCODE = [
    ("start", "start: the first two points and the vertex at infinity (two ghost triangles)"),
    ("locate", "for each new point p: find the triangle that contains p"),
    ("bad", "    bad = every triangle whose circumcircle contains p"),
    ("boundary", "    boundary = the edges that belong to exactly one bad triangle"),
    ("new", "    delete the bad triangles; join p to every boundary edge"),
    ("done", "return the triangles that do not touch the vertex at infinity"),
]

LAWSON_PSEUDOCODE = [
    ("start", "start from any triangulation of the points"),
    ("test", "find an interior edge whose opposite vertex lies inside the other circumcircle"),
    ("flip", "    flip it: replace it by the other diagonal of its quadrilateral"),
    ("done", "no such edge left: every edge is locally Delaunay, so the whole is Delaunay"),
]


@dataclass(frozen=True)
class BWFrame:
    """One picture of a Bowyer-Watson run: a phase of one insertion.

    ``step`` is the library's ``Step`` record, ``before`` the real triangles before
    it, ``inserted`` how many points are in the triangulation after it.
    """

    phase: str
    step: Step | None
    before: np.ndarray
    inserted: int


@dataclass(frozen=True)
class FlipFrame:
    """One picture of a Lawson run: the triangles, and the edge about to flip or just flipped."""

    phase: str
    triangles: np.ndarray
    edge: tuple[int, int] | None
    flips_done: int


def bowyer_watson_frames(points, order: str = "input") -> tuple[np.ndarray, list[BWFrame]]:
    """The frames of ``StepPlayer.bowyer_watson``: (points, frames).

    >>> pts, frames = bowyer_watson_frames([(1, 1), (3, 2), (5, 1), (4, 4)])
    >>> [f.phase for f in frames]
    ['start', 'start', 'locate', 'bad', 'boundary', 'new', 'locate', 'bad', 'boundary', 'new', 'done']
    """
    pts = as_points(points)
    steps: list[Step] = []
    result = bowyer_watson(pts, trace=steps, order=order)
    frames: list[BWFrame] = []
    before = np.zeros((0, 3), dtype=np.int64)
    for k, s in enumerate(steps, start=1):
        if not s.bad:
            frames.append(BWFrame("start", s, before, k))
        else:
            for phase in ("locate", "bad", "boundary", "new"):
                frames.append(BWFrame(phase, s, before, k))
        before = s.triangles
    # the last line of the pseudocode: the answer, without the ghost triangles
    frames.append(BWFrame("done", None, result, len(steps)))
    return pts, frames


def _order_of(steps: Sequence[BWFrame]) -> list[int]:
    return list(dict.fromkeys(f.step.index for f in steps if f.step is not None))


def _draw_bw(pts: np.ndarray, order: list[int], bounds) -> Callable[[Any, BWFrame, int], None]:
    def draw(ax, f: BWFrame, index: int) -> None:
        ax.set_xlim(bounds[0], bounds[2])
        ax.set_ylim(bounds[1], bounds[3])
        done = set(order[:f.inserted])
        future = [i for i in range(len(pts)) if i not in done]
        s = f.step
        if s is None or f.phase in ("start", "done"):
            shown = f.before if s is None else s.triangles
            draw_triangles(ax, pts, shown)
        else:
            real_bad = [t for t in s.bad if INFINITE not in t]
            if f.phase == "locate" and s.located is not None:
                fill_triangles(ax, pts, [s.located], color=COLORS["located"])
            if f.phase in ("bad", "boundary"):
                fill_triangles(ax, pts, real_bad, color=COLORS["bad"])
            if f.phase == "bad":
                for t in real_bad:
                    draw_circumcircle(ax, *pts[list(t)])
                ghosts = [(t[0], t[1]) for t in s.bad if INFINITE in t]
                draw_edges(ax, pts, ghosts, color=COLORS["circle"], linestyle=":", linewidth=2.5)
            if f.phase == "new":
                fill_triangles(ax, pts, [t for t in s.new if INFINITE not in t], color=COLORS["new"])
                draw_triangles(ax, pts, s.triangles)
            else:
                draw_triangles(ax, pts, f.before)
            if f.phase == "boundary":
                draw_edges(ax, pts, [e for e in s.boundary if INFINITE not in e])
        draw_points(ax, pts[future], color=COLORS["future"], labels=[str(i) for i in future])
        draw_points(ax, pts[sorted(done)], labels=[str(i) for i in sorted(done)])
        if s is not None and f.phase != "done":
            draw_points(ax, pts[[s.index]], color=COLORS["new_point"], size=60)

    return draw


def _describe_bw(pts: np.ndarray) -> Callable[[BWFrame], str]:
    def name(t) -> str:
        return "(" + ", ".join("inf" if v == INFINITE else str(v) for v in t) + ")"

    def describe(f: BWFrame) -> str:
        s = f.step
        if s is None:
            if not len(f.before):
                return "fewer than three points off one line: no triangle to build"
            return (f"done: the answer is the {len(f.before)} triangles that do not touch the vertex at "
                    "infinity (the ghost triangles are dropped)")
        x, y = (float(v) for v in s.point)
        head = f"insert point {s.index} at ({x:g}, {y:g})"
        if f.phase == "start":
            return head + (": the first point, nothing to connect yet" if not s.new else
                           ": the second point; its line with the first splits the plane into 2 ghost triangles")
        if f.phase == "locate":
            return head + (f": it lies in triangle {name(s.located)}" if s.located is not None else
                           ": it lies outside the current hull (only ghost triangles contain it)")
        if f.phase == "bad":
            ghosts = sum(INFINITE in t for t in s.bad)
            extra = f" ({ghosts} of them ghost triangles outside a hull edge, dotted)" if ghosts else ""
            return f"{len(s.bad)} bad triangles: " + ", ".join(map(name, s.bad)) + extra
        if f.phase == "boundary":
            return (f"cavity boundary of {len(s.boundary)} edges: "
                    + ", ".join(f"{name(e)}" for e in s.boundary))
        real = [t for t in s.new if INFINITE not in t]
        return (f"{len(s.new)} new triangles ({len(real)} real): " + ", ".join(map(name, s.new))
                + f"; the triangulation now has {len(s.triangles)} triangles")

    return describe


# ----------------------------------------------------------------------------- Lawson
def scrambled_triangulation(points, flips: int | None = None, seed: int = 0) -> np.ndarray:
    """A valid but (usually) non-Delaunay triangulation: the Delaunay one with random edges flipped.

    Any interior edge whose quadrilateral is strictly convex may be flipped and
    the result is still a triangulation of the same points; ``flips`` of them
    (default: one per point) are flipped at random.

    >>> pts = [(0, 0), (4, 0), (4, 3), (0, 3), (2, 1.4)]
    >>> from reference_impl.structures.flips import validate_triangulation
    >>> len(validate_triangulation(pts, scrambled_triangulation(pts)))
    4
    """
    P = as_points(points)
    T = [tuple(int(v) for v in t) for t in Delaunay(P).simplices]
    rng = np.random.default_rng(seed)
    apex: dict[tuple[int, int], tuple[int, int]] = {}   # directed edge a->b: (its triangle, the third vertex)

    def attach(k: int) -> None:
        t = T[k]
        for j in range(3):
            apex[(t[j], t[(j + 1) % 3])] = (k, t[(j + 2) % 3])

    def detach(k: int) -> None:
        t = T[k]
        for j in range(3):
            del apex[(t[j], t[(j + 1) % 3])]

    def flippable(a: int, b: int) -> bool:
        if (a, b) not in apex or (b, a) not in apex:
            return False
        c, d = apex[(a, b)][1], apex[(b, a)][1]
        return orient2d(P[c], P[d], P[a]) * orient2d(P[c], P[d], P[b]) < 0  # strictly convex

    for k in range(len(T)):
        attach(k)
    # the flippable edges (a < b), kept up to date after each flip: only the quadrilateral's change
    candidates = [e for e in sorted(apex) if e[0] < e[1] and flippable(*e)]
    where = {e: i for i, e in enumerate(candidates)}

    def refresh(u: int, v: int) -> None:
        e = (min(u, v), max(u, v))
        if flippable(*e):
            if e not in where:
                where[e] = len(candidates)
                candidates.append(e)
        elif e in where:
            i = where.pop(e)
            last = candidates.pop()
            if i < len(candidates):
                candidates[i] = last
                where[last] = i

    for _ in range(len(P) if flips is None else flips):
        if not candidates:
            break
        a, b = candidates[int(rng.integers(len(candidates)))]
        (k, c), (k2, d) = apex[(a, b)], apex[(b, a)]
        # triangles (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c)
        detach(k)
        detach(k2)
        T[k], T[k2] = (c, a, d), (d, b, c)
        attach(k)
        attach(k2)
        for u, v in ((a, b), (c, d), (a, c), (c, b), (b, d), (d, a)):
            refresh(u, v)
    return np.array(T, dtype=np.int64).reshape(-1, 3)


def lawson_frames(points, triangles=None) -> tuple[np.ndarray, list[FlipFrame]]:
    """The frames of ``StepPlayer.lawson``: the start, then a "test" and a "flip" frame per flip.

    >>> pts, frames = lawson_frames([(0, 0), (4, 0), (4, 1), (0, 3)], [(0, 1, 3), (1, 2, 3)])
    >>> [(f.phase, f.edge) for f in frames]
    [('start', None), ('test', (1, 3)), ('flip', (0, 2)), ('done', None)]
    """
    P = as_points(points)
    T = scrambled_triangulation(P) if triangles is None else np.asarray(triangles, dtype=np.int64)
    _, flips = lawson_flip(P, T)
    current = apply_flips(P, T, [])
    frames = [FlipFrame("start", current, None, 0)]
    for k, (i, j) in enumerate(flips):
        frames.append(FlipFrame("test", current, (i, j), k))
        after = apply_flips(P, current, [(i, j)])
        old = {tuple(sorted(e)) for t in current.tolist() for e in zip(t, t[1:] + t[:1])}
        new_edge = next(tuple(sorted(e)) for t in after.tolist() for e in zip(t, t[1:] + t[:1])
                        if tuple(sorted(e)) not in old)
        frames.append(FlipFrame("flip", after, new_edge, k + 1))
        current = after
    frames.append(FlipFrame("done", current, None, len(flips)))
    return P, frames


def _draw_lawson(P: np.ndarray, bounds) -> Callable[[Any, FlipFrame, int], None]:
    def draw(ax, f: FlipFrame, index: int) -> None:
        ax.set_xlim(bounds[0], bounds[2])
        ax.set_ylim(bounds[1], bounds[3])
        draw_triangles(ax, P, f.triangles)
        if f.edge is not None:
            i, j = f.edge
            pair = [t for t in f.triangles.tolist() if i in t and j in t]
            fill_triangles(ax, P, pair, color=COLORS["bad"] if f.phase == "test" else COLORS["new"])
            draw_edges(ax, P, [f.edge], color=COLORS["flip"], linewidth=3)
            if f.phase == "test" and pair:
                draw_circumcircle(ax, *P[pair[0]])
        draw_points(ax, P, labels=len(P) <= 30)

    return draw


def _describe_lawson(f: FlipFrame) -> str:
    if f.phase == "start":
        return f"the starting triangulation: {len(f.triangles)} triangles"
    if f.phase == "test":
        return (f"flip {f.flips_done + 1}: edge {f.edge[0]}-{f.edge[1]} is not locally Delaunay "
                "(the opposite vertex is inside the dashed circumcircle)")
    if f.phase == "flip":
        return f"flipped: the new edge is {f.edge[0]}-{f.edge[1]}"
    return f"done after {f.flips_done} flips: every edge is locally Delaunay"


# ----------------------------------------------------------------------------- the widget
class StepPlayer(KitWidget):
    """Play / pause, a slider, previous / next through ``steps``; highlights the pseudocode line.

    ``draw(ax, step, index)`` draws one step; ``phases(step)`` names its line of
    ``pseudocode`` (a list of ``(key, text)``); ``describe(step)`` is the caption
    (default ``str(step)``).

    >>> p = StepPlayer(["a", "b", "c"], lambda ax, s, i: ax.text(0.5, 0.5, s),
    ...                phases=lambda s: s, pseudocode=[("a", "first"), ("b", "second")])
    >>> p.slider.value = 2; p.index, p.current_line      # the slider counts from 1, as the caption does
    (1, 'b')
    >>> p.prev.click(); p.prev.click(); p.index      # stops at the first step
    0
    """

    def __init__(self, steps: Sequence, draw: Callable[[Any, Any, int], None], *,
                 phases: Callable[[Any], str] | None = None,
                 pseudocode: Sequence[tuple[str, str]] | None = None, title: str = "",
                 describe: Callable[[Any], str] | None = None, bounds=None,
                 size: tuple[int, int] = (480, 400), interval: int = 900) -> None:
        self.steps = list(steps)
        if not self.steps:
            raise ValueError("StepPlayer needs at least one step to show")
        self._draw = draw
        self._phases = phases
        self.pseudocode = list(pseudocode or [])
        self.title = title
        self._describe = describe or str
        self.canvas = Canvas(*size)
        self._bounds = bounds
        # the slider counts steps from 1, as the caption does ("step 6/10" beside 6); ``index`` is 0-based
        last = len(self.steps)
        self.play = widgets.Play(value=1, min=1, max=last, step=1, interval=interval,
                                 description="play")
        self.slider = widgets.IntSlider(value=1, min=1, max=last, description="step",
                                        continuous_update=True)
        widgets.jslink((self.play, "value"), (self.slider, "value"))
        self.prev = button("previous", "step-backward")
        self.next = button("next", "step-forward")
        self.image = SceneView(*size, interactive=False, stepper=True)   # drawn by the browser (kit/canvas.js)
        self.image.add_class("kit-player-image")
        self.image.label = (f"{title or 'step player'}: left and right arrow keys step, Home and End go to "
                            "the first and last step, Space plays and pauses")
        self.image.on_gesture(self.guard(self.handle_gesture))
        self.prev.tooltip, self.next.tooltip = "the previous step", "the next step"
        self.caption = widgets.HTML()
        self.code = widgets.HTML(layout=widgets.Layout(flex="1 1 auto", min_width="14em"))
        controls = widgets.HBox([self.play, self.prev, self.next, self.slider])
        super().__init__([widgets.HTML(f"<b>{html.escape(title)}</b>") if title else widgets.HTML(),
                          controls, widgets.HBox([self.image, self.code]), self.caption])
        self.add_class("kit-step-player")
        self.prev.on_click(self.guard(lambda _: self._go(self.index - 1)))
        self.next.on_click(self.guard(lambda _: self._go(self.index + 1)))
        self.slider.observe(self.guard(lambda _: self._render()), names="value")
        self._render()

    # -- state
    @property
    def index(self) -> int:
        """The step shown (0-based; the slider shows it 1-based); setting it moves the slider."""
        return int(self.slider.value) - 1

    @index.setter
    def index(self, value: int) -> None:
        self._go(value)

    @property
    def step(self) -> Any:
        return self.steps[self.index]

    @property
    def current_line(self) -> str | None:
        """The pseudocode key of the current step (``None`` without ``phases``)."""
        return None if self._phases is None else self._phases(self.step)

    def _go(self, value: int) -> None:
        self.slider.value = max(0, min(len(self.steps) - 1, int(value))) + 1

    def handle_gesture(self, gesture: Any) -> None:
        """A key pressed on the focused picture: ``{"kind": "step", "by": k}`` moves k steps (clamped),
        ``{"kind": "play"}`` plays or pauses."""
        g = SceneView.parse(gesture)
        if g["kind"] == "play":                     # Space: play / pause (the Play widget runs in the page)
            self.play.playing = not self.play.playing
            return
        if g["kind"] != "step":
            raise ValueError(f"a step player's picture takes step and play gestures, got {g['kind']!r}")
        self._go(self.index + g["by"])

    # -- drawing
    def _draw_step(self, ax, k: int) -> None:
        self._draw(ax, self.steps[k], k)

    def _render(self) -> None:
        k = self.index
        ax = self.canvas.clear(bounds=self._bounds, title=self.title)
        self._draw_step(ax, k)
        self.image.scene = axes_scene(self.canvas)
        said = self._describe(self.steps[k])
        self.caption.value = f"<b>step {k + 1}/{len(self.steps)}</b>: " + html.escape(said)
        self.image.announce = f"step {k + 1}/{len(self.steps)}: {said}"
        self.code.value = self._pseudocode_html()

    def _pseudocode_html(self) -> str:
        if not self.pseudocode:
            return ""
        here = self.current_line
        rows = []
        for key, text in self.pseudocode:
            style = ("background:#ffe08a;font-weight:bold;" if key == here else "color:#555;")
            rows.append(f'<div class="kit-line" data-key="{html.escape(key)}" '
                        f'style="{style}white-space:pre-wrap;padding:1px 4px 1px 2em;text-indent:-1.6em">'
                        f'{html.escape(text)}</div>')
        # long lines wrap (indented under their start) instead of being clipped by the output area
        return ('<div style="font-family:monospace;font-size:12px;margin-left:8px;max-width:34em;'
                'overflow-wrap:anywhere">' + "".join(rows) + "</div>")

    # -- static fallback: a filmstrip of (at most 8) steps
    def static_png(self) -> bytes:
        n = len(self.steps)
        picks = sorted(set(np.linspace(0, n - 1, min(n, 8)).round().astype(int).tolist()))
        bounds = self._bounds

        def frame(ax, k, _):
            if bounds is not None:
                ax.set_xlim(bounds[0], bounds[2])
                ax.set_ylim(bounds[1], bounds[3])
            self._draw_step(ax, k)

        titles = [f"step {k + 1}" + (f": {self._phases(self.steps[k])}" if self._phases else "")
                  for k in picks]
        return filmstrip(frame, picks, titles=titles)

    def static_text(self) -> str:
        return f"StepPlayer{': ' + self.title if self.title else ''} ({len(self.steps)} steps; " \
               f"step {self.index + 1}: {self._describe(self.step)})"

    # -- ready-made players
    @classmethod
    def bowyer_watson(cls, points, *, order: str = "input", title: str = "Bowyer-Watson",
                      **kwargs: Any) -> "StepPlayer":
        """Step through ``reference_impl.bowyer_watson``'s recorded trace, four phases per point.

        ``order="input"`` (default) inserts the points in the given order, as in a dry run.
        """
        pts, frames = bowyer_watson_frames(points, order)
        bounds = kwargs.pop("bounds", None) or fit_bounds(pts)
        return cls(frames, _draw_bw(pts, _order_of(frames), bounds), phases=lambda f: f.phase,
                   pseudocode=BOWYER_WATSON_PSEUDOCODE, title=title, describe=_describe_bw(pts),
                   bounds=bounds, **kwargs)

    @classmethod
    def lawson(cls, points, triangles=None, *, title: str = "Lawson edge flips",
               **kwargs: Any) -> "StepPlayer":
        """Step through Lawson's flips from ``triangles`` (default: a scrambled triangulation)."""
        P, frames = lawson_frames(points, triangles)
        bounds = kwargs.pop("bounds", None) or fit_bounds(P)
        return cls(frames, _draw_lawson(P, bounds), phases=lambda f: f.phase,
                   pseudocode=LAWSON_PSEUDOCODE, title=title, describe=_describe_lawson,
                   bounds=bounds, **kwargs)


class PickAndStep(KitWidget):
    """A point picker above a Bowyer-Watson player that replays whatever points are picked.

    Every click (add, move, remove, preset) rebuilds the player on the new points,
    inserted in the order they were picked.

    >>> lab = PickAndStep([(0.2, 0.2), (0.8, 0.3), (0.5, 0.9)])
    >>> len(lab.player.steps)
    7
    >>> lab.picker.add_point(0.5, 0.5); len(lab.player.steps), len(lab.picker.triangles)
    (11, 3)
    """

    def __init__(self, points=(), **picker_kwargs: Any) -> None:
        from .picker import PointPicker

        picker_kwargs.setdefault("size", (400, 380))
        self.picker = PointPicker(points, on_change=self.guard(lambda _: self._rebuild()), **picker_kwargs)
        self.player = self._player()
        self._slot = widgets.VBox([self.player])
        super().__init__([self.picker, self._slot])
        self.add_class("kit-pick-and-step")

    def _player(self) -> StepPlayer:
        return StepPlayer.bowyer_watson(self.picker.points, bounds=self.picker.bounds,
                                        title="Bowyer-Watson on your points", size=(400, 380))

    def _rebuild(self) -> None:
        self.player = self._player()
        self._slot.children = [self.player]

    def static_png(self) -> bytes:
        return self.player.static_png()

    def static_text(self) -> str:
        return f"PickAndStep: {len(self.picker.points)} points; " + self.player.static_text()
