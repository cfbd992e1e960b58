"""Tests of the lesson kit (reference_impl/kit/): widget state and callbacks, without a browser.

    .venv/bin/python -m pytest tests/kit -q

Widgets are driven the way a browser drives them: ``button.click()`` fires the
on_click callbacks, setting ``slider.value`` fires the observers, and a point
picker's view receives the gesture messages its front end (kit/canvas.js) sends
(``add``/``remove``/``move`` in image pixels) through the widget's message path.  Pictures are checked to be
PNGs of the promised size that change when the state changes.  Oracles: the
triangles a widget shows are compared with scipy.spatial.Delaunay (general
position), with the exact checker ``verify.check_delaunay`` and with the
library's trace; the quiz's answers with a brute-force in-circle test on
Python integers (``exact_oracle``).
"""
from __future__ import annotations

import base64
import json

import numpy as np
import pytest
from scipy.spatial import Delaunay as ScipyDelaunay

from exact_oracle import canon, exact, incircle as exact_incircle, orient as exact_orient
from reference_impl import bowyer_watson
from reference_impl.structures.flips import validate_triangulation
from reference_impl.kit import MeasurePanel, PointPicker, PredictReveal, PredictRevealMany, StepPlayer, pick, quick_mode
from reference_impl.kit.picker import delaunay_triangles
from reference_impl.kit.player import BOWYER_WATSON_PSEUDOCODE, scrambled_triangulation
from reference_impl.kit.quiz import bad_triangles_quiz, locally_delaunay_quiz
from reference_impl.kit.render import Canvas, png_size
from reference_impl.exact.verify import check_delaunay

TUTORIAL = [(1, 1), (3, 2), (5, 1), (4, 4)]


def scipy_canon(points) -> set:
    d = ScipyDelaunay(np.asarray(points, dtype=float))
    P = np.asarray(points, dtype=float)
    rows = []
    for a, b, c in d.simplices.tolist():     # scipy does not promise counter-clockwise rows
        if exact_orient(*exact(P[[a, b, c]])) < 0:
            b, c = c, b
        rows.append((a, b, c))
    return canon(rows)


def png_of(bundle: dict) -> bytes:
    return base64.b64decode(bundle["image/png"])


# ----------------------------------------------------------------------------- render
def test_canvas_pixel_mapping_round_trips_and_png_has_the_promised_size():
    c = Canvas(width=300, height=200)
    c.clear(bounds=(-2, -1, 5, 3))
    for x, y in [(-2, -1), (0, 0), (4.5, 2.5), (1.25, 0.75)]:
        px, py = c.to_pixel(x, y)
        assert 0 <= px <= 300 and 0 <= py <= 200
        assert np.allclose(c.to_data(px, py), (x, y), atol=1e-9)
    # y grows downwards in image pixels
    assert c.to_pixel(0, 2)[1] < c.to_pixel(0, 0)[1]
    assert png_size(c.png()) == (300, 200)


# ----------------------------------------------------------------------------- player
def test_bowyer_watson_player_steps_through_the_trace_and_highlights_each_phase():
    p = StepPlayer.bowyer_watson(TUTORIAL)
    steps = []
    bowyer_watson(TUTORIAL, trace=steps, order="input")
    inserting = [s for s in steps if s.bad]
    assert len(p.steps) == 2 + 4 * len(inserting) + 1    # start-up, 4 phases per insertion, the answer
    seen_lines, seen_images = [], set()
    for k in range(len(p.steps)):
        assert p.index == k
        seen_lines.append(p.current_line)
        seen_images.add(json.dumps(p.image.scene, sort_keys=True))     # what the browser is told to draw
        # the highlighted pseudocode line is the current phase's, and only that one
        highlighted = [key for key, _ in BOWYER_WATSON_PSEUDOCODE
                       if f'data-key="{key}" style="background' in p.code.value]
        assert highlighted == [p.current_line]
        p.next.click()
    assert p.index == len(p.steps) - 1                     # next on the last step stays there
    assert seen_lines[:2] == ["start", "start"]
    assert seen_lines[2:6] == ["locate", "bad", "boundary", "new"]
    assert len(seen_images) == len(p.steps)               # every step draws a different picture
    assert seen_lines[-1] == "done"                         # every line of the pseudocode is reached
    assert {key for key, _ in BOWYER_WATSON_PSEUDOCODE} == set(seen_lines)
    last = p.steps[-1]
    assert canon(last.before) == canon(bowyer_watson(TUTORIAL)) == scipy_canon(TUTORIAL)
    p.prev.click()
    assert p.index == len(p.steps) - 2
    p.slider.value = 4                                      # the slider counts from 1: step 4 is index 3
    assert p.index == 3 and f"step 4/{len(p.steps)}" in p.caption.value
    assert p.current_line == "bad" and "bad triangles" in p.caption.value


