"""Root's pool of dedicated sandbox uids, and the folder of its lock files (root only).

Each root sandbox runs as a uid of its own, ``UID_BASE + k`` (``k < UID_COUNT``), held for the
sandbox's life by an exclusive ``flock`` on ``<LOCK_DIR>/<uid>.lock``, so concurrent graders on
one host never share a uid (a sandbox's cleanup kills every process of its uid).

The lock folder is shared between root's grader runs, so it lies where only root can write:
``/run/grader/sandbox-uids`` (``/run`` is root's; on systemd and Debian hosts a tmpfs emptied at
boot), or ``/var/lib/grader/sandbox-uids`` where there is no ``/run``. It used to be
``/tmp/grader-sandbox-uids``, where any account could create it first: hold every lock (every
root grading failed), or make each lock file a symbolic link (root created empty files wherever
the links pointed). Now, before each use:

* every component of the folder's path is opened from ``/`` with ``O_DIRECTORY|O_NOFOLLOW``
  (a symbolic link anywhere on the path is refused) and checked on its descriptor: owned by
  root, not writable by group or others (an ancestor may be a root-owned sticky folder such as
  ``/tmp``: others can neither rename nor remove what root made there); missing components are
  created (0755; the lock folder itself 0700);
* lock files are opened relative to the folder's descriptor with ``O_NOFOLLOW`` and must be
  regular files owned by root.

An unsafe folder raises :class:`~grader.jail.errors.UnsafeSharedState`; a pool whose every uid
stays taken for :data:`SLOT_WAIT_S` raises :class:`~grader.jail.errors.NoFreeSlot`. Both are
:class:`~grader.jail.errors.JailUnavailable`: the CLI prints one line and exits 2. An ordinary
account never uses the pool (its sandboxes run as itself, in a user namespace).

Example:
    >>> str(default_lock_dir("/no-such-run"))
    '/var/lib/grader/sandbox-uids'
"""

from __future__ import annotations

import fcntl
import os
import stat
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from .errors import NoFreeSlot, UnsafeSharedState

__all__ = ["UID_BASE", "UID_COUNT", "LOCK_DIR", "LEGACY_LOCK_DIR", "SLOT_WAIT_S", "Slot", "acquire", "hold",
           "default_lock_dir", "open_private_dir", "check_lock_dir", "describe"]

#: First uid/gid of the pool of dedicated sandbox users (root mode); one per concurrent sandbox.
UID_BASE = 62000
UID_COUNT = 512
#: How long :func:`acquire` waits for a uid to come free before refusing (seconds).
SLOT_WAIT_S = 10.0
SLOT_POLL_S = 0.25
#: Where older graders kept their locks. While one may still run on the host (an upgrade), a uid
#: is taken only when it is free there too; the folder is used only when it is root's and private
#: (never created, never followed), anything else there is ignored.
LEGACY_LOCK_DIR: Path | None = Path(tempfile.gettempdir()) / "grader-sandbox-uids"

_DIR_FLAGS = os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC
_LOCK_FLAGS = os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW | os.O_CLOEXEC


def default_lock_dir(run: str = "/run") -> Path:
    """The lock folder: ``<run>/grader/sandbox-uids``, or ``/var/lib/grader/sandbox-uids`` where
    ``run`` is not a directory."""
    base = Path(run) / "grader" if os.path.isdir(run) and not os.path.islink(run) else Path("/var/lib/grader")
    return base / "sandbox-uids"


#: The folder of root's uid locks (patch this module's name to move it, e.g. in tests).
LOCK_DIR = default_lock_dir()


def _unsafe(where: str, why: str, folder: str | os.PathLike | None = None) -> UnsafeSharedState:
    """The one-line refusal: ``where`` (on the path of ``folder``, default :data:`LOCK_DIR`) ``why``."""
    return UnsafeSharedState(
        f"unsafe sandbox lock folder {folder or LOCK_DIR}: {where} {why}, so another account could hold or redirect "
        f"root's sandbox locks; grading refuses. Remove it or make it root's alone (chown root:root, chmod go-w) "
        "and grade again ('python -m grader.sandbox' checks it)")


def _why_unsafe(st: os.stat_result, final: bool) -> str:
    """Why a directory's status makes it unsafe for root's shared state ('' when it is safe)."""
    if st.st_uid != 0:
        return f"is owned by uid {st.st_uid}, not root"
    if st.st_mode & 0o022 and (final or not st.st_mode & stat.S_ISVTX):
        return f"is writable by group or others (mode {stat.S_IMODE(st.st_mode):04o})"
    return ""


