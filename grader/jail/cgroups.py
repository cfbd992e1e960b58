"""Accounting for a whole sandbox: CPU time, peak memory (RSS) and process count of every
process in it, forked helpers included.

Three mechanisms, tried in this order (:func:`open_group`):

* ``cgroup-v1``: one child group per sandbox slot under the grader's own group in the
  ``cpuacct``, ``memory`` and ``pids`` hierarchies (``cpuacct.usage``,
  ``memory.max_usage_in_bytes`` reset per test, ``memory.limit_in_bytes`` = the memory limit,
  ``pids.max``; the OOM-kill counter of ``memory.oom_control`` tells an MLE);
* ``cgroup-v2``: one child group under the grader's own group in the unified hierarchy
  (``cpu.stat`` ``usage_usec``, ``memory.peak``, ``memory.max``, ``pids.max``) when the
  controllers are delegated there;
* ``proc-uid``: no writable cgroup: sum over the live processes of the sandbox uid in
  ``/proc`` (CPU of exited, reaped helpers is counted through their parent's ``cutime``;
  memory is the sum of per-process peaks). No memory limit on the whole sandbox then.

Not root (:class:`ProcTree`): ``proc-tree``, the same sums over the processes below the ones
the sandbox started (bubblewrap, its pid-1 reaper and the student's process: the sandbox's pid
namespace, where orphans are reparented to that reaper). There the seccomp filter refuses new
processes, so the limits of the one student process (RLIMIT_CPU, RLIMIT_AS) are the sandbox's.

A child joins its group from the ``preexec`` hook, before it drops privileges, by writing
its pid to every path of :attr:`Group.procs_files`.

Run ``python -m grader.jail.cgroups`` (as root) to print which mechanism this machine gives.

Example:
    >>> g = open_group("doctest", memory_mb=256, processes=16, uid=None)   # doctest: +SKIP
    >>> g.mechanism, g.cpu_seconds() >= 0                                 # doctest: +SKIP
    ('cgroup-v1', True)
"""

from __future__ import annotations

import os
from pathlib import Path

from .procs import descendants, parent, uid_processes

CGROUP_ROOT = Path("/sys/fs/cgroup")
CLK_TCK = os.sysconf("SC_CLK_TCK")


def _read(path: Path) -> str:
    with open(path) as f:
        return f.read()


def _write(path: Path, text: str) -> None:
    with open(path, "w") as f:
        f.write(text)


def _own_groups() -> dict[str, str]:
    """Controller (or '' for cgroup2) -> this process's group path, from /proc/self/cgroup."""
    out = {}
    for line in _read(Path("/proc/self/cgroup")).splitlines():
        _, ctrls, path = line.split(":", 2)
        for c in ctrls.split(",") if ctrls else [""]:
            out[c] = path
    return out


def _mounts() -> dict[str, Path]:
    """Controller -> v1 mount point, and '' -> the cgroup2 mount point."""
    out: dict[str, Path] = {}
    for line in _read(Path("/proc/self/mounts")).splitlines():
        dev, mnt, fstype, opts = line.split()[:4]
        if fstype == "cgroup2":
            out.setdefault("", Path(mnt))
        elif fstype == "cgroup":
            for o in opts.split(","):
                if o in ("cpuacct", "memory", "pids"):
                    out.setdefault(o, Path(mnt))
    return out


class Group:
    """One sandbox's accounting; :meth:`close` removes the cgroups it created."""

    mechanism = "none"

    def __init__(self) -> None:
        self.procs_files: list[str] = []  # where the child writes its pid (preexec)
        self.limit_bytes = 0

    def cpu_seconds(self) -> float:  # pragma: no cover - overridden
        return 0.0

    def peak_memory_mb(self) -> float:  # pragma: no cover - overridden
        return 0.0

    def reset_peak(self) -> None:
        pass

    def memory_limit_hit(self) -> bool:
        """True when the whole sandbox reached its memory limit since the last reset."""
        return False

    def pids(self) -> list[int]:
        """The processes in the group now (host pids), from its first ``cgroup.procs``."""
        for name in self.procs_files[:1]:
            try:
                return [int(x) for x in _read(Path(name)).split()]
            except (OSError, ValueError):
                return []
        return []

    def close(self) -> None:
        pass


