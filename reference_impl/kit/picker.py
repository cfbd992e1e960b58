"""The point picker: click to add a point, drag to move it, click it to remove it.

Run the examples:  python -m pytest reference_impl/kit/picker.py

The browser draws the picture (``canvas.SceneView``, an anywidget drawing SVG):
the lesson's ``draw(ax, points)`` runs on a matplotlib axes in the kernel, and
``scene.axes_scene`` sends what it drew as shapes in image pixels, each vertex on
a picker point written as that point's index.  While a point is dragged the
browser moves it, its triangles, circles and label in the same frame, and sends
the position to the kernel at most every 50 ms (and at release); the kernel
recomputes the triangulation and sends the new scene back.  A press on empty space
adds a point on release; a press on a point followed by a move drags it; a press
and release on a point without moving removes it.  Every change is undoable (a
whole drag is one change) and redraws the triangulation (by default the Delaunay
triangulation; pass ``draw(ax, points)`` to draw something else, e.g. a convex
hull or Voronoi cells).  A notebook run without a browser keeps a PNG of the same
axes (``static_png``).

Without a mouse: Tab gives the picture the focus (a blue ring); the arrow keys move a
+ cursor, Enter adds a point there, ``]`` / ``[`` (or Space: the nearest) select a point,
the arrow keys then move it (Shift: five times as far) and Delete or Backspace removes it
(``canvas.KEYS``; a key's moves are one drag, one undo step).  Tab goes on to the preset
menu, undo, clear, the text box and "set points".  The text box holds the points as text,
one ``x, y`` a line; "set points" replaces the points by the box's lines (undoable), and a
line that is not two numbers is named in a message and changes nothing
(``parse_points_text``).  The picture is labelled for screen readers (``aria-label``) and
the status line is also said by a live region.

Measured with 100 points (JupyterLab in headless chromium on a shared 2-core host,
``pytest tests/browser/test_jupyterlab.py -k drag -s``): the page draws a move in
0.6 ms (median; 1.4 ms at most), 7.2 ms from the pointer event to the frame (15.8 ms
at most); the kernel's answer reaches the page 56 ms after the move was sent
(median; 66 ms at most).  The kernel's part, ``python benchmarks/bench_picker.py``:
8.8 ms per answer at n = 100, 34 ms at n = 1000.

>>> p = PointPicker()
>>> p.load_preset("tutorial"); p.points.tolist()
[[1.0, 1.0], [3.0, 2.0], [5.0, 1.0], [4.0, 4.0]]
>>> len(p.triangles)
3
>>> p.add_point(3.5, 2.5); len(p.triangles)     # inside the hull: one triangle becomes three
5
>>> p.undo(); len(p.points)
4
>>> p.remove_point(0); p.move_point(0, 3.0, 1.5); p.points.tolist()
[[3.0, 1.5], [5.0, 1.0], [4.0, 4.0]]
>>> p.text.value = "0, 0\\n2, 0\\n1, two"; p.apply_text(); p.message.value.count("line 3")
1
>>> p.text.value = "0, 0\\n2, 0\\n1, 2"; p.apply_text(); len(p.points), len(p.triangles)
(3, 1)
"""
from __future__ import annotations

import html
import math
import re
from typing import Any, Callable, Mapping

import ipywidgets as widgets
import numpy as np

from reference_impl.teaching.bowyer_watson import TUTORIAL_POINTS
from reference_impl.mesh.delaunay import Delaunay
from reference_impl.validate import as_points

from .canvas import KEYS, SceneView
from .render import Canvas, draw_points, draw_triangles
from .scene import axes_scene, pixel_points
from .widget import KitWidget, button

__all__ = ["PointPicker", "PRESETS", "preset_points", "parse_points_text", "points_text"]

Bounds = tuple[float, float, float, float]


def _grid(bounds: Bounds, n: int) -> np.ndarray:
    k = max(2, int(round(math.sqrt(n))))
    x0, y0, x1, y1 = bounds
    xs = np.linspace(x0 + 0.15 * (x1 - x0), x1 - 0.15 * (x1 - x0), k)
    ys = np.linspace(y0 + 0.15 * (y1 - y0), y1 - 0.15 * (y1 - y0), k)
    return np.array([(x, y) for y in ys for x in xs])


