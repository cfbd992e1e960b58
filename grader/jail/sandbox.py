"""Process isolation for untrusted student code (the grader's jail).

A :class:`Sandbox` starts child processes that run student code with resource limits (CPU time,
address space, file size, open files, processes, no core files), in a new session killed as a
whole on timeout, inside a kernel jail chosen by :func:`jail_kind`:

* **root**, one of two jails, both with a dedicated unprivileged uid/gid per concurrent sandbox
  (so RLIMIT_NPROC binds and every leftover process can be killed with ``kill(-1)`` as that
  uid), ``PR_SET_NO_NEW_PRIVS`` and the seccomp filter of :mod:`grader.jail.seccomp`, the whole
  sandbox charged for CPU, memory and processes through a cgroup (:mod:`grader.jail.cgroups`):

  - ``bwrap`` (Debian's bubblewrap, preferred): an allow-list by construction: a new root
    holding only ``/usr`` (and the ``/bin``, ``/lib*`` links), a few ``/etc`` files the dynamic
    loader needs, the Python installations (read-only), a fresh ``/proc`` and minimal ``/dev``
    (read-only), a private sized ``/dev/shm`` and a private sized ``/tmp`` with the working
    directory; new user, pid, network, IPC, UTS and cgroup namespaces; dies with the grader;
  - ``namespaces`` (fallback where bubblewrap is missing or cannot create a user namespace):
    a private mount namespace in which every top-level directory except the system ones and any
    extra hidden path is covered by an empty, root-owned tmpfs (:mod:`grader.jail.mounts`), with
    a private sized ``/tmp`` and ``/dev/shm``;

* **an ordinary user** (an instructor's account): the same ``bwrap`` allow-list jail, started
  by that user (bubblewrap needs only unprivileged user namespaces), with a seccomp filter that
  also refuses new processes (there is no cgroup to charge forked helpers to, so the one student
  process's RLIMIT_CPU and RLIMIT_AS are the whole sandbox's), RLIMIT_NPROC set inside the
  sandbox's user namespace (it counts the sandbox's threads, not the user's other processes),
  accounting summed over the sandbox's process tree (``proc-tree``);
* **no kernel jail** for this user (bubblewrap missing, user namespaces disabled): grading
  refuses with :class:`JailUnavailable`, whose message names the fixes, unless the caller asked
  for the **trusted** mode (``trusted=True``, ``GRADER_TRUSTED=1``, ``judge --trusted``: a student
  checking their own code): rlimits and a temporary working directory only.

In every jail the only writable mounts are ``/tmp`` and ``/dev/shm``: tmpfs (RAM) sized within the
memory limit (:mod:`grader.jail.tmpfs`; bubblewrap's own root, its ``/dev`` and every covering
tmpfs are remounted read-only). As root the cgroup charges their files; an ordinary account's
RLIMIT_AS is the memory limit minus their sizes. What a submission keeps there is sampled
(:meth:`Sandbox.sample_files`): a filled one is an MLE.

In every jail all installed copies of the forbidden packages and engines
(:func:`grader.jail.engines.cover_paths`) are covered and the paths in ``hide`` are hidden
wherever they are (under ``/usr`` too).

Run ``python -m grader.sandbox`` (or ``python -m grader.jail``) for what this machine gives to
root and to this user (:mod:`grader.jail.doctor`).

Example:
    >>> with Sandbox(Limits(cpu_s=2, memory_mb=512)) as box:   # doctest: +SKIP
    ...     proc = box.spawn([sys.executable, "-I", "-c", "print(1)"], stdout=out_fd)
"""

from __future__ import annotations

import functools
import os
import resource
import shutil
import signal
import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

