"""Every kit widget used with the keyboard only, in JupyterLab in headless chromium.

    .venv/bin/python -m pytest tests/browser/test_keyboard.py -q -s    # needs /usr/bin/chromium

One small notebook is built here (a point picker, a step player, both predict-then-reveal
questions, a measurement panel and a timed-practice panel), opened once in its own JupyterLab
and run; each test then drives one widget by keys (``page.keyboard``; the mouse is never used)
and checks clock-free facts: where the focus is, what the kernel's model holds afterwards,
that the answer reached the page.  The times from a key to the page's redraw and to the kernel's
answer are printed (``-s``), not asserted.  The mouse half is tests/browser/test_jupyterlab.py.
"""
from __future__ import annotations

import json
import os
import time

import nbformat
import pytest

from .labdriver import CHROMIUM, IN_KERNEL, SHOTS, kernel_says, launch_browser, open_and_run, serve_lab, \
    shut_down_session

NOTEBOOK = "keyboard-widgets.ipynb"
CELLS = [
    "import json, pathlib, tempfile\n"
    "from reference_impl.kit import MeasurePanel, PointPicker, PredictReveal, PredictRevealMany, StepPlayer\n"
    "from reference_impl.kit.timer import TimedPractice",
    "picker = PointPicker([(0.2, 0.2), (0.8, 0.2), (0.5, 0.8), (0.5, 0.45)])\npicker",
    "player = StepPlayer.bowyer_watson([(1, 1), (3, 2), (5, 1), (4, 4)])\nplayer",
    "quiz = PredictReveal('Is 2 prime?', ['yes', 'no'], 'yes', explain='Its divisors are 1 and 2.')\nquiz",
    "many = PredictRevealMany('Which are even?', [1, 2, 3, 4], [2, 4])\nmany",
    "panel = MeasurePanel(lambda n: {'sum': n / 1e6}, [10, 100, 1000])\npanel",
    "practice = TimedPractice('bowyer-watson-timed', 'kbd', 'mine.py',\n"
    "                         pathlib.Path(tempfile.mkdtemp()) / 'timed.sqlite')\npractice",
]

pytestmark = [pytest.mark.skipif(not os.path.exists(CHROMIUM),
                                 reason="Debian chromium is not installed (apt-get install chromium)"),
              pytest.mark.xdist_group("jupyterlab-keyboard")]
sync_api = pytest.importorskip("playwright.sync_api", reason="playwright is not installed (pip install '.[test]')")

# what has the focus: tag, then its accessible name as the page gives it
ACTIVE = """() => { const a = document.activeElement;
    return [a.tagName.toLowerCase(), a.getAttribute('aria-label') || a.getAttribute('placeholder')
            || (a.textContent || '').trim() || a.type || '']; }"""
# the time from now (just before a key) to the first change under ``el`` (what the kernel's answer redraws)
MARK = """(el) => { const k = window.__kbd = {t0: performance.now(), t1: null};
    const obs = new MutationObserver(() => { if (k.t1 === null) { k.t1 = performance.now(); obs.disconnect(); } });
    obs.observe(el, {subtree: true, childList: true, characterData: true, attributes: true}); }"""