def open_private_dir(path: str | os.PathLike, create: bool = True, mode: int = 0o700) -> int:
    """A descriptor of the directory ``path``, opened one component at a time from ``/`` without
    following symbolic links, every component checked (owned by root, not writable by group or
    others; an ancestor may be a sticky folder); missing components are created when ``create``
    (0755; the last one ``mode``). Raises :class:`UnsafeSharedState`, or ``FileNotFoundError``
    for a missing component when not ``create``."""
    parts = Path(os.path.abspath(path)).parts
    fd = os.open("/", _DIR_FLAGS)
    try:
        why = _why_unsafe(os.fstat(fd), final=len(parts) == 1)
        if why:
            raise _unsafe("/", why, path)
        for i, name in enumerate(parts[1:], start=1):
            final, where = i == len(parts) - 1, os.path.join(*parts[:i + 1])
            try:
                try:
                    nfd = os.open(name, _DIR_FLAGS, dir_fd=fd)
                except FileNotFoundError:
                    if not create:
                        raise
                    try:
                        os.mkdir(name, mode if final else 0o755, dir_fd=fd)
                    except FileExistsError:  # a concurrent grader made it: checked below like any other
                        pass
                    nfd = os.open(name, _DIR_FLAGS, dir_fd=fd)
            except FileNotFoundError:
                raise
            except OSError as exc:  # ELOOP: a symbolic link; ENOTDIR: not a directory
                kind = "is a symbolic link" if os.path.islink(where) else f"cannot be opened as a directory ({exc.strerror})"
                raise _unsafe(where, kind, path) from None
            os.close(fd)
            fd = nfd
            why = _why_unsafe(os.fstat(fd), final)
            if why:
                raise _unsafe(where, why, path)
        return fd
    except BaseException:
        os.close(fd)
        raise


def check_lock_dir() -> None:
    """Create (if missing) and check :data:`LOCK_DIR`; raise :class:`UnsafeSharedState` when it is
    not root's alone. Root only (an ordinary account cannot create it and never uses it)."""
    os.close(open_private_dir(LOCK_DIR))


def describe() -> str:
    """One line for the jail doctor: where root's uid locks are and whether that folder is safe."""
    if os.geteuid() != 0:
        return f"sandbox uid locks: {LOCK_DIR} (root only; this account's sandboxes run as itself)"
    try:
        check_lock_dir()
    except UnsafeSharedState as exc:
        return f"sandbox uid locks: UNSAFE: {exc}"
    except OSError as exc:
        return f"sandbox uid locks: {LOCK_DIR} cannot be created ({exc.strerror or exc}): root cannot grade"
    return (f"sandbox uid locks: {LOCK_DIR} (root's, not writable by others, no symbolic link on the path: safe); "
            f"uids {UID_BASE}-{UID_BASE + UID_COUNT - 1}")


@dataclass
class Slot:
    """One held uid of the pool: its lock file descriptors (closing them frees the uid)."""

    uid: int
    fds: list[int] = field(default_factory=list)

    def close(self) -> None:
        """Release the uid."""
        while self.fds:
            os.close(self.fds.pop())


def _lock(dir_fd: int, uid: int, where: Path) -> int | None:
    """The locked descriptor of ``<uid>.lock`` in ``dir_fd``, or None when another sandbox holds it."""
    try:
        fd = os.open(f"{uid}.lock", _LOCK_FLAGS, 0o600, dir_fd=dir_fd)
    except OSError as exc:  # ELOOP: a symbolic link (only root can write the folder: refuse loudly)
        raise _unsafe(str(where / f"{uid}.lock"), f"cannot be opened ({exc.strerror})") from None
    st = os.fstat(fd)
    if not stat.S_ISREG(st.st_mode) or st.st_uid != 0:
        os.close(fd)
        raise _unsafe(str(where / f"{uid}.lock"), "is not a regular file of root's")
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        return None
    return fd


def hold(uid: int, dir_fd: int, legacy_fd: int | None = None) -> Slot | None:
    """Take ``uid`` if it is free (in the lock folder ``dir_fd``, and in the legacy folder
    ``legacy_fd`` when given); None when another sandbox holds it."""
    fd = _lock(dir_fd, uid, LOCK_DIR)
    if fd is None:
        return None
    slot = Slot(uid, [fd])
    if legacy_fd is not None and LEGACY_LOCK_DIR is not None:
        try:
            old = _lock(legacy_fd, uid, LEGACY_LOCK_DIR)
        except UnsafeSharedState:
            old = -1  # a stray entry in root's own old folder: no older grader can lock it either
        if old is None:
            slot.close()
            return None
        if old >= 0:
            slot.fds.append(old)
    return slot


def _legacy_fd() -> int | None:
    """A descriptor of :data:`LEGACY_LOCK_DIR` when it exists and is root's alone, else None."""
    if LEGACY_LOCK_DIR is None:
        return None
    try:
        return open_private_dir(LEGACY_LOCK_DIR, create=False)
    except (OSError, UnsafeSharedState):
        return None


def acquire(start: int | None = None) -> Slot:
    """A free uid of the pool, tried from ``start`` (default: this process's pid modulo the pool
    size), waiting up to :data:`SLOT_WAIT_S` for one to come free. Raises
    :class:`UnsafeSharedState` (the lock folder is not root's alone) or :class:`NoFreeSlot`."""
    dir_fd = open_private_dir(LOCK_DIR)
    legacy_fd = _legacy_fd()
    try:
        first = os.getpid() % UID_COUNT if start is None else start
        deadline = time.monotonic() + SLOT_WAIT_S
        while True:
            for k in range(UID_COUNT):
                slot = hold(UID_BASE + (first + k) % UID_COUNT, dir_fd, legacy_fd)
                if slot is not None:
                    return slot
            if time.monotonic() >= deadline:
                raise NoFreeSlot(f"no free sandbox uid: all {UID_COUNT} uids of root's pool ({UID_BASE}-"
                                 f"{UID_BASE + UID_COUNT - 1}, locks in {LOCK_DIR}) stayed taken for {SLOT_WAIT_S:g} s "
                                 "(too many sandboxes at once on this host); grade again later or with fewer --jobs")
            time.sleep(SLOT_POLL_S)
    finally:
        os.close(dir_fd)
        if legacy_fd is not None:
            os.close(legacy_fd)