def _circle(bounds: Bounds, n: int) -> np.ndarray:
    x0, y0, x1, y1 = bounds
    cx, cy, r = (x0 + x1) / 2, (y0 + y1) / 2, 0.38 * min(x1 - x0, y1 - y0)
    # the 12 integer points of x^2 + y^2 = 25, scaled by a power of two and centred on a multiple
    # of it, so that every coordinate is exact in binary and every four are exactly cocircular
    # (exact incircle 0); more points use angles and are cocircular only up to rounding
    if n <= 12:
        unit = [(5, 0), (4, 3), (3, 4), (0, 5), (-3, 4), (-4, 3), (-5, 0), (-4, -3), (-3, -4),
                (0, -5), (3, -4), (4, -3)]
        step = 2.0 ** math.floor(math.log2(r / 5))
        cx, cy = round(cx / step) * step, round(cy / step) * step
        return np.array([(cx + step * u, cy + step * v) for u, v in unit[:max(4, n)]])
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])


def _collinear(bounds: Bounds, n: int) -> np.ndarray:
    x0, y0, x1, y1 = bounds
    xs = np.linspace(x0 + 0.1 * (x1 - x0), x1 - 0.1 * (x1 - x0), max(3, n))
    return np.column_stack([xs, np.full(len(xs), (y0 + y1) / 2)])   # exactly collinear: one y


def _duplicates(bounds: Bounds, n: int) -> np.ndarray:
    x0, y0, x1, y1 = bounds
    w, h = x1 - x0, y1 - y0
    base = [(x0 + 0.2 * w, y0 + 0.2 * h), (x0 + 0.8 * w, y0 + 0.3 * h), (x0 + 0.5 * w, y0 + 0.8 * h),
            (x0 + 0.45 * w, y0 + 0.45 * h)]
    return np.array(base + base[:2])   # two points given twice


def _random(bounds: Bounds, n: int, seed: int = 0) -> np.ndarray:
    x0, y0, x1, y1 = bounds
    u = np.random.default_rng(seed).random((n, 2))
    return np.column_stack([x0 + (0.05 + 0.9 * u[:, 0]) * (x1 - x0), y0 + (0.05 + 0.9 * u[:, 1]) * (y1 - y0)])


PRESETS: dict[str, Callable[[Bounds, int], np.ndarray]] = {
    "tutorial": lambda bounds, n: np.array(TUTORIAL_POINTS),   # the dry-run example
    "grid": _grid,
    "circle": _circle,
    "collinear": _collinear,
    "duplicates": _duplicates,
    "random": _random,
}
"""Preset point sets: name -> f(bounds, n) -> (k, 2) points ("tutorial" ignores both)."""


def _count(k: int, word: str) -> str:
    """``k`` and ``word``, plural unless k is 1: ``_count(1, "triangle") == "1 triangle"``."""
    return f"{k} {word}" if k == 1 else f"{k} {word}s"


def preset_points(name: str, bounds: Bounds = (0, 0, 1, 1), n: int = 16) -> np.ndarray:
    """The points of a preset.

    >>> preset_points("grid", n=9).shape, preset_points("duplicates").shape
    ((9, 2), (6, 2))
    >>> preset_points("nope")
    Traceback (most recent call last):
    ...
    ValueError: unknown preset 'nope'; choose from tutorial, grid, circle, collinear, duplicates, random
    """
    if name not in PRESETS:
        raise ValueError(f"unknown preset {name!r}; choose from {', '.join(PRESETS)}")
    return np.asarray(PRESETS[name](tuple(bounds), n), dtype=float).reshape(-1, 2)


_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_LINE = re.compile(rf"^\(?\s*({_NUMBER})\s*(?:,\s*|\s+)({_NUMBER})\s*\)?$")


def parse_points_text(text: str) -> np.ndarray:
    """The points of a text, one ``x, y`` a line (``x y`` and ``(x, y)`` too); blank lines and
    lines starting with ``#`` are skipped.  A line that is not two finite numbers raises
    ``ValueError`` naming its number and text.

    >>> parse_points_text("0, 0\\n# a comment\\n\\n(1.5, -2)\\n3 4e-1").tolist()
    [[0.0, 0.0], [1.5, -2.0], [3.0, 0.4]]
    >>> parse_points_text("0, 0\\n1; 2")
    Traceback (most recent call last):
    ...
    ValueError: line 2: '1; 2' is not a point: write two numbers, x, y (e.g. 0.5, 0.25)
    """
    if not isinstance(text, str):
        raise ValueError(f"points as text must be a string, got {type(text).__name__}")
    out = []
    for k, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        m = _LINE.match(line)
        if m is None:
            raise ValueError(f"line {k}: {line[:40]!r} is not a point: write two numbers, x, y (e.g. 0.5, 0.25)")
        x, y = float(m.group(1)), float(m.group(2))
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"line {k}: {line[:40]!r} is not a point: both numbers must be finite")
        out.append((x, y))
    return np.array(out, dtype=float).reshape(-1, 2)


