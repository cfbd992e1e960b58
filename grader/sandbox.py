"""Process isolation for untrusted student code (the grader's jail).

A :class:`Sandbox` starts child processes that run student code with:

* resource limits (CPU time, address space, file size, open files, processes, no core files);
* a new session/process group, killed as a whole on timeout;
* when the grader is root, one of two jails (:func:`jail_kind`), both with a dedicated
  unprivileged uid/gid per concurrent sandbox (so RLIMIT_NPROC binds and every leftover
  process can be killed with ``kill(-1)`` as that uid), ``PR_SET_NO_NEW_PRIVS`` (setuid
  binaries run without privileges) and the seccomp filter of :mod:`grader.seccomp`:

  - ``bwrap`` (Debian's bubblewrap, preferred): an allow-list by construction: a new root
    holding only ``/usr`` (and the ``/bin``, ``/lib*`` links), a few ``/etc`` files the dynamic
    loader needs, the Python installations (read-only), a fresh ``/proc`` and minimal ``/dev``,
    and a private size-limited ``/tmp`` with the working directory; new user, pid, network,
    IPC, UTS and cgroup namespaces; dies with the grader;
  - ``namespaces`` (fallback where bubblewrap is missing or cannot create a user namespace):
    a private mount namespace in which every top-level directory except the system ones
    (``/usr``, ``/lib*``, ``/bin``, ``/sbin``, ``/etc``, ``/proc``, ``/dev``, ``/sys``) and any
    extra hidden path is covered by an empty, root-owned tmpfs (the Python installation is
    bound back), ``/tmp`` private, network/IPC/UTS namespaces;

  in both, every installed copy of the forbidden packages and engines
  (:func:`grader.engines.cover_paths`) is covered, and the whole sandbox is charged for CPU,
  memory and processes through a cgroup (:mod:`grader.cgroups`);
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
import functools
import json
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Sequence

from . import cgroups, engines, seccomp
from .fontcache import matplotlib_fontlist

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
#: Top-level directories the fallback jail leaves visible; every other one is covered.
KEPT_TOP_LEVEL = frozenset({"/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/etc", "/proc",
                            "/dev", "/sys", "/tmp"})
#: The only /etc entries the bubblewrap jail shows (dynamic loader, time zone, alternatives links).
ETC_ALLOWED = ("/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/localtime", "/etc/alternatives")
#: Path of the child's private working directory inside its mount namespace (root mode).
JAIL_WORKDIR = "/tmp/work"
#: Matplotlib's configuration directory inside the working directory (holds a pre-built font cache).
MPL_DIR = JAIL_WORKDIR + "/.matplotlib"
#: ``GRADER_JAIL=namespaces`` forces the fallback jail (tests of both jails); ``bwrap`` requires bubblewrap.
JAIL_ENV = "GRADER_JAIL"
#: Address space allowed beyond the memory limit when a cgroup bounds the real memory (MiB).
ADDRESS_HEADROOM_MB = 1024
#: Processes a bubblewrap jail adds to the student's: its monitor and its pid-1 reaper, plus room
#: for reapers of earlier runs: bubblewrap's monitor exits without reaping its reaper, which the
#: host's init then reaps within about a second (a dead zombie meanwhile, still counted).
BWRAP_PROCESSES = 2 + 8

_libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
_libc.mount.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_ulong, ctypes.c_char_p]
_libc.unshare.argtypes = [ctypes.c_int]
_bwrap_works: dict[str, bool] = {}
_last_mechanism = ""


@dataclass(frozen=True)
class Limits:
    """Resource limits for one child process.

    Example:
        >>> Limits(cpu_s=1.0, memory_mb=256).memory_mb
        256
    """

    cpu_s: float = 2.0  #: RLIMIT_CPU (whole process life), seconds; wall time is the runner's job
    memory_mb: int = 1024  #: RLIMIT_AS per process, and the memory (RSS) of the whole sandbox (cgroup), MiB
    output_mb: int = 16  #: RLIMIT_FSIZE: largest file (stdout/stderr captures too), MiB
    open_files: int = 64  #: RLIMIT_NOFILE
    processes: int = 16  #: RLIMIT_NPROC (threads count too), binding because of the uid drop; cgroup pids.max
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


def _outermost(paths: Sequence[str]) -> list[str]:
    return [p for p in paths if not any(p != o and _under(p, o) for o in paths)]


@functools.lru_cache(maxsize=32)
def _expand_cover(cover: tuple[str, ...]) -> tuple[list[str], list[str]]:
    """(forbidden module names, paths to cover) for the installed paths a judge asks to cover:
    every other installed copy and the engines they wrap are added, and wrappers that allowed
    libraries import (``matplotlib/tri``) are left readable. Cached: it scans site directories."""
    given = sorted({os.path.realpath(c) for c in cover if os.path.exists(c)})
    modules = engines.modules_of(given)
    wrappers = {p for p in given if set(engines.modules_of([p])) & set(engines.IMPORTED_BY_LIBRARIES)}
    return modules, _outermost(sorted((set(given) - wrappers) | set(engines.cover_paths(modules))))


def bwrap_path() -> str | None:
    """The bubblewrap binary, if installed."""
    return shutil.which("bwrap", path="/usr/bin:/bin:/usr/local/bin")


def jail_kind(uid: int | None = None) -> str:
    """``bwrap``, ``namespaces`` (root without a working bubblewrap) or ``rlimits`` (not root).

    Example:
        >>> jail_kind() in ("bwrap", "namespaces", "rlimits")
        True
    """
    if not is_root():
        return "rlimits"
    wanted = os.environ.get(JAIL_ENV, "")
    if wanted == "namespaces":
        return "namespaces"
    path = bwrap_path()
    if path is None:
        if wanted == "bwrap":
            raise RuntimeError(f"{JAIL_ENV}=bwrap but bubblewrap is not installed (apt-get install bubblewrap)")
        return "namespaces"
    if path not in _bwrap_works:
        _bwrap_works[path] = _probe_bwrap(path, UID_BASE if uid is None else uid)
    return "bwrap" if _bwrap_works[path] else "namespaces"


def _probe_bwrap(path: str, uid: int) -> bool:
    """Can an unprivileged uid start bubblewrap here (user namespaces enabled)?"""
    def drop() -> None:
        os.setgroups([])
        os.setresgid(uid, uid, uid)
        os.setresuid(uid, uid, uid)
    try:
        r = subprocess.run([path, "--unshare-all", "--ro-bind", "/", "/", "true"], preexec_fn=drop, timeout=30,
                           stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    except (OSError, subprocess.SubprocessError):
        return False
    return r.returncode == 0


def mechanism() -> str:
    """What the last sandbox of this process ran with, e.g. ``bwrap+cgroup-v1+seccomp``."""
    if not _last_mechanism:
        kind = jail_kind()
        return kind if kind == "rlimits" else f"{kind}+seccomp"
    return _last_mechanism


@dataclass
class _Plan:
    """What the root-mode preexec does, computed in the parent before fork."""

    hide: list[str]
    expose: list[str]  # paths re-bound under a hidden path (namespaces) / staged for bubblewrap
    staging: str  # an existing directory, outside every hidden path, used while re-binding
    cover: list[str]  # forbidden package dirs/files covered by empty tmpfs or /dev/null
    disk_mb: int
    fontlist: bytes = b""  # matplotlib font cache written into the work directory (namespaces)
    cgroup_procs: list[str] = field(default_factory=list)  # files the child writes its pid to
    seccomp: bytes | None = None  # installed by the preexec (namespaces) or given to bubblewrap
    bwrap: list[str] = field(default_factory=list)  # bubblewrap's options (empty: the namespaces jail)


class Sandbox:
    """A reusable jail slot: one uid (root mode), one private directory for the parent's files.

    ``hide`` lists extra host paths the child must not see (submissions, results, caches);
    ``cover`` lists installed forbidden packages (directories or files) to make unreadable: every
    other installed copy of the same modules, and the engines they wrap, are covered too.
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
        self.forbidden_modules, self._cover = _expand_cover(tuple(sorted(cover)))
        self._plan: _Plan | None = None
        self.group: cgroups.Group | None = None
        self.kind = "rlimits"
        self.mechanism = "rlimits"

    # -- lifecycle -------------------------------------------------------------------------
    def __enter__(self) -> "Sandbox":
        global _last_mechanism
        self.private_dir = tempfile.mkdtemp(prefix="grader-private-")
        os.chmod(self.private_dir, 0o700)
        if self.root_mode:
            self._acquire_uid()
            self.kill_all()  # leftovers from a crashed grader
            self.kind = jail_kind(self.uid)
            extra = BWRAP_PROCESSES if self.kind == "bwrap" else 0
            self.group = cgroups.open_group(f"grader-sandbox-{self.uid}", self.limits.memory_mb,
                                            self.limits.processes + extra, self.uid)
            self._plan = self._make_plan()
            parts = [self.kind, self.group.mechanism] + (["seccomp"] if self._plan.seccomp else [])
            self.mechanism = "+".join(parts)
        else:
            self.host_workdir = tempfile.mkdtemp(prefix="grader-work-")
            fontlist = matplotlib_fontlist()
            if fontlist:
                os.mkdir(os.path.join(self.host_workdir, ".matplotlib"))
                shutil.copy(fontlist, os.path.join(self.host_workdir, ".matplotlib"))
        _last_mechanism = self.mechanism
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        """Kill every process of the slot and delete its files (and its cgroup)."""
        self.kill_all()
        if self.group is not None:
            self.group.close()
            self.group = None
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
        assert self.group is not None
        fontlist = matplotlib_fontlist()
        prog = seccomp.program()
        if self.kind == "bwrap":
            expose = _outermost(python_roots()) + ([fontlist] if fontlist else [])
            plan = _Plan([], expose, self.private_dir, self._cover, self.limits.disk_mb,
                         cgroup_procs=self.group.procs_files, seccomp=prog)
            plan.bwrap = self._bwrap_options(plan, fontlist)
            return plan
        top = [f"/{d}" for d in os.listdir("/") if os.path.isdir(f"/{d}") and not os.path.islink(f"/{d}")]
        hidden = sorted(set(self._hidden) | {t for t in top if t not in KEPT_TOP_LEVEL})
        hide = _outermost(hidden)
        # the interpreter may live under a hidden path or under /tmp (a checkout cloned there):
        # either way it is bound back into the child's view
        roots = [r for r in python_roots() if any(_under(r, h) for h in [*hide, "/tmp"])]
        font = Path(fontlist).read_bytes() if fontlist else b""
        return _Plan(hide, _outermost(roots), self.private_dir, self._cover, self.limits.disk_mb, font,
                     self.group.procs_files, prog)

    def _bwrap_options(self, plan: _Plan, fontlist: str | None) -> list[str]:
        a = ["--unshare-all", "--unshare-user", "--disable-userns", "--die-with-parent", "--new-session", "--cap-drop", "ALL",
             "--hostname", "sandbox"]
        for d in ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"):
            if os.path.islink(d):
                a += ["--symlink", os.readlink(d), d]
            elif os.path.isdir(d):
                a += ["--ro-bind", d, d]
        for e in ETC_ALLOWED:
            a += ["--ro-bind-try", e, e]
        a += ["--proc", "/proc", "--dev", "/dev",
              "--size", str(plan.disk_mb << 20), "--perms", "1777", "--tmpfs", "/tmp",
              "--perms", "0700", "--dir", JAIL_WORKDIR]
        staged = [os.path.join(plan.staging, str(i)) for i in range(len(plan.expose))]
        for st, path in zip(staged, plan.expose):
            if path != fontlist:
                a += ["--ro-bind", st, path]
        if fontlist:
            a += ["--perms", "0700", "--dir", MPL_DIR,
                  "--ro-bind", staged[-1], f"{MPL_DIR}/{os.path.basename(fontlist)}"]
        bound = ["/usr", *plan.expose]
        for c in plan.cover:
            if not any(_under(c, b) for b in bound):
                continue  # not in the jail at all
            a += ["--tmpfs", c] if os.path.isdir(c) else ["--ro-bind", "/dev/null", c]
        a += ["--chdir", JAIL_WORKDIR]
        return a

    def address_space_mb(self) -> int:
        """RLIMIT_AS of each process: the memory limit itself without a cgroup; with one (which
        bounds the real memory, RSS, of the whole sandbox) the limit plus
        :data:`ADDRESS_HEADROOM_MB`, since libraries map far more than they touch (numpy, scipy
        and matplotlib together do not even load under a 256 MiB address space)."""
        if self.group is not None and self.group.limit_bytes and self.group.mechanism.startswith("cgroup"):
            return self.limits.memory_mb + ADDRESS_HEADROOM_MB
        return self.limits.memory_mb

    def decode_exit(self, code: int) -> int:
        """The student process's exit code as ``waitstatus_to_exitcode`` gives it (negative:
        killed by that signal): bubblewrap reports a death by signal N as exit code 128 + N."""
        if self.kind == "bwrap" and code > 128:
            return -(code - 128)
        return code

    # -- children --------------------------------------------------------------------------
    @property
    def child_workdir(self) -> str:
        """The working directory as the child sees it."""
        return JAIL_WORKDIR if self.root_mode else self.host_workdir

    def child_env(self) -> dict[str, str]:
        """The scrubbed environment given to children."""
        home = self.child_workdir
        env = {
            "PATH": "/usr/local/bin:/usr/bin:/bin", "HOME": home, "TMPDIR": home, "LANG": "C.UTF-8",
            "LC_ALL": "C.UTF-8", "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1",
            "MKL_NUM_THREADS": "1", "NUMEXPR_NUM_THREADS": "1", "PYTHONDONTWRITEBYTECODE": "1",
            "PYTHONHASHSEED": "0", "MPLBACKEND": "Agg",
        }
        env["MPLCONFIGDIR"] = os.path.join(home, ".matplotlib")  # holds the pre-built font cache
        return env

    def spawn(self, argv: Sequence[str], stdin: int, stdout: int, stderr: int,
              pass_fds: Sequence[int] = (), cpu_s: float | None = None) -> subprocess.Popen:
        """Start ``argv`` jailed; ``cpu_s`` overrides the RLIMIT_CPU of ``self.limits``."""
        cpu = int(cpu_s if cpu_s is not None else self.limits.cpu_s) + 1
        plan, uid, lim = self._plan, self.uid, self.limits
        nproc = lim.processes + (BWRAP_PROCESSES if self.kind == "bwrap" else 0)
        address_mb = self.address_space_mb()
        argv, fds, seccomp_fd = list(argv), list(pass_fds), -1
        if plan is not None and plan.bwrap:
            opts = list(plan.bwrap)
            if plan.seccomp:
                seccomp_fd = seccomp.program_fd(plan.seccomp)
                opts += ["--seccomp", str(seccomp_fd)]
                fds.append(seccomp_fd)
            argv = [bwrap_path() or "bwrap", *opts, "--", *argv]

        def preexec() -> None:  # runs in the forked child, before exec
            os.setsid()
            if plan is not None:
                for procs in plan.cgroup_procs:  # join the sandbox's accounting group
                    with open(procs, "w") as f:
                        f.write(str(os.getpid()))
                if plan.bwrap:
                    _stage_for_bwrap(plan)
                else:
                    _jail_filesystem(plan, uid)
            else:
                _unshare(CLONE_NEWUSER | CLONE_NEWNET)  # best effort
            for res, val in ((resource.RLIMIT_CPU, cpu), (resource.RLIMIT_AS, address_mb << 20),
                             (resource.RLIMIT_FSIZE, lim.output_mb << 20), (resource.RLIMIT_NOFILE, lim.open_files),
                             (resource.RLIMIT_CORE, 0), (resource.RLIMIT_NPROC, nproc)):
                resource.setrlimit(res, (val, val))
            if uid is not None:
                os.setgroups([])
                os.setresgid(uid, uid, uid)
                os.setresuid(uid, uid, uid)
            if plan is not None and not plan.bwrap:
                os.chdir(JAIL_WORKDIR)
                if plan.seccomp:
                    seccomp.install(plan.seccomp)  # also sets NO_NEW_PRIVS
            elif plan is None:
                os.chdir(self.host_workdir)

        try:
            return subprocess.Popen(argv, stdin=stdin, stdout=stdout, stderr=stderr, pass_fds=tuple(fds),
                                    close_fds=True, env=self.child_env(), cwd="/", preexec_fn=preexec)
        finally:
            if seccomp_fd >= 0:
                os.close(seccomp_fd)

    def terminate(self, pid: int) -> None:
        """SIGKILL a child started by :meth:`spawn` and everything it started. For bubblewrap,
        its pid-1 reaper goes first: the kernel then kills and reaps the whole pid namespace and
        bubblewrap exits by itself, so no zombie is left to the host's init (which reaps slowly,
        about a second here, holding RLIMIT_NPROC slots meanwhile)."""
        reapers = _children(pid) if self.kind == "bwrap" else []
        for child in reapers:
            try:
                os.kill(child, signal.SIGKILL)
            except OSError:
                pass
        deadline = time.monotonic() + 1.0
        while reapers and time.monotonic() < deadline and _alive(pid):
            time.sleep(0.002)
        try:
            os.killpg(pid, signal.SIGKILL)
        except OSError:
            pass

    def kill_all(self, wait_s: float = 5.0) -> None:
        """SIGKILL every process of this slot's uid (root mode) and wait until all are gone
        (reaped), so the next run starts with a clean RLIMIT_NPROC count."""
        if self.uid is None:
            return
        deadline = time.monotonic() + wait_s
        me = os.getpid()
        while True:
            self._kill_uid()
            # done when nothing runs: zombies left to the host's init (bubblewrap's reapers) are
            # dead and hold no resources; our own zombie children are reaped by our wait4
            left = [p for p in uid_processes(self.uid) if _alive(p) or _parent(p) == me]
            if not left or time.monotonic() > deadline:
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


