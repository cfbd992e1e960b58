"""The jail's writable file systems are memory: their sizes, and what a submission keeps in them.

Everything a jailed submission can write lives in a ``tmpfs`` (RAM): the private ``/tmp`` (with
the working directory) and ``/dev/shm``. Every other mount of both jails is read-only or not
writable by the sandbox's uid (bubblewrap's own root and ``/dev`` are remounted read-only). So:

* :func:`sizes` gives each writable tmpfs a size derived from the memory limit (``/tmp``:
  ``Limits.disk_mb``, ``/dev/shm``: ``Limits.shm_mb``, each at most an eighth of the memory
  limit). Where no cgroup charges the tmpfs pages (an ordinary account's jail) the sandbox's
  RLIMIT_AS is the memory limit minus their sum, so the address space plus the files never hold
  more than the limit on the host (as root the cgroup charges both, up to the limit);
* :class:`FileUse` measures what the submission keeps there while it runs: ``statvfs`` of the
  mounts as the jailed process sees them (``/proc/<pid>/root/tmp``; the grader may look there:
  it is root, or the owner of the sandbox's user namespace), sampled with the CPU time. A
  tmpfs filled to its size is an MLE (:meth:`FileUse.full_message`), and where no cgroup
  counts them the files are added to the reported memory.

Example:
    >>> from grader.jail.sandbox import Limits
    >>> sizes(Limits(memory_mb=256))
    {'/tmp': 32, '/dev/shm': 8}
    >>> sizes(Limits(memory_mb=64, disk_mb=32, shm_mb=32))
    {'/tmp': 8, '/dev/shm': 8}
"""

from __future__ import annotations

import os
from typing import Protocol

#: A tmpfs with less free space than this (bytes) is full: the submission filled it.
FULL_SLACK = 256 << 10


class _Sized(Protocol):
    memory_mb: int
    disk_mb: int
    shm_mb: int


def sizes(limits: _Sized) -> dict[str, int]:
    """MiB of each writable tmpfs of the jail (path inside the jail -> size), each at most an
    eighth of the memory limit (at least 1 MiB)."""
    cap = max(1, limits.memory_mb // 8)
    return {"/tmp": max(1, min(limits.disk_mb, cap)), "/dev/shm": max(1, min(limits.shm_mb, cap))}


def used_mb(pid: int, mount: str) -> tuple[float, float] | None:
    """(used, size) in MiB of ``mount`` as process ``pid`` sees it (its mount namespace and root),
    or None where that cannot be read (the process is gone)."""
    try:
        st = os.statvfs(f"/proc/{pid}/root{mount}")
    except OSError:
        return None
    size = st.f_blocks * st.f_frsize
    return (size - st.f_bfree * st.f_frsize) / (1 << 20), size / (1 << 20)


class FileUse:
    """Peak use of the jail's tmpfs mounts since :meth:`reset`, from samples (:meth:`sample`)."""

    def __init__(self, mounts: dict[str, int]):
        self.mounts = dict(mounts)  #: path inside the jail -> size (MiB)
        self.peak: dict[str, float] = {}  #: path -> most MiB seen used since the last reset
        self.filled: set[str] = set()  #: mounts seen full since the last reset

    def reset(self) -> None:
        """Forget the peaks (a new test starts)."""
        self.peak.clear()
        self.filled.clear()

    def sample(self, pid: int | None) -> bool:
        """Measure every mount as ``pid`` (a process inside the jail) sees it; False when none
        was the jail's (``pid`` gone, or not inside the jail)."""
        if pid is None:
            return False
        inside = False
        for mount, size_mb in self.mounts.items():
            got = used_mb(pid, mount)
            if got is None or abs(got[1] - size_mb) > 0.5:
                continue  # gone, or not the jail's mount (the process is not inside it yet)
            inside = True
            used = got[0]
            self.peak[mount] = max(self.peak.get(mount, 0.0), used)
            if (got[1] - used) * (1 << 20) < FULL_SLACK:
                self.filled.add(mount)
        return inside

    def note(self, mount: str, used_mb: float) -> None:
        """Record ``used_mb`` MiB seen used in ``mount`` by someone inside the jail (a compiled
        program's server measures its mounts when a test's process has ended, before emptying them)."""
        if mount not in self.mounts:
            raise ValueError(f"{mount!r} is not a writable mount of the jail ({', '.join(self.mounts)})")
        self.peak[mount] = max(self.peak.get(mount, 0.0), used_mb)
        if (self.mounts[mount] - used_mb) * (1 << 20) < FULL_SLACK:
            self.filled.add(mount)

    def peak_mb(self) -> float:
        """MiB the submission kept in the jail's file systems at most (summed over the mounts)."""
        return sum(self.peak.values())

    def full_message(self) -> str:
        """Why a filled tmpfs is an MLE, or '' when none was filled."""
        if not self.filled:
            return ""
        kept = ", ".join(f"{self.peak.get(m, self.mounts[m]):.0f} MB in {m}" for m in sorted(self.filled))
        budget = ", ".join(f"{m} {mb} MB" for m, mb in self.mounts.items())
        return (f"the submission kept {kept}, all the room there: files in the jail are memory and count "
                f"towards the memory limit (the room for files: {budget})")
