"""Driving JupyterLab in headless chromium for the browser tests: a server, a browser, waits that say why.

Used by every test module in tests/browser (run them with ``.venv/bin/python -m pytest tests/browser``)::

    with serve_lab(root, env) as url:            # JupyterLab on a free port, serving ``root``
        with launch_browser() as browser:
            page = browser.new_page()
            open_and_run(page, url, "01-prerequisites.ipynb")
            kernel_says(page, "print(1 + 1)", "2")

``serve_lab`` starts JupyterLab with no token on a free port, a temporary config and runtime directory and the news
toast disabled, waits for ``/api/status`` (bounded) and stops it by SIGTERM (killpg as a fallback).  Playwright never
downloads a browser here: ``launch_browser`` starts Debian's /usr/bin/chromium.  ``open_and_run`` opens a notebook in a
workspace of its own and runs every cell; a cell that raises fails at once, naming the cell; a time-out saves
``build/screenshots/timeout-<notebook>.png`` and names the running cell.
"""
from __future__ import annotations

import contextlib
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
from typing import Iterator, Sequence

import pytest

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
SHOTS = ROOT / "build" / "screenshots"

try:
    from playwright import sync_api
except ImportError:  # the test modules skip with a reason (pytest.importorskip) before using it
    sync_api = None


def free_port() -> int:
    """A TCP port that was free a moment ago (the server is started with port_retries=0 and fails loudly)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@contextlib.contextmanager
def serve_lab(root: Path, env: dict | None = None, start_timeout: float = 90.0,
              app: str = "lab", args: Sequence[str] = ()) -> Iterator[str]:
    """JupyterLab serving ``root`` (config, runtime and workspaces inside it); yields its base URL.

    ``app="server"`` starts a plain ``jupyter server`` instead; ``args`` are added to its command
    line (e.g. ``--config=deploy/jupyterhub/jupyter_server_config.py``).
    """
    root = Path(root)
    config = root / "config"
    (config / "labconfig").mkdir(parents=True, exist_ok=True)
    (config / "labconfig" / "page_config.json").write_text(json.dumps(
        {"disabledExtensions": {"@jupyterlab/apputils-extension:announcements": True}}))
    env = dict(os.environ if env is None else env, JUPYTER_CONFIG_DIR=str(config),
               JUPYTER_RUNTIME_DIR=str(root / "runtime"), MPLBACKEND="Agg")
    port = free_port()
    log = open(root / "server.log", "w")
    lab_only = ["--LabApp.expose_app_in_browser=True", f"--LabApp.workspaces_dir={root / 'ws'}"]
    proc = subprocess.Popen(
        [sys.executable, "-m", "jupyter", app, "--no-browser", "--allow-root", f"--port={port}",
         "--ServerApp.port_retries=0", f"--ServerApp.root_dir={root}", "--IdentityProvider.token=",
         "--ServerApp.password=", "--ServerApp.disable_check_xsrf=True",
         *(lab_only if app == "lab" else []), *args],
        env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + start_timeout
        while True:
            try:
                with urllib.request.urlopen(url + "/api/status", timeout=2) as r:
                    if r.status == 200:
                        break
            except OSError:
                pass
            if proc.poll() is not None or time.monotonic() > deadline:
                pytest.fail("JupyterLab did not start:\n" + (root / "server.log").read_text()[-3000:])
            time.sleep(0.3)
        yield url
    finally:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait(timeout=10)
        log.close()


@contextlib.contextmanager
def launch_browser():
    """Headless Debian chromium under Playwright (never a downloaded browser)."""
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, headless=True,
                              args=["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"])
        try:
            yield b
        finally:
            b.close()


# Every test opens its notebook in a workspace of its own, reset on load (``?reset``): a shared
# workspace would restore the previous test's tabs, whose kernels the fixture has shut down, and
# ``shell.currentWidget`` could then be that other notebook.  The widget of the notebook that was
# asked for is found by its path and kept as ``window.__courseNb``; every later step uses it.
FIND_NOTEBOOK = """(name) => {
    const app = window.jupyterapp;
    if (!app || !app.shell) return false;
    for (const w of app.shell.widgets('main')) {
        if (w.context && w.context.path === name && w.sessionContext && w.content) {
            window.__courseNb = w;
            app.shell.activateById(w.id);
            return true;
        }
    }
    return false;
}"""

# Bounded: a notebook without a kernelspec would wait on JupyterLab's kernel dialog for ever.
READY = """async () => {
    const w = window.__courseNb;
    const late = new Promise(resolve => setTimeout(() => resolve('late'), 60000));
    const ready = Promise.all([w.context.ready, w.sessionContext.ready]).then(() => 'ready');
    if (await Promise.race([ready, late]) === 'late') return false;
    return window.jupyterapp.shell.currentWidget === w && w.sessionContext.session !== null;
}"""

KERNEL_IDLE = """() => { const s = window.__courseNb.sessionContext.session;
    return !!(s && s.kernel && s.kernel.status === 'idle'); }"""

# What the notebook is doing now, for the wait loop and for the message when it times out.
RUN_STATE = """() => {
    const w = window.__courseNb;
    const s = w.sessionContext.session;
    const kernel = s && s.kernel;
    const cells = w.content.widgets;
    let total = 0, done = 0, running = null, pending = null, error = null;
    cells.forEach((c, i) => {
        if (c.model.type !== 'code') return;
        total += 1;
        const prompt = c.node.querySelector('.jp-InputPrompt');
        const head = c.model.sharedModel.getSource().split('\\n')[0].slice(0, 100);
        if (prompt && prompt.textContent.includes('*')) {
            if (running === null) running = {index: i, head};
        } else if (c.model.executionCount !== null) {
            done += 1;
        } else if (pending === null) {
            pending = {index: i, head};
        }
        if (error === null) {
            for (let k = 0; k < c.model.outputs.length; k++) {
                const out = c.model.outputs.get(k);
                if (out.type === 'error') {
                    const j = out.toJSON();
                    error = {index: i, head, text: (j.ename || '') + ': ' + (j.evalue || '')};
                    break;
                }
            }
        }
    });
    return {kernel: kernel ? kernel.status : 'none', connection: kernel ? kernel.connectionStatus : 'none',
            total, done, running, pending, error};
}"""

IN_KERNEL = """async (code) => {
    const kernel = window.__courseNb.sessionContext.session.kernel;
    let text = '';
    const future = kernel.requestExecute({code, silent: false, store_history: false});
    future.onIOPub = msg => {
        if (msg.header.msg_type === 'stream') text += msg.content.text;
        if (msg.header.msg_type === 'error') text += 'ERROR ' + msg.content.ename + ': ' + msg.content.evalue;
    };
    await future.done;
    return text.trim();
}"""


def describe(state: dict) -> str:
    """One line on a notebook's run: kernel state, cells done, the running and the next cell."""
    def cell(c):
        return f"cell {c['index']} ({c['head']!r})" if c else "none"
    text = (f"kernel {state['kernel']} ({state['connection']}), {state['done']}/{state['total']} code cells run, "
            f"running: {cell(state['running'])}, next not run: {cell(state['pending'])}")
    if state.get("error"):
        text += f", error in {cell(state['error'])}: {state['error']['text']}"
    return text