def test_player_on_random_points_ends_in_the_delaunay_triangulation():
    pts = np.random.default_rng(3).random((25, 2))
    p = StepPlayer.bowyer_watson(pts)
    p.index = 10 ** 6                                      # clamps to the last step
    assert p.index == len(p.steps) - 1
    assert p.step.phase == "done" and canon(p.step.before) == scipy_canon(pts)
    assert (p.image.scene["w"], p.image.scene["h"]) == (480, 400) and not p.image.interactive
    from reference_impl.kit.scene import pixel_points
    P = pixel_points(p.canvas, pts)                         # the browser's triangles, read back as indices
    drawn = set()
    for item in p.image.scene["items"]:
        if item["t"] == "path" and item["closed"] and set(item["n"]) == {3}:
            for tri in np.asarray(item["xy"]).reshape(-1, 3, 2):
                d = np.hypot(*(P[None, :, :] - tri[:, None, :]).transpose(2, 0, 1))
                if d.min(axis=1).max() < 1e-2:
                    drawn.add(tuple(sorted(d.argmin(axis=1).tolist())))
    assert {tuple(sorted(t)) for t in p.step.before} <= drawn


def test_generic_player_with_phases_and_bad_input():
    drawn = []
    p = StepPlayer([10, 20, 30], lambda ax, s, i: drawn.append((s, i)),
                   phases=lambda s: "odd" if s % 20 else "even",
                   pseudocode=[("odd", "x"), ("even", "y")])
    p.next.click()
    assert drawn[-1] == (20, 1) and p.current_line == "even"
    with pytest.raises(ValueError, match="at least one step"):
        StepPlayer([], lambda ax, s, i: None)


def test_player_callback_errors_go_to_its_log_not_to_the_void():
    def draw(ax, s, i):
        if i == 1:
            raise RuntimeError("drawing step 1 failed")

    p = StepPlayer([0, 1], draw)
    p.next.click()                                         # must not raise (as in JupyterLab)
    assert "drawing step 1 failed" in str(p.errors.outputs)