def _children(pid: int) -> list[int]:
    try:
        with open(f"/proc/{pid}/task/{pid}/children") as f:
            return [int(c) for c in f.read().split()]
    except (OSError, ValueError):
        return []


def _parent(pid: int) -> int:
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            return int(f.read().rsplit(b")", 1)[1].split()[1])
    except (OSError, IndexError, ValueError):
        return 0


def _alive(pid: int) -> bool:
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


def _stage_for_bwrap(plan: _Plan) -> None:
    """Child side, bubblewrap jail, still root: bind the Python installations (which may sit
    under a directory the sandbox uid cannot enter, like ``/root``) to a private staging
    directory that bubblewrap, started as the sandbox uid, can read from."""
    if not _unshare(CLONE_NEWNS):
        raise OSError(ctypes.get_errno(), "unshare failed")
    _mount(None, "/", None, MS_REC | MS_PRIVATE)
    _mount("tmpfs", plan.staging, "tmpfs", MS_NOSUID | MS_NODEV, "mode=755,size=16k")
    for i, path in enumerate(plan.expose):
        st = os.path.join(plan.staging, str(i))
        if os.path.isdir(path):
            os.mkdir(st)
        else:
            open(st, "w").close()
        _mount(path, st, None, MS_BIND | MS_REC)