ELAPSED = "() => window.__kbd.t1 === null ? null : window.__kbd.t1 - window.__kbd.t0"


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    """The keyboard notebook, run in its own JupyterLab; one tab shared by the tests (in order)."""
    root = tmp_path_factory.mktemp("kbd-lab")
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in CELLS], metadata={
        "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}})
    nbformat.write(nb, root / NOTEBOOK)
    SHOTS.mkdir(parents=True, exist_ok=True)
    with serve_lab(root, dict(os.environ, COURSE_QUICK="1")) as url, launch_browser() as browser:
        tab = browser.new_page(viewport={"width": 1400, "height": 1000})
        try:
            open_and_run(tab, url, NOTEBOOK)
            yield tab
        finally:
            try:
                shut_down_session(tab, url)
            finally:
                tab.close()


def kernel(page, code: str) -> object:
    """``code``'s last line printed as JSON in the kernel, read back."""
    return json.loads(page.evaluate(IN_KERNEL, code))


def wait_kernel(page, code: str, want: object, timeout: float = 30.0) -> object:
    """Poll until the kernel's JSON answer to ``code`` equals ``want``; returns the last answer."""
    deadline = time.monotonic() + timeout
    while True:
        got = kernel(page, code)
        if got == want or time.monotonic() > deadline:
            return got
        time.sleep(0.2)


def timed_key(page, key: str, watched) -> float:
    """Press ``key``; wait until ``watched`` changes; the milliseconds in between (the page's clock)."""
    page.evaluate(MARK, watched.element_handle())
    page.keyboard.press(key)
    page.wait_for_function("() => window.__kbd.t1 !== null", timeout=30_000)
    return page.evaluate(ELAPSED)


def test_picker_tab_order_focus_ring_and_aria(page):
    picker = page.locator(".kit-point-picker").first
    picker.scroll_into_view_if_needed()
    picker.locator("select").focus()
    seen = []
    for _ in range(5):
        page.keyboard.press("Tab")
        seen.append(page.evaluate(ACTIVE))
        if seen[-1][0] == "svg":
            ring = picker.locator("svg.kit-canvas").evaluate(
                "svg => [getComputedStyle(svg).outlineStyle, getComputedStyle(svg).outlineWidth]")
    assert [s[0] for s in seen] == ["button", "button", "svg", "textarea", "button"], seen
    assert seen[0][1] == "undo" and seen[1][1] == "clear" and seen[4][1] == "set points", seen
    assert "Enter adds a point" in seen[2][1] and "x, y" in seen[3][1], seen
    assert ring[0] == "solid" and ring[1] != "0px", f"no focus ring on the picture: {ring}"
    svg = picker.locator("svg.kit-canvas")
    assert svg.get_attribute("role") == "application"
    live = picker.locator(".kit-live[aria-live='polite'][role='status']")
    assert live.count() == 1 and live.inner_text().startswith("4 points")


def test_picker_enter_adds_arrows_move_delete_removes(page):
    picker = page.locator(".kit-point-picker").first
    svg = picker.locator("svg.kit-canvas")
    status = picker.locator(".widget-html", has=page.locator(".kit-status"))   # its inner span is replaced
    svg.focus()
    before = kernel(page, "print(json.dumps(picker.view.points))")
    # Enter: a point at the + cursor, which starts in the middle of the axes
    add_ms = timed_key(page, "Enter", status)
    got = wait_kernel(page, "print(json.dumps(len(picker.points)))", 5)
    assert got == 5, f"Enter added no point: the kernel has {got}"
    clip = kernel(page, "sc = picker.view.scene\nprint(json.dumps(sc.get('clip') or [0, 0, sc['w'], sc['h']]))")
    new = kernel(page, "print(json.dumps(picker.view.points[8:10]))")
    assert abs(new[0] - (clip[0] + clip[2] / 2)) < 0.01 and abs(new[1] - (clip[1] + clip[3] / 2)) < 0.01, (new, clip)
    assert picker.locator(".kit-live").inner_text().startswith("5 points")
    # ] selects point 0; Shift+right moves it 20 px, down 4 px: each key is a drag, ended by its release
    page.keyboard.press("]")
    assert svg.locator("circle.kit-selected").count() == 1
    page.keyboard.press("Shift+ArrowRight")
    page.keyboard.press("ArrowDown")
    want = [round(before[0] + 20, 1), round(before[1] + 4, 1)]
    got = wait_kernel(page, "print(json.dumps([round(v, 1) for v in picker.view.points[0:2]]))", want)
    assert got == want, f"the arrows moved point 0 to {got}, not {want}"
    assert kernel(page, "print(json.dumps(len(picker._history)))") == 3      # add + two key drags
    # [ goes back round to the last point (the one Enter added); Delete removes it
    page.keyboard.press("[")
    remove_ms = timed_key(page, "Delete", status)
    got = wait_kernel(page, "print(json.dumps(len(picker.points)))", 4)
    assert got == 4
    left = kernel(page, "print(json.dumps([round(v, 1) for v in picker.view.points]))")
    assert left == want + [round(v, 1) for v in before[2:]], (left, before)
    stats = svg.evaluate("svg => ({frames: svg.__kitStats.frames.filter(f => f.key), answers: svg.__kitStats.answers})")
    draws = sorted(f["draw"] for f in stats["frames"])
    answers = sorted(stats["answers"])
    assert len(draws) == 2 and len(answers) >= 2, stats        # both key moves drawn, their moves answered
    print(f"\nkeyboard picker: key move drawn in {draws[-1]:.1f} ms (at most), key moves answered in "
          f"{answers[len(answers) // 2]:.0f} ms (median of {len(answers)}); Enter -> kernel's status "
          f"{add_ms:.0f} ms, Delete -> status {remove_ms:.0f} ms")
    picker.screenshot(path=str(SHOTS / "keyboard-picker.png"))


def test_picker_points_typed_as_text(page):
    picker = page.locator(".kit-point-picker").first
    picker.locator("svg.kit-canvas").focus()
    page.keyboard.press("Tab")
    assert page.evaluate(ACTIVE)[0] == "textarea"
    page.keyboard.press("Control+A")
    page.keyboard.type("0.1, 0.1\n0.9, 0.1\n0.5, 0.9")
    page.keyboard.press("Tab")
    assert page.evaluate(ACTIVE) == ["button", "set points"]
    t_ms = timed_key(page, "Enter", picker.locator(".widget-html", has=page.locator(".kit-status")))
    want = [[0.1, 0.1], [0.9, 0.1], [0.5, 0.9]]
    got = wait_kernel(page, "print(json.dumps(picker.points.tolist()))", want)
    assert got == want and kernel(page, "print(json.dumps(len(picker.triangles)))") == 1
    # a bad line: named in the message, the points unchanged
    picker.locator("textarea").focus()
    assert page.evaluate(ACTIVE)[0] == "textarea"
    page.keyboard.press("Control+A")
    page.keyboard.type("0, 0\n1; 2\n3, 4")
    page.keyboard.press("Tab")
    assert page.evaluate(ACTIVE) == ["button", "set points"]
    # the box's text reaches the kernel when it loses the focus. On a loaded CI machine the error
    # once never came (the kernel kept the old points): waiting until the kernel holds the new
    # text first tells a lost text apart from a lost click
    bad = "0, 0\n1; 2\n3, 4"
    assert wait_kernel(page, "print(json.dumps(picker.text.value))", bad) == bad
    page.keyboard.press("Enter")
    message = picker.locator(".kit-text-error[role='alert']")
    message.wait_for(timeout=30_000)
    assert message.inner_text().startswith("line 2: '1; 2' is not a point"), message.inner_text()
    assert kernel(page, "print(json.dumps(picker.points.tolist()))") == want
    print(f"\nkeyboard picker: 'set points' -> kernel's status {t_ms:.0f} ms")


def test_player_by_keys(page):
    player = page.locator(".kit-step-player").first
    player.scroll_into_view_if_needed()
    caption = player.locator(".widget-html", has_text="step 1/11")
    caption.wait_for(timeout=30_000)
    player.get_by_role("button", name="next").focus()
    page.keyboard.press("Enter")
    assert wait_kernel(page, "print(json.dumps(player.index))", 1) == 1
    for _ in range(8):                         # Tab on to the picture
        page.keyboard.press("Tab")
        if page.evaluate(ACTIVE)[0] == "svg":
            break
    name = page.evaluate(ACTIVE)
    assert name[0] == "svg" and "arrow keys step" in name[1], name
    svg = player.locator("svg.kit-canvas")
    step_ms = timed_key(page, "ArrowRight", svg)
    assert wait_kernel(page, "print(json.dumps(player.index))", 2) == 2
    page.keyboard.press("End")
    assert wait_kernel(page, "print(json.dumps(player.index))", 10) == 10
    player.locator(".widget-html", has_text="step 11/11").wait_for(timeout=30_000)
    assert player.locator(".kit-live").inner_text().startswith("step 11/11: done")
    page.keyboard.press("Home")
    assert wait_kernel(page, "print(json.dumps(player.index))", 0) == 0
    # Space plays (the page's Play widget moves the slider, the kernel follows), Space again pauses
    page.keyboard.press("Space")
    assert wait_kernel(page, "print(json.dumps(player.play.playing and player.index >= 2))", True) is True
    page.keyboard.press("Space")
    assert wait_kernel(page, "print(json.dumps(player.play.playing))", False) is False
    print(f"\nkeyboard player: right arrow -> the next step drawn {step_ms:.0f} ms")


def test_quizzes_by_keys(page):
    quiz = page.locator(".kit-predict-reveal").nth(0)
    quiz.scroll_into_view_if_needed()
    quiz.get_by_role("radio").first.focus()
    page.keyboard.press("Space")
    button = quiz.get_by_role("button", name="commit and reveal")
    page.wait_for_function("b => !b.disabled", arg=button.element_handle(), timeout=30_000)
    for _ in range(3):                          # past the other radio buttons (each is a tab stop)
        page.keyboard.press("Tab")
        if page.evaluate(ACTIVE)[0] == "button":
            break
    assert page.evaluate(ACTIVE) == ["button", "commit and reveal"]
    page.keyboard.press("Enter")
    quiz.locator(".kit-feedback.right").wait_for(timeout=30_000)
    assert kernel(page, "print(json.dumps([quiz.revealed, quiz.correct]))") == [True, True]

    many = page.locator(".kit-predict-reveal").nth(1)
    boxes = many.get_by_role("checkbox")
    boxes.nth(1).focus()
    page.keyboard.press("Space")                # 2
    page.keyboard.press("Tab")
    page.keyboard.press("Tab")
    page.keyboard.press("Space")                # 4
    button = many.get_by_role("button", name="commit and reveal")
    page.wait_for_function("b => !b.disabled", arg=button.element_handle(), timeout=30_000)
    button.focus()
    page.keyboard.press("Enter")
    many.locator(".kit-feedback.right").wait_for(timeout=30_000)
    assert kernel(page, "print(json.dumps([many.revealed, many.correct]))") == [True, True]


def test_measure_panel_and_timed_practice_by_keys(page):
    panel = page.locator(".kit-measure-panel").first
    panel.scroll_into_view_if_needed()
    panel.locator("button", has_text="measure").first.focus()      # "measure", then "measure all"
    assert page.evaluate(ACTIVE) == ["button", "measure"]
    page.keyboard.press("Enter")
    got = wait_kernel(page, "print(json.dumps(panel.results))", {"sum": {"10": 1e-05}})
    assert got == {"sum": {"10": 1e-05}}, got
    plot = panel.locator("svg.kit-panel-picture[role='img']")          # drawn by the page from the numbers
    plot.locator("path.kit-series").wait_for(state="attached", timeout=30_000)
    assert plot.get_attribute("aria-label") == "log-log plot of the timings: sum: 1 sizes"
    practice = page.locator(".kit-timed-practice").first
    practice.scroll_into_view_if_needed()
    practice.get_by_role("button", name="start the clock").focus()
    page.keyboard.press("Enter")
    got = wait_kernel(page, "print(json.dumps(practice.remaining() is not None))", True, timeout=90)
    assert got is True
    assert kernel_says(page, "print(practice.submit_button.disabled)", "False", timeout=30) == "False"
    clock = practice.locator("svg.kit-panel-picture[role='timer']")      # the page counts down by itself
    page.wait_for_function("c => / left$/.test(c.getAttribute('aria-label'))", arg=clock.element_handle(),
                           timeout=30_000)
    draws = int(clock.get_attribute("data-draws"))
    page.wait_for_function("([c, d]) => +c.dataset.draws >= d + 2", arg=[clock.element_handle(), draws],
                           timeout=10_000)                              # two ticks, no kernel message
    assert kernel(page, "print(json.dumps(practice.image.deadline > 0))") is True