def test_lawson_player_flips_to_the_delaunay_triangulation_one_legal_flip_at_a_time():
    pts = np.random.default_rng(5).random((30, 2))
    start = scrambled_triangulation(pts)
    validate_triangulation(pts, start)                     # a real triangulation of the points...
    assert not check_delaunay(pts, start)[0]               # ...that is not Delaunay
    p = StepPlayer.lawson(pts, start)
    phases = [f.phase for f in p.steps]
    assert phases[0] == "start" and phases[-1] == "done"
    assert phases[1:-1] == ["test", "flip"] * ((len(phases) - 2) // 2)
    X = exact(pts)
    for f in p.steps:
        validate_triangulation(pts, f.triangles)          # every frame is a triangulation
        if f.phase == "test":                              # the edge is illegal: exact check
            i, j = f.edge
            pair = [t for t in f.triangles.tolist() if i in t and j in t]
            far = next(v for v in pair[1] if v not in (i, j))
            assert exact_incircle(*[X[v] for v in pair[0]], X[far]) > 0
    assert canon(p.steps[-1].triangles) == scipy_canon(pts)
    p.slider.value = 2
    assert p.current_line == "test"
    assert png_size(png_of(p._repr_mimebundle_()))[0] > 0


def test_player_static_picture_is_a_filmstrip_and_text_says_what_it_shows():
    p = StepPlayer.bowyer_watson(TUTORIAL)
    bundle = p._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    w, h = png_size(png_of(bundle))
    assert w > 480 and h >= 190                            # several frames side by side
    assert bundle["text/plain"].startswith("StepPlayer: Bowyer-Watson (11 steps")


# ----------------------------------------------------------------------------- picker
def send(picker: PointPicker, **gesture) -> None:
    """A message from the picker's front end, through the widget's own message path."""
    picker.view._handle_custom_msg(gesture, [])


def hit(picker: PointPicker, px: float, py: float):
    """The point the front end grabs at pixel (px, py): canvas.js's rule, nearest within ``hit``."""
    P = np.asarray(picker.view.points).reshape(-1, 2)
    if len(P) == 0:
        return None
    d = np.hypot(P[:, 0] - px, P[:, 1] - py)
    return int(d.argmin()) if d.min() <= picker.view.hit else None


def click(picker: PointPicker, x: float, y: float) -> None:
    """A click at data point (x, y): on empty space it adds, on a point it removes (as canvas.js does)."""
    px, py = picker.canvas.to_pixel(x, y)
    i = hit(picker, px, py)
    if i is None:
        send(picker, kind="add", x=px, y=py)
    else:
        send(picker, kind="remove", i=i)


def drag(picker: PointPicker, i: int, path, *, drag_id: int, seq0: int = 0) -> int:
    """Point i dragged through the data points ``path`` (the last one is the release); the last seq."""
    for k, (x, y) in enumerate(path):
        px, py = picker.canvas.to_pixel(x, y)
        send(picker, kind="move", i=i, x=px, y=py, seq=seq0 + k + 1, drag=drag_id, end=k == len(path) - 1)
    return seq0 + len(path)


def scene_triangles(picker: PointPicker) -> set:
    """The triangles the browser is told to draw: the scene's closed parts whose 3 vertices are points."""
    out = []
    for item in picker.view.scene["items"]:
        if item["t"] != "path" or not item["closed"]:
            continue
        j = 0
        for n in item["n"]:
            refs = item["ref"][j:j + n]
            j += n
            if n == 3 and min(refs) >= 0:
                out.append(tuple(refs))
    return canon(out)


def test_picker_click_adds_drag_moves_click_on_point_removes():
    p = PointPicker([(0.2, 0.2), (0.8, 0.25), (0.5, 0.8)])
    before = p.view.scene
    click(p, 0.5, 0.45)                                     # empty space: a new point
    assert len(p.points) == 4 and np.allclose(p.points[3], (0.5, 0.45), atol=0.01)
    assert canon(p.triangles) == scipy_canon(p.points) and len(p.triangles) == 3
    assert p.view.scene != before and scene_triangles(p) == canon(p.triangles)
    # drag point 3 to (0.5, 0.1): two moves, the second one the release
    last = drag(p, 3, [(0.5, 0.3), (0.5, 0.1)], drag_id=1)
    assert p.view.ack == last                               # the kernel answered the release
    assert len(p.points) == 4 and np.allclose(p.points[3], (0.5, 0.1), atol=0.01)
    assert check_delaunay(p.points, p.triangles) == (True, "ok")
    assert scene_triangles(p) == canon(p.triangles)
    P = np.asarray(p.view.points).reshape(-1, 2)            # the browser's points are the kernel's, in pixels
    assert np.allclose(P, [p.canvas.to_pixel(*q) for q in p.points], atol=1e-3)
    p.undo()                                                # one undo reverts the whole drag
    assert np.allclose(p.points[3], (0.5, 0.45), atol=0.01)
    click(p, *p.points[0])                                  # click on a point: removed
    assert len(p.points) == 3 and not np.allclose(p.points[0], (0.2, 0.2))
    p.undo()
    assert np.allclose(p.points[0], (0.2, 0.2))


def test_picker_drag_reports_once_and_always_answers():
    changes = []
    p = PointPicker([(0.2, 0.2), (0.8, 0.25), (0.5, 0.8), (0.5, 0.4)], on_change=lambda w: changes.append(1))
    px, py = p.canvas.to_pixel(0.5, 0.5)
    send(p, kind="move", i=3, x=px, y=py, seq=1, drag=7, end=False)
    assert p.view.ack == 1 and changes == []                # answered at once; on_change waits for the release
    send(p, kind="move", i=3, x=px, y=py + 5, seq=2, drag=7, end=True)
    assert p.view.ack == 2 and changes == [1]
    # a move the kernel cannot apply (the point is gone) is still answered, and the error is shown
    send(p, kind="move", i=9, x=px, y=py, seq=3, drag=8, end=True)
    shown = lambda: "".join(o.get("text", "") for o in p.errors.outputs)     # noqa: E731
    assert p.view.ack == 3 and "no point 9" in shown()
    for bad, message in [({"kind": "move", "i": 0, "x": float("nan"), "y": 1, "seq": 4, "drag": 9},
                          "x must be a finite number"),
                         ({"kind": "add", "x": "1", "y": 2}, "x must be a finite number"),
                         ({"kind": "remove", "i": True}, "i must be a point index"),
                         ({"kind": "zoom"}, "unknown gesture 'zoom'")]:
        send(p, **bad)
        assert message in shown(), message
    assert len(p.points) == 4                               # nothing changed by the bad messages


def test_picker_scene_follows_the_lessons_drawing():
    """A custom draw's triangles, circles and labels reach the scene, tied to the points they sit on."""
    from reference_impl.kit.render import draw_circumcircle, draw_points, draw_triangles

    def draw(ax, pts):
        tris = delaunay_triangles(pts)
        draw_triangles(ax, pts, tris)
        for t in tris:
            draw_circumcircle(ax, *pts[t])
        draw_points(ax, pts, labels=True)
        ax.plot([0.1, 0.9], [0.05, 0.05], "g--")           # a line on no point: fixed pixels

    p = PointPicker([(0.2, 0.2), (0.8, 0.25), (0.5, 0.8), (0.45, 0.45)], draw=draw)
    kinds = [item["t"] for item in p.view.scene["items"]]
    assert kinds.count("circle") == len(p.triangles) == 3 and kinds.count("dots") == 1
    circles = [item for item in p.view.scene["items"] if item["t"] == "circle"]
    assert sorted(tuple(sorted(c["through"])) for c in circles) == sorted(tuple(sorted(t)) for t in p.triangles.tolist())
    P = np.asarray(p.view.points).reshape(-1, 2)
    for c in circles:                                        # each circle passes through its three points
        assert np.allclose(np.hypot(*(P[c["through"]] - c["c"]).T), c["r"], rtol=1e-4)
    labels = [item for item in p.view.scene["items"] if item["t"] == "text" and item["ref"] >= 0]
    assert sorted((item["ref"], item["s"]) for item in labels) == [(i, str(i)) for i in range(4)]
    line = [item for item in p.view.scene["items"] if item["t"] == "path" and item["dash"]]
    assert len(line) == 1 and line[0]["ref"] == [-1, -1] and line[0]["stroke"] == ["#008000"]
    assert p.view.scene["raster"] == ""                     # nothing here needs a PNG layer


def test_picker_scene_puts_what_svg_cannot_say_in_a_png_layer():
    def draw(ax, pts):
        ax.imshow(np.arange(16.0).reshape(4, 4), extent=(0, 1, 0, 1))
        ax.scatter(pts[:, 0], pts[:, 1])
    p = PointPicker([(0.2, 0.2), (0.8, 0.25), (0.5, 0.8)], draw=draw)
    raster = p.view.scene["raster"]
    assert raster.startswith("data:image/png;base64,")
    assert png_size(base64.b64decode(raster.split(",", 1)[1])) == (440, 400)
    assert [item["t"] for item in p.view.scene["items"]].count("dots") == 1


def test_picker_presets_undo_clear_and_on_change():
    changes = []
    p = PointPicker(on_change=lambda w: changes.append(len(w.points)))
    p.load_preset("tutorial")
    assert p.points.tolist() == [[1, 1], [3, 2], [5, 1], [4, 4]]
    assert canon(p.triangles) == canon(bowyer_watson(TUTORIAL))
    px, py = p.canvas.to_pixel(4, 4)                        # the view was fitted to the points
    assert 0 < px < 440 and 0 < py < 400
    p.preset.value = "grid"                                 # the dropdown loads a preset
    assert len(p.points) == 16 and len(p.triangles) == 18  # 3x3 squares, 2 triangles each
    p.load_preset("collinear")
    assert len(p.triangles) == 0 and "0 Delaunay triangles" in p.status.value
    p.load_preset("duplicates")
    assert len(p.points) == 6 and "(4 distinct)" in p.status.value and len(p.triangles) == 3
    p.load_preset("circle")
    assert len(p.triangles) == len(p.points) - 2
    p.load_preset("random", n=40)
    assert canon(p.triangles) == scipy_canon(p.points)
    p.clear()
    assert len(p.points) == 0 and len(p.triangles) == 0
    p.undo()
    assert len(p.points) == 40
    assert changes[-2:] == [0, 40]
    with pytest.raises(ValueError, match="unknown preset"):
        p.load_preset("spiral")
    with pytest.raises(ValueError, match="no point 99"):
        p.remove_point(99)
    with pytest.raises(ValueError, match="not finite"):
        p.add_point(float("nan"), 0)


def test_picker_view_fits_points_given_outside_its_bounds():
    p = PointPicker(TUTORIAL)                              # default bounds are the unit square
    for x, y in TUTORIAL:
        px, py = p.canvas.to_pixel(x, y)
        assert 0 < px < 440 and 0 < py < 400
    click(p, 3.5, 2.5)
    assert len(p.points) == 5 and len(p.triangles) == 5


def test_picker_custom_draw_and_static_picture():
    calls = []
    p = PointPicker([(0, 0), (1, 0), (0, 1)], draw=lambda ax, pts: calls.append(len(pts)))
    p.add_point(1, 1)
    assert calls == [3, 4]
    bundle = p._repr_mimebundle_()
    assert png_size(png_of(bundle)) == (440, 400)            # the headless picture: Agg, same axes
    # a picture the lesson draws itself: the line counts the points, it claims no Delaunay triangles
    assert "4 points (4 distinct);" in bundle["text/plain"] and "Delaunay" not in bundle["text/plain"]
    assert "Delaunay" not in p.status.value
    said = PointPicker([(0, 0), (1, 0)], draw=lambda ax, pts: None, status=lambda pts, tris: f"{len(pts)} stops")
    assert "2 stops" in said.status.value and "2 stops;" in said.static_text()
    assert "application/vnd.jupyter.widget-view+json" in bundle


# ----------------------------------------------------------------------------- quizzes
def test_predict_reveal_locks_the_choice_and_gives_feedback():
    q = PredictReveal("2 + 2?", [("three", 3), ("four", 4)], 4, explain="Count.")
    assert q.submit_button.disabled                       # nothing chosen: cannot commit
    q.choose(4)
    assert not q.submit_button.disabled and "four" not in q.feedback.value
    q.submit_button.click()
    assert q.revealed and q.correct and q.options.disabled
    assert "Right." in q.feedback.value and "four" in q.feedback.value
    with pytest.raises(ValueError, match="locked"):
        q.choose(3)
    html = q._repr_mimebundle_()["text/html"]
    assert "<details>" in html and "four" in html.split("<details>")[1]
    with pytest.raises(ValueError, match="not one of the choices"):
        PredictReveal("?", [1, 2], 3)


def test_bad_triangle_quiz_answers_are_the_triangles_whose_circle_holds_the_point():
    rng = np.random.default_rng(11)
    pts = rng.random((9, 2))
    X = exact(pts)
    q = bad_triangles_quiz(pts, 6)
    steps = []
    bowyer_watson(pts, trace=steps, order="input")
    new = steps[6].index
    expected = {t for _, t in q.choices
                if -1 not in t and exact_incircle(X[t[0]], X[t[1]], X[t[2]], X[new]) > 0}
    expected |= {t for _, t in q.choices if -1 in t and exact_orient(X[t[0]], X[t[1]], X[new]) > 0}
    assert set(q.answers) == expected
    for t in q.answers:
        q.choose(t)
    assert q.submit() is True and "Right." in q.feedback.value
    wrong = bad_triangles_quiz(pts, 6)
    assert wrong.submit() is (len(wrong.answers) == 0)     # ticking nothing is a prediction too
    assert png_size(png_of(q._repr_mimebundle_()))[0] == 360


def test_locally_delaunay_quiz_against_exact_incircle():
    pts = [(0, 0), (4, 0), (4, 1), (0, 3)]
    q = locally_delaunay_quiz(pts, (1, 3), [(0, 1, 3), (1, 2, 3)])
    assert q.answer == "no"
    q.choose("yes")
    assert q.submit() is False and "Not quite." in q.feedback.value
    legal = locally_delaunay_quiz(pts, (0, 2), [(0, 1, 2), (0, 2, 3)])
    assert legal.answer == "yes"
    with pytest.raises(ValueError, match="interior edge"):
        locally_delaunay_quiz(pts, (0, 1), [(0, 1, 3), (1, 2, 3)])


def test_many_quiz_needs_exactly_the_right_set():
    m = PredictRevealMany("?", ["a", "b", "c"], ["a", "c"])
    m.choose("a")
    assert m.submit() is False and "a, c" in m.feedback.value


# ----------------------------------------------------------------------------- measurement
def test_measure_panel_records_plots_and_fits_slopes():
    calls = []

    def run(n):
        calls.append(n)
        return {"square": (n / 100) ** 2, "linear": n / 100}

    panel = MeasurePanel(run, [100, 200, 400, 800], label="fake timings")
    assert panel.image.series == [] and panel.image.kind == "loglog"     # drawn by the page (panels.js)
    empty = panel.static_png()
    panel.n.value = 200
    panel.measure_button.click()
    assert calls == [200] and panel.results["square"] == {200: 4.0}
    panel.measure_all()
    assert calls == [200, 100, 200, 400, 800]
    assert panel.slope("square") == pytest.approx(2.0) and panel.slope("linear") == pytest.approx(1.0)
    assert panel.static_png() != empty
    shown = {s["name"]: s for s in panel.image.series}              # what the page plots
    assert shown["square"]["ns"] == [100, 200, 400, 800] and shown["square"]["slope"] == pytest.approx(2.0)
    assert shown["linear"]["ts"] == [1.0, 2.0, 4.0, 8.0]
    assert "slope 2.00" in panel._repr_mimebundle_()["text/plain"]
    bad = MeasurePanel(lambda n: None, [1])
    bad.measure_button.click()                              # a broken run() is reported in the log
    assert "ValueError" in str(bad.errors.outputs)


def test_quick_mode_follows_the_environment(monkeypatch):
    monkeypatch.setenv("COURSE_QUICK", "1")
    assert quick_mode() and pick("small", "big") == "small"
    monkeypatch.setenv("COURSE_QUICK", "0")
    assert not quick_mode() and pick("small", "big") == "big"


def test_plain_import_of_the_library_does_not_load_the_kit():
    import subprocess
    import sys
    code = "import sys, reference_impl; print('reference_impl.kit' in sys.modules, 'ipywidgets' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False", "False"]


