"""3D pictures drawn and turned by the browser: ``Player3D``, a step player for points, edges and faces in space.

Run the examples:  python -m pytest reference_impl/kit/canvas3d.py

The kernel sends the geometry once (``geometry_3d``: the points scaled into the unit ball, the edges
and faces as flat index arrays) and the steps once (a turn about the vertical axis and a caption
each).  The page (``canvas3d.js``) does the rest: it draws a step as soon as the Play widget or the
slider reaches it (the three are linked in the page, so play never waits for the kernel and shows
every step), a mouse drag turns the picture, and so do the arrow keys once the picture has the focus
(``KEYS_3D``).  The kernel hears the step and the final view, never a frame.  Without a browser
(nbconvert, CI) ``static_png`` is a filmstrip of the steps drawn by matplotlib.

>>> import numpy as np
>>> cube = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
>>> p = Player3D(cube, edges=[(0, 1), (0, 2), (0, 4)], angles=np.linspace(0, np.pi, 4, endpoint=False),
...              describe=lambda a: f"turned {np.degrees(a):.0f} degrees")
>>> p.next.click(); p.index, p.view.step, p.caption.value
(1, 2, '<b>step 2/4</b>: turned 45 degrees')
>>> p.view.geometry["edges"]
[0, 1, 0, 2, 0, 4]
>>> geometry_3d(cube, edges=[(0, 9)])
Traceback (most recent call last):
...
ValueError: edges: vertex 9 is not a point index (8 points)
"""
from __future__ import annotations

import html
import math
from pathlib import Path
from typing import Any, Callable, Sequence

import anywidget
import ipywidgets as widgets
import numpy as np
import traitlets

from .render import COLORS, filmstrip
from .widget import KitWidget, button

__all__ = ["View3D", "Player3D", "geometry_3d", "project", "KEYS_3D"]

KEYS_3D = (
    ("Tab", "focus the picture (a blue ring shows it has the focus)"),
    ("arrow keys", "turn it: left / right about the vertical axis, up / down tilt it (5 degrees; Shift: 20)"),
    ("Page Down / Page Up", "the next / previous step; Home / End: the first / last step"),
    ("Space", "play / pause"),
    ("0", "back to the starting view"),
)
"""A 3D picture's keys (canvas3d.js); a mouse drag turns it too."""


def _indices(rows: Any, width: int, n: int, name: str) -> np.ndarray:
    a = np.asarray(rows if rows is not None else [], dtype=float)
    if a.size == 0:
        return np.zeros((0, width), dtype=np.int64)
    if a.ndim != 2 or a.shape[1] != width:
        raise ValueError(f"{name}: expected rows of {width} point indices, got shape {a.shape}")
    if not np.all(np.isfinite(a)) or not np.all(a == np.round(a)):
        raise ValueError(f"{name}: point indices must be whole numbers")
    bad = a[(a < 0) | (a >= n)]
    if bad.size:
        raise ValueError(f"{name}: vertex {int(bad[0])} is not a point index ({n} points)")
    return a.astype(np.int64)


def geometry_3d(points, *, edges=None, faces=None, marks: Sequence[int] = (), depth_colors: bool = True,
                **style: Any) -> dict:
    """The JSON the page draws: points centred and scaled into the unit ball, edges and faces as flat lists.

    ``marks`` are drawn larger and red (the new point); ``depth_colors`` colours points and edges by
    their depth (viridis), else ``style`` gives ``edge_color``, ``point_color``, ``face_color``,
    ``face_alpha``, ``point_r``, ``mark_r``, ``lw``.

    >>> g = geometry_3d([(0, 0, 0), (2, 0, 0)], edges=[(0, 1)])
    >>> g["xyz"], g["edges"]
    ([-1.0, 0.0, 0.0, 1.0, 0.0, 0.0], [0, 1])
    """
    P = np.asarray(points, dtype=float) if not isinstance(points, str) else None
    if P is None or P.ndim != 2 or P.shape[1] != 3 or len(P) == 0:
        raise ValueError(f"points must be a non-empty (n, 3) array, got {'text' if P is None else P.shape}")
    if not np.all(np.isfinite(P)):
        raise ValueError("points must be finite (no NaN or infinity)")
    n = len(P)
    E = _indices(edges, 2, n, "edges")
    F = _indices(faces, 3, n, "faces")
    M = _indices([[m] for m in marks], 1, n, "marks").ravel()
    Q = P - (P.min(axis=0) + P.max(axis=0)) / 2
    radius = float(np.sqrt((Q ** 2).sum(axis=1)).max()) or 1.0
    Q = Q / radius
    known = {"edge_color", "point_color", "face_color", "mark_color", "face_alpha", "point_r", "mark_r", "lw"}
    unknown = sorted(set(style) - known)
    if unknown:
        raise ValueError(f"unknown style {unknown[0]!r} (expected one of {', '.join(sorted(known))})")
    return {"xyz": [round(float(v), 6) for v in Q.ravel()], "edges": E.ravel().tolist(),
            "faces": F.ravel().tolist(), "marks": M.tolist(), "depth_colors": bool(depth_colors), **style}


