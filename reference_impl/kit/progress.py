"""A progress line for a cell that runs longer than a few seconds.

Run the examples:  python -m pytest reference_impl/kit/progress.py

``progress(items, label)`` yields the items and keeps one line of output up to
date: which item is running, how many are done, the seconds so far.  It is a
plain display (``display(..., display_id=True)`` then ``update``), not a widget,
so it needs no widget model: a saved notebook reopened without a kernel, an
HTML export and a headless run all show its last state ("done: 4 of 4 in 3.1 s").

>>> list(progress([1, 2, 3], "counting", show=False))
[1, 2, 3]
>>> line = Progress("counting", 3, show=False)
>>> line.text(2, "n = 10")
'counting: 2 of 3 (n = 10), 0.0 s so far'
"""
from __future__ import annotations

import time
from typing import Iterable, Iterator, TypeVar

__all__ = ["Progress", "progress"]

T = TypeVar("T")


def _in_ipython() -> bool:
    """True inside an IPython kernel or shell (elsewhere a progress line would only print noise)."""
    try:
        from IPython.core.interactiveshell import InteractiveShell
    except ImportError:
        return False
    return InteractiveShell.initialized()


class Progress:
    """One output line that says how far a long cell has got (``step``, then ``done``)."""

    def __init__(self, label: str, total: int, *, show: bool = True) -> None:
        self.label = label
        self.total = int(total)
        self.start = time.perf_counter()
        self.handle = None
        if show and _in_ipython():
            from IPython.display import display

            self.handle = display(self._bundle(self.text(0, "starting")), raw=True, display_id=True)

    def text(self, done: int, what: str = "") -> str:
        """The line shown after ``done`` items, ``what`` naming the one running now."""
        seconds = 0.0 if self.handle is None else time.perf_counter() - self.start
        return f"{self.label}: {done} of {self.total}" + (f" ({what})" if what else "") + f", {seconds:.1f} s so far"

    @staticmethod
    def _bundle(line: str) -> dict:
        return {"text/plain": line, "text/html": f'<span class="kit-progress">{line}</span>'}

    def step(self, done: int, what: str = "") -> None:
        """Say that ``done`` items are finished and ``what`` runs now."""
        if self.handle is not None:
            self.handle.update(self._bundle(self.text(done, what)), raw=True)

    def done(self) -> None:
        """The last state: every item done, and how long it took."""
        if self.handle is not None:
            line = f"{self.label}: done, {self.total} of {self.total} in {time.perf_counter() - self.start:.1f} s"
            self.handle.update(self._bundle(line), raw=True)


def progress(items: Iterable[T], label: str, *, show: bool = True) -> Iterator[T]:
    """Yield ``items`` while one output line shows how many are done (see ``Progress``)."""
    items = list(items)
    line = Progress(label, len(items), show=show)
    for k, item in enumerate(items):
        line.step(k, str(item))
        yield item
    line.done()
