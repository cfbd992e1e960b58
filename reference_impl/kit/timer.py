"""The timed-practice panel: a visible countdown and the judge one click away.

Run the examples:  python -m pytest --doctest-modules reference_impl/kit/timer.py -q

``TimedPractice(problem, student, path, db)`` drives the grader's timed attempts
through its command line, exactly as a student in a terminal would:
**start** runs ``python -m grader timed start PROBLEM STUDENT --db DB`` (the clock
starts on the grader's side and a second start keeps the first time), **submit**
runs ``python -m grader timed submit PROBLEM STUDENT PATH --db DB`` and shows the
judge's report.  The countdown is redrawn every second by a ``Play`` ticker in
the browser; without a browser the static picture shows the time left when the
notebook was executed.

>>> import tempfile, pathlib
>>> db = pathlib.Path(tempfile.mkdtemp()) / "exam.sqlite"
>>> panel = TimedPractice("bowyer-watson-timed", "ada", "mine.py", db)
>>> panel.remaining() is None          # not started yet
True
"""
from __future__ import annotations

import html
import json
import subprocess
import sys
import time
from pathlib import Path

import ipywidgets as widgets
from matplotlib.patches import Rectangle

from .render import Canvas
from .widget import KitWidget, button, png_image

__all__ = ["TimedPractice", "format_clock"]

ROOT = Path(__file__).resolve().parents[2]


def format_clock(seconds: float) -> str:
    """``mm:ss`` left, or ``late by mm:ss`` once the time is up.

    >>> format_clock(1799.2), format_clock(-65)
    ('29:59 left', 'late by 01:05')
    """
    s = int(abs(seconds)) if seconds < 0 else int(seconds)
    text = f"{s // 60:02d}:{s % 60:02d}"
    return f"late by {text}" if seconds < 0 else f"{text} left"


class TimedPractice(KitWidget):
    """Start the clock, see it count down, submit the file to the judge; ``.report`` is the last report."""

    def __init__(self, problem: str, student: str, path: str | Path, db: str | Path, *,
                 python: str = sys.executable, cwd: str | Path = ROOT, size: tuple[int, int] = (420, 90)) -> None:
        self.problem, self.student = problem, student
        self.path, self.db = Path(path), Path(db)
        self.python, self.cwd = python, Path(cwd)
        self.started_at: float | None = None
        self.deadline: float | None = None
        self.duration_min: float | None = None
        self.report = ""
        self.canvas = Canvas(*size)
        self.clock = widgets.HTML()
        self.image = png_image(size[0])
        self.ticker = widgets.Play(value=0, min=0, max=6 * 3600, step=1, interval=1000, description="clock",
                                   layout=widgets.Layout(display="none"))
        self.start_button = button("start the clock", "clock-o", width="12em", button_style="primary")
        self.submit_button = button("submit to the judge", "gavel", width="14em", disabled=True)
        self.output = widgets.HTML()
        super().__init__([widgets.HBox([self.start_button, self.submit_button, self.ticker]),
                          self.clock, self.image, self.output])
        self.add_class("kit-timed-practice")
        self.start_button.on_click(self.guard(lambda _: self.start()))
        self.submit_button.on_click(self.guard(lambda _: self.submit()))
        self.ticker.observe(self.guard(lambda _: self._render()), names="value")
        self._render()

    def _grader(self, *args: str) -> subprocess.CompletedProcess:
        return subprocess.run([self.python, "-m", "grader", "timed", *args, "--db", str(self.db)],
                              cwd=self.cwd, capture_output=True, text=True)

    def start(self) -> dict:
        """Start (or resume) the attempt on the grader's clock; returns what the grader recorded."""
        proc = self._grader("start", self.problem, self.student, "--json")
        if proc.returncode != 0:
            raise ValueError(f"timed start failed: {proc.stderr.strip() or proc.stdout.strip()}")
        info = json.loads(proc.stdout)
        self.started_at, self.deadline = float(info["started_at"]), float(info["deadline"])
        self.duration_min = float(info["duration_min"])
        self.submit_button.disabled = False
        self.ticker.playing = True
        self._render()
        return info

    def remaining(self, now: float | None = None) -> float | None:
        """Seconds until the deadline (negative when late); ``None`` before the start."""
        if self.deadline is None:
            return None
        return self.deadline - (time.time() if now is None else now)

    def submit(self) -> str:
        """Judge ``path`` as a timed submission (the grader's ``timed submit``); returns its report."""
        if not self.path.is_file():
            self.report = f"no file {self.path}: save your solution there first"
        else:
            proc = self._grader("submit", self.problem, self.student, str(self.path))
            self.report = (proc.stdout + proc.stderr).strip()
        self.output.value = f'<pre class="kit-judge-report">{html.escape(self.report)}</pre>'
        self._render()
        return self.report

    def _render(self) -> None:
        left = self.remaining()
        ax = self.canvas.clear(bounds=(0, 0, 1, 1))
        ax.set_aspect("auto")
        ax.set_axis_off()
        if left is None:
            text, frac = f"{self.problem}: press start ({self.student})", 0.0
        else:
            text = f"{self.problem}: {format_clock(left)}"
            total = 60 * (self.duration_min or 30)
            frac = min(1.0, max(0.0, 1 - left / total))
        ax.add_patch(Rectangle((0.02, 0.15), 0.96, 0.3, fill=False, lw=1.5))
        ax.add_patch(Rectangle((0.02, 0.15), 0.96 * frac, 0.3, color="#d62728" if left is not None and left < 0 else "#2a7f2a"))
        ax.text(0.02, 0.75, text, fontsize=13, va="center")
        self.image.value = self.canvas.png()
        self.clock.value = f'<span class="kit-clock">{html.escape(text)}</span>'

    def static_png(self) -> bytes:
        return bytes(self.image.value)

    def static_text(self) -> str:
        left = self.remaining()
        state = "not started" if left is None else format_clock(left)
        return f"TimedPractice: {self.problem} for {self.student} ({state}; submits {self.path.name})"