from . import cgroups, engines, launcher, profiles, seccomp, uidpool
from .bwrap_probe import bwrap_path, bwrap_status
from .errors import JailUnavailable
from .fontcache import matplotlib_fontlist
from .mounts import CLONE_NEWNET, CLONE_NEWUSER, JAIL_WORKDIR, MPL_DIR, Plan, jail_filesystem, stage_for_bwrap, unshare
from .paths import outermost, python_roots, under
from .procs import alive, children, parent, uid_processes
from . import tmpfs

__all__ = ["Limits", "Sandbox", "JailUnavailable", "jail_kind", "mechanism", "is_root", "bwrap_path", "python_roots",
           "uid_processes", "refusal_message", "refuses_processes", "require_jail", "JAIL_ENV", "TRUSTED_ENV", "LOCK_DIR", "JAIL_WORKDIR", "UID_BASE"]

#: The pool of dedicated sandbox uids (root mode) and its lock folder: :mod:`grader.jail.uidpool`.
UID_BASE, UID_COUNT, LOCK_DIR = uidpool.UID_BASE, uidpool.UID_COUNT, uidpool.LOCK_DIR
#: Never covered even if asked (e.g. a results file in the current directory "/").
SYSTEM_DIRS = frozenset({"/", "/usr", "/lib", "/lib64", "/bin", "/sbin", "/etc", "/proc", "/dev", "/sys", "/var",
                         "/tmp", "/run", "/opt"})
#: Top-level directories the fallback jail leaves visible; every other one is covered.
KEPT_TOP_LEVEL = frozenset({"/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/etc", "/proc",
                            "/dev", "/sys", "/tmp"})
#: The only /etc entries the bubblewrap jail shows (dynamic loader, time zone, alternatives links).
ETC_ALLOWED = ("/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/localtime", "/etc/alternatives")
#: ``GRADER_JAIL=namespaces`` forces root's fallback jail (tests of both jails), ``bwrap`` requires
#: bubblewrap; ``none`` behaves as a machine without user namespaces (not root: grading refuses).
JAIL_ENV = "GRADER_JAIL"
#: ``GRADER_TRUSTED=1``: where no kernel jail can be built, run without one (a student's own code).
TRUSTED_ENV = "GRADER_TRUSTED"
#: Address space allowed beyond the memory limit when a cgroup bounds the real memory (MiB).
ADDRESS_HEADROOM_MB = 1024
#: Processes a bubblewrap jail adds: its monitor and pid-1 reaper, plus room for the zombie reapers
#: of earlier jails, which the host's init reaps late (every 2 s here). Only compiles have a reaper:
#: a run's submission is pid 1 (``--as-pid-1``), else many 40 ms tests filled this ("Can't fork").
BWRAP_PROCESSES = 2 + 8
#: Not root: processes of the sandbox's user namespace besides the student's threads (the
#: pid-1 reaper), added to the RLIMIT_NPROC set inside it.
USERNS_EXTRA = 1
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
    disk_mb: int = 32  #: size of the private /tmp, at most an eighth of ``memory_mb`` (:func:`tmpfs.sizes`)
    shm_mb: int = 8  #: size of the private /dev/shm, at most an eighth of ``memory_mb``


def is_root() -> bool:
    """True when the grader runs with uid 0 (then children get a dedicated uid)."""
    return os.geteuid() == 0


@functools.lru_cache(maxsize=32)
def _expand_cover(cover: tuple[str, ...]) -> tuple[list[str], list[str]]:
    """(forbidden module names, paths to cover) for the installed paths a judge asks to cover:
    every other installed copy and the engines they wrap are added, and wrappers that allowed
    libraries import (``matplotlib/tri``) are left readable. Cached: it scans site directories."""
    given = sorted({os.path.realpath(c) for c in cover if os.path.exists(c)})
    modules = engines.modules_of(given)
    wrappers = {p for p in given if set(engines.modules_of([p])) & set(engines.IMPORTED_BY_LIBRARIES)}
    return modules, outermost(sorted((set(given) - wrappers) | set(engines.cover_paths(modules))))


