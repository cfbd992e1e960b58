"""Every lesson in a real browser: Run All in JupyterLab in chromium, then one interaction per widget.

    .venv/bin/python -m pytest tests/browser/test_every_lesson.py -n 0 -q           # quick mode (CI)
    COURSE_BROWSER_FULL=1 .venv/bin/python -m pytest tests/browser/test_every_lesson.py -n 0 -q -s

One test per lesson (``notebooks/[0-9]*.ipynb``: a new lesson is covered without editing this file).
JupyterLab serves a temporary copy of ``notebooks/`` (a lesson that writes files writes them there).
Each lesson is opened in a workspace of its own and run with Run All; then

* no cell raised, no output holds a Python traceback, and the page shows no "Error displaying widget";
* every kit widget the page shows is used once, and the kernel must have seen it: a step player's
  "next" moves exactly one player of the kernel one step on (and its caption in the page), a question
  answered and committed reveals exactly one question in the kernel (and its feedback in the page), a
  measure panel's "measure" adds a timing in the kernel, a point picker's preset menu changes exactly
  one picker's points in the kernel (the picture may be drawn by the browser or the kernel; the menu is
  the same);
* no widget's error log (``KitWidget.errors``) holds anything afterwards.

The timed-practice panel is not pressed: its "start the clock" starts a real exam clock in the student's
judge store (tests/kit/test_timer.py drives it in the kernel).

Quick mode (``COURSE_QUICK=1``, CI) by default; ``COURSE_BROWSER_FULL=1`` runs the lessons at full size
and is how the full-mode times in tests/README.md were measured.  Each lesson's Run All wall time is
printed and written to ``build/browser-lesson-times-<mode>.json``.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import time

import pytest

from .labdriver import CHROMIUM, IN_KERNEL, ROOT, SHOTS, launch_browser, open_and_run, serve_lab, shut_down_session

FULL = os.environ.get("COURSE_BROWSER_FULL", "").strip() in ("1", "true", "yes")
MODE = "full" if FULL else "quick"
LESSONS = sorted(p.name for p in (ROOT / "notebooks").glob("[0-9]*.ipynb"))
TIMES = ROOT / "build" / f"browser-lesson-times-{MODE}.json"
RUN_LIMIT_S = 600.0 if FULL else 300.0   # a hang fails with a screenshot; speed is measured, not asserted

pytestmark = [pytest.mark.skipif(not os.path.exists(CHROMIUM),
                                 reason="Debian chromium is not installed (apt-get install chromium)"),
              pytest.mark.xdist_group("every-lesson")]   # one server for the module, beside test_jupyterlab's
sync_api = pytest.importorskip("playwright.sync_api", reason="playwright is not installed (pip install '.[test]')")

# Run in the lesson's own kernel: what every kit widget holds, keyed by its model id (one JSON line).
KIT_STATE = """
def _kit_state():
    import hashlib, json
    from ipywidgets.widgets.widget import _instances
    from reference_impl.kit import MeasurePanel, Player3D, PointPicker, StepPlayer
    from reference_impl.kit.quiz import _Quiz   # PredictReveal and PredictRevealMany
    from reference_impl.kit.widget import KitWidget
    state = {"player": {}, "quiz": {}, "measure": {}, "picker": {}, "errors": []}
    for mid, w in list(_instances.items()):
        if isinstance(w, (StepPlayer, Player3D)):
            state["player"][mid] = w.index
        elif isinstance(w, _Quiz):
            state["quiz"][mid] = bool(w.revealed)
        elif isinstance(w, MeasurePanel):
            state["measure"][mid] = repr(sorted((k, sorted(v.items())) for k, v in w.results.items()))
        elif isinstance(w, PointPicker):
            state["picker"][mid] = hashlib.sha1(w.points.tobytes()).hexdigest()
        if isinstance(w, KitWidget) and w.errors.outputs:
            state["errors"].append(type(w).__name__ + ": " + str(w.errors.outputs)[:400])
    return json.dumps(state)
