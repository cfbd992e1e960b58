"""Process isolation for untrusted student code (the grader's jail).

A :class:`Sandbox` starts child processes that run student code with:

* resource limits (CPU time, address space, file size, open files, processes, no core files);
* a new session/process group, killed as a whole on timeout;
* when the grader is root: a private mount namespace in which the checkout, ``/root``, ``/home``
  and any extra hidden paths are covered by empty tmpfs (only the Python installation is bound
  back), forbidden packages are covered too, ``/tmp`` is a small private tmpfs, a network
  namespace without interfaces, and a dedicated unprivileged uid/gid per concurrent sandbox (so
  RLIMIT_NPROC binds and every leftover process can be killed with ``kill(-1)`` as that uid);
* when the grader is not root: a new user+network namespace where the kernel allows it, an empty
  temporary working directory, and the same rlimits (documented as weaker in grader/README.md).

Run ``python -m grader.sandbox`` to print what this machine supports.

Example:
    >>> with Sandbox(Limits(cpu_s=2, memory_mb=512)) as box:   # doctest: +SKIP
    ...     proc = box.spawn([sys.executable, "-I", "-c", "print(1)"], stdout=out_fd)
"""

from __future__ import annotations

import ctypes
import ctypes.util
import fcntl
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

CLONE_NEWNS = 0x00020000
CLONE_NEWUTS = 0x04000000
CLONE_NEWIPC = 0x08000000
CLONE_NEWUSER = 0x10000000
CLONE_NEWNET = 0x40000000
MS_NOSUID, MS_NODEV, MS_REMOUNT, MS_BIND, MS_REC, MS_PRIVATE = 2, 4, 32, 4096, 16384, 1 << 18
MS_RDONLY, MS_MOVE = 1, 8192

#: First uid/gid of the pool of dedicated sandbox users (root mode); one per concurrent sandbox.
UID_BASE = 62000
UID_COUNT = 512
LOCK_DIR = Path(tempfile.gettempdir()) / "grader-sandbox-uids"
#: Never covered even if asked (e.g. a results file in the current directory "/").
SYSTEM_DIRS = frozenset({"/", "/usr", "/lib", "/lib64", "/bin", "/sbin", "/etc", "/proc", "/dev", "/sys", "/var",
                         "/tmp", "/run", "/opt"})
#: Path of the child's private working directory inside its mount namespace (root mode).
JAIL_WORKDIR = "/tmp/work"

_libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
_libc.mount.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_ulong, ctypes.c_char_p]
_libc.unshare.argtypes = [ctypes.c_int]


@dataclass(frozen=True)
class Limits:
    """Resource limits for one child process.

    Example:
        >>> Limits(cpu_s=1.0, memory_mb=256).memory_mb
        256
    """

    cpu_s: float = 2.0  #: RLIMIT_CPU (whole process life), seconds; wall time is the runner's job
    memory_mb: int = 1024  #: RLIMIT_AS, MiB
    output_mb: int = 16  #: RLIMIT_FSIZE: largest file (stdout/stderr captures too), MiB
    open_files: int = 64  #: RLIMIT_NOFILE
    processes: int = 16  #: RLIMIT_NPROC (threads count too), binding because of the uid drop
    disk_mb: int = 32  #: size of the private /tmp (root mode)


def is_root() -> bool:
    """True when the grader runs with uid 0 (then children get a dedicated uid)."""
    return os.geteuid() == 0


def _mount(src: str | None, target: str, fstype: str | None, flags: int, data: str | None = None) -> None:
    enc = lambda s: None if s is None else s.encode()  # noqa: E731
    if _libc.mount(enc(src), enc(target), enc(fstype), flags, enc(data)) != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"mount {target}: {os.strerror(err)}")


def _unshare(flags: int) -> bool:
    return _libc.unshare(flags) == 0


def _under(path: str, root: str) -> bool:
    return path == root or path.startswith(root.rstrip("/") + "/")


def python_roots() -> list[str]:
    """Directories the child interpreter needs to read (installation prefixes, realpaths)."""
    roots = {os.path.realpath(p) for p in (sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix)}
    roots.add(os.path.realpath(os.path.dirname(sys.executable)))
    return sorted(r for r in roots if os.path.isdir(r))


@dataclass
class _Plan:
    """What the root-mode preexec does, computed in the parent before fork."""

    hide: list[str]
    expose: list[str]  # paths re-bound under a hidden path
    staging: str  # an existing directory, outside every hidden path, used while re-binding
    cover: list[str]  # forbidden package dirs/files covered by empty tmpfs or /dev/null
    disk_mb: int