def project(xyz: np.ndarray, yaw: float, pitch: float) -> tuple[np.ndarray, np.ndarray]:
    """The page's projection: (x, y) on the screen (y up) and the depth (larger: farther).

    >>> xy, z = project(np.array([[1.0, 0, 0]]), math.pi / 2, 0.0)
    >>> np.round(xy, 6).tolist(), np.round(z, 6).tolist()
    ([[0.0, 0.0]], [1.0])
    """
    cy, sy, cp, sp = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    x, y, z = xyz[:, 0], xyz[:, 1], xyz[:, 2]
    qx, qz = cy * x - sy * z, sy * x + cy * z
    return np.c_[qx, cp * y - sp * qz], sp * y + cp * qz


class View3D(anywidget.AnyWidget):
    """The picture: ``geometry`` and ``steps`` sent once, ``step`` (1-based) linked to the controls in the page."""

    _esm = Path(__file__).with_name("canvas3d.js")
    _css = """
    .kit-canvas3d { display: block; cursor: grab; background: white; }
    .kit-canvas3d:active { cursor: grabbing; }
    .kit-canvas3d:focus { outline: none; }
    .kit-canvas3d:focus-visible { outline: 3px solid #1a73e8; outline-offset: 2px; }
    .kit-3d-caption { margin-top: 4px; max-width: 40em; }
    """
    geometry = traitlets.Dict().tag(sync=True)
    steps = traitlets.List(traitlets.Dict()).tag(sync=True)
    """Per step: ``{"yaw": radians, "caption": text}``."""
    step = traitlets.Int(1).tag(sync=True)
    playing = traitlets.Bool(False).tag(sync=True)
    yaw = traitlets.Float(0.0).tag(sync=True)
    """The viewer's own turn (a drag, the arrow keys), added to the step's."""
    pitch = traitlets.Float(0.3).tag(sync=True)
    start_pitch = traitlets.Float(0.3).tag(sync=True)
    width = traitlets.Int(480).tag(sync=True)
    height = traitlets.Int(400).tag(sync=True)
    label = traitlets.Unicode("").tag(sync=True)
    """The picture's ARIA label (the page adds the current step's caption)."""


