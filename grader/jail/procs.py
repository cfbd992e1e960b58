"""Reading the process table (``/proc``): who runs as a uid, a process's children and state.

Used by the sandbox (cleanup by uid, bubblewrap's reaper) and by the ``/proc`` accounting of
:mod:`grader.jail.cgroups`; kept apart so that neither imports the other.

Example:
    >>> import os
    >>> alive(os.getpid()), parent(os.getpid()) == os.getppid()
    (True, True)
"""

from __future__ import annotations

import os


def children(pid: int) -> list[int]:
    """The direct children of ``pid`` (every thread's), [] when it is gone."""
    out: list[int] = []
    try:
        tasks = os.listdir(f"/proc/{pid}/task")
    except OSError:
        return out
    for tid in tasks:
        try:
            with open(f"/proc/{pid}/task/{tid}/children") as f:
                out += [int(c) for c in f.read().split()]
        except (OSError, ValueError):
            pass
    return out


def descendants(roots: list[int]) -> list[int]:
    """``roots`` that still exist and every process below them (breadth first)."""
    seen: list[int] = []
    todo = [r for r in roots if os.path.exists(f"/proc/{r}")]
    while todo:
        pid = todo.pop(0)
        if pid in seen:
            continue
        seen.append(pid)
        todo += children(pid)
    return seen


def parent(pid: int) -> int:
    """The parent pid of ``pid`` (0 when it is gone)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            return int(f.read().rsplit(b")", 1)[1].split()[1])
    except (OSError, IndexError, ValueError):
        return 0


def alive(pid: int) -> bool:
    """Running (not a zombie, not gone)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            return f.read().rsplit(b")", 1)[1].split()[0] != b"Z"
    except (OSError, IndexError):
        return False


def uid_processes(uid: int) -> list[int]:
    """PIDs of processes (zombies included) whose real uid is ``uid``."""
    pids = []
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                if os.stat(f"/proc/{d}").st_uid == uid:
                    pids.append(int(d))
            except OSError:
                pass
    return pids
