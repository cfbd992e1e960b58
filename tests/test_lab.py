"""`make lab` opens JupyterLab on notebooks/, also as root (course containers and CI run as root).

The test runs the Makefile's own `lab` target (so a regression in the recipe is caught) with
LAB_ARGS for a free port, no browser and no token, waits for /api/status, checks that the
server's root is notebooks/ (its contents listing holds the lessons), then stops the server.

Run: .venv/bin/python -m pytest tests/test_lab.py -q
"""
from __future__ import annotations

import json
import os
import shutil
import signal
import socket
import subprocess
import time
import urllib.request
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _get(url: str) -> dict | None:
    try:
        with urllib.request.urlopen(url, timeout=5) as r:
            return json.loads(r.read())
    except OSError:
        return None


@pytest.mark.skipif(shutil.which("make") is None, reason="make is not installed")
def test_make_lab_serves_the_notebooks(tmp_path):
    port = _free_port()
    args = (f"--no-browser --ip=127.0.0.1 --port={port} --ServerApp.port_retries=0 --IdentityProvider.token= "
            f"--ServerApp.password= --LabApp.workspaces_dir={tmp_path / 'ws'}")
    env = {**os.environ, "JUPYTER_CONFIG_DIR": str(tmp_path / "config"), "JUPYTER_RUNTIME_DIR": str(tmp_path / "rt"),
           "JUPYTER_DATA_DIR": str(tmp_path / "data")}
    proc = subprocess.Popen(["make", "-s", "lab", f"LAB_ARGS={args}"], cwd=REPO, env=env, start_new_session=True,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        status = None
        deadline = time.monotonic() + 120  # a loaded shared machine: bounded, generous
        while status is None and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.5)
            status = _get(f"http://127.0.0.1:{port}/api/status")
        assert status is not None, f"JupyterLab did not answer (exit {proc.poll()})"
        assert "started" in status
        listing = _get(f"http://127.0.0.1:{port}/api/contents")
        names = {item["name"] for item in listing["content"]}
        expected = {p.name for p in (REPO / "notebooks").iterdir() if not p.name.startswith(".")}
        assert names == expected  # the lab's root is notebooks/
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGTERM)  # our own session: make and the server it started
        try:
            out, _ = proc.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            out, _ = proc.communicate()
    assert "Running as root is not recommended" not in out