class Player3D(KitWidget):
    """Play / pause, previous / next and a slider through turns of a 3D picture the browser draws.

    ``angles`` are the steps (turns about the vertical axis, radians); ``describe(angle)`` is a
    step's caption.  ``.index`` is the step shown (0-based), ``.view`` the picture.
    """

    def __init__(self, points, *, edges=None, faces=None, marks: Sequence[int] = (),
                 angles: Sequence[float] = (0.0,), describe: Callable[[float], str] | None = None,
                 title: str = "", size: tuple[int, int] = (480, 400), interval: int = 300, pitch: float = 0.3,
                 depth_colors: bool = True, **style: Any) -> None:
        self.steps = [float(a) for a in angles]
        if not self.steps or not all(math.isfinite(a) for a in self.steps):
            raise ValueError("Player3D needs at least one finite angle (a step) to show")
        self.title = title
        self._describe = describe or (lambda a: f"turned {math.degrees(a):.0f} degrees")
        self.captions = [str(self._describe(a)) for a in self.steps]
        last = len(self.steps)
        self.view = View3D(geometry=geometry_3d(points, edges=edges, faces=faces, marks=marks,
                                                depth_colors=depth_colors, **style),
                           steps=[{"yaw": a, "caption": c} for a, c in zip(self.steps, self.captions)],
                           width=int(size[0]), height=int(size[1]), pitch=float(pitch), start_pitch=float(pitch),
                           label=f"{title or '3D picture'}: drag or use the arrow keys to turn it, Page Down and "
                                 "Page Up step, Home and End go to the first and last step, Space plays and pauses")
        self.play = widgets.Play(value=1, min=1, max=last, step=1, interval=interval, description="play")
        self.slider = widgets.IntSlider(value=1, min=1, max=last, description="step", continuous_update=True)
        # all three linked in the page: a step reaches the picture without the kernel
        self.links = [widgets.jslink((self.play, "value"), (self.slider, "value")),
                      widgets.jslink((self.play, "value"), (self.view, "step")),
                      widgets.jslink((self.play, "playing"), (self.view, "playing"))]
        self.prev = button("previous", "step-backward")
        self.next = button("next", "step-forward")
        self.prev.tooltip, self.next.tooltip = "the previous step", "the next step"
        self.caption = widgets.HTML()
        """The caption as the kernel knows it (the page draws its own under the picture, at once)."""
        super().__init__([widgets.HTML(f"<b>{html.escape(title)}</b>") if title else widgets.HTML(),
                          widgets.HBox([self.play, self.prev, self.next, self.slider]), self.view])
        self.add_class("kit-step-player")
        self.add_class("kit-player-3d")
        self.prev.on_click(self.guard(lambda _: self._go(self.index - 1)))
        self.next.on_click(self.guard(lambda _: self._go(self.index + 1)))
        self.slider.observe(self.guard(lambda _: self._caption()), names="value")
        self._caption()

    @property
    def index(self) -> int:
        """The step shown (0-based; the slider shows it 1-based); setting it moves the slider."""
        return int(self.slider.value) - 1

    @index.setter
    def index(self, value: int) -> None:
        self._go(value)

    def _go(self, value: int) -> None:
        k = max(0, min(len(self.steps) - 1, int(value))) + 1
        self.slider.value = k
        self.view.step = k          # the page links them too; here for a kernel without a page

    def _caption(self) -> None:
        k = self.index            # never sets view.step back: during play the page is ahead of the kernel
        self.caption.value = f"<b>step {k + 1}/{len(self.steps)}</b>: " + html.escape(self.captions[k])

    # -- the static stand-in: a filmstrip of (at most 8) steps, as the page draws them
    def _draw(self, ax, k: int) -> None:
        from matplotlib import colormaps
        from matplotlib.collections import LineCollection, PolyCollection

        g = self.view.geometry
        xyz = np.asarray(g["xyz"], dtype=float).reshape(-1, 3)
        xy, z = project(xyz, self.steps[k] + self.view.yaw, self.view.pitch)
        near = 1 - (z - z.min()) / (np.ptp(z) or 1.0)
        faces = np.asarray(g["faces"], dtype=np.int64).reshape(-1, 3)
        edges = np.asarray(g["edges"], dtype=np.int64).reshape(-1, 2)
        ax.set_xlim(-1.15, 1.15)
        ax.set_ylim(-1.15, 1.15)
        if len(faces):
            order = np.argsort(-z[faces].sum(axis=1))
            ax.add_collection(PolyCollection(xy[faces[order]], facecolors=g.get("face_color", COLORS["bad"]),
                                             alpha=g.get("face_alpha", 0.25), edgecolors="none"))
        if len(edges):
            cmap = colormaps["viridis"]
            edges = edges[np.argsort(-z[edges].sum(axis=1))]            # far ones first, as the page draws
            colors = (cmap(near[edges].mean(axis=1)) if g["depth_colors"] else g.get("edge_color", COLORS["edge"]))
            ax.add_collection(LineCollection(xy[edges], colors=colors, linewidths=g.get("lw", 0.8)))
        marks = np.zeros(len(xyz), dtype=bool)
        marks[g["marks"]] = True
        colors = colormaps["viridis"](near[~marks]) if g["depth_colors"] else g.get("point_color", COLORS["point"])
        ax.scatter(xy[~marks, 0], xy[~marks, 1], c=colors, s=10, zorder=3)
        if marks.any():
            ax.scatter(xy[marks, 0], xy[marks, 1], color=g.get("mark_color", COLORS["new_point"]), s=40, zorder=4)

    def static_png(self) -> bytes:
        n = len(self.steps)
        picks = sorted(set(np.linspace(0, n - 1, min(n, 8)).round().astype(int).tolist()))
        return filmstrip(lambda ax, k, _: self._draw(ax, k), picks,
                         titles=[f"step {k + 1}: {self.captions[k]}"[:40] for k in picks])

    def static_text(self) -> str:
        return (f"Player3D{': ' + self.title if self.title else ''} ({len(self.steps)} steps; "
                f"step {self.index + 1}: {self.captions[self.index]})")