class Sandbox:
    """A reusable jail slot: one uid (root mode), one private directory for the parent's files.

    ``hide`` lists extra host paths the child must not see (submissions, results, caches);
    ``cover`` lists installed forbidden packages (directories or files) to make unreadable.
    """

    def __init__(self, limits: Limits, hide: Sequence[str | os.PathLike] = (), cover: Sequence[str] = ()):
        self.limits = limits
        self.root_mode = is_root()
        self.uid: int | None = None
        self._lock_fd: int | None = None
        self.private_dir = ""  # parent-only files (captured output, inputs)
        self.host_workdir = ""  # non-root mode: the child's working directory
        repo = str(Path(__file__).resolve().parent.parent)
        hidden = {"/root", "/home", repo, *(os.path.realpath(p) for p in hide)}
        self._hidden = sorted(h for h in hidden if os.path.isdir(h) and h not in SYSTEM_DIRS)
        self._cover = sorted({os.path.realpath(c) for c in cover if os.path.exists(c)})
        self._plan: _Plan | None = None

    # -- lifecycle -------------------------------------------------------------------------
    def __enter__(self) -> "Sandbox":
        self.private_dir = tempfile.mkdtemp(prefix="grader-private-")
        os.chmod(self.private_dir, 0o700)
        if self.root_mode:
            self._acquire_uid()
            self.kill_all()  # leftovers from a crashed grader
            self._plan = self._make_plan()
        else:
            self.host_workdir = tempfile.mkdtemp(prefix="grader-work-")
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        """Kill every process of the slot and delete its files."""
        self.kill_all()
        for d in (self.private_dir, self.host_workdir):
            if d:
                shutil.rmtree(d, ignore_errors=True)
        if self._lock_fd is not None:
            os.close(self._lock_fd)
            self._lock_fd = None

    def _acquire_uid(self) -> None:
        LOCK_DIR.mkdir(mode=0o700, exist_ok=True)
        start = os.getpid() % UID_COUNT
        for k in range(UID_COUNT):
            uid = UID_BASE + (start + k) % UID_COUNT
            fd = os.open(LOCK_DIR / f"{uid}.lock", os.O_RDWR | os.O_CREAT, 0o600)
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                os.close(fd)
                continue
            self.uid, self._lock_fd = uid, fd
            return
        raise RuntimeError("no free sandbox uid (too many concurrent sandboxes)")

    def _make_plan(self) -> _Plan:
        hide = [h for h in self._hidden if not any(h != o and _under(h, o) for o in self._hidden)]
        # the interpreter may live under a hidden path or under /tmp (a checkout cloned there):
        # either way it is bound back into the child's view
        roots = [r for r in python_roots() if any(_under(r, h) for h in [*hide, "/tmp"])]
        expose = [r for r in roots if not any(r != o and _under(r, o) for o in roots)]
        return _Plan(hide, expose, self.private_dir, self._cover, self.limits.disk_mb)

    # -- children --------------------------------------------------------------------------
    @property
    def child_workdir(self) -> str:
        """The working directory as the child sees it."""
        return JAIL_WORKDIR if self.root_mode else self.host_workdir

    def child_env(self) -> dict[str, str]:
        """The scrubbed environment given to children."""
        home = self.child_workdir
        return {
            "PATH": "/usr/local/bin:/usr/bin:/bin", "HOME": home, "TMPDIR": home, "LANG": "C.UTF-8",
            "LC_ALL": "C.UTF-8", "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1",
            "MKL_NUM_THREADS": "1", "NUMEXPR_NUM_THREADS": "1", "PYTHONDONTWRITEBYTECODE": "1",
            "PYTHONHASHSEED": "0", "MPLBACKEND": "Agg",
        }

    def spawn(self, argv: Sequence[str], stdin: int, stdout: int, stderr: int,
              pass_fds: Sequence[int] = (), cpu_s: float | None = None) -> subprocess.Popen:
        """Start ``argv`` jailed; ``cpu_s`` overrides the RLIMIT_CPU of ``self.limits``."""
        cpu = int(cpu_s if cpu_s is not None else self.limits.cpu_s) + 1
        plan, uid, lim = self._plan, self.uid, self.limits

        def preexec() -> None:  # runs in the forked child, before exec
            os.setsid()
            if plan is not None:
                _jail_filesystem(plan, uid)
            else:
                _unshare(CLONE_NEWUSER | CLONE_NEWNET)  # best effort
            for res, val in ((resource.RLIMIT_CPU, cpu), (resource.RLIMIT_AS, lim.memory_mb << 20),
                             (resource.RLIMIT_FSIZE, lim.output_mb << 20), (resource.RLIMIT_NOFILE, lim.open_files),
                             (resource.RLIMIT_CORE, 0), (resource.RLIMIT_NPROC, lim.processes)):
                resource.setrlimit(res, (val, val))
            if uid is not None:
                os.setgroups([])
                os.setresgid(uid, uid, uid)
                os.setresuid(uid, uid, uid)
            os.chdir(JAIL_WORKDIR if plan is not None else self.host_workdir)

        return subprocess.Popen(list(argv), stdin=stdin, stdout=stdout, stderr=stderr, pass_fds=tuple(pass_fds),
                                close_fds=True, env=self.child_env(), cwd="/", preexec_fn=preexec)

    def kill_all(self, wait_s: float = 5.0) -> None:
        """SIGKILL every process of this slot's uid (root mode) and wait until all are gone
        (reaped), so the next run starts with a clean RLIMIT_NPROC count."""
        if self.uid is None:
            return
        deadline = time.monotonic() + wait_s
        while True:
            self._kill_uid()
            if not uid_processes(self.uid) or time.monotonic() > deadline:
                return
            time.sleep(0.01)

    def _kill_uid(self) -> None:
        pid = os.fork()
        if pid == 0:  # pragma: no cover - child
            try:
                os.setresgid(self.uid, self.uid, self.uid)
                os.setresuid(self.uid, self.uid, self.uid)
                for _ in range(3):
                    os.kill(-1, signal.SIGKILL)
            except OSError:
                pass
            os._exit(0)
        os.waitpid(pid, 0)


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


