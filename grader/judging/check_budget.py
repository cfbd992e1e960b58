"""A CPU-time limit of its own for each check, so a slow checker costs a verdict, not the batch.

Checkers bound their work by the input size (they reject an answer larger than a correct one can
be before looking at it), but a checker bug, or an answer that is within the bounds and still
costly, must not hold a grader for minutes. The judge runs ``from_result``/``read_output`` and
``check`` of every test inside :func:`cpu_budget`: after ``seconds`` of the grader process's CPU
time (``ITIMER_PROF``), :class:`CheckTimeout` is raised inside the checker, and the test gets
``TLE`` ("checking your answer took more than ... of the grader's CPU"). ``CheckTimeout`` derives
from ``BaseException``, so a checker's ``except Exception`` cannot swallow it.

Signals are delivered to the main thread only: in another thread (a Dask worker thread) the check
runs without this limit, as before.

Example:
    >>> with cpu_budget(5.0):
    ...     sum(range(1000))
    499500
"""

from __future__ import annotations

import contextlib
import signal
import threading
from typing import Iterator


class CheckTimeout(BaseException):
    """The check used up its CPU budget."""


def check_seconds(time_limit: float) -> float:
    """The CPU budget of one check: generous next to a correct answer's check on the largest test
    (under a second for every problem here), small next to minutes.

    >>> check_seconds(6)
    30.0
    """
    return max(10.0, 3.0 * time_limit + 12.0)


def _raise(signum, frame) -> None:
    raise CheckTimeout()


@contextlib.contextmanager
def cpu_budget(seconds: float) -> Iterator[None]:
    """Raise :class:`CheckTimeout` in the body once it has used ``seconds`` of CPU time."""
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "setitimer"):
        yield
        return
    previous = signal.signal(signal.SIGPROF, _raise)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, previous)