print(_kit_state())
"""

ERRORS_SHOWN = """() => {
    const nb = window.__courseNb.content.node;
    const texts = [];
    nb.querySelectorAll('.jp-OutputArea-output').forEach(o => {
        const t = o.innerText || '';
        if (t.includes('Traceback (most recent call last)') || t.includes('Error displaying widget'))
            texts.push(t.slice(0, 300));
    });
    return texts;
}"""


def kit_state(page) -> dict:
    out = page.evaluate(IN_KERNEL, KIT_STATE)
    try:
        return json.loads(out.strip().splitlines()[-1])
    except (ValueError, IndexError):
        pytest.fail(f"the kernel could not list the kit's widgets: {out[:500]}", pytrace=False)


def changed(before: dict, after: dict) -> dict:
    return {k: (before.get(k), v) for k, v in after.items() if before.get(k) != v}


def wait_for_change(page, kind: str, before: dict, what: str, timeout: float = 20.0) -> dict:
    """Poll the kernel until exactly one widget of ``kind`` changed from ``before``; return that change."""
    deadline = time.monotonic() + timeout
    while True:
        now = kit_state(page)
        diff = changed(before[kind], now[kind])
        if diff or time.monotonic() > deadline:
            assert len(diff) == 1, f"{what}: the kernel saw {len(diff)} {kind} widgets change ({diff})"
            return now
        time.sleep(0.3)


def press(page, element, name: str) -> None:
    # the accessible name holds the icon's glyph too: match the words, not the whole name
    button = element.get_by_role("button", name=re.compile(rf"^\W*{re.escape(name)}\W*$")).first
    button.scroll_into_view_if_needed()
    button.click()


def use_players(page, lesson: str) -> int:
    players = page.locator(".kit-step-player")
    used = 0
    for k in range(players.count()):
        player = players.nth(k)
        before = kit_state(page)
        if not before["player"]:
            break
        press(page, player, "next")
        after = wait_for_change(page, "player", before, f"{lesson}: step player {k}'s next")
        (old, new), = changed(before["player"], after["player"]).values()
        assert new == old + 1, f"{lesson}: step player {k}: next moved the kernel's index {old} -> {new}"
        page.wait_for_function("([el, s]) => el.innerText.includes(s)",
                               arg=[player.element_handle(), f"step {new + 1}"], timeout=10000)
        used += 1
    return used


def use_quizzes(page, lesson: str) -> int:
    quizzes = page.locator(".kit-predict-reveal")
    used = 0
    for k in range(quizzes.count()):
        quiz = quizzes.nth(k)
        choice = quiz.locator("input[type=radio], input[type=checkbox]").first
        choice.scroll_into_view_if_needed()
        choice.check()
        before = kit_state(page)
        commit = quiz.get_by_role("button", name=re.compile(r"commit and reveal"))
        page.wait_for_function("el => !el.disabled", arg=commit.element_handle(), timeout=10000)
        commit.click()
        after = wait_for_change(page, "quiz", before, f"{lesson}: question {k} committed")
        assert list(changed(before["quiz"], after["quiz"]).values()) == [(False, True)]
        quiz.locator(".kit-feedback").wait_for(timeout=10000)
        used += 1
    return used


def use_measure_panels(page, lesson: str) -> int:
    panels = page.locator(".kit-measure-panel")
    for k in range(panels.count()):
        before = kit_state(page)
        press(page, panels.nth(k), "measure")
        wait_for_change(page, "measure", before, f"{lesson}: measure panel {k}'s measure", timeout=60)
    return panels.count()


def use_pickers(page, lesson: str) -> int:
    pickers = page.locator(".kit-point-picker")
    for k in range(pickers.count()):
        menu = pickers.nth(k).locator("select").first
        menu.scroll_into_view_if_needed()
        count, current = menu.evaluate("el => [el.options.length, el.selectedIndex]")
        # presets other than the one shown (option 0 is the "(choose ...)" placeholder); a preset may
        # hold the very points shown (the lesson's own set), so the next one is tried then
        tried = []
        for choice in (i for i in range(1, count) if i != current):
            before = kit_state(page)
            menu.select_option(index=choice)
            tried.append(menu.evaluate("(el, i) => el.options[i].text", choice))
            deadline = time.monotonic() + 5
            while not changed(before["picker"], kit_state(page)["picker"]) and time.monotonic() < deadline:
                time.sleep(0.3)
            diff = changed(before["picker"], kit_state(page)["picker"])
            if diff:
                assert len(diff) == 1, f"{lesson}: preset {tried[-1]!r} changed {len(diff)} pickers in the kernel"
                break
        else:
            pytest.fail(f"{lesson}: point picker {k}: no preset changed the kernel's points (tried {tried})")
    return pickers.count()


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    root = tmp_path_factory.mktemp("lessons")
    shutil.copytree(ROOT / "notebooks", root, dirs_exist_ok=True,
                    ignore=shutil.ignore_patterns(".ipynb_checkpoints", "screenshots"))
    env = dict(os.environ)
    env.pop("COURSE_QUICK", None)
    if not FULL:
        env["COURSE_QUICK"] = "1"
    with serve_lab(root, env) as url:
        yield url


@pytest.fixture(scope="module")
def browser():
    with launch_browser() as b:
        yield b


@pytest.fixture(scope="module")
def times():
    measured: dict[str, float] = {}
    yield measured
    if measured:
        TIMES.parent.mkdir(parents=True, exist_ok=True)
        TIMES.write_text(json.dumps(measured, indent=1) + "\n")
        print(f"\nRun All wall times ({MODE} mode), written to {TIMES}:")
        for name, seconds in measured.items():
            print(f"  {name:45s} {seconds:6.1f} s")


@pytest.mark.parametrize("lesson", LESSONS)
def test_lesson_runs_all_in_chromium_and_every_widget_answers(lab, browser, times, lesson):
    SHOTS.mkdir(parents=True, exist_ok=True)
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    try:
        start = time.monotonic()
        open_and_run(page, lab, lesson, timeout_s=RUN_LIMIT_S)
        times[lesson] = round(time.monotonic() - start, 1)
        shown = page.evaluate(ERRORS_SHOWN)
        assert not shown, f"{lesson}: error output after Run All: {shown}"
        state = kit_state(page)
        assert not state["errors"], f"{lesson}: a widget logged an error: {state['errors']}"
        used = (use_players(page, lesson) + use_quizzes(page, lesson) + use_measure_panels(page, lesson)
                + use_pickers(page, lesson))
        kinds = sum(len(state[k]) for k in ("player", "quiz", "measure", "picker"))
        assert used or not kinds, f"{lesson}: the kernel holds {kinds} kit widgets, none was found in the page"
        state = kit_state(page)
        assert not state["errors"], f"{lesson}: a widget logged an error when used: {state['errors']}"
        shown = page.evaluate(ERRORS_SHOWN)
        assert not shown, f"{lesson}: error output after using the widgets: {shown}"
    finally:
        try:
            shut_down_session(page, lab)
        finally:
            page.close()
