"""The lesson kit: the interactive widgets every lesson of the course is built from.

Run the examples:  python -m pytest reference_impl/kit/__init__.py

Import it explicitly (``import reference_impl`` does not load it, so the judge
and the library never import ipywidgets):

* ``StepPlayer`` (player.py): play / pause / slider / previous / next through any
  recorded algorithm, with the current pseudocode line highlighted;
  ``StepPlayer.bowyer_watson(points)``, ``StepPlayer.lawson(points)``;
* ``PointPicker`` (picker.py): click to add a point, drag to move it, click it to
  remove it; presets, undo, clear; the triangulation redrawn live;
* ``PredictReveal`` / ``PredictRevealMany`` (quiz.py): commit to an answer, then see it;
* ``MeasurePanel`` (measure.py): choose n, run, plot the timings log-log;
* ``TimedPractice`` (timer.py): a countdown and the judge's ``timed submit`` one click away;
* ``Player3D`` (canvas3d.py, canvas3d.js): a 3D picture (points, edges, faces) that the browser
  draws, plays through its steps and turns under a mouse drag or the arrow keys;
* ``progress`` (progress.py): one output line that says how far a long cell has got;
* ``theory`` (theory.py): lesson 13's players, one constrained segment inserted
  (``segment_player``), one 3D cavity turned (``cavity_player``), each Lawson flip's six
  angles (``flip_angle_player``), each insertion's new triangles (``star_player``);
* ``render`` (render.py): the drawing helpers they share;
* ``canvas`` / ``scene`` (canvas.py, canvas.js, scene.py): the picker's and the players'
  pictures drawn by the browser as SVG (an anywidget), from what the lesson drew on a
  matplotlib axes; a dragged point and its triangles move in the page at once;
* ``panels`` (panels.py, panels.js): the measurement panel's log-log plot and the timed-practice
  panel's countdown, drawn by the browser from the numbers (the clock ticks in the page).

Every widget is usable without a mouse: Tab reaches its buttons, menus, sliders and its
picture (a focus ring shows where); on a picker's picture the arrow keys move a cursor or the
selected point (Shift: farther), Enter adds a point, ``]`` / ``[`` select one, Delete removes it,
and a text box takes the points as ``x, y`` lines (``picker.parse_points_text``); a player's
picture steps with the left / right arrows, Home and End (``canvas.KEYS``, ``canvas.PLAYER_KEYS``);
a 3D picture turns with the arrow keys and steps with Page Down / Page Up, Home and End
(``canvas3d.KEYS_3D``).
Pictures carry an ARIA label, and a live region reads out the status line or the caption.

Every widget also carries a static PNG for notebooks run without a browser (drawn by matplotlib
when the widget is displayed; in the page, the browser draws the picture).
``quick_mode()`` is true when the environment sets ``COURSE_QUICK=1`` (CI):
lessons then use small sizes.

>>> from reference_impl.kit import PointPicker
>>> picker = PointPicker([(0.2, 0.2), (0.8, 0.2)])
>>> picker.add_point(0.5, 0.7); len(picker.triangles)
1
"""
from __future__ import annotations

import os

__all__ = ["StepPlayer", "PickAndStep", "Player3D", "PointPicker", "PredictReveal", "PredictRevealMany",
           "MeasurePanel", "TimedPractice", "quick_mode", "pick", "progress"]


def quick_mode() -> bool:
    """True when ``COURSE_QUICK=1`` is set: lessons run with small sizes (CI, headless checks).

    >>> import os; os.environ.pop("COURSE_QUICK", None) and None; quick_mode()
    False
    """
    return os.environ.get("COURSE_QUICK", "").strip().lower() in ("1", "true", "yes")


def pick(quick, full):
    """``quick`` in quick mode, else ``full`` (e.g. ``n = pick(200, 5000)``).

    >>> pick(1, 2) in (1, 2)
    True
    """
    return quick if quick_mode() else full


from .canvas3d import Player3D  # noqa: E402
from .measure import MeasurePanel  # noqa: E402
from .picker import PointPicker  # noqa: E402
from .progress import progress  # noqa: E402
from .player import PickAndStep, StepPlayer  # noqa: E402
from .quiz import PredictReveal, PredictRevealMany  # noqa: E402
from .timer import TimedPractice  # noqa: E402
