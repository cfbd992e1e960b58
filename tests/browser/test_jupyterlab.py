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

Lesson 01 is opened and run too.  Screenshots are kept in build/screenshots/
(the test's artifacts; ``notebooks/screenshots/`` holds committed copies).
Playwright never downloads a browser here: it launches /usr/bin/chromium.
"""
from __future__ import annotations

import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
SHOTS = ROOT / "build" / "screenshots"
LESSON_01 = "01-prerequisites.ipynb"
LESSON_03 = "03-bowyer-watson-step-by-step.ipynb"

pytestmark = [pytest.mark.skipif(not os.path.exists(CHROMIUM),
                                 reason="Debian chromium is not installed (apt-get install chromium)"),
              pytest.mark.xdist_group("jupyterlab")]  # one worker starts the lab server once
sync_api = pytest.importorskip("playwright.sync_api", reason="playwright is not installed (pip install '.[test]')")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    """A JupyterLab server on a temporary copy of the lessons; yields its base URL."""
    root = tmp_path_factory.mktemp("lab")
    for name in (LESSON_01, LESSON_03):
        shutil.copy(ROOT / "notebooks" / name, root / name)
    config = root / "config"
    (config / "labconfig").mkdir(parents=True)
    (config / "labconfig" / "page_config.json").write_text(json.dumps(
        {"disabledExtensions": {"@jupyterlab/apputils-extension:announcements": True}}))
    env = dict(os.environ, JUPYTER_CONFIG_DIR=str(config), JUPYTER_RUNTIME_DIR=str(root / "runtime"),
               COURSE_QUICK="1", MPLBACKEND="Agg")
    port = free_port()
    log = open(root / "server.log", "w")
    proc = subprocess.Popen(
        [sys.executable, "-m", "jupyter", "lab", "--no-browser", "--allow-root", f"--port={port}",
         "--ServerApp.port_retries=0", f"--ServerApp.root_dir={root}", "--IdentityProvider.token=",
         "--ServerApp.password=", "--ServerApp.disable_check_xsrf=True",
         "--LabApp.expose_app_in_browser=True", f"--LabApp.workspaces_dir={root / 'ws'}"],
        env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 90
    while True:
        try:
            with urllib.request.urlopen(url + "/api/status", timeout=2) as r:
                if r.status == 200:
                    break
        except OSError:
            pass
        if proc.poll() is not None or time.monotonic() > deadline:
            proc.kill()
            pytest.fail("JupyterLab did not start:\n" + (root / "server.log").read_text()[-3000:])
        time.sleep(0.3)
    yield url
    proc.send_signal(signal.SIGTERM)
    try:
        proc.wait(timeout=15)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait(timeout=10)
    log.close()


@pytest.fixture(scope="module")
def browser():
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, headless=True,
                              args=["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"])
        yield b
        b.close()


OPEN_AND_READY = """async () => {
    const app = window.jupyterapp;
    const w = app.shell.currentWidget;
    await w.context.ready;
    await w.sessionContext.ready;
    return w.sessionContext.session !== null;
}"""

ALL_RUN = """() => {
    const w = window.jupyterapp.shell.currentWidget;
    const kernel = w.sessionContext.session && w.sessionContext.session.kernel;
    if (!kernel || kernel.status !== 'idle') return false;
    const code = w.content.widgets.filter(c => c.model.type === 'code');
    return code.length > 0 && code.every(c => c.model.executionCount !== null);
}"""

IN_KERNEL = """async (code) => {
    const kernel = window.jupyterapp.shell.currentWidget.sessionContext.session.kernel;
    let text = '';
    const future = kernel.requestExecute({code, silent: false, store_history: false});
    future.onIOPub = msg => {
        if (msg.header.msg_type === 'stream') text += msg.content.text;
        if (msg.header.msg_type === 'error') text += 'ERROR ' + msg.content.ename + ': ' + msg.content.evalue;
    };
    await future.done;
    return text.trim();
}"""


def open_and_run(page, url: str, name: str) -> None:
    page.goto(f"{url}/lab/tree/{name}")
    page.wait_for_function("() => window.jupyterapp && window.jupyterapp.shell.currentWidget"
                           " && window.jupyterapp.shell.currentWidget.sessionContext", timeout=120_000)
    assert page.evaluate(OPEN_AND_READY)
    page.wait_for_function("() => { const s = window.jupyterapp.shell.currentWidget.sessionContext.session;"
                           " return s && s.kernel && s.kernel.status === 'idle'; }", timeout=120_000)
    page.evaluate("() => window.jupyterapp.commands.execute('notebook:run-all-cells')")
    page.wait_for_function(ALL_RUN, timeout=240_000, polling=500)


def kernel_says(page, code: str, expected: str, timeout: float = 20.0) -> str:
    """Poll the kernel until ``code`` prints ``expected`` (widget values reach it with a delay)."""
    deadline = time.monotonic() + timeout
    while True:
        out = page.evaluate(IN_KERNEL, code)
        if out == expected or time.monotonic() > deadline:
            return out
        time.sleep(0.3)


def shut_down_kernel(page, url: str) -> None:
    kid = page.evaluate("() => window.jupyterapp.shell.currentWidget.sessionContext.session.kernel.id")
    req = urllib.request.Request(f"{url}/api/kernels/{kid}", method="DELETE")
    urllib.request.urlopen(req, timeout=10).close()


@pytest.fixture
def page(lab, browser):
    """A fresh browser tab; its notebook's kernel is shut down afterwards."""
    SHOTS.mkdir(parents=True, exist_ok=True)
    tab = browser.new_page(viewport={"width": 1400, "height": 1000})
    yield tab
    try:
        shut_down_kernel(tab, lab)
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