class _V1(Group):
    mechanism = "cgroup-v1"

    def __init__(self, dirs: dict[str, Path], memory_mb: int, processes: int):
        super().__init__()
        self.dirs = dirs
        self.limit_bytes = memory_mb << 20
        mem = dirs["memory"]
        for name, value in (("memory.limit_in_bytes", self.limit_bytes),
                            ("memory.memsw.limit_in_bytes", self.limit_bytes)):
            try:
                _write(mem / name, str(value))
            except OSError:  # memsw needs swap accounting; the RAM limit is what matters
                pass
        _write(dirs["pids"] / "pids.max", str(processes))
        self.procs_files = [str(d / "cgroup.procs") for d in dirs.values()]
        self._kills0 = 0
        self.reset_peak()

    def cpu_seconds(self) -> float:
        return int(_read(self.dirs["cpuacct"] / "cpuacct.usage")) / 1e9

    def peak_memory_mb(self) -> float:
        return int(_read(self.dirs["memory"] / "memory.max_usage_in_bytes")) / (1 << 20)

    def reset_peak(self) -> None:
        try:
            _write(self.dirs["memory"] / "memory.max_usage_in_bytes", "0")
        except OSError:
            pass
        self._kills0 = self._oom_kills()

    def _oom_kills(self) -> int:
        # reaching the limit only reclaims page cache (memory.failcnt counts that too); an OOM
        # kill is what the submission's processes together going over it does
        for line in _read(self.dirs["memory"] / "memory.oom_control").splitlines():
            if line.startswith("oom_kill "):
                return int(line.split()[1])
        return int(_read(self.dirs["memory"] / "memory.failcnt"))  # old kernels: no counter

    def memory_limit_hit(self) -> bool:
        return self._oom_kills() > self._kills0

    def close(self) -> None:
        for d in self.dirs.values():
            try:
                d.rmdir()
            except OSError:
                pass


class _V2(Group):
    mechanism = "cgroup-v2"

    def __init__(self, path: Path, memory_mb: int, processes: int):
        super().__init__()
        self.path = path
        self.limit_bytes = memory_mb << 20
        _write(path / "memory.max", str(self.limit_bytes))
        _write(path / "pids.max", str(processes))
        self.procs_files = [str(path / "cgroup.procs")]
        self._events0 = 0
        self.reset_peak()

    def cpu_seconds(self) -> float:
        for line in _read(self.path / "cpu.stat").splitlines():
            if line.startswith("usage_usec "):
                return int(line.split()[1]) / 1e6
        return 0.0

    def peak_memory_mb(self) -> float:
        return int(_read(self.path / "memory.peak")) / (1 << 20)

    def _oom_kills(self) -> int:
        for line in _read(self.path / "memory.events").splitlines():
            if line.startswith("oom_kill "):
                return int(line.split()[1])
        return 0

    def reset_peak(self) -> None:
        try:  # writing resets the peak on Linux >= 6.12
            _write(self.path / "memory.peak", "0")
        except OSError:
            pass
        self._events0 = self._oom_kills()

    def memory_limit_hit(self) -> bool:
        return self._oom_kills() > self._events0

    def close(self) -> None:
        try:
            self.path.rmdir()
        except OSError:
            pass


class _ProcSum(Group):
    """Accounting summed from ``/proc`` over the processes :meth:`_pids` names."""

    def __init__(self, memory_mb: int):
        super().__init__()
        self.limit_bytes = memory_mb << 20
        self._peak = 0.0

    def _pids(self) -> list[int]:  # pragma: no cover - overridden
        return []

    def pids(self) -> list[int]:
        return self._pids()

    def cpu_seconds(self) -> float:
        total = 0.0
        for pid in self._pids():
            try:
                with open(f"/proc/{pid}/stat", "rb") as f:
                    fields = f.read().rsplit(b")", 1)[1].split()
                total += sum(int(x) for x in fields[11:15]) / CLK_TCK  # utime stime cutime cstime
            except (OSError, IndexError, ValueError):
                pass
        return total

    def peak_memory_mb(self) -> float:
        total = 0.0
        for pid in self._pids():
            try:
                with open(f"/proc/{pid}/status", "rb") as f:
                    total += next((int(ln.split()[1]) for ln in f if ln.startswith(b"VmHWM:")), 0) / 1024
            except OSError:
                pass
        self._peak = max(self._peak, total)
        return self._peak

    def reset_peak(self) -> None:
        self._peak = 0.0
        for pid in self._pids():
            try:
                with open(f"/proc/{pid}/clear_refs", "w") as f:
                    f.write("5")
            except OSError:
                pass

    def memory_limit_hit(self) -> bool:
        return self._peak * (1 << 20) >= self.limit_bytes


