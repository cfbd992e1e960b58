"""Tests of the timed-practice panel (reference_impl/kit/timer.py) against the real grader CLI.

    .venv/bin/python -m pytest tests/kit/test_timer.py -q

The panel shells out to ``python -m grader timed start/submit``; the oracle is the
grader's own store (``grader.classroom.timed`` reads the same SQLite file) and its report.
Each test uses its own temporary database, so it runs beside other graders.
"""
from __future__ import annotations

import base64
import sqlite3
import time
from pathlib import Path

from reference_impl.kit import TimedPractice
from reference_impl.kit.render import png_size
from reference_impl.kit.timer import format_clock

ROOT = Path(__file__).resolve().parents[2]


def test_clock_text():
    assert format_clock(1800) == "30:00 left"
    assert format_clock(0.4) == "00:00 left"
    assert format_clock(-61) == "late by 01:01"


def test_submit_before_start_is_refused_and_start_is_recorded(tmp_path):
    mine = tmp_path / "mine.py"
    mine.write_text("def helper():\n    return 1\n")
    panel = TimedPractice("bowyer-watson-timed", "ada", mine, tmp_path / "exam.sqlite")
    assert panel.remaining() is None and panel.submit_button.disabled
    before = panel.static_png()
    t0 = time.time()
    info = panel.start()
    assert not panel.submit_button.disabled
    assert 29 * 60 < panel.remaining() <= 30 * 60
    assert info["started_at"] >= t0 - 1 and info["deadline"] - info["started_at"] == 30 * 60
    rows = sqlite3.connect(tmp_path / "exam.sqlite").execute("SELECT student, problem FROM timed").fetchall()
    assert rows == [("ada", "bowyer-watson-timed")]
    again = panel.start()                               # a second start keeps the first time
    assert again["started_at"] == info["started_at"]
    assert panel.static_png() != before                 # the picture shows the clock now
    assert panel.image.deadline == info["deadline"] and panel.image.total == 30 * 60   # the page counts down
    assert "left" in panel.static_text()
    report = panel.submit()                             # no entry function: compile error, a verdict
    assert "CE" in report and "bowyer_watson" in report
    assert "CE" in panel.output.value


def test_accepted_solution_through_the_panel(tmp_path):
    accepted = ROOT / "solutions" / "bowyer-watson-timed" / "accepted_scan.py"
    panel = TimedPractice("bowyer-watson-timed", "bob", accepted, tmp_path / "exam.sqlite")
    panel.start_button.click()
    assert panel.remaining() is not None
    panel.submit_button.click()
    assert not panel.errors.outputs, panel.errors.outputs
    assert "AC (accepted), score 100/100" in panel.report


def test_missing_file_and_static_picture(tmp_path):
    panel = TimedPractice("bowyer-watson-timed", "cy", tmp_path / "nothing.py", tmp_path / "exam.sqlite")
    panel.start()
    assert "no file" in panel.submit()
    bundle = panel._repr_mimebundle_()
    png = base64.b64decode(bundle["image/png"])
    assert png_size(png) == (420, 90)
    assert "TimedPractice" in bundle["text/plain"]
