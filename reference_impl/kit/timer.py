"""The timed-practice panel: a visible countdown and the judge one click away.

Run the examples:  python -m pytest --doctest-modules reference_impl/kit/timer.py -q

``TimedPractice(problem, student, path, db)`` drives the grader's timed attempts
through its command line, exactly as a student in a terminal would:
**start** runs ``python -m grader timed start PROBLEM STUDENT --db DB`` (the clock
starts on the grader's side and a second start keeps the first time), **submit**
runs ``python -m grader timed submit PROBLEM STUDENT PATH --db DB`` and shows the
judge's report.  The countdown is drawn by the browser (``panels.js``), which
redraws it every second by itself: the kernel sends the deadline once.  Without a
browser the static picture shows the time left when the notebook was executed.

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

from .panels import PanelView, clock_png
from .widget import KitWidget, button

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
        self.size = (int(size[0]), int(size[1]))
        self.clock = widgets.HTML()
        self.image = PanelView(kind="clock", width=self.size[0], height=self.size[1], title=problem,
                               idle=f"{problem}: press start ({student})")
        self.start_button = button("start the clock", "clock-o", width="12em", button_style="primary")
        self.submit_button = button("submit to the judge", "gavel", width="14em", disabled=True)
        self.output = widgets.HTML()
        super().__init__([widgets.HBox([self.start_button, self.submit_button]),
                          self.clock, self.image, self.output])
        self.add_class("kit-timed-practice")
        self.start_button.on_click(self.guard(lambda _: self.start()))
        self.submit_button.on_click(self.guard(lambda _: self.submit()))
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

    def _state(self) -> tuple[str, float, bool]:
        """The clock's text, the share of the time used, whether it is up."""
        left = self.remaining()
        if left is None:
            return f"{self.problem}: press start ({self.student})", 0.0, False
        total = 60 * (self.duration_min or 30)
        return f"{self.problem}: {format_clock(left)}", min(1.0, max(0.0, 1 - left / total)), left < 0

    def _render(self) -> None:
        """Send the deadline (the page counts down by itself) and the text as it stands now."""
        with self.image.hold_sync():
            self.image.total = 60 * (self.duration_min or 30)
            self.image.now = time.time()
            self.image.deadline = -1.0 if self.deadline is None else self.deadline
        due = ("" if self.deadline is None else
               f"due at {time.strftime('%H:%M:%S', time.localtime(self.deadline))} (the bar below counts down)")
        self.clock.value = f'<span class="kit-clock">{html.escape(due)}</span>'

    def static_png(self) -> bytes:
        return clock_png(*self._state(), size=self.size)

    def static_text(self) -> str:
        left = self.remaining()
        state = "not started" if left is None else format_clock(left)
        return f"TimedPractice: {self.problem} for {self.student} ({state}; submits {self.path.name})"