class _ProcUid(_ProcSum):
    """Fallback as root: the live processes of the sandbox uid, from /proc."""

    mechanism = "proc-uid"

    def __init__(self, uid: int | None, memory_mb: int):
        super().__init__(memory_mb)
        self.uid = uid

    def _pids(self) -> list[int]:
        return [] if self.uid is None else uid_processes(self.uid)


#: How often the runner samples a ``proc-tree`` sandbox while a test runs (seconds): what an exiting
#: process used after its last sample is not seen.
SAMPLE_S = 0.02


class ProcTree(_ProcSum):
    """Not root: the processes the sandbox started (:attr:`roots`) and all below them."""

    mechanism = "proc-tree"

    def __init__(self, memory_mb: int):
        super().__init__(memory_mb)
        self.roots: list[int] = []
        self._last: dict[tuple[int, bytes], float] = {}  # (pid, start time) -> its own CPU when last seen

    def cpu_seconds(self) -> float:
        """Each process's own CPU (not ``cutime``: bubblewrap's reaper collects the student's
        process, which would count it twice), as last seen: a process that has exited (a stdio
        run) still counts what it had used at the last sample (samples: :data:`SAMPLE_S`)."""
        for pid in self._pids():
            try:
                with open(f"/proc/{pid}/stat", "rb") as f:
                    fields = f.read().rsplit(b")", 1)[1].split()
                self._last[pid, fields[19]] = (int(fields[11]) + int(fields[12])) / CLK_TCK
            except (OSError, IndexError, ValueError):
                pass
        return sum(self._last.values())

    def _pids(self) -> list[int]:
        me = os.getpid()  # a root reaped and its pid reused by another process is not ours
        self.roots = [r for r in self.roots if parent(r) == me]
        return descendants(self.roots)


def _make_dir(path: Path) -> Path:
    path.mkdir(exist_ok=True)
    return path


def open_group(name: str, memory_mb: int, processes: int, uid: int | None) -> Group:
    """Create (or reuse) the accounting group ``name`` with the given limits; never raises:
    falls back to ``proc-uid`` where no cgroup is writable (not root, read-only sysfs...)."""
    if os.geteuid() == 0:
        try:
            own, mounts = _own_groups(), _mounts()
        except (OSError, ValueError):
            own, mounts = {}, {}
        if all(c in mounts and c in own for c in ("cpuacct", "memory", "pids")):
            created: list[Path] = []
            try:
                dirs = {}
                for c in ("cpuacct", "memory", "pids"):
                    d = mounts[c] / own[c].lstrip("/") / name
                    existed = d.exists()
                    dirs[c] = _make_dir(d)
                    if not existed:
                        created.append(d)
                return _V1(dirs, memory_mb, processes)
            except OSError:
                for d in created:
                    try:
                        d.rmdir()
                    except OSError:
                        pass
        if "" in mounts and "" in own:
            base = mounts[""] / own[""].lstrip("/")
            try:
                ctrls = set(_read(base / "cgroup.subtree_control").split())
                if {"memory", "pids"} <= ctrls:
                    return _V2(_make_dir(base / name), memory_mb, processes)
            except OSError:
                pass
    return _ProcUid(uid, memory_mb)


def main() -> None:
    """The command ``python -m grader.jail.cgroups``."""
    g = open_group(f"grader-probe-{os.getpid()}", 64, 8, None)
    print(g.mechanism)
    g.close()


if __name__ == "__main__":
    main()
