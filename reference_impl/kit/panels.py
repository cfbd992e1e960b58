"""The measurement panel's plot and the timed-practice panel's clock, drawn by the browser (panels.js).

Run the examples:  python -m pytest reference_impl/kit/panels.py

``PanelView(kind="loglog")`` holds ``series`` (per contender its n's, its seconds and the fitted
slope) and the page draws the log-log plot as SVG; ``PanelView(kind="clock")`` holds a deadline and
the kernel's clock, and the page counts down once a second by itself (no message to the kernel).
The kernel draws no picture for them; ``loglog_png`` and ``clock_png`` are the static stand-ins for
a notebook run without a browser.

>>> v = PanelView(kind="loglog", series=[{"name": "f", "ns": [10, 100], "ts": [0.1, 1.0], "slope": 1.0}])
>>> v.kind, v.series[0]["slope"]
('loglog', 1.0)
>>> PanelView(kind="pie")
Traceback (most recent call last):
...
traitlets.traitlets.TraitError: The 'kind' trait of a PanelView instance expected any of ['loglog', 'clock'], not the str 'pie'.
"""
from __future__ import annotations

import warnings
from pathlib import Path

import anywidget
import traitlets

from .render import Canvas

__all__ = ["PanelView", "loglog_png", "clock_png"]


class PanelView(anywidget.AnyWidget):
    """An SVG picture drawn by the page: a log-log plot (``series``) or a countdown (``deadline``)."""

    _esm = Path(__file__).with_name("panels.js")
    _css = ".kit-panel-picture { display: block; max-width: 100%; height: auto; }"
    kind = traitlets.Enum(["loglog", "clock"], default_value="loglog").tag(sync=True)
    width = traitlets.Int(480).tag(sync=True)
    height = traitlets.Int(340).tag(sync=True)
    title = traitlets.Unicode("").tag(sync=True)
    series = traitlets.List(traitlets.Dict()).tag(sync=True)
    """Per contender ``{"name", "ns", "ts", "slope"}`` (slope ``None`` below two sizes)."""
    deadline = traitlets.Float(-1.0).tag(sync=True)
    """The clock's deadline (seconds since the epoch, the kernel's clock); negative: not started."""
    total = traitlets.Float(1800.0).tag(sync=True)
    now = traitlets.Float(0.0).tag(sync=True)
    """The kernel's clock when the deadline was sent: the page corrects its own clock by the difference."""
    idle = traitlets.Unicode("").tag(sync=True)
    """What the clock says before the start."""


def loglog_png(series: list[dict], title: str = "", size: tuple[int, int] = (480, 340)) -> bytes:
    """The plot as a PNG (matplotlib): the static stand-in for a notebook run without a browser."""
    canvas = Canvas(*size)
    ax = canvas.ax
    ax.cla()
    with warnings.catch_warnings():   # log axes with a single value warn about singular limits
        warnings.simplefilter("ignore", UserWarning)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("n")
        ax.set_ylabel("seconds")
        ax.set_title(title, fontsize=10)
        for s in series:
            legend = s["name"] + (f" (slope {s['slope']:.2f})" if s.get("slope") is not None else "")
            ax.plot(s["ns"], s["ts"], "o-", label=legend)
        values = [t for s in series for t in s["ts"] if t > 0]
        if values and min(values) == max(values):     # one value: give the log axis some room
            ax.set_ylim(values[0] / 3, values[0] * 3)
        if series:
            ax.legend(fontsize=8, loc="upper left")
        else:
            ax.text(0.5, 0.5, "press measure", transform=ax.transAxes, ha="center")
        ax.set_position((0.14, 0.14, 0.82, 0.76))
        return canvas.png()


def clock_png(text: str, frac: float, late: bool, size: tuple[int, int] = (420, 90)) -> bytes:
    """The clock as a PNG (matplotlib): the time left when the notebook was run, and its bar."""
    from matplotlib.patches import Rectangle

    canvas = Canvas(*size)
    ax = canvas.clear(bounds=(0, 0, 1, 1))
    ax.set_aspect("auto")
    ax.set_axis_off()
    ax.add_patch(Rectangle((0.02, 0.15), 0.96, 0.3, fill=False, lw=1.5))
    ax.add_patch(Rectangle((0.02, 0.15), 0.96 * min(1.0, max(0.0, frac)), 0.3, color="#d62728" if late else "#2a7f2a"))
    ax.text(0.02, 0.75, text, fontsize=13, va="center")
    return canvas.png()
