"""The 3D players in JupyterLab in headless chromium: turned by a drag and by keys, stepped, played.

    .venv/bin/python -m pytest tests/browser/test_player3d.py -q -s    # needs /usr/bin/chromium

Lesson 07 is run in full mode (its 3D player: 60 points, 24 steps), and lesson 13's 3D cavity
player is built from the lesson's own cells (its set-up cell and the cavity cell, full size) in a
small notebook beside it.  Each player is then used as a student would: a mouse drag turns it
(every move drawn by the page, the final view reaches the kernel), the arrow keys turn it and
Page Down / Home / End step it once it has the focus, "next" asks the kernel for a step, and Space
plays it to the end.  The page counts its drawings (``__kit3dStats``): the test asserts clock-free
facts (every step drawn in play, in order, none skipped, the picture on the slider's step at the
end; the kernel's view equals the page's) and prints the times (``-s``): a step's redraw, a turn's
redraw, and the kernel's answer to "next".
"""
from __future__ import annotations

import json
import math
import os
import time
from pathlib import Path

import nbformat
import pytest

from .labdriver import CHROMIUM, IN_KERNEL, ROOT, SHOTS, launch_browser, open_and_run, serve_lab, shut_down_session

LESSON_07 = "07-optimisations-and-variants.ipynb"
LESSON_13 = "13-the-theory-checked.ipynb"
CAVITY = "cavity-player-13.ipynb"

pytestmark = [pytest.mark.skipif(not os.path.exists(CHROMIUM),
                                 reason="Debian chromium is not installed (apt-get install chromium)"),
              pytest.mark.xdist_group("jupyterlab-3d")]
sync_api = pytest.importorskip("playwright.sync_api", reason="playwright is not installed (pip install '.[test]')")

STATS = "c => { const s = c.__kit3dStats; return {draws: s.draws, steps: s.steps.slice(), drawMs: s.drawMs.slice()," \
        " stepMs: s.stepMs.slice(), turnMs: s.turnMs.slice()}; }"
# click a button in the page, then the milliseconds until the picture shows step ``want``
NEXT_ANSWER = """([button, canvas, want]) => new Promise(resolve => {
    const t0 = performance.now();
    const obs = new MutationObserver(() => {
        if (canvas.dataset.step === String(want)) { obs.disconnect(); resolve(performance.now() - t0); }
    });
    obs.observe(canvas, {attributes: true, attributeFilter: ['data-step']});
    button.click();
    setTimeout(() => { obs.disconnect(); resolve(null); }, 30000);
})"""
ACTIVE = "() => [document.activeElement.tagName.toLowerCase(), document.activeElement.getAttribute('aria-label') || '']"


def median(values):
    v = sorted(values)
    return v[len(v) // 2] if v else float("nan")


def cells_of(lesson: Path, ids: list[str]) -> list[str]:
    nb = json.loads(lesson.read_text())
    by_id = {c.get("id"): "".join(c["source"]) for c in nb["cells"]}
    return [by_id[i] for i in ids]


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    """JupyterLab in full mode (no COURSE_QUICK) on a copy of lesson 07 and the lesson 13 cavity notebook."""
    root = tmp_path_factory.mktemp("lab3d")
    notebooks = ROOT / "notebooks"
    (root / LESSON_07).write_text((notebooks / LESSON_07).read_text())
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in
                                         cells_of(notebooks / LESSON_13, ["13-01", "13-26"])],
                                  metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                           "language": "python"}})
    nbformat.write(nb, root / CAVITY)
    SHOTS.mkdir(parents=True, exist_ok=True)
    env = {k: v for k, v in os.environ.items() if k != "COURSE_QUICK"}
    with serve_lab(root, env) as url, launch_browser() as browser:
        yield url, browser


def kernel(page, code: str):
    return json.loads(page.evaluate(IN_KERNEL, "import json\n" + code))


def wait_kernel(page, code: str, want, timeout: float = 30.0):
    deadline = time.monotonic() + timeout
    while True:
        got = kernel(page, code)
        if got == want or time.monotonic() > deadline:
            return got
        time.sleep(0.2)