def _jail_filesystem(plan: _Plan, uid: int | None) -> None:
    """Child side of the fallback jail: new mount/net/ipc/uts namespaces and the filesystem view."""
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
    for h in plan.hide:  # root-owned and empty: nothing to read, nothing writable (/run/lock...)
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
        elif os.path.exists(c):
            _mount("/dev/null", c, None, MS_BIND)
    if os.path.isdir("/dev/shm"):
        _mount("tmpfs", "/dev/shm", "tmpfs", MS_NOSUID | MS_NODEV, f"mode=1777,size={plan.disk_mb}m")
    os.mkdir(JAIL_WORKDIR, 0o700)
    if plan.fontlist:
        os.mkdir(MPL_DIR, 0o700)
        with open(os.path.join(MPL_DIR, f"fontlist-v{json.loads(plan.fontlist).get('_version', 0)}.json"), "wb") as f:
            f.write(plan.fontlist)
    if uid is not None:
        for d in (JAIL_WORKDIR, MPL_DIR):
            if os.path.isdir(d):
                os.chown(d, uid, uid)


def describe() -> str:
    """One paragraph on what isolation this machine gives (``python -m grader.sandbox``)."""
    if is_root():
        kind = jail_kind()
        group = cgroups.open_group(f"grader-probe-{os.getpid()}", 64, 8, None)
        acct = group.mechanism
        group.close()
        sec = "seccomp filter" if seccomp.program() else "no seccomp (unsupported architecture)"
        jail = ("bubblewrap allow-list jail (user/pid/net/ipc/uts/cgroup namespaces)" if kind == "bwrap" else
                "hand-written namespace jail (top-level directories covered)")
        return (f"root: {kind}+{acct}: {jail}, dedicated uid per sandbox, NO_NEW_PRIVS, {sec}, "
                f"whole-sandbox accounting by {acct}, private /tmp, rlimits")
    pid = os.fork()
    if pid == 0:  # pragma: no cover
        os._exit(0 if _unshare(CLONE_NEWUSER | CLONE_NEWNET) else 1)
    _, status = os.waitpid(pid, 0)
    net = "network namespace" if os.waitstatus_to_exitcode(status) == 0 else "NO network isolation"
    return f"not root: {net}, rlimits, temporary working directory (no uid drop: see grader/README.md)"


if __name__ == "__main__":
    print(describe())
