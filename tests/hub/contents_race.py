"""A read of a notebook through jupyter_server's contents API while a save of it is being written.

Why the hub test reads the student's saved notebook from the disk (hub_browser.wait_saved) and
never through ``GET /api/contents/...?content=1`` while JupyterLab saves. With jupyter_server 2.21,
a read that comes while a save is writing can find the file half written. It then "recovers" the
file: it renames the notebook to ``.invalid`` and puts the save's backup ``.~name`` back in its
place. The save in flight then answers 404, or answers 200 while the file holds an older save.

This script measures that. It starts JupyterLab's server on a temporary folder (the browser
tests' ``serve_lab``). One thread saves a large notebook, each save with a new number in its
metadata, while another thread reads it. After each save it reads the file back from the disk. It then does the same with saves alone, as a control.

    .venv/bin/python tests/hub/contents_race.py [--seconds 30]

Measured here (2 cores, jupyter_server 2.21.1, 30 s each):

  | machine | saves that answered 404 | 2xx saves with another save on the disk | saves alone |
  | --- | --- | --- | --- |
  | idle | 30 of 151 | 70 of 121 | 205 of 205 answered 200 and were on the disk |
  | busy with a test run | 4 of 67 | 44 of 63 | 100 of 100 the same |

In both runs the reads got 400, 404 and 500 answers, and an ``n.ipynb.invalid`` was left behind.
"""
from __future__ import annotations

import argparse
import collections
import json
import sys
import tempfile
import threading
import time
from pathlib import Path

import nbformat
import requests

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "browser"))
from labdriver import serve_lab  # noqa: E402 - the browser tests' JupyterLab server


def measure(root: Path, seconds: float, reader: bool) -> collections.Counter:
    """Saves (and reads, if ``reader``) of ``root/n.ipynb`` for ``seconds``; what they answered."""
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("x = 1\n" * 20000) for _ in range(20)])
    nbformat.write(nb, root / "n.ipynb")
    seen: collections.Counter = collections.Counter()
    with serve_lab(root) as lab:                 # no token, no XSRF check: plain requests work
        url = f"{lab}/api/contents/n.ipynb"
        stop = time.monotonic() + seconds

        def save() -> None:
            body = {"type": "notebook", "format": "json", "content": nb}
            k = 0
            while time.monotonic() < stop:
                k += 1
                nb.metadata["k"] = k
                r = requests.put(url, json=body, timeout=120)
                seen[f"save answered {r.status_code}"] += 1
                try:
                    on_disk = json.loads((root / "n.ipynb").read_text())["metadata"].get("k")
                except (OSError, ValueError):
                    on_disk = None
                if r.ok and on_disk != k:
                    seen["save answered 2xx, the disk holds another save"] += 1

        def read() -> None:
            while time.monotonic() < stop:
                seen[f"read answered {requests.get(url + '?content=1', timeout=120).status_code}"] += 1

        threads = [threading.Thread(target=save)] + ([threading.Thread(target=read)] if reader else [])
        for t in threads:
            t.start()
        for t in threads:
            t.join()
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