# ----------------------------------------------------------------------------- issue 25's small ones
def test_picker_title_can_follow_the_points_and_counts_say_triangle_once():
    title = lambda pts, tris: f"{len(tris)} now"                      # noqa: E731
    p = PointPicker([(0.1, 0.1), (0.5, 0.5), (0.9, 0.9)], title=title)
    assert p.title_text() == "0 now"
    p.add_point(0.9, 0.1)
    assert p.title_text() == f"{len(p.triangles)} now" and len(p.triangles) > 0
    q = PointPicker([(0.2, 0.2), (0.8, 0.2), (0.5, 0.7)])
    assert "1 Delaunay triangle<" in q.status.value and "1 Delaunay triangle;" in q.static_text()
    assert all(len(o) <= 12 for o in q.preset.options)                # nothing cut off in the dropdown


def test_circle_preset_is_exactly_cocircular():
    from itertools import combinations

    from reference_impl.kit.picker import preset_points

    P = preset_points("circle", n=12)
    assert all(exact_incircle(*exact(P[list(q)])) == 0 for q in combinations(range(12), 4))


def test_ghost_choices_name_the_side_they_cover():
    q = bad_triangles_quiz(TUTORIAL, 2)           # two points: both ghosts share the line 0-1
    labels = [label for label, _ in q.choices]
    assert labels == ["ghost (0, 1, inf): the half-plane above the line through 0 and 1",
                      "ghost (1, 0, inf): the half-plane below the line through 1 and 0"]
    assert q.answers == [(1, 0, -1)]              # (5, 1) lies below the line through (1, 1), (3, 2)
    later = [label for label, _ in bad_triangles_quiz(TUTORIAL, 3).choices]
    assert "ghost (0, 1, inf): outside hull edge 0-1" in later


def test_scrambled_triangulation_stays_valid_and_differs_from_delaunay():
    pts = np.random.default_rng(5).random((60, 2))
    for seed in range(3):
        T = scrambled_triangulation(pts, seed=seed)
        assert len(validate_triangulation(pts, T)) == len(T)
        assert canon(T) != scipy_canon(pts)


def test_progress_line_is_silent_outside_a_kernel_and_measure_all_still_measures():
    from reference_impl.kit.progress import progress

    assert list(progress(range(3), "x")) == [0, 1, 2]
    panel = MeasurePanel(lambda n: {"f": n * 1e-6}, [10, 20])
    assert sorted(panel.measure_all()["f"]) == [10, 20]
