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

Every counter is read through a file descriptor kept open for the group's life
(:class:`ControlFile`: ``pread`` from offset 0, no open and close per read), the processes'
``schedstat`` files too (:meth:`Group.usage`): a function-mode test reads each counter it needs
once before and once after the call.

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

from .procs import alive, descendants, parent, uid_processes

CGROUP_ROOT = Path("/sys/fs/cgroup")
CLK_TCK = os.sysconf("SC_CLK_TCK")


def _read(path: Path) -> str:
    with open(path) as f:
        return f.read()


def _write(path: Path, text: str) -> None:
    with open(path, "w") as f:
        f.write(text)


class ControlFile:
    """A control file (cgroup or ``/proc``) opened on first use and kept open: each :meth:`read`
    is one ``pread`` from its start, each :meth:`write` one ``pwrite``. A file that cannot be
    opened or read raises :class:`OSError` then, as an ``open`` would.

    >>> f = ControlFile("/proc/self/stat")
    >>> f.read().split()[0].isdigit(), f.read() != b""
    (True, True)
    >>> f.close()
    """

    __slots__ = ("path", "flags", "fd")

    def __init__(self, path: str, writable: bool = False):
        self.path = path
        self.flags = (os.O_RDWR if writable else os.O_RDONLY) | os.O_CLOEXEC
        self.fd = -1

    def _open(self) -> int:
        if self.fd < 0:
            self.fd = os.open(self.path, self.flags)
        return self.fd

    def read(self, size: int = 4096) -> bytes:
        """The whole content (up to ``size`` bytes at a time, read until the end)."""
        fd = self._open()
        data = os.pread(fd, size, 0)
        if len(data) < size:
            return data
        parts = [data]
        while True:
            more = os.pread(fd, size, sum(len(p) for p in parts))
            if not more:
                return b"".join(parts)
            parts.append(more)

    def write(self, data: bytes) -> None:
        os.pwrite(self._open(), data, 0)

    def close(self) -> None:
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1


