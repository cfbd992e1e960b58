"""The lessons in a real browser: JupyterLab started here, Debian's chromium driven by Playwright.

    .venv/bin/python -m pytest tests/browser -q          # needs /usr/bin/chromium (apt-get install chromium)

The test starts its own JupyterLab (free port, temporary root, config and runtime
directories, no token) on a copy of the lessons, opens lesson 03 in headless
chromium, runs every cell, then acts like a student and checks both what the
page shows and what the kernel holds:

* presses "next" in the step player: the caption moves to step 2 and the
  kernel's ``player.index`` becomes 1;
* clicks on empty space in the point picker: the page says 5 points and the
  kernel's picker has 5 points and a different triangulation, and its player
  was rebuilt on them;
* answers a predict-then-reveal question: the feedback appears and is right.

Lesson 01 is opened and run too, and a copy of it is run, saved and reopened in a new tab without
running anything: every widget must show its last picture, not "Error displaying widget: model
not found" (JupyterLab never renders the PNG beside a widget view; the picture comes from the
widget state that ``make setup``'s overrides.json makes JupyterLab save).  Each test opens its notebook in a workspace of its own,
reset on load, and finds the notebook's widget by its path (a shared workspace restored the
previous test's tab, whose kernel was gone, and the run waited on it for ever).  A cell that
raises fails the test at once, naming the cell; a wait that times out saves
``build/screenshots/timeout-<lesson>.png`` and says which cell was running.
Screenshots are kept in build/screenshots/ (the test's artifacts; ``notebooks/screenshots/``
holds committed copies).  Playwright never downloads a browser here: it launches /usr/bin/chromium.
"""
from __future__ import annotations

import json
import os
import shutil
import sys
import time
import urllib.request
from pathlib import Path

import nbformat
import numpy as np
import pytest

from .labdriver import (CHROMIUM, FIND_NOTEBOOK, IN_KERNEL, ROOT, SHOTS, kernel_says, launch_browser,  # noqa: F401
                        open_and_run, serve_lab, shut_down_session, wait_until)

LESSON_01 = "01-prerequisites.ipynb"
LESSON_03 = "03-bowyer-watson-step-by-step.ipynb"
SAVED = "saved-01-prerequisites.ipynb"
DRAG = "drag-100-points.ipynb"
DRAG_CELLS = ["import json\nfrom reference_impl.kit import PointPicker\n"
              "picker = PointPicker(n=100)\npicker.load_preset('random')\npicker"]
PROBES = {DRAG: DRAG_CELLS,
          "hangs.ipynb": ["x = 1", "import time; time.sleep(120)", "y = 2"],
          "raises.ipynb": ["x = 1", "raise ValueError('boom at ' + str(x))", "y = 2"]}

pytestmark = [pytest.mark.skipif(not os.path.exists(CHROMIUM),
                                 reason="Debian chromium is not installed (apt-get install chromium)"),
              pytest.mark.xdist_group("jupyterlab")]  # one worker starts the lab server once