def jail_kind(uid: int | None = None) -> str:
    """The jail this process can build: ``bwrap`` or ``namespaces`` (root without a working
    bubblewrap) as root; ``bwrap`` or ``none`` (no kernel jail: grading refuses) otherwise.

    Example:
        >>> jail_kind() in ("bwrap", "namespaces", "none")
        True
    """
    wanted = os.environ.get(JAIL_ENV, "")
    if not is_root():
        return "bwrap" if wanted != "none" and bwrap_status(None)[0] else "none"
    if wanted == "namespaces":
        return "namespaces"
    if bwrap_path() is None:
        if wanted == "bwrap":
            raise RuntimeError(f"{JAIL_ENV}=bwrap but bubblewrap is not installed (apt-get install bubblewrap)")
        return "namespaces"
    return "bwrap" if bwrap_status(UID_BASE if uid is None else uid)[0] else "namespaces"


def refusal_message(reason: str) -> str:
    """Why grading refuses for this user, and the fixes (the text of :class:`JailUnavailable`)."""
    return (f"no kernel jail can be built for this user (uid {os.getuid()}): {reason}. Student code is not run "
            "without one. Fixes: install bubblewrap (apt-get install bubblewrap); allow unprivileged user "
            "namespaces (sysctl user.max_user_namespaces=15000, kernel.unprivileged_userns_clone=1, and on "
            "Ubuntu kernel.apparmor_restrict_unprivileged_userns=0); or grade as root. A student checking their "
            f"own code may judge it without a jail in the trusted mode (--trusted or {TRUSTED_ENV}=1). "
            "'python -m grader.sandbox' says what this machine gives.")


def require_jail() -> None:
    """Raise :class:`JailUnavailable` unless this process can build a kernel jail (class grading
    checks this before it starts, instead of failing once per student). Root: raises
    :class:`grader.jail.errors.UnsafeSharedState` when the folder of its uid locks is not root's
    alone (:func:`grader.jail.uidpool.check_lock_dir`)."""
    if is_root():
        uidpool.check_lock_dir()
    elif jail_kind() == "none":
        why = ("user namespaces are disabled here (GRADER_JAIL=none)" if os.environ.get(JAIL_ENV) == "none"
               else bwrap_status(None)[1])
        raise JailUnavailable(refusal_message(why))


def refuses_processes() -> bool:
    """True when this process's sandboxes refuse new processes (an ordinary user's jail)."""
    return not is_root() and jail_kind() == "bwrap"


def mechanism() -> str:
    """What the last sandbox of this process ran with, e.g. ``bwrap+cgroup-v1+seccomp``."""
    if not _last_mechanism:
        kind = jail_kind()
        return kind if kind == "none" else f"{kind}+seccomp"
    return _last_mechanism