def _schedstat_fields(files: dict[int, ControlFile], pid: int) -> list[bytes]:
    """The fields of ``/proc/<pid>/schedstat`` through a descriptor kept in ``files`` (a pid's
    file keeps naming the process it was opened for: a reused pid number fails, and is opened again)."""
    f = files.get(pid)
    if f is None:
        f = files[pid] = ControlFile(f"/proc/{pid}/schedstat")
    try:
        return f.read(256).split()
    except OSError:
        f.close()
        del files[pid]
        f = files[pid] = ControlFile(f"/proc/{pid}/schedstat")
        return f.read(256).split()


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
        self._procs: ControlFile | None = None
        self._sched: dict[int, ControlFile] = {}  # pid -> its schedstat, kept open

    def cpu_seconds(self) -> float:  # pragma: no cover - overridden
        return 0.0

    def usage(self, fallback: int = 0) -> tuple[float, float]:
        """(CPU seconds used by the whole group so far, 0.0 when unreadable; seconds its processes
        spent runnable but waiting for a CPU: ``schedstat`` field 2, summed over the processes in
        it now, or of process ``fallback`` when it lists none)."""
        pids = self.pids() or ([fallback] if fallback else [])
        try:
            cpu = self.cpu_seconds()
        except (OSError, ValueError):
            cpu = 0.0
        return cpu, self.runqueue_seconds(pids)

    def runqueue_seconds(self, pids: list[int]) -> float:
        """Run-queue wait of ``pids`` (``schedstat`` field 2, read through kept descriptors)."""
        total = 0.0
        for pid in pids:
            try:
                total += int(_schedstat_fields(self._sched, pid)[1]) / 1e9
            except (OSError, IndexError, ValueError):
                gone = self._sched.pop(pid, None)
                if gone is not None:
                    gone.close()
        if len(self._sched) > len(pids):  # forget the processes that left
            for pid in set(self._sched) - set(pids):
                self._sched.pop(pid).close()
        return total

    def peak_memory_mb(self) -> float:  # pragma: no cover - overridden
        return 0.0

    def reset_peak(self) -> None:
        pass

    def memory_limit_hit(self) -> bool:
        """True when the whole sandbox reached its memory limit since the last reset."""
        return False

    def pids(self) -> list[int]:
        """The processes in the group now (host pids), from its first ``cgroup.procs`` (through
        the kept descriptor: on cgroup v1 the kernel keeps the list an open file read for about
        a second, so a process that joined since may be missing; :meth:`held` reads afresh)."""
        if not self.procs_files:
            return []
        if self._procs is None:
            self._procs = ControlFile(self.procs_files[0])
        try:
            return [int(x) for x in self._procs.read().split()]
        except (OSError, ValueError):
            return []

    def held(self) -> list[int] | None:
        """Every process in the group now, read afresh from each ``cgroup.procs`` (a new open: the
        list a kept descriptor gives can be a second old), or None when one cannot be read."""
        if not self.procs_files:
            return None
        pids: set[int] = set()
        try:
            for path in self.procs_files:
                pids.update(int(x) for x in _read(Path(path)).split())
        except (OSError, ValueError):
            return None
        return sorted(pids)

    def close(self) -> None:
        """Close the kept descriptors (subclasses also remove what they created)."""
        for f in [self._procs, *self._sched.values(), *getattr(self, "_files", {}).values()]:
            if f is not None:
                f.close()
        self._procs = None
        self._sched.clear()


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
        self._files = {"cpu": ControlFile(str(dirs["cpuacct"] / "cpuacct.usage")),
                       "peak": ControlFile(str(mem / "memory.max_usage_in_bytes"), writable=True),
                       "oom": ControlFile(str(mem / "memory.oom_control")),
                       "failcnt": ControlFile(str(mem / "memory.failcnt"))}
        self._kills0 = 0
        self.reset_peak()

    def cpu_seconds(self) -> float:
        return int(self._files["cpu"].read(64)) / 1e9

    def peak_memory_mb(self) -> float:
        return int(self._files["peak"].read(64)) / (1 << 20)

    def reset_peak(self) -> None:
        try:
            self._files["peak"].write(b"0")
        except OSError:
            pass
        self._kills0 = self._oom_kills()

    def _oom_kills(self) -> int:
        # reaching the limit only reclaims page cache (memory.failcnt counts that too); an OOM
        # kill is what the submission's processes together going over it does
        for line in self._files["oom"].read().splitlines():
            if line.startswith(b"oom_kill "):
                return int(line.split()[1])
        return int(self._files["failcnt"].read(64))  # old kernels: no counter

    def memory_limit_hit(self) -> bool:
        return self._oom_kills() > self._kills0

    def close(self) -> None:
        super().close()
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
        # memory.peak is written and read through the same descriptor: since Linux 6.12 a write
        # resets the peak seen by later reads of that descriptor (older kernels refuse the write)
        self._files = {"cpu": ControlFile(str(path / "cpu.stat")),
                       "peak": ControlFile(str(path / "memory.peak"), writable=True),
                       "events": ControlFile(str(path / "memory.events"))}
        self._events0 = 0
        self.reset_peak()

    def cpu_seconds(self) -> float:
        for line in self._files["cpu"].read().splitlines():
            if line.startswith(b"usage_usec "):
                return int(line.split()[1]) / 1e6
        return 0.0

    def peak_memory_mb(self) -> float:
        try:
            return int(self._files["peak"].read(64)) / (1 << 20)
        except PermissionError:  # a memory.peak that cannot be opened for writing: read-only
            self._files["peak"] = ControlFile(str(self.path / "memory.peak"))
            return int(self._files["peak"].read(64)) / (1 << 20)

    def _oom_kills(self) -> int:
        for line in self._files["events"].read().splitlines():
            if line.startswith(b"oom_kill "):
                return int(line.split()[1])
        return 0

    def reset_peak(self) -> None:
        try:  # writing resets the peak on Linux >= 6.12
            self._files["peak"].write(b"0")
        except OSError:
            pass
        self._events0 = self._oom_kills()

    def memory_limit_hit(self) -> bool:
        return self._oom_kills() > self._events0

    def close(self) -> None:
        super().close()
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
        return self._cpu(self._pids())

    def usage(self, fallback: int = 0) -> tuple[float, float]:
        """As :meth:`Group.usage`, from one walk of the processes."""
        pids = self._pids()
        return self._cpu(pids), self.runqueue_seconds(pids or ([fallback] if fallback else []))

    def _cpu(self, pids: list[int]) -> float:
        total = 0.0
        for pid in pids:
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

    def _cpu(self, pids: list[int]) -> float:
        """Each process's own CPU (not ``cutime``: bubblewrap's reaper collects the student's
        process, which would count it twice), as last seen: a process that has exited (a stdio
        run) still counts what it had used at the last sample (samples: :data:`SAMPLE_S`)."""
        for pid in pids:
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


def sandbox_group_name(uid: int) -> str:
    """The accounting group of root's sandbox slot ``uid`` (one at a time: the slot is locked)."""
    return f"grader-sandbox-{uid}"


def existing_group_pids(name: str) -> list[int] | None:
    """The processes in every hierarchy's group ``name`` as :func:`open_group` would make it
    ([] where it does not exist), or None where that cannot be told: not root, no cgroup
    hierarchy that :func:`open_group` would use, a group that cannot be read."""
    if os.geteuid() != 0:
        return None
    try:
        own, mounts = _own_groups(), _mounts()
    except (OSError, ValueError):
        return None
    if all(c in mounts and c in own for c in ("cpuacct", "memory", "pids")):
        dirs = [mounts[c] / own[c].lstrip("/") / name for c in ("cpuacct", "memory", "pids")]
    elif "" in mounts and "" in own:
        dirs = [mounts[""] / own[""].lstrip("/") / name]
    else:
        return None
    pids: list[int] = []
    for d in dirs:
        try:
            pids += [int(x) for x in _read(d / "cgroup.procs").split()]
        except FileNotFoundError:
            continue
        except (OSError, ValueError):
            return None
    return pids


def nothing_left(group: Group | None, uid: int) -> bool:
    """True when a sweep of root's sandbox uid ``uid`` would find nothing: the kernel cgroup that
    holds the slot's processes (``group``, or before it is opened the one a crashed grader would
    have left; none of them can leave it, whatever its ``/proc`` entry shows) lists none, read
    afresh, and no process of the uid is alive or is our unreaped child. False where there is no
    such cgroup (``proc-uid``) or it cannot be read: then the sweep runs."""
    if group is not None:
        held = group.held() if group.mechanism.startswith("cgroup") else None
    else:
        held = existing_group_pids(sandbox_group_name(uid))
    if held is None or held:
        return False
    me = os.getpid()
    return not any(alive(p) or parent(p) == me for p in uid_processes(uid))


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