sync_api = pytest.importorskip("playwright.sync_api", reason="playwright is not installed (pip install '.[test]')")


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    """A JupyterLab server on a temporary copy of the lessons; yields its base URL."""
    root = tmp_path_factory.mktemp("lab")
    for name in (LESSON_01, LESSON_03):
        shutil.copy(ROOT / "notebooks" / name, root / name)
    shutil.copy(ROOT / "notebooks" / LESSON_01, root / SAVED)   # the copy that the save test saves
    for name, cells in PROBES.items():   # notebooks that hang or raise: the waits' own failures
        nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells], metadata={
            "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}})
        nbformat.write(nb, root / name)
    with serve_lab(root, dict(os.environ, COURSE_QUICK="1")) as url:
        yield url


def on_screen(picture, px: float, py: float) -> tuple[float, float]:
    """Image pixel (px, py) of a picker's SVG (its viewBox) -> page coordinates for ``page.mouse``."""
    box = picture.bounding_box()
    w, h = picture.evaluate("svg => [svg.viewBox.baseVal.width, svg.viewBox.baseVal.height]")
    return box["x"] + px * box["width"] / w, box["y"] + py * box["height"] / h


@pytest.fixture(scope="module")
def browser():
    with launch_browser() as b:
        yield b


@pytest.fixture
def page(lab, browser):
    """A fresh browser tab; its notebook's kernel is shut down afterwards."""
    SHOTS.mkdir(parents=True, exist_ok=True)
    tab = browser.new_page(viewport={"width": 1400, "height": 1000})
    yield tab
    try:
        shut_down_session(tab, lab)
    finally:
        tab.close()


def test_lesson_03_player_picker_and_quiz_work_in_chromium(lab, page):
    open_and_run(page, lab, LESSON_03)
    errors = page.locator(".jp-OutputArea-output[data-mime-type='application/vnd.jupyter.stderr']")
    assert page.locator(".jp-RenderedText[data-mime-type='application/vnd.jupyter.error']").count() == 0

    # -- the step player: press "next"
    player = page.locator(".kit-step-player").first
    player.scroll_into_view_if_needed()
    player.locator(".widget-html", has_text="step 1/11").wait_for(timeout=30_000)
    picture = player.locator("svg.kit-canvas").first
    picture.locator("path").first.wait_for(state="attached", timeout=30_000)
    before = picture.inner_html()
    player.get_by_role("button", name="next").click()
    player.locator(".widget-html", has_text="step 2/11").wait_for(timeout=30_000)
    page.wait_for_function("([svg, old]) => svg.innerHTML !== old", arg=[picture.element_handle(), before],
                           timeout=30_000)               # the browser redrew the step
    assert kernel_says(page, "print(player.index)", "1") == "1"
    for k in range(3, 9):           # on to step 8: the bad triangles of the last point
        player.get_by_role("button", name="next").click()
        player.locator(".widget-html", has_text=f"step {k}/11").wait_for(timeout=30_000)
    assert kernel_says(page, "print(player.index, player.current_line)", "7 bad") == "7 bad"
    player.screenshot(path=str(SHOTS / "lesson03-player.png"))

    # -- the point picker: click on empty space inside the hull
    assert kernel_says(page, "print(len(lab.picker.points), len(lab.picker.triangles))", "4 3") == "4 3"
    px, py = json.loads(page.evaluate(IN_KERNEL, "import json; print(json.dumps(lab.picker.canvas.to_pixel(3.5, 2.5)))"))
    picture = page.locator(".kit-pick-and-step svg.kit-canvas").first
    picture.evaluate("svg => svg.scrollIntoView({block: 'center', inline: 'center'})")
    page.wait_for_timeout(300)
    status = page.locator(".kit-pick-and-step .kit-status").first
    assert status.inner_text().startswith("4 points")
    # a real press and release at that spot (the browser's pointer events, which canvas.js reads)
    page.mouse.click(*on_screen(picture, px, py))
    try:
        page.locator(".kit-pick-and-step .kit-status", has_text="5 points").wait_for(timeout=30_000)
    except sync_api.TimeoutError:
        page.screenshot(path=str(SHOTS / "lesson03-click-failed.png"))
        diag = page.evaluate(IN_KERNEL, "print(len(lab.picker.points), lab.picker.errors.outputs, lab.errors.outputs)")
        pytest.fail(f"the click at pixel ({px:.0f}, {py:.0f}) added no point; kernel: {diag}")
    assert "5 Delaunay triangles" in status.inner_text()
    got = kernel_says(page, "print(len(lab.picker.points), len(lab.picker.triangles), len(lab.player.steps))", "5 5 15")
    assert got == "5 5 15", got
    x, y = json.loads(page.evaluate(IN_KERNEL, "print(json.dumps(lab.picker.points[-1].tolist()))"))
    assert abs(x - 3.5) < 0.05 and abs(y - 2.5) < 0.05
    page.locator(".kit-pick-and-step").first.screenshot(path=str(SHOTS / "lesson03-picker.png"))

    # -- predict, then reveal: tick the right triangles, commit, see the feedback
    quiz = page.locator(".kit-predict-reveal").first
    quiz.scroll_into_view_if_needed()
    answers = json.loads(page.evaluate(IN_KERNEL, (
        "import json; q = bad_triangles_quiz(TUTORIAL_POINTS, 2)\n"
        "print(json.dumps([label for label, v in q.choices if v in q.answers]))")))
    assert answers
    for label in answers:
        quiz.get_by_label(label, exact=True).check()
    quiz.get_by_role("button", name="commit and reveal").click()
    quiz.locator(".kit-feedback.right").wait_for(timeout=30_000)
    assert "Right." in quiz.locator(".kit-feedback").inner_text()
    quiz.screenshot(path=str(SHOTS / "lesson03-quiz.png"))
    page.screenshot(path=str(SHOTS / "lesson03.png"))
    assert errors.count() == 0 or "Traceback" not in " ".join(errors.all_inner_texts())


def test_lesson_01_runs_in_chromium_and_its_picker_draws(lab, page):
    open_and_run(page, lab, LESSON_01)
    pickers = page.locator(".kit-point-picker")
    assert pickers.count() >= 3
    first = pickers.first
    first.scroll_into_view_if_needed()
    first.locator("svg.kit-canvas circle").nth(3).wait_for(state="attached", timeout=30_000)   # drawn by the browser
    assert first.locator("svg.kit-canvas text").count() >= 1           # the title, drawn as text
    first.screenshot(path=str(SHOTS / "lesson01-picker.png"))
    page.screenshot(path=str(SHOTS / "lesson01.png"))


def test_a_run_that_hangs_or_raises_says_which_cell(lab, page):
    """The waits explain their own failures: the hanging cell named, with a screenshot; a raising
    cell named with its error at once, not after the time-out."""
    shot = SHOTS / "timeout-hangs.png"
    shot.unlink(missing_ok=True)
    with pytest.raises(pytest.fail.Exception) as hung:
        open_and_run(page, lab, "hangs.ipynb", timeout_s=4)
    message = str(hung.value)
    assert "hangs.ipynb: Run All did not finish in 4 s" in message, message
    assert "running: cell 1 ('import time; time.sleep(120)')" in message, message
    assert "1/3 code cells run" in message, message
    assert shot.exists() and shot.stat().st_size > 0
    shut_down_session(page, lab)

    with pytest.raises(pytest.fail.Exception) as raised:
        open_and_run(page, lab, "raises.ipynb", timeout_s=120)
    message = str(raised.value)
    assert "raises.ipynb: a cell raised" in message, message
    assert "ValueError: boom at 1" in message and "cell 1 (" in message, message


PICTURES = """() => { const nb = window.__courseNb.content.node;
    return {images: nb.querySelectorAll('.jp-OutputArea-output img, .jp-OutputArea-output svg.kit-canvas').length,
            missing: (nb.innerText.match(/model not found/g) || []).length}; }"""


def test_a_saved_lesson_reopened_without_running_shows_its_pictures(lab, page, browser):
    overrides = Path(sys.prefix) / "share" / "jupyter" / "lab" / "settings" / "overrides.json"
    assert json.loads(overrides.read_text())["@jupyter-widgets/jupyterlab-manager:plugin"]["saveState"], \
        "make setup writes the venv's JupyterLab overrides.json (saveState: true)"
    open_and_run(page, lab, SAVED)
    shown = page.evaluate(PICTURES)
    assert shown["images"] >= 3 and shown["missing"] == 0
    page.evaluate("() => window.jupyterapp.commands.execute('docmanager:save')")
    deadline = time.monotonic() + 30
    while True:
        with urllib.request.urlopen(f"{lab}/api/contents/{SAVED}?content=1", timeout=10) as r:
            saved = json.load(r)["content"]
        if "widgets" in saved["metadata"] or time.monotonic() > deadline:
            break
        time.sleep(0.5)
    assert "widgets" in saved["metadata"], "saving did not store the widget state"
    shut_down_session(page, lab)     # a live session would hand the reopened tab the kernel's widgets
    page.evaluate("() => { window.__courseNb = null; }")    # the fixture has nothing left to shut down

    again = browser.new_page(viewport={"width": 1400, "height": 1000})
    try:
        again.goto(f"{lab}/lab/workspaces/reopen-{os.getpid()}-{time.monotonic_ns()}/tree/{SAVED}?reset")
        wait_until(again, SAVED, FIND_NOTEBOOK, "the reopened notebook's tab", 120, SAVED)
        deadline = time.monotonic() + 60
        while True:
            now = again.evaluate(PICTURES)
            if now["images"] >= shown["images"] or time.monotonic() > deadline:
                break
            time.sleep(0.5)
        again.screenshot(path=str(SHOTS / "lesson01-reopened.png"))
        assert now == {"images": shown["images"], "missing": 0}, \
            f"reopened without running: {now}, after Run All: {shown}"
    finally:
        try:
            shut_down_session(again, lab)
        finally:
            again.close()


def test_a_drag_redraws_in_the_page_every_move_and_the_kernel_follows(lab, page):
    """A real mouse drag of one of 100 points: each move is drawn by the page at once, the kernel's
    answers arrive, and the kernel ends with the point where the mouse let go and the Delaunay
    triangles of the new points.  The page's own timings are written to build/ and printed."""
    from scipy.spatial import Delaunay as ScipyDelaunay

    open_and_run(page, lab, DRAG)
    picture = page.locator(".kit-point-picker svg.kit-canvas").first
    picture.locator("circle").nth(99).wait_for(state="attached", timeout=30_000)
    picture.evaluate("svg => svg.scrollIntoView({block: 'center', inline: 'center'})")
    # the point nearest the middle of the picture, and a spot 60 pixels to its right
    k, (px, py) = json.loads(page.evaluate(IN_KERNEL, (
        "import numpy as np\nP = np.asarray(picker.view.points).reshape(-1, 2)\n"
        "k = int(np.argmin(np.hypot(P[:, 0] - 220, P[:, 1] - 200)))\n"
        "print(json.dumps([k, P[k].tolist()]))")))
    x0, y0 = on_screen(picture, px, py)
    x1, y1 = on_screen(picture, px + 60, py + 15)
    steps = 40
    page.mouse.move(x0, y0)
    page.mouse.down()
    for s in range(1, steps + 1):
        page.mouse.move(x0 + (x1 - x0) * s / steps, y0 + (y1 - y0) * s / steps)
        page.wait_for_timeout(16)                      # about one frame between moves, as a hand drags
    page.mouse.up()
    page.wait_for_function("svg => svg.__kitStats && svg.__kitStats.answers.length > 0"
                           " && !svg.querySelector('circle[r=\"6\"]')", arg=picture.element_handle(),
                           timeout=30_000)            # the release answered: the drag ring is gone
    stats = picture.evaluate("svg => ({frames: svg.__kitStats.frames, answers: svg.__kitStats.answers})")
    draws = sorted(f["draw"] for f in stats["frames"])
    frames = sorted(f["toFrame"] for f in stats["frames"])
    answers = sorted(stats["answers"])
    median = lambda v: v[len(v) // 2]              # noqa: E731
    report = {"points": 100, "moves_drawn": len(draws), "answers": len(answers),
              "draw_ms_median": median(draws), "draw_ms_max": draws[-1],
              "event_to_frame_ms_median": median(frames), "event_to_frame_ms_max": frames[-1],
              "answer_ms_median": median(answers), "answer_ms_max": answers[-1]}
    out = ROOT / "build" / "canvas-picker-timings.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(report, indent=1))
    print("\ndrag of 1 of 100 points in chromium:", json.dumps({k: round(v, 2) for k, v in report.items()}))
    assert len(draws) >= steps // 2, f"the page drew only {len(draws)} of {steps} moves"
    assert len(answers) >= 2, "the kernel answered fewer than two moves during the drag"
    assert median(draws) < 20, report                  # one frame: generous (measured values in the report)
    assert median(answers) < 1000, report              # the kernel's answers arrive (generous on a loaded host)
    # the kernel: the point is where the mouse let go, and the triangles are Delaunay's for the new points
    got = json.loads(page.evaluate(IN_KERNEL, (
        f"print(json.dumps([picker.view.points[2 * {k}:2 * {k} + 2], picker.points.tolist(),"
        " picker.triangles.tolist(), picker.view.ack]))")))
    (gx, gy), points, triangles, ack = got
    assert abs(gx - (px + 60)) < 1.5 and abs(gy - (py + 15)) < 1.5, (gx, gy, px + 60, py + 15)
    want = {tuple(sorted(t)) for t in ScipyDelaunay(np.asarray(points)).simplices.tolist()}
    assert {tuple(sorted(t)) for t in triangles} == want
    assert ack >= len(answers)
    shot = SHOTS / "canvas-drag.png"
    picture.screenshot(path=str(shot))