class Sandbox:
    """A reusable jail slot: one uid (root mode), one private directory for the parent's files.

    ``hide`` lists extra host paths the child must not see (submissions, results, caches);
    ``cover`` lists installed forbidden packages (directories or files) to make unreadable: every
    other installed copy of the same modules, and the engines they wrap, are covered too.
    ``trusted`` (default: ``$GRADER_TRUSTED`` is ``1``) allows running without a kernel jail where
    none can be built, instead of raising :class:`JailUnavailable` (a student's own code only).
    ``profile="compile"``: the compile jail (:mod:`grader.jail.profiles`; host folder :attr:`scratch`);
    ``program``: a binary shown read-only in the run jail, started by the C launcher (:attr:`launcher`,
    :mod:`grader.jail.launcher`) or the Python bootstrap; ``no_processes``: the seccomp filter kills
    new processes (default: without a cgroup). Both need bubblewrap (``namespaces`` refuses them).
    """

    def __init__(self, limits: Limits, hide: Sequence[str | os.PathLike] = (), cover: Sequence[str] = (),
                 trusted: bool | None = None, profile: str = "run", program: str | None = None,
                 no_processes: bool | None = None):
        if profile not in ("run", "compile"):
            raise ValueError(f"unknown sandbox profile {profile!r} (run, compile)")
        self.profile, self.program = profile, program
        self.launcher: str | None = None  #: host path of the C launcher of :attr:`program` (None: the bootstrap)
        self.no_processes = (not is_root()) if no_processes is None else no_processes
        if profile == "compile":
            self.no_processes = False
        self.scratch = ""  # compile profile: the host folder the compiler reads and writes
        self.limits = limits
        self.trusted = os.environ.get(TRUSTED_ENV) == "1" if trusted is None else trusted
        self.root_mode = is_root()
        self.uid: int | None = None
        self._slot: uidpool.Slot | None = None
        self.private_dir = ""  # parent-only files (captured output, inputs)
        self.host_workdir = ""  # non-root mode: the child's working directory
        repo = str(Path(__file__).resolve().parent.parent)
        hidden = {"/root", "/home", repo, *(os.path.realpath(p) for p in hide)}
        self._hidden = sorted(h for h in hidden if os.path.isdir(h) and h not in SYSTEM_DIRS)
        self.forbidden_modules, self._cover = _expand_cover(tuple(sorted(cover)))
        self._plan: Plan | None = None
        self.group: cgroups.Group | None = None
        self.kind = "none"
        self.mechanism = "none"
        #: what the submission keeps in the jail's tmpfs mounts (sampled by the runner)
        self.files = tmpfs.FileUse(tmpfs.sizes(limits))
        self._inner = (0, 0)  # (a bubblewrap pid, its child inside the jail): see sample_files
        self._swept = False  # kill_all left no process of the uid and nothing was spawned since
        self._attached: dict[str, object] = {}  # what lives as long as the sandbox (see attach)

    # -- lifecycle -------------------------------------------------------------------------
    def __enter__(self) -> "Sandbox":
        global _last_mechanism
        if not self.root_mode:
            self.kind = jail_kind()
            if self.kind == "none" and not self.trusted:
                require_jail()
        self.private_dir = tempfile.mkdtemp(prefix="grader-private-")
        os.chmod(self.private_dir, 0o700)
        self.launcher = launcher.host_path() if self.program and self.profile == "run" else None
        if self.root_mode:
            try:
                self._slot = uidpool.acquire()  # UnsafeSharedState, NoFreeSlot: a one-line refusal
            except BaseException:
                self.close()  # __exit__ is not called when __enter__ raises
                raise
            self.uid = self._slot.uid
            self.kill_all()  # leftovers from a crashed grader
            self.kind = jail_kind(self.uid)
            self._swept = False  # the first jail_kind probes bubblewrap as the uid
            try:
                self._check_profile()
            except BaseException:
                self.close()
                raise
            self._make_scratch()
            extra = BWRAP_PROCESSES if self.kind == "bwrap" else 0
            self.group = cgroups.open_group(cgroups.sandbox_group_name(self.uid), self.limits.memory_mb,
                                            self.limits.processes + extra, self.uid)
            self._plan = self._make_plan()
            parts = [self.kind, self.group.mechanism] + (["seccomp"] if self._plan.seccomp else [])
            self.mechanism = "+".join(parts)
        elif self.kind == "bwrap":  # an ordinary user: the same allow-list, no processes but the student's
            self.group = cgroups.ProcTree(self.limits.memory_mb)
            self._make_scratch()
            self._plan = self._make_plan()
            filt = "seccomp-noproc" if self.no_processes else "seccomp"
            self.mechanism = "+".join(["bwrap", self.group.mechanism] + ([filt] if self._plan.seccomp else []))
        else:
            self.kind = self.mechanism = "trusted"
            self.host_workdir = tempfile.mkdtemp(prefix="grader-work-")
            self.scratch = self.host_workdir if self.profile == "compile" else ""
            fontlist = matplotlib_fontlist()
            if fontlist:
                os.mkdir(os.path.join(self.host_workdir, ".matplotlib"))
                shutil.copy(fontlist, os.path.join(self.host_workdir, ".matplotlib"))
        _last_mechanism = self.mechanism
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _check_profile(self) -> None:
        """The compile jail and a program need bubblewrap (``namespaces`` has no view for them)."""
        if self.kind == "namespaces" and (self.profile == "compile" or self.program):
            raise JailUnavailable("compiling and running a compiled submission need the bubblewrap jail (apt-get "
                                  f"install bubblewrap; {JAIL_ENV}={os.environ.get(JAIL_ENV, '')!r} gives the "
                                  "'namespaces' jail)")

    def _make_scratch(self) -> None:
        """Compile profile: the host folder bound writable into the jail, owned by the sandbox's
        uid (root) or this user, readable by nobody else."""
        if self.profile != "compile":
            return
        self.scratch = tempfile.mkdtemp(prefix="grader-build-")
        if self.uid is not None:
            os.chown(self.scratch, self.uid, self.uid)

    def attach(self, name: str, thing: object | None = None) -> object | None:
        """What was attached under ``name`` (None: nothing); with ``thing``, attach it first. An
        attached object lives as long as the sandbox: its ``close()`` is called first by
        :meth:`close` (a compiled program's server, :mod:`grader.judging.program_server`)."""
        if thing is not None:
            self._attached[name] = thing
        return self._attached.get(name)

    def close(self) -> None:
        """Close what is attached, kill every process of the slot and delete its files (and its cgroup)."""
        for thing in list(self._attached.values()):
            try:
                thing.close()  # type: ignore[attr-defined]
            except OSError:
                pass
        self._attached.clear()
        if not self._swept:  # else the last sweep left none, and none can have started since
            self.kill_all()
        if isinstance(self.group, cgroups.ProcTree):
            for pid in self.group.roots:
                if parent(pid) == os.getpid():  # still our child (not reaped: its pid is not reused)
                    self.terminate(pid)
        if self.group is not None:
            self.group.close()
            self.group = None
        for d in (self.private_dir, self.host_workdir, self.scratch):
            if d:
                shutil.rmtree(d, ignore_errors=True)
        if self._slot is not None:
            self._slot.close()
            self._slot = None

    def _make_plan(self) -> Plan:
        assert self.group is not None
        # a compiled program under the static C launcher needs neither matplotlib's font list nor Python,
        # and a path bound into its /tmp (a checkout under /tmp) would stop /tmp being emptied per test
        fontlist = None if self.program else matplotlib_fontlist()
        prog = seccomp.program(no_processes=self.no_processes)
        if self.kind == "bwrap" and self.profile == "compile":
            staging = self.private_dir if self.root_mode else ""
            plan = Plan([], [self.scratch], staging, [], self.files.mounts["/tmp"],
                        cgroup_procs=self.group.procs_files, seccomp=prog, shm_mb=self.files.mounts["/dev/shm"])
            trees = [d for d in profiles.SYSTEM_TREES if os.path.lexists(d)]
            plan.bwrap = profiles.compile_bwrap_options(trees, os.path.join(staging, "0") if staging else self.scratch,
                                                        plan.disk_mb, self._hidden)
            return plan
        if self.kind == "bwrap":
            pythons = [] if self.program and self.launcher else outermost(python_roots())
            expose = pythons + [p for p in (self.program, self.launcher) if p] \
                + ([fontlist] if fontlist else [])  # the font list last (see _bwrap_options)
            # root stages what bubblewrap (started as the sandbox uid) could not reach; a user binds directly
            plan = Plan([], expose, self.private_dir if self.root_mode else "", self._cover, self.files.mounts["/tmp"],
                        cgroup_procs=self.group.procs_files, seccomp=prog, shm_mb=self.files.mounts["/dev/shm"])
            plan.bwrap = self._bwrap_options(plan, fontlist)
            return plan
        top = [f"/{d}" for d in os.listdir("/") if os.path.isdir(f"/{d}") and not os.path.islink(f"/{d}")]
        hidden = sorted(set(self._hidden) | {t for t in top if t not in KEPT_TOP_LEVEL})
        hide = outermost(hidden)
        # the interpreter may live under a hidden path or under /tmp (a checkout cloned there):
        # either way it is bound back into the child's view
        roots = [r for r in python_roots() if any(under(r, h) for h in [*hide, "/tmp"])]
        font = Path(fontlist).read_bytes() if fontlist else b""
        return Plan(hide, outermost(roots), self.private_dir, self._cover, self.files.mounts["/tmp"], font,
                    self.group.procs_files, prog, shm_mb=self.files.mounts["/dev/shm"])

    def _bwrap_options(self, plan: Plan, fontlist: str | None) -> list[str]:
        """bubblewrap's options: the allow-list (``/usr``, loader files, the Python installations),
        then the hidden paths that lie inside it (a course kept under ``/usr/local``) covered by
        empty tmpfs, then the forbidden engines covered. The only writable mounts are the sized
        ``/tmp`` and ``/dev/shm`` (:func:`tmpfs.sizes`): bubblewrap's ``--dev`` and its new root are
        unsized tmpfs owned by the sandbox's uid, so they and every covering tmpfs are remounted
        read-only once set up (``--size`` applies only to the next ``--tmpfs``)."""
        a = profiles.base_bwrap_options(profiles.SYSTEM_TREES, ETC_ALLOWED)
        a += ["--proc", "/proc", "--dev", "/dev",
              "--size", str(plan.shm_mb << 20), "--perms", "1777", "--tmpfs", "/dev/shm", "--remount-ro", "/dev",
              "--size", str(plan.disk_mb << 20), "--perms", "1777", "--tmpfs", "/tmp",
              "--perms", "0700", "--dir", JAIL_WORKDIR]
        staged = [os.path.join(plan.staging, str(i)) if plan.staging else p for i, p in enumerate(plan.expose)]
        bound = ["/usr", *plan.expose]
        inside = [h for h in self._hidden if any(under(h, b) for b in bound)]
        holds = [h for h in inside if not any(under(h, e) for e in plan.expose)]  # may hold an installation
        for h in holds:
            a += ["--size", "4096", "--perms", "0755", "--tmpfs", h]
        for st, path in zip(staged, plan.expose):
            if path in (self.program, self.launcher):
                a += ["--ro-bind", st, profiles.JAIL_PROGRAM if path == self.program else profiles.JAIL_LAUNCHER]
            elif path != fontlist:
                a += ["--ro-bind", st, path]
        for h in inside:
            if h not in holds:
                a += ["--size", "4096", "--perms", "0755", "--tmpfs", h]
        if fontlist:
            a += ["--perms", "0700", "--dir", MPL_DIR,
                  "--ro-bind", staged[-1], f"{MPL_DIR}/{os.path.basename(fontlist)}"]
        covered = []
        for c in plan.cover:
            if not any(under(c, b) for b in bound):
                continue  # not in the jail at all
            a += ["--size", "4096", "--tmpfs", c] if os.path.isdir(c) else ["--ro-bind", "/dev/null", c]
            covered += [c] if os.path.isdir(c) else []
        for path in ["/", *inside, *covered]:  # empty tmpfs owned by the sandbox's uid: read-only
            a += ["--remount-ro", path]
        a += ["--chdir", JAIL_WORKDIR]
        if self.profile == "run":  # the submission is pid 1, no reaper: see BWRAP_PROCESSES
            a.append("--as-pid-1")
        return a

    def address_space_mb(self) -> int:
        """RLIMIT_AS of each process: with a cgroup (which bounds the real memory, RSS and tmpfs
        files, of the whole sandbox) the limit plus :data:`ADDRESS_HEADROOM_MB`, since libraries
        map far more than they touch (numpy, scipy and matplotlib together do not even load under
        a 256 MiB address space); without one, in a jail, the limit minus the sizes of its
        writable tmpfs (:func:`tmpfs.sizes`: address space plus files stay within the limit);
        without a jail the limit itself."""
        if self.files_charged():
            return self.limits.memory_mb + ADDRESS_HEADROOM_MB
        if self.kind in ("bwrap", "namespaces"):  # the files in its tmpfs mounts count too
            return max(1, self.limits.memory_mb - sum(self.files.mounts.values()))
        return self.limits.memory_mb

    def files_charged(self) -> bool:
        """True when a cgroup bounds the sandbox's memory: it charges the pages of its tmpfs
        files too (shmem), so the files need no separate accounting."""
        return self.group is not None and bool(self.group.limit_bytes) and self.group.mechanism.startswith("cgroup")

    def sample_files(self, pid: int) -> None:
        """Measure what the submission keeps in the jail's tmpfs mounts (:attr:`files`), seen from
        a process inside the jail: for bubblewrap a child of ``pid`` (bubblewrap itself stays in
        the host's mounts), else ``pid``."""
        if self.kind == "namespaces":
            self.files.sample(pid)
        elif self.kind == "bwrap" and not (self._inner[0] == pid and self.files.sample(self._inner[1])):
            inner = children(pid)[:1]  # found once while ``pid`` is the same (kept when inside the jail)
            self._inner = (pid, inner[0]) if inner and self.files.sample(inner[0]) else (0, 0)

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
        if self.profile == "compile":
            return profiles.COMPILE_WORKDIR if self.kind == "bwrap" else self.scratch
        return JAIL_WORKDIR if self.kind in ("bwrap", "namespaces") else self.host_workdir

    @property
    def program_path(self) -> str:
        """Where the child finds :attr:`program` (the bound copy in a jail, the file itself when trusted)."""
        return profiles.JAIL_PROGRAM if self.kind == "bwrap" else (self.program or "")

    @property
    def launcher_path(self) -> str:
        """Where the child finds :attr:`launcher` ("": the Python bootstrap starts the program)."""
        return (profiles.JAIL_LAUNCHER if self.kind == "bwrap" else self.launcher) if self.launcher else ""

    def inner_nproc(self) -> int | None:
        """RLIMIT_NPROC for the child to set on itself once inside its own user namespace (not
        root: there it counts only the sandbox's threads; set before, it would count all of the
        user's processes), or None (root sets it before the uid drop)."""
        return self.limits.processes + USERNS_EXTRA if not self.root_mode and self.kind == "bwrap" else None

    def child_env(self) -> dict[str, str]:
        """The scrubbed environment given to children."""
        home = self.child_workdir
        if self.profile == "compile":  # the compiler's temporary files go to the jail's sized /tmp
            return {"PATH": "/usr/bin:/bin", "HOME": profiles.COMPILE_WORKDIR if self.kind == "bwrap" else home,
                    "TMPDIR": "/tmp" if self.kind == "bwrap" else home, "LANG": "C.UTF-8", "LC_ALL": "C.UTF-8"}
        env = {
            "PATH": "/usr/local/bin:/usr/bin:/bin", "HOME": home, "TMPDIR": home, "LANG": "C.UTF-8",
            "LC_ALL": "C.UTF-8", "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1",
            "MKL_NUM_THREADS": "1", "NUMEXPR_NUM_THREADS": "1", "PYTHONDONTWRITEBYTECODE": "1",
            "PYTHONHASHSEED": "0", "MPLBACKEND": "Agg"}
        env["MPLCONFIGDIR"] = os.path.join(home, ".matplotlib")  # holds the pre-built font cache
        return env

    def spawn(self, argv: Sequence[str], stdin: int, stdout: int, stderr: int,
              pass_fds: Sequence[int] = (), cpu_s: float | None = None,
              seccomp_filter: bytes | None = None) -> subprocess.Popen:
        """Start ``argv`` jailed; ``cpu_s`` overrides the RLIMIT_CPU of ``self.limits``;
        ``seccomp_filter`` (bubblewrap only) the jail's seccomp filter: a compiled program's server
        gets the base deny-list and installs the stricter one on each test's process itself."""
        self._swept = False
        cpu = int(cpu_s if cpu_s is not None else self.limits.cpu_s) + 1
        plan, uid, lim = self._plan, self.uid, self.limits
        # an account's jail sets RLIMIT_NPROC inside its user namespace (inner_nproc); trusted: as before
        nproc = lim.processes + (BWRAP_PROCESSES if self.kind == "bwrap" else 0) if self.root_mode else \
            (lim.processes if self.kind == "trusted" and self.profile == "run" else -1)
        address_mb = self.address_space_mb()
        argv, fds, seccomp_fd = list(argv), list(pass_fds), -1
        if plan is not None and plan.bwrap:
            opts = list(plan.bwrap)
            prog = seccomp_filter if seccomp_filter is not None else plan.seccomp
            if prog:
                seccomp_fd = seccomp.program_fd(prog)
                opts += ["--seccomp", str(seccomp_fd)]
                fds.append(seccomp_fd)
            argv = [bwrap_path() or "bwrap", *opts, "--", *argv]

        def preexec() -> None:  # runs in the forked child, before exec
            os.setsid()
            if plan is not None and self.root_mode:
                for procs in plan.cgroup_procs:  # join the sandbox's accounting group
                    with open(procs, "w") as f:
                        f.write(str(os.getpid()))
                if plan.bwrap:
                    stage_for_bwrap(plan)
                else:
                    jail_filesystem(plan, uid)
            elif plan is None:
                unshare(CLONE_NEWUSER | CLONE_NEWNET)  # trusted mode: best effort
            for res, val in ((resource.RLIMIT_CPU, cpu), (resource.RLIMIT_AS, address_mb << 20),
                             (resource.RLIMIT_FSIZE, lim.output_mb << 20), (resource.RLIMIT_NOFILE, lim.open_files),
                             (resource.RLIMIT_CORE, 0), (resource.RLIMIT_NPROC, nproc)):
                if val >= 0:
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
            proc = subprocess.Popen(argv, stdin=stdin, stdout=stdout, stderr=stderr, pass_fds=tuple(fds),
                                    close_fds=True, env=self.child_env(), cwd="/", preexec_fn=preexec)
            if isinstance(self.group, cgroups.ProcTree):
                self.group.roots.append(proc.pid)
            return proc
        finally:
            if seccomp_fd >= 0:
                os.close(seccomp_fd)

    def terminate(self, pid: int) -> None:
        """SIGKILL a child started by :meth:`spawn` and everything it started. For bubblewrap,
        its pid-1 reaper goes first: the kernel then kills and reaps the whole pid namespace and
        bubblewrap exits by itself, so no zombie is left to the host's init (which reaps slowly,
        about a second here, holding RLIMIT_NPROC slots meanwhile)."""
        reapers = children(pid) if self.kind == "bwrap" else []
        for child in reapers:
            try:
                os.kill(child, signal.SIGKILL)
            except OSError:
                pass
        deadline = time.monotonic() + 1.0
        while reapers and time.monotonic() < deadline and alive(pid):
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
        if cgroups.nothing_left(self.group, self.uid):  # the common case after a run: no fork to kill nothing
            self._swept = True
            return
        deadline = time.monotonic() + wait_s
        me = os.getpid()
        while True:
            self._kill_uid()
            # done when nothing runs: zombies left to the host's init (bubblewrap's reapers) are
            # dead and hold no resources; our own zombie children are reaped by our wait4
            left = [p for p in uid_processes(self.uid) if alive(p) or parent(p) == me]
            if not left or time.monotonic() > deadline:
                self._swept = not left
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

