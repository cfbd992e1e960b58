"""A read of a notebook through jupyter_server's contents API while a save of it is being written.

Why the hub test reads the student's saved notebook from the disk (hub_browser.wait_saved) and
never through ``GET /api/contents/...?content=1`` while JupyterLab saves. With jupyter_server 2.21,
a read that comes while a save is writing can find the file half written. It then "recovers" the
file: it renames the notebook to ``.invalid`` and puts the save's backup ``.~name`` back in its
place. The save in flight then answers 404, or answers 200 while the file holds an older save.

This script measures that. It starts a jupyter server on a temporary folder. One thread saves a
large notebook (each save with a new number in its metadata) while another reads it. After each
save it reads the file back from the disk. It then does the same with saves alone, as a control.

    .venv/bin/python tests/hub/contents_race.py [--seconds 30]

Measured here (2 cores busy with a test run, jupyter_server 2.21.1, 30 s each). With a reader,
4 of 67 saves answered 404, and 44 of the 63 that answered 2xx left another save on the disk. The
reads got 400 (18), 404 (10) and 500 (4), and an ``n.ipynb.invalid`` was left behind. Saves
alone: 100 of 100 answered 200, and each one was on the disk.
"""
from __future__ import annotations

import argparse
import collections
import json
import secrets
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import nbformat
import requests

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "browser"))
from labdriver import free_port  # noqa: E402


def measure(root: Path, seconds: float, reader: bool) -> collections.Counter:
    """Saves (and reads, if ``reader``) of ``root/n.ipynb`` for ``seconds``; what they answered."""
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("x = 1\n" * 20000) for _ in range(20)])
    nbformat.write(nb, root / "n.ipynb")
    token, port = secrets.token_hex(8), free_port()
    server = subprocess.Popen([sys.executable, "-m", "jupyter_server", f"--ServerApp.root_dir={root}",
                               f"--port={port}", "--ServerApp.port_retries=0", f"--IdentityProvider.token={token}",
                               "--no-browser", "--allow-root"],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    url, auth = f"http://127.0.0.1:{port}/api/contents/n.ipynb", {"Authorization": f"token {token}"}
    seen: collections.Counter = collections.Counter()
    try:
        for _ in range(300):
            try:
                requests.get(url, headers=auth, timeout=2)
                break
            except requests.ConnectionError:
                time.sleep(0.2)
        stop = time.monotonic() + seconds

        def save() -> None:
            body = {"type": "notebook", "format": "json", "content": nb}
            k = 0
            while time.monotonic() < stop:
                k += 1
                nb.metadata["k"] = k
                r = requests.put(url, headers=auth, json=body, timeout=120)
                seen[f"save answered {r.status_code}"] += 1
                try:
                    on_disk = json.loads((root / "n.ipynb").read_text())["metadata"].get("k")
                except (OSError, ValueError):
                    on_disk = None
                if r.ok and on_disk != k:
                    seen["save answered 2xx, the disk holds another save"] += 1

        def read() -> None:
            while time.monotonic() < stop:
                seen[f"read answered {requests.get(url + '?content=1', headers=auth, timeout=120).status_code}"] += 1

        threads = [threading.Thread(target=save)] + ([threading.Thread(target=read)] if reader else [])
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    finally:
        server.terminate()
        server.wait(30)
    return seen


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seconds", type=float, default=30.0)
    args = ap.parse_args()
    for reader in (True, False):
        with tempfile.TemporaryDirectory() as d:
            seen = measure(Path(d), args.seconds, reader)
            left = sorted(p.name for p in Path(d).iterdir() if p.name.startswith("n.ipynb"))
        print(("saves with a concurrent reader" if reader else "saves alone (control)") + ":")
        for what, n in sorted(seen.items()):
            print(f"  {n:5d}  {what}")
        print(f"  files left: {left}")


if __name__ == "__main__":
    main()
