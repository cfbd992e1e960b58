"""Saves of one notebook through jupyter_server's contents API while others read it: is any lost?

One thread saves a large notebook ``N`` times over the contents API, each save with a new number
(``metadata.save_marker``); two threads read it over the API meanwhile, and one reads the file from
the disk and parses it (as the kernel's ``%check_samples`` does). A save is *lost* when it answers
an error, or answers 2xx while the disk holds an earlier save. ``tests/hub/test_saves.py`` asserts on
:func:`race` (a plain ``jupyter server`` with the course's configuration); the hub test runs a short
race through the hub. As a script it measures the stock server and the course's side by side::

    .venv/bin/python tests/hub/contents_race.py [--saves 200]

Measured here (2 cores shared with other sessions, load average 7, jupyter_server 2.21.1,
``--saves 200 --cells 4 --lines 3000``): the stock server lost 47 of 200 saves (32 answered 404,
15 answered 2xx over an older save) and the disk reader found 47,727 half-written files and 152,899
times no file; with the course's configuration 0 of 200 and 0 of 8,946. See
deploy/jupyterhub/README.md, "Saves".

With the stock server the reads "recover" the half-written notebook: they rename it to
``n.ipynb.invalid`` and move the save's backup ``.~n.ipynb`` back, so the save in flight answers 404
or reports success over an older save; the disk reader finds half-written or missing files.
"""
from __future__ import annotations

import argparse
import collections
import contextlib
import dataclasses
import json
import sys
import tempfile
import threading
from pathlib import Path
from typing import Callable, Iterator

import nbformat
import requests

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "browser"))
from labdriver import ROOT, serve_lab  # noqa: E402 - the browser tests' server starter

COURSE_CONFIG = ROOT / "deploy" / "jupyterhub" / "jupyter_server_config.py"


def big_notebook(cells: int = 20, lines: int = 20000) -> nbformat.NotebookNode:
    """A notebook of ``cells`` code cells of ``lines`` lines each (20 x 20000: 6 MB on the disk; 4 x 3000: 180 KB)."""
    return nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("x = 1\n" * lines) for _ in range(cells)],
                                    metadata={"save_marker": 0})


def marker(text: str) -> int | None:
    """The save marker of a notebook's text, None unless it parses as a whole notebook."""
    try:
        nb = json.loads(text)
        return nb["metadata"]["save_marker"] if nb["nbformat"] == 4 and isinstance(nb["cells"], list) else None
    except (ValueError, KeyError, TypeError):
        return None


def on_disk(path: Path) -> int | None:
    """The save marker of the notebook at ``path`` (None: missing or not a whole notebook)."""
    try:
        return marker(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError):
        return None


@dataclasses.dataclass
class Race:
    """What a race saw."""

    answers: collections.Counter = dataclasses.field(default_factory=collections.Counter)
    lost: list[str] = dataclasses.field(default_factory=list)    # one line per lost save
    saves: int = 0
    saves_ok: int = 0
    last_ok: int | None = None         # the marker of the last save that answered 2xx
    disk_reads: int = 0
    torn_disk_reads: int = 0           # missing, or not a whole notebook
    missing_disk_reads: int = 0        # of those, missing
    extra: dict = dataclasses.field(default_factory=dict)     # what ``also`` returned

    def summary(self) -> str:
        """A few lines for a report or an assertion message."""
        return (f"{len(self.lost)} of {self.saves} saves lost"
                f" ({self.lost[:5]}{' ...' if len(self.lost) > 5 else ''}); disk reads not a whole notebook:"
                f" {self.torn_disk_reads} of {self.disk_reads} ({self.missing_disk_reads} found no file); answers: {dict(sorted(self.answers.items()))}")


def race(put: Callable[[dict], requests.Response], get: Callable[[], requests.Response], path: Path,
         nb: nbformat.NotebookNode, saves: int, readers: int = 2, disk_reader: bool = True,
         also: Callable[[threading.Event], object] | None = None) -> Race:
    """``saves`` saves of ``nb`` by ``put`` (its JSON body), one after the other, while ``readers``
    threads call ``get`` and one reads ``path`` (the notebook's file) and ``also(stop)`` runs."""
    seen = Race(saves=saves)
    stop = threading.Event()
    lock = threading.Lock()

    def count(what: str) -> None:
        with lock:
            seen.answers[what] += 1

    def read_api() -> None:
        while not stop.is_set():
            count(f"read answered {get().status_code}")

    def read_disk() -> None:
        while not stop.is_set():
            missing = not path.exists()
            got = None if missing else on_disk(path)
            with lock:
                seen.disk_reads += 1
                seen.torn_disk_reads += got is None
                seen.missing_disk_reads += missing

    def other() -> None:
        seen.extra["also"] = also(stop)

    threads = [threading.Thread(target=read_api) for _ in range(readers)]
    threads += [threading.Thread(target=read_disk)] if disk_reader else []
    threads += [threading.Thread(target=other)] if also else []
    for t in threads:
        t.start()
    try:
        for k in range(1, saves + 1):
            nb.metadata["save_marker"] = k
            r = put({"type": "notebook", "format": "json", "content": nb})
            count(f"save answered {r.status_code}")
            if not r.ok:
                seen.lost.append(f"save {k} answered {r.status_code}")
                continue
            seen.saves_ok += 1
            seen.last_ok = k
            now = on_disk(path)
            if now is None or now < k:
                seen.lost.append(f"save {k} answered {r.status_code}, the disk holds {now}")
    finally:
        stop.set()
        for t in threads:
            t.join()
    return seen


@contextlib.contextmanager
def served(root: Path, config: Path | None) -> Iterator[str]:
    """A plain ``jupyter server`` on ``root`` (no token, no XSRF check), with ``--config=config``
    unless it is None (the stock server); yields its base URL."""
    with serve_lab(root, app="server", args=[f"--config={config}"] if config else []) as url:
        yield url


def race_on_server(root: Path, config: Path | None, saves: int, nb: nbformat.NotebookNode | None = None,
                   name: str = "n.ipynb", also: Callable[[threading.Event], object] | None = None) -> Race:
    """:func:`race` on the notebook ``root/name`` (written first) served by :func:`served`."""
    nb = nb or big_notebook()
    nbformat.write(nb, root / name)
    with served(root, config) as url:
        api = f"{url}/api/contents/{name}"
        return race(lambda body: requests.put(api, json=body, timeout=120),
                    lambda: requests.get(api + "?content=1", timeout=120), root / name, nb, saves, also=also)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--saves", type=int, default=200)
    ap.add_argument("--cells", type=int, default=20)
    ap.add_argument("--lines", type=int, default=20000, help="lines per cell")
    args = ap.parse_args()
    for name, config in (("stock jupyter_server", None), ("course config", COURSE_CONFIG)):
        with tempfile.TemporaryDirectory() as d:
            seen = race_on_server(Path(d), config, args.saves, big_notebook(args.cells, args.lines))
            left = sorted(p.name for p in Path(d).iterdir() if p.name.startswith((".~n", "n.ipynb")))
        print(f"{name}: {seen.summary()}\n  files left: {left}")


if __name__ == "__main__":
    main()
