"""The picture the browser draws: an anywidget whose front end (canvas.js) draws a scene as SVG.

Run the examples:  python -m pytest reference_impl/kit/canvas.py

``SceneView`` holds three synced traits: ``scene`` (scene.py's JSON: what the
lesson's matplotlib drawing holds, in image pixels), ``points`` (the picker's
points in pixels, flat ``[x0, y0, x1, y1, ...]``) and ``ack`` (the ``seq`` of the
last move the kernel has answered).  The browser draws the scene, moves a dragged
point and everything that refers to it at once, and sends the gestures back as
messages, which ``on_gesture`` callbacks receive as sent (``SceneView.parse`` checks
one, so that a callback that reports its own errors sees a malformed one too).  Only traits whose value changed
travel: a move that leaves the triangles as they were sends the new points only.
The picture is
usable without a mouse: it takes the keyboard focus (Tab; a visible focus ring), a picker's
picture turns keys into the same gestures (see ``KEYS``) and a player's into ``step`` and ``play``; ``label``
is its ARIA label and ``announce`` the text of a polite live region that screen readers read
out when it changes (the status line).  The front end is a file in the package (no build step, no network), and the widget
state that JupyterLab saves in a notebook holds the last scene, so a saved lesson
reopened without a kernel still shows its pictures.

>>> view = SceneView(width=200, height=100)
>>> got = []
>>> view.on_gesture(got.append)
>>> view._handle_custom_msg({"kind": "add", "x": 10, "y": 20}, [])     # what a message from the page does
>>> got, SceneView.parse(got[0])
([{'kind': 'add', 'x': 10, 'y': 20}], {'kind': 'add', 'x': 10.0, 'y': 20.0})
>>> SceneView.parse({"kind": "spin"})
Traceback (most recent call last):
...
ValueError: unknown gesture 'spin' (expected add, remove, move, step or play)
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Callable

import anywidget
import traitlets

__all__ = ["SceneView", "ESM", "KEYS", "PLAYER_KEYS"]

ESM = Path(__file__).with_name("canvas.js")
"""The front end: an ES module that anywidget loads into the page."""

KEYS = (
    ("Tab", "focus the picture (a blue ring shows it has the focus), then the buttons and the text box"),
    ("arrow keys", "move the + cursor, or the selected point (4 pixels a press; with Shift 20)"),
    ("Enter", "add a point at the + cursor"),
    ("] or [", "select the next or previous point (its ring turns orange); Space: the point nearest the cursor"),
    ("Delete or Backspace", "remove the selected point"),
    ("Escape", "unselect the point (the arrow keys move the cursor again)"),
)
"""The picker's keys (canvas.js), as the kit's docs and the picker's help line list them."""

PLAYER_KEYS = (
    ("left / right arrow", "the previous / next step (with Shift: 5 steps)"),
    ("Home / End", "the first / last step"),
    ("Space", "play / pause"),
)
"""A player's picture's keys once it has the focus."""


def _number(content: dict, key: str) -> float:
    value = content.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"gesture {content.get('kind')!r}: {key} must be a finite number, got {value!r}")
    return float(value)


def _index(content: dict, key: str = "i") -> int:
    value = content.get(key)
    if isinstance(value, bool) or not isinstance(value, int) or value < 0:
        raise ValueError(f"gesture {content.get('kind')!r}: {key} must be a point index, got {value!r}")
    return value


class SceneView(anywidget.AnyWidget):
    """An SVG picture drawn in the browser from ``scene``; mouse gestures come back to ``on_gesture``."""

    _esm = ESM
    _css = """
    .kit-canvas { max-width: 100%; height: auto; }
    .kit-canvas.kit-interactive { cursor: crosshair; }
    .kit-canvas text { pointer-events: none; }
    .kit-canvas:focus { outline: none; }
    .kit-canvas:focus-visible { outline: 3px solid #1a73e8; outline-offset: 2px; }
    .kit-live { position: absolute; width: 1px; height: 1px; overflow: hidden; clip: rect(0 0 0 0);
                white-space: nowrap; }
    """
    scene = traitlets.Dict().tag(sync=True)
    points = traitlets.List(traitlets.Float()).tag(sync=True)
    ack = traitlets.Int(0).tag(sync=True)
    hit = traitlets.Float(9.0).tag(sync=True)
    interactive = traitlets.Bool(True).tag(sync=True)
    """False: a picture only (a step player's), the mouse sends nothing."""
    stepper = traitlets.Bool(False).tag(sync=True)
    """True (a player's picture): the arrow keys, Home and End send ``step`` gestures."""
    label = traitlets.Unicode("").tag(sync=True)
    """The picture's ARIA label (what a screen reader says it is)."""
    announce = traitlets.Unicode("").tag(sync=True)
    """The text of the picture's live region (``aria-live="polite"``): the status line."""

    def __init__(self, width: int = 440, height: int = 400, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.width, self.height = int(width), int(height)
        self.scene = {"w": self.width, "h": self.height, "items": [], "raster": ""}

    def on_gesture(self, callback: Callable[[dict], None]) -> None:
        """Call ``callback(message)`` for every message the browser sends (check it with ``parse``)."""
        self.on_msg(lambda _widget, content, _buffers: callback(content))

    @staticmethod
    def parse(content: Any) -> dict:
        """A gesture message checked and normalised; a malformed one raises ``ValueError`` naming the field.

        >>> SceneView.parse({"kind": "move", "i": 2, "x": 1, "y": 2.5, "seq": 7, "drag": 1, "end": True})
        {'kind': 'move', 'i': 2, 'x': 1.0, 'y': 2.5, 'seq': 7, 'drag': 1, 'end': True}
        >>> SceneView.parse({"kind": "remove", "i": -1})
        Traceback (most recent call last):
        ...
        ValueError: gesture 'remove': i must be a point index, got -1
        >>> SceneView.parse({"kind": "step", "by": -1})
        {'kind': 'step', 'by': -1}
        """
        if not isinstance(content, dict):
            raise ValueError(f"a gesture is a dict, got {type(content).__name__}")
        kind = content.get("kind")
        if kind == "add":
            return {"kind": "add", "x": _number(content, "x"), "y": _number(content, "y")}
        if kind == "remove":
            return {"kind": "remove", "i": _index(content)}
        if kind == "play":
            return {"kind": "play"}
        if kind == "step":
            by = content.get("by")
            if isinstance(by, bool) or not isinstance(by, int):
                raise ValueError(f"gesture 'step': by must be a whole number of steps, got {by!r}")
            return {"kind": "step", "by": by}
        if kind == "move":
            return {"kind": "move", "i": _index(content), "x": _number(content, "x"), "y": _number(content, "y"),
                    "seq": _index(content, "seq"), "drag": _index(content, "drag"), "end": bool(content.get("end"))}
        raise ValueError(f"unknown gesture {kind!r} (expected add, remove, move, step or play)")