def fail_with_picture(page, name: str, what: str, lab_url: str | None = None) -> None:
    """Save a screenshot named after the notebook, then fail saying what was being waited for."""
    shot = SHOTS / f"timeout-{Path(name).stem}.png"
    try:
        page.screenshot(path=str(shot), full_page=False)
    except Exception as exc:  # the page itself may be gone; the message still says what was waited for
        shot = f"(no screenshot: {exc})"
    try:
        state = describe(page.evaluate(RUN_STATE))
    except Exception as exc:
        state = f"(no notebook state: {exc})"
    pytest.fail(f"{name}: {what}; {state}; screenshot {shot}", pytrace=False)


def wait_until(page, name: str, predicate: str, what: str, timeout_s: float, arg=None) -> None:
    """Poll ``predicate`` in the page until it is true; on time-out, a picture and the notebook's state."""
    deadline = time.monotonic() + timeout_s
    while True:
        try:
            if page.evaluate(predicate, arg):
                return
        except sync_api.Error:
            pass  # the page is still loading: window.jupyterapp or the widget is not there yet
        if time.monotonic() > deadline:
            fail_with_picture(page, name, f"timed out after {timeout_s:.0f} s waiting for {what}")
        time.sleep(0.25)


def open_and_run(page, url: str, name: str, timeout_s: float = 240.0) -> None:
    """Open ``name`` in a fresh workspace, wait for an idle kernel, run every cell, wait until all ran.

    Fails at once, with the cell and its error, when a cell raises (Run All stops there, so the
    remaining cells would never run); on a time-out it saves ``build/screenshots/timeout-*.png``
    and says which cell was running."""
    workspace = f"t-{Path(name).stem}-{os.getpid()}-{time.monotonic_ns()}"
    page.goto(f"{url}/lab/workspaces/{workspace}/tree/{name}?reset")
    wait_until(page, name, FIND_NOTEBOOK, "the notebook's tab", 120, name)
    if not page.evaluate(READY):
        fail_with_picture(page, name, "the notebook did not become ready in 60 s (not the current tab,"
                          " no session, or a dialog in the way)")
    wait_until(page, name, KERNEL_IDLE, "an idle kernel", 120)
    # Not awaited: the command's promise settles only when the last cell has run, and a page call
    # that waits on it would hang without saying where; the loop below watches the cells instead.
    page.evaluate("() => { window.jupyterapp.commands.execute('notebook:run-all-cells'); return true; }")
    deadline = time.monotonic() + timeout_s
    while True:
        state = page.evaluate(RUN_STATE)
        if state["error"] and state["kernel"] == "idle":
            pytest.fail(f"{name}: a cell raised: {describe(state)}", pytrace=False)
        if state["kernel"] in ("dead", "none") or state["connection"] == "disconnected":
            fail_with_picture(page, name, "the kernel is gone")
        if state["kernel"] == "idle" and state["total"] and state["done"] == state["total"]:
            return
        if time.monotonic() > deadline:
            fail_with_picture(page, name, f"Run All did not finish in {timeout_s:.0f} s")
        time.sleep(0.5)


def kernel_says(page, code: str, expected: str, timeout: float = 20.0) -> str:
    """Poll the kernel until ``code`` prints ``expected`` (widget values reach it with a delay)."""
    deadline = time.monotonic() + timeout
    while True:
        out = page.evaluate(IN_KERNEL, code)
        if out == expected or time.monotonic() > deadline:
            return out
        time.sleep(0.3)


def shut_down_session(page, url: str) -> None:
    """End the test's notebook session (and so its kernel) through the server's REST API."""
    sid = page.evaluate("() => window.__courseNb && window.__courseNb.sessionContext.session"
                        " ? window.__courseNb.sessionContext.session.id : null")
    if sid:
        req = urllib.request.Request(f"{url}/api/sessions/{sid}", method="DELETE")
        urllib.request.urlopen(req, timeout=10).close()