def points_text(points) -> str:
    """The points as text, one ``x, y`` a line (6 significant digits), as the picker's text box shows them.

    >>> print(points_text([(0.5, 1), (2 / 3, -4)]))
    0.5, 1
    0.666667, -4
    """
    return "\n".join(f"{float(x):.6g}, {float(y):.6g}" for x, y in np.asarray(points, dtype=float).reshape(-1, 2))


def delaunay_triangles(points) -> np.ndarray:
    """The Delaunay triangles of the points ((0, 3) when there are none).

    >>> delaunay_triangles([(0, 0), (1, 0), (0, 1)]).tolist()
    [[0, 1, 2]]
    """
    P = as_points(points)
    if len(P) < 3:
        return np.zeros((0, 3), dtype=np.int64)
    return np.asarray(Delaunay(P).simplices, dtype=np.int64).reshape(-1, 3)


def draw_delaunay(ax, points) -> None:
    """The picker's default picture: the Delaunay triangulation and the points."""
    draw_triangles(ax, points, delaunay_triangles(points))
    draw_points(ax, points, labels=len(points) <= 30)


class PointPicker(KitWidget):
    """Click to add, drag to move, click a point to remove; presets, undo, clear; live redraw.

    ``draw(ax, points)`` draws the picture (default: ``draw_delaunay``);
    ``presets`` adds or overrides presets (name -> points, or f(bounds, n));
    ``on_change(picker)`` runs after every change; ``title`` is a string or
    ``title(points, triangles)``, redrawn with the picture (so it never goes stale);
    ``status(points, triangles)`` writes the line under the picture (default: the point
    count, and the Delaunay triangle count when the picture is the default one: a lesson
    that draws something else says what it drew, or only the points are counted).
    A drag is one change: ``on_change`` runs when the point is released.
    """

    HIT_PIXELS = 9.0
    """A press closer than this (in image pixels) to a point grabs that point."""

    def __init__(self, points=(), *, draw: Callable[[Any, np.ndarray], None] | None = None,
                 presets: Mapping[str, Any] | None = None, bounds: Bounds = (0, 0, 1, 1),
                 on_change: Callable[["PointPicker"], None] | None = None, n: int = 16,
                 size: tuple[int, int] = (440, 400),
                 title: str | Callable[[np.ndarray, np.ndarray], str] = "",
                 status: Callable[[np.ndarray, np.ndarray], str] | None = None) -> None:
        self._points = as_points(points).reshape(-1, 2) if len(points) else np.zeros((0, 2))
        self._draw = draw or draw_delaunay
        self.presets: dict[str, Any] = dict(PRESETS)
        for name, value in (presets or {}).items():
            self.presets[name] = value
        self.bounds: Bounds = tuple(float(v) for v in bounds)  # type: ignore[assignment]
        self.on_change = on_change
        self.n = n
        self.title = title
        self.describe = status
        self._history: list[np.ndarray] = []
        self._drag: int | None = None       # the id of the drag whose moves are arriving
        self._ack: int | None = None        # the seq of the move being answered
        self.canvas = Canvas(*size)
        self.view = SceneView(*size)
        self.view.hit = self.HIT_PIXELS
        self.preset = widgets.Dropdown(options=["(choose one)"] + list(self.presets),
                                       description="preset", layout=widgets.Layout(width="17em"),
                                       style={"description_width": "4em"})
        self.undo_button = button("undo", "undo", "7em", tooltip="undo the last change")
        self.clear_button = button("clear", "trash", "7em", tooltip="remove every point")
        self.status = widgets.HTML()
        # the points as text: the box, the button that applies it, the message about a bad line
        # continuous_update=False: the box's text reaches the kernel whole when it loses the focus
        # (Tab to "set points", or a click on it), never as a half-synced prefix (CI under load saw
        # "line 1: '0'" when the text was typed fast and the button pressed at once)
        self.text = widgets.Textarea(description="points", placeholder="one point a line: x, y",
                                     continuous_update=False,
                                     layout=widgets.Layout(width="19em", height="7em"),
                                     style={"description_width": "4em"})
        self.text_button = button("set points", "check", "9em", tooltip="replace the points by the box's lines")
        self.message = widgets.HTML()
        keys = "; ".join(f"<b>{html.escape(k)}</b>: {html.escape(v)}" for k, v in KEYS)
        self.help = widgets.HTML(f'<details class="kit-keys"><summary>keyboard</summary>'
                                 f'<span style="font-size:12px">{keys}</span></details>')
        self.view.label = "point picker: Tab here, arrow keys move the cursor or the selected point, " \
                          "Enter adds a point, ] and [ select one, Delete removes it"
        super().__init__([widgets.HBox([self.preset, self.undo_button, self.clear_button]),
                          self.view, self.status,
                          widgets.HBox([self.text, widgets.VBox([self.text_button, self.message])]), self.help])
        self.add_class("kit-point-picker")
        self.preset.observe(self.guard(self._on_preset), names="value")
        self.undo_button.on_click(self.guard(lambda _: self.undo()))
        self.clear_button.on_click(self.guard(lambda _: self.clear()))
        self.text_button.on_click(self.guard(lambda _: self.apply_text()))
        self.view.on_gesture(self.guard(self.handle_gesture))
        self.triangles = np.zeros((0, 3), dtype=np.int64)
        self._fit_view(self._points)
        self._refresh(notify=False)
        self.text.value = points_text(self._points)

    # -- the state
    @property
    def points(self) -> np.ndarray:
        """The points, an (n, 2) float array (a copy)."""
        return self._points.copy()

    def _change(self, new: np.ndarray, *, record: bool = True, notify: bool = True) -> None:
        if record:
            self._history.append(self._points)
        self._points = np.asarray(new, dtype=float).reshape(-1, 2)
        self._refresh(notify=notify)

    def add_point(self, x: float, y: float) -> None:
        """Add the point (x, y)."""
        self._change(np.vstack([self._points, as_points([(x, y)])]))

    def move_point(self, i: int, x: float, y: float, *, record: bool = True) -> None:
        """Move point ``i`` to (x, y)."""
        self._check_index(i)
        new = self._points.copy()
        new[i] = as_points([(x, y)])[0]
        self._change(new, record=record)

    def remove_point(self, i: int) -> None:
        """Remove point ``i`` (later points shift down by one)."""
        self._check_index(i)
        self._change(np.delete(self._points, i, axis=0))

    def set_points(self, points) -> None:
        """Replace all points (undoable)."""
        P = as_points(points) if len(points) else np.zeros((0, 2))
        self._change(P.reshape(-1, 2))

    def undo(self) -> None:
        """Go back one change (nothing happens when there is none)."""
        if self._history:
            self._change(self._history.pop(), record=False)

    def clear(self) -> None:
        """Remove every point (undoable)."""
        self._change(np.zeros((0, 2)))

    def set_points_text(self, text: str) -> None:
        """Replace the points by those of ``text``, one ``x, y`` a line (undoable); a bad line
        raises ``ValueError`` naming it, and the points stay as they were."""
        P = parse_points_text(text)
        self._fit_view(P)
        self.set_points(P)

    def apply_text(self) -> None:
        """What "set points" does: the text box's points replace the picker's, or the message
        under the button names the bad line (the points stay as they were)."""
        try:
            self.set_points_text(self.text.value)
        except ValueError as err:
            self.message.value = (f'<span class="kit-text-error" role="alert" style="color:#b00020">'
                                  f'{html.escape(str(err))}</span>')
            self.view.announce = str(err)
            return
        self.message.value = (f'<span class="kit-text-ok" role="status">'
                              f'{_count(len(self._points), "point")} set</span>')

    def load_preset(self, name: str, n: int | None = None) -> None:
        """Replace the points by a preset (see ``PRESETS``); the view fits the points."""
        if name not in self.presets:
            raise ValueError(f"unknown preset {name!r}; choose from {', '.join(self.presets)}")
        value = self.presets[name]
        P = value(self.bounds, n or self.n) if callable(value) else value
        P = np.asarray(P, dtype=float).reshape(-1, 2)
        self._fit_view(P)
        self.set_points(P)

    def _fit_view(self, P: np.ndarray) -> None:
        """Widen the view to whole units around the points when some are outside it."""
        x0, y0, x1, y1 = self.bounds
        if len(P) and (P[:, 0].min() < x0 or P[:, 0].max() > x1 or P[:, 1].min() < y0 or P[:, 1].max() > y1):
            lo, hi = np.floor(P.min(axis=0)) - 1, np.ceil(P.max(axis=0)) + 1
            self.bounds = (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))

    def _check_index(self, i: int) -> None:
        if not 0 <= int(i) < len(self._points):
            raise ValueError(f"no point {i}: the picker has {len(self._points)} points")

    # -- gestures from the browser (canvas.js), in image pixels
    def handle_gesture(self, gesture: Any) -> None:
        """Apply one gesture the browser sent (``SceneView.parse`` checks it first).

        ``{"kind": "add", "x", "y"}`` adds a point at that pixel, ``{"kind": "remove", "i"}``
        removes point i, ``{"kind": "move", "i", "x", "y", "seq", "drag", "end"}`` moves point i;
        the first move of a drag records one undo step, ``end`` marks the release, and the
        answer carries ``ack = seq`` whatever happens, so the browser never waits forever.
        """
        try:
            g = SceneView.parse(gesture)
        except ValueError:
            seq = gesture.get("seq") if isinstance(gesture, Mapping) else None
            if isinstance(seq, int) and not isinstance(seq, bool) and seq > self.view.ack:
                self.view.ack = seq                      # answered, so the browser lets the drag go
            raise
        if g["kind"] in ("step", "play"):
            raise ValueError(f"a point picker takes add, remove and move gestures, got {g['kind']!r}")
        if g["kind"] == "add":
            self.add_point(*self.canvas.to_data(g["x"], g["y"]))
        elif g["kind"] == "remove":
            self.remove_point(g["i"])
        else:
            self._ack = g["seq"]
            try:
                self._check_index(g["i"])
                if g["drag"] != self._drag:
                    self._drag = g["drag"]
                    self._history.append(self._points)   # one undo step for the whole drag
                new = self._points.copy()
                new[g["i"]] = as_points([self.canvas.to_data(g["x"], g["y"])])[0]
                self._change(new, record=False, notify=g["end"])
            finally:
                if self._ack is not None:                 # not answered (an error): answer anyway
                    self.view.ack = self._ack
                    self._ack = None
                if g["end"]:
                    self._drag = None

    def _on_preset(self, change) -> None:
        if change["new"] in self.presets:
            self.load_preset(change["new"])

    # -- drawing
    def _draw_axes(self) -> None:
        ax = self.canvas.clear(bounds=self.bounds, title=self.title_text())
        self._draw(ax, self._points)
        ax.set_xlim(self.bounds[0], self.bounds[2])
        ax.set_ylim(self.bounds[1], self.bounds[3])

    def _refresh(self, notify: bool = True) -> None:
        self.triangles = delaunay_triangles(self._points)
        self._draw_axes()
        scene = axes_scene(self.canvas, self._points)
        pixels = [round(float(v), 3) for v in pixel_points(self.canvas, self._points).ravel()]
        with self.view.hold_sync():       # one message: the scene, the points and the answer's ack
            self.view.scene = scene
            self.view.points = pixels
            if self._ack is not None:
                self.view.ack, self._ack = self._ack, None
        status = self.status_text()
        self.status.value = f'<span class="kit-status">{html.escape(status)}</span>'
        if notify or not self.view.announce:   # a finished change (not each move of a drag): the box and
            self.view.announce = status        # the live region follow, once
        if notify:
            self.text.value = points_text(self._points)
            self.message.value = ""
        if notify and self.on_change is not None:
            self.on_change(self)

    def title_text(self) -> str:
        """The title drawn now: ``title``, or ``title(points, triangles)`` when it is a function."""
        return self.title(self._points, self.triangles) if callable(self.title) else self.title

    def static_png(self) -> bytes:
        """The picture as PNG bytes, drawn by Agg from the same axes (for notebooks run headless)."""
        return self.canvas.png()

    def status_text(self) -> str:
        """The line under the picture: ``status(points, triangles)`` when the lesson gives one, else the
        points (and the Delaunay triangles, when the picture is the default Delaunay drawing).

        >>> PointPicker([(0, 0), (1, 0), (0, 1)]).status_text()
        '3 points (3 distinct), 1 Delaunay triangle'
        >>> PointPicker([(0, 0), (1, 0)], draw=lambda ax, pts: None).status_text()
        '2 points (2 distinct)'
        """
        if self.describe is not None:
            return self.describe(self._points, self.triangles)
        distinct = len(np.unique(self._points, axis=0)) if len(self._points) else 0
        text = f"{len(self._points)} points ({distinct} distinct)"
        if self._draw is draw_delaunay:
            text += f", {_count(len(self.triangles), 'Delaunay triangle')}"
        return text

    def static_text(self) -> str:
        title = self.title_text()
        return (f"PointPicker{': ' + title if title else ''} ({self.status_text()}; "
                "click to add, drag to move, click a point to remove)")