def use_player(page, var: str, label: str) -> dict:
    """Drag, keys, steps, "next" and play on the 3D player ``var``; returns the measured numbers."""
    player = page.locator(".kit-player-3d").first
    canvas = player.locator("canvas.kit-canvas3d")
    canvas.wait_for(timeout=60_000)
    for _ in range(20):        # JupyterLab may still scroll after Run All: until the picture stays in view
        canvas.evaluate("c => c.scrollIntoView({block: 'center', inline: 'center'})")
        page.wait_for_timeout(250)
        box = canvas.bounding_box()
        if box and 0 <= box["y"] and box["y"] + box["height"] <= 1000:
            break
    n = kernel(page, f"print(json.dumps(len({var}.steps)))")
    geometry = kernel(page, f"g = {var}.view.geometry\nprint(json.dumps([len(g['xyz']) // 3, len(g['edges']) // 2,"
                            " len(g['faces']) // 3]))")
    start_pitch = kernel(page, f"print(json.dumps({var}.view.pitch))")

    # a mouse drag: 20 moves, each drawn by the page; the kernel hears the final view only
    before = canvas.evaluate(STATS)
    box = canvas.bounding_box()
    cx, cy = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    under = page.evaluate("([x, y]) => { const e = document.elementFromPoint(x, y); return e ? e.tagName + '.' + e.className : null; }",
                          [cx, cy])
    if not (under or "").startswith("CANVAS"):
        page.screenshot(path=str(SHOTS / f"player3d-{label}-covered.png"))
    assert (under or "").startswith("CANVAS"), f"{label}: the middle of the picture is under {under} ({box})"
    page.mouse.move(cx, cy)
    page.mouse.down()
    for s in range(1, 21):
        page.mouse.move(cx + 6 * s, cy + 2 * s)
        page.wait_for_timeout(16)
    page.mouse.up()
    after = canvas.evaluate(STATS)
    assert after["draws"] - before["draws"] >= 20, f"{label}: 20 drag moves, {after['draws'] - before['draws']} drawings"
    want = [round(120 * 0.01, 3), round(start_pitch + 40 * 0.01, 3)]
    got = wait_kernel(page, f"print(json.dumps([round({var}.view.yaw, 3), round({var}.view.pitch, 3)]))", want)
    assert got == want, f"{label}: the kernel's view after the drag is {got}, not {want}"
    drag_turns = after["turnMs"][len(before["turnMs"]):]

    # the keyboard: focus (Tab order is the browser's: the canvas is a tab stop), turn, reset, step
    canvas.focus()
    active = page.evaluate(ACTIVE)
    assert active[0] == "canvas" and "arrow keys to turn" in active[1], active
    before = canvas.evaluate(STATS)
    for key in ("ArrowRight", "ArrowRight", "ArrowRight", "ArrowDown"):
        page.keyboard.press(key)
    want = [round(1.2 + 3 * math.pi / 36, 3), round(start_pitch + 0.4 + math.pi / 36, 3)]
    got = wait_kernel(page, f"print(json.dumps([round({var}.view.yaw, 3), round({var}.view.pitch, 3)]))", want)
    assert got == want, f"{label}: the kernel's view after the arrow keys is {got}, not {want}"
    after = canvas.evaluate(STATS)
    assert after["draws"] - before["draws"] >= 4
    key_turns = after["turnMs"][len(before["turnMs"]):]
    page.keyboard.press("0")
    assert wait_kernel(page, f"print(json.dumps([{var}.view.yaw, {var}.view.pitch]))", [0, start_pitch]) \
        == [0, start_pitch]
    page.keyboard.press("End")
    assert wait_kernel(page, f"print(json.dumps({var}.index))", n - 1) == n - 1
    page.keyboard.press("Home")
    page.keyboard.press("PageDown")
    assert wait_kernel(page, f"print(json.dumps({var}.index))", 1) == 1
    assert player.locator(".kit-3d-caption").inner_text().startswith(f"step 2/{n}")
    page.keyboard.press("PageUp")
    assert wait_kernel(page, f"print(json.dumps({var}.index))", 0) == 0

    # "next" (a button: the kernel moves the slider): the kernel's answer, five times
    button = player.get_by_role("button", name="next").element_handle()
    answers = []
    for k in range(2, 7):
        ms = page.evaluate(NEXT_ANSWER, [button, canvas.element_handle(), k])
        assert ms is not None, f"{label}: 'next' to step {k} never reached the picture"
        answers.append(ms)
    assert wait_kernel(page, f"print(json.dumps({var}.index))", 5) == 5

    # play from the first step to the last: every step drawn, in order, and the picture ends on the slider's step
    canvas.focus()
    page.keyboard.press("Home")
    assert wait_kernel(page, f"print(json.dumps({var}.index))", 0) == 0
    before = canvas.evaluate(STATS)
    page.keyboard.press("Space")
    interval = kernel(page, f"print(json.dumps({var}.play.interval))")
    canvas.evaluate(f"c => c.__want = '{n}'")
    page.wait_for_function("c => c.dataset.step === c.__want", arg=canvas.element_handle(),
                           timeout=n * interval + 60_000)
    assert wait_kernel(page, f"print(json.dumps([{var}.play.playing, {var}.index]))", [False, n - 1]) == [False, n - 1]
    after = canvas.evaluate(STATS)
    played = after["steps"][len(before["steps"]):]
    shown = [s for k, s in enumerate(played) if k == 0 or s != played[k - 1]]
    assert shown[-1] == n and shown == sorted(shown) and set(range(2, n + 1)) <= set(shown), \
        f"{label}: play drew the steps {shown} of 1..{n}"
    readout = player.locator(".widget-readout").first.inner_text()
    assert readout == str(n), f"{label}: the slider says {readout}, the picture {n}"
    step_ms = after["stepMs"][len(before["stepMs"]):]
    draw_ms = after["drawMs"][len(before["drawMs"]):]
    player.screenshot(path=str(SHOTS / f"player3d-{label}.png"))
    report = {"player": label, "points_edges_faces": geometry, "steps": n,
              "play_steps_shown": f"{len(set(shown) | {1})}/{n}",   # step 1 was drawn by Home "play_interval_ms": interval,
              "step_redraw_ms_median": median(step_ms), "step_redraw_ms_max": max(step_ms),
              "draw_ms_median": median(draw_ms),
              "drag_turn_ms_median": median(drag_turns), "key_turn_ms_median": median(key_turns),
              "next_answer_ms_median": median(answers), "next_answer_ms_max": max(answers)}
    out = ROOT / "build" / f"player3d-{label}.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(report, indent=1))
    print(f"\n3D player {label} in chromium:",
          json.dumps({k: round(v, 2) if isinstance(v, float) else v for k, v in report.items()}))
    return report


@pytest.mark.parametrize("notebook, var, label", [(LESSON_07, "spin", "lesson07"), (CAVITY, "turning", "lesson13")])
def test_3d_player_turns_steps_and_plays_every_step(lab, notebook, var, label):
    url, browser = lab
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    try:
        open_and_run(page, url, notebook, timeout_s=600)
        use_player(page, var, label)
    finally:
        try:
            shut_down_session(page, url)
        finally:
            page.close()
