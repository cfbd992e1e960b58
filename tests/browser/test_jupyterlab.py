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
import pytest

from .labdriver import (CHROMIUM, FIND_NOTEBOOK, IN_KERNEL, ROOT, SHOTS, kernel_says, launch_browser,  # noqa: F401
                        open_and_run, serve_lab, shut_down_session, wait_until)

LESSON_01 = "01-prerequisites.ipynb"
LESSON_03 = "03-bowyer-watson-step-by-step.ipynb"
SAVED = "saved-01-prerequisites.ipynb"
PROBES = {"hangs.ipynb": ["x = 1", "import time; time.sleep(120)", "y = 2"],
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
    player.locator(".widget-html", has_text="step 1/10").wait_for(timeout=30_000)
    before = player.locator("img").first.get_attribute("src")
    player.get_by_role("button", name="next").click()
    player.locator(".widget-html", has_text="step 2/10").wait_for(timeout=30_000)
    assert player.locator("img").first.get_attribute("src") != before
    assert kernel_says(page, "print(player.index)", "1") == "1"
    for k in range(3, 9):           # on to step 8: the bad triangles of the last point
        player.get_by_role("button", name="next").click()
        player.locator(".widget-html", has_text=f"step {k}/10").wait_for(timeout=30_000)
    assert kernel_says(page, "print(player.index, player.current_line)", "7 bad") == "7 bad"
    player.screenshot(path=str(SHOTS / "lesson03-player.png"))

    # -- the point picker: click on empty space inside the hull
    assert kernel_says(page, "print(len(lab.picker.points), len(lab.picker.triangles))", "4 3") == "4 3"
    px, py = json.loads(page.evaluate(IN_KERNEL, "import json; print(json.dumps(lab.picker.canvas.to_pixel(3.5, 2.5)))"))
    image = page.locator(".kit-pick-and-step .kit-picker-image").first
    image.evaluate("img => img.scrollIntoView({block: 'center', inline: 'center'})")
    page.wait_for_timeout(300)
    status = page.locator(".kit-pick-and-step .kit-status").first
    assert status.inner_text().startswith("4 points")
    shown = image.bounding_box()
    natural = image.evaluate("img => [img.naturalWidth, img.naturalHeight]")
    # a real press and release at that spot (what ipyevents listens to)
    page.mouse.click(shown["x"] + px * shown["width"] / natural[0], shown["y"] + py * shown["height"] / natural[1])
    try:
        page.locator(".kit-pick-and-step .kit-status", has_text="5 points").wait_for(timeout=30_000)
    except sync_api.TimeoutError:
        page.screenshot(path=str(SHOTS / "lesson03-click-failed.png"))
        diag = page.evaluate(IN_KERNEL, "print(len(lab.picker.points), lab.picker.errors.outputs, lab.errors.outputs)")
        pytest.fail(f"the click at pixel ({px:.0f}, {py:.0f}) added no point; kernel: {diag}")
    assert "5 Delaunay triangles" in status.inner_text()
    got = kernel_says(page, "print(len(lab.picker.points), len(lab.picker.triangles), len(lab.player.steps))", "5 5 14")
    assert got == "5 5 14", got
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
    assert first.locator("img").first.get_attribute("src").startswith("blob:") or \
        first.locator("img").first.get_attribute("src").startswith("data:")
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
    return {images: nb.querySelectorAll('.jp-OutputArea-output img').length,
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
