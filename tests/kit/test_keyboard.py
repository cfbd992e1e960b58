"""The kit without a mouse: points typed as text, and the gestures the keyboard sends, in the kernel.

    .venv/bin/python -m pytest tests/kit/test_keyboard.py -q

canvas.js turns keys into the same messages as the mouse (an arrow key on a selected point is
a drag whose release is the key's release, Enter an ``add`` at the + cursor, Delete a
``remove``; a player's picture sends ``step``).  Here those messages go through the widget's
message path, as the page sends them, and the text box is filled and applied as a student
would.  Oracles: scipy.spatial.Delaunay for the triangles, the points typed for the points.
The browser half (real key presses in chromium) is tests/browser/test_keyboard.py.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import Delaunay as ScipyDelaunay

from reference_impl.kit import PointPicker, StepPlayer
from reference_impl.kit.canvas import KEYS, SceneView
from reference_impl.kit.picker import parse_points_text, points_text


def send(view: SceneView, content: dict) -> None:
    """What a message from the page does (the path ``on_gesture`` listens on)."""
    view._handle_custom_msg(content, [])


def errors_text(widget) -> str:
    """The tracebacks a kit widget printed into its error area."""
    return "".join(o.get("text", "") for o in widget.errors.outputs)


def delaunay_set(points) -> set:
    return {tuple(sorted(t)) for t in ScipyDelaunay(np.asarray(points)).simplices.tolist()}


# -- the text: parsing
@pytest.mark.parametrize("text, want", [
    ("0, 0\n1, 0\n0, 1", [[0, 0], [1, 0], [0, 1]]),
    ("  2.5 ,-1e-3  \n(3, 4)\n5 6", [[2.5, -0.001], [3, 4], [5, 6]]),
    ("# a comment\n\n.5, +7.\n", [[0.5, 7]]),
    ("", []),
])
def test_points_parse_from_text(text, want):
    got = parse_points_text(text)
    assert got.shape == (len(want), 2)
    assert got.tolist() == [[float(a), float(b)] for a, b in want]


@pytest.mark.parametrize("text, line, bad", [
    ("0, 0\n1, 0\n1, two", 3, "'1, two'"),
    ("0, 0\n1, 2, 3", 2, "'1, 2, 3'"),
    ("7", 1, "'7'"),
    ("0, 0\n\n# ok\ninf, 1", 4, "'inf, 1'"),
    ("1e999, 1", 1, "both numbers must be finite"),
    ("0,, 1", 1, "'0,, 1'"),
])
def test_a_bad_line_is_named(text, line, bad):
    with pytest.raises(ValueError, match=f"^line {line}: ") as err:
        parse_points_text(text)
    assert bad in str(err.value)


def test_text_that_is_not_a_string_is_refused():
    with pytest.raises(ValueError, match="must be a string, got list"):
        parse_points_text([(0, 0)])


def test_points_text_round_trips_to_six_digits():
    P = np.random.default_rng(3).random((20, 2)) * 100 - 50
    back = parse_points_text(points_text(P))
    assert back.shape == P.shape and np.allclose(back, P, rtol=1e-5, atol=1e-4)


# -- the text box in the picker
def test_set_points_replaces_the_points_and_is_undoable():
    p = PointPicker([(0.2, 0.2), (0.8, 0.2), (0.5, 0.8)])
    assert parse_points_text(p.text.value).tolist() == p.points.tolist()     # the box shows the points
    p.text.value = "0.1, 0.1\n0.9, 0.1\n0.9, 0.9\n0.1, 0.9\n0.5, 0.45"
    p.text_button.click()
    assert p.points.tolist() == [[0.1, 0.1], [0.9, 0.1], [0.9, 0.9], [0.1, 0.9], [0.5, 0.45]]
    assert {tuple(sorted(t)) for t in p.triangles.tolist()} == delaunay_set(p.points)
    assert "5 points set" in p.message.value and "kit-text-error" not in p.message.value
    assert p.view.announce == p.status_text() and "5 points" in p.view.announce
    p.undo()
    assert len(p.points) == 3 and len(p.triangles) == 1


def test_a_bad_line_changes_nothing_and_says_which():
    p = PointPicker([(0.2, 0.2), (0.8, 0.2), (0.5, 0.8)])
    before, history = p.points, len(p._history)
    p.text.value = "0.1, 0.1\n0.9; 0.1\n0.5, 0.5"
    p.text_button.click()
    assert p.points.tolist() == before.tolist() and len(p._history) == history
    assert 'role="alert"' in p.message.value and "line 2: &#x27;0.9; 0.1&#x27; is not a point" in p.message.value
    assert p.view.announce.startswith("line 2:")
    assert not p.errors.outputs                    # a message for the student, not a traceback


def test_text_outside_the_view_widens_it():
    p = PointPicker([(0.2, 0.2), (0.8, 0.2), (0.5, 0.8)])
    p.set_points_text("0, 0\n10, 0\n5, 8")
    x0, y0, x1, y1 = p.bounds
    assert x0 <= 0 and y0 <= 0 and x1 >= 10 and y1 >= 8
    assert len(p.triangles) == 1


# -- the keyboard's gestures
def test_enter_adds_a_point_at_the_cursor_pixel():
    p = PointPicker([(0.2, 0.2), (0.8, 0.2), (0.5, 0.8)])
    px, py = p.canvas.to_pixel(0.5, 0.4)
    send(p.view, {"kind": "add", "x": px, "y": py})
    assert len(p.points) == 4 and np.allclose(p.points[-1], (0.5, 0.4), atol=1e-9)
    assert len(p.triangles) == 3
    assert p.text.value.splitlines()[-1] == "0.5, 0.4"       # the box follows a finished change


def test_arrow_presses_on_a_selected_point_are_one_drag_and_one_undo_step():
    p = PointPicker([(0.2, 0.2), (0.8, 0.2), (0.5, 0.8), (0.5, 0.4)])
    changes = []
    p.on_change = lambda picker: changes.append(len(picker.points))
    x, y = p.view.points[6:8]
    text_before = p.text.value
    # a held right arrow: three key repeats, then the release (canvas.js: 4 px a press)
    for k, end in ((1, False), (2, False), (3, True)):
        send(p.view, {"kind": "move", "i": 3, "x": x + 4 * k, "y": y, "seq": k, "drag": 7, "end": end})
        assert p.view.ack == k                            # every move is answered
        if not end:
            assert p.text.value == text_before and changes == []    # mid-drag: no notification
    assert p.view.points[6:8] == [pytest.approx(x + 12, abs=1e-3), pytest.approx(y, abs=1e-3)]
    assert changes == [4] and p.text.value != text_before
    assert {tuple(sorted(t)) for t in p.triangles.tolist()} == delaunay_set(p.points)
    p.undo()
    assert p.view.points[6:8] == [pytest.approx(x, abs=1e-3), pytest.approx(y, abs=1e-3)]


def test_delete_removes_the_selected_point():
    p = PointPicker([(0.2, 0.2), (0.8, 0.2), (0.5, 0.8), (0.5, 0.4)])
    send(p.view, {"kind": "remove", "i": 1})
    assert p.points.tolist() == [[0.2, 0.2], [0.5, 0.8], [0.5, 0.4]]
    assert "3 points" in p.view.announce


def test_a_bad_key_gesture_is_reported_in_the_widget():
    p = PointPicker([(0.2, 0.2), (0.8, 0.2)])
    send(p.view, {"kind": "remove", "i": 5})
    assert "no point 5" in errors_text(p) and len(p.points) == 2
    send(p.view, {"kind": "step", "by": 1})          # a player's gesture is not a picker's
    assert "takes add, remove and move gestures, got 'step'" in errors_text(p) and len(p.points) == 2


def test_the_picture_is_labelled_and_focusable_by_design():
    p = PointPicker([(0.2, 0.2), (0.8, 0.2)])
    assert p.view.interactive and not p.view.stepper and "Enter adds a point" in p.view.label
    assert [k for k, _ in KEYS][:3] == ["Tab", "arrow keys", "Enter"]
    assert "keyboard" in p.help.value and "Delete or Backspace" in p.help.value
    assert p.text.description == "points" and p.text_button.tooltip


# -- a player's picture
def test_player_keys_step_and_clamp():
    player = StepPlayer.bowyer_watson([(1, 1), (3, 2), (5, 1), (4, 4)])
    assert player.image.stepper and not player.image.interactive and "arrow keys" in player.image.label
    send(player.image, {"kind": "step", "by": 1})
    assert player.index == 1 and player.image.announce.startswith("step 2/11: ")
    send(player.image, {"kind": "step", "by": 5})
    assert player.index == 6
    send(player.image, {"kind": "step", "by": 1_000_000})      # End
    assert player.index == 10 and player.image.announce.startswith("step 11/11: done")
    send(player.image, {"kind": "step", "by": -1_000_000})     # Home
    assert player.index == 0


def test_space_plays_and_pauses():
    player = StepPlayer.bowyer_watson([(1, 1), (3, 2), (5, 1), (4, 4)])
    assert player.play.playing is False and "Space plays" in player.image.label
    send(player.image, {"kind": "play"})
    assert player.play.playing is True
    send(player.image, {"kind": "play"})
    assert player.play.playing is False


@pytest.mark.parametrize("bad, message", [
    ({"kind": "step", "by": 1.5}, "by must be a whole number of steps, got 1.5"),
    ({"kind": "step", "by": True}, "by must be a whole number of steps, got True"),
    ({"kind": "add", "x": 1, "y": 1}, "takes step and play gestures, got 'add'"),
])
def test_player_refuses_a_bad_gesture_visibly(bad, message):
    player = StepPlayer.bowyer_watson([(1, 1), (3, 2), (5, 1), (4, 4)])
    send(player.image, bad)
    assert message in errors_text(player) and player.index == 0