def _jail_filesystem(plan: _Plan, uid: int | None) -> None:
    """Child side of root mode: new mount/net/ipc/uts namespaces and the filesystem view."""
    if not _unshare(CLONE_NEWNS | CLONE_NEWNET | CLONE_NEWIPC | CLONE_NEWUTS):
        raise OSError(ctypes.get_errno(), "unshare failed")
    _mount(None, "/", None, MS_REC | MS_PRIVATE)
    # Bind what must stay visible to a staging tmpfs, cover the hidden paths, move the binds back.
    _mount("tmpfs", plan.staging, "tmpfs", MS_NOSUID | MS_NODEV, "mode=700,size=4k")
    staged = []
    for i, path in enumerate(plan.expose):
        st = os.path.join(plan.staging, str(i))
        os.mkdir(st)
        _mount(path, st, None, MS_BIND | MS_REC)
        staged.append(st)
    for h in plan.hide:
        _mount("tmpfs", h, "tmpfs", MS_NOSUID | MS_NODEV, "mode=755,size=1m")
    # The child's private /tmp is prepared inside the staging area (which itself lives under
    # the host's /tmp), so that exposed paths under /tmp can be moved into it first.
    new_tmp = os.path.join(plan.staging, "tmp")
    os.mkdir(new_tmp)
    _mount("tmpfs", new_tmp, "tmpfs", MS_NOSUID | MS_NODEV, f"mode=1777,size={plan.disk_mb}m")
    for st, path in zip(staged, plan.expose):
        target = os.path.join(new_tmp, os.path.relpath(path, "/tmp")) if _under(path, "/tmp") else path
        os.makedirs(target, exist_ok=True)
        _mount(st, target, None, MS_MOVE)
    _mount(new_tmp, "/tmp", None, MS_MOVE)
    for c in plan.cover:  # after the move: a covered package may live under /tmp too
        if os.path.isdir(c):
            _mount("tmpfs", c, "tmpfs", MS_NOSUID | MS_NODEV, "mode=755,size=4k")
        else:
            _mount("/dev/null", c, None, MS_BIND)
    for d in ("/dev/shm", "/var/tmp"):
        if os.path.isdir(d):
            _mount("tmpfs", d, "tmpfs", MS_NOSUID | MS_NODEV, f"mode=1777,size={plan.disk_mb}m")
    os.mkdir(JAIL_WORKDIR, 0o700)
    if uid is not None:
        os.chown(JAIL_WORKDIR, uid, uid)


def describe() -> str:
    """One paragraph on what isolation this machine gives (``python -m grader.sandbox``)."""
    if is_root():
        return ("root: dedicated uid per sandbox, private mount/net/ipc namespaces, hidden checkout, "
                "private /tmp, rlimits")
    pid = os.fork()
    if pid == 0:  # pragma: no cover
        os._exit(0 if _unshare(CLONE_NEWUSER | CLONE_NEWNET) else 1)
    _, status = os.waitpid(pid, 0)
    net = "network namespace" if os.waitstatus_to_exitcode(status) == 0 else "NO network isolation"
    return f"not root: {net}, rlimits, temporary working directory (no uid drop: see grader/README.md)"


if __name__ == "__main__":
    print(describe())
