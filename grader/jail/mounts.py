"""Child side of the root-mode jails, run in the forked child before ``exec``: mount calls.

* :func:`stage_for_bwrap` (bubblewrap jail): bind the Python installations to a private staging
  directory that bubblewrap, started as the sandbox uid, can read from;
* :func:`jail_filesystem` (the hand-written ``namespaces`` fallback): new mount, network, IPC and
  UTS namespaces and the filesystem view (hidden paths covered by empty tmpfs, private ``/tmp``).

Both take a :class:`Plan` computed in the parent (nothing here decides anything).

Example (root only, in a forked child):
    >>> jail_filesystem(plan, uid)                                     # doctest: +SKIP
"""

from __future__ import annotations

import ctypes
import ctypes.util
import json
import os
from dataclasses import dataclass, field

from .paths import under

CLONE_NEWNS = 0x00020000
CLONE_NEWUTS = 0x04000000
CLONE_NEWIPC = 0x08000000
CLONE_NEWUSER = 0x10000000
CLONE_NEWNET = 0x40000000
MS_NOSUID, MS_NODEV, MS_REMOUNT, MS_BIND, MS_REC, MS_PRIVATE = 2, 4, 32, 4096, 16384, 1 << 18
MS_RDONLY, MS_MOVE = 1, 8192
#: Path of the child's private working directory inside its mount namespace.
JAIL_WORKDIR = "/tmp/work"
#: Matplotlib's configuration directory inside the working directory (holds a pre-built font cache).
MPL_DIR = JAIL_WORKDIR + "/.matplotlib"

_libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
_libc.mount.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_ulong, ctypes.c_char_p]
_libc.unshare.argtypes = [ctypes.c_int]


@dataclass
class Plan:
    """What the preexec does, computed in the parent before fork."""

    hide: list[str]
    expose: list[str]  # paths re-bound under a hidden path (namespaces) / staged for bubblewrap
    staging: str  # an existing directory, outside every hidden path, used while re-binding ("": no staging)
    cover: list[str]  # forbidden package dirs/files covered by empty tmpfs or /dev/null
    disk_mb: int
    fontlist: bytes = b""  # matplotlib font cache written into the work directory (namespaces)
    cgroup_procs: list[str] = field(default_factory=list)  # files the child writes its pid to
    seccomp: bytes | None = None  # installed by the preexec (namespaces) or given to bubblewrap
    bwrap: list[str] = field(default_factory=list)  # bubblewrap's options (empty: the namespaces jail)
    shm_mb: int = 8  # size of the private /dev/shm


def mount(src: str | None, target: str, fstype: str | None, flags: int, data: str | None = None) -> None:
    """mount(2), raising OSError."""
    enc = lambda s: None if s is None else s.encode()  # noqa: E731
    if _libc.mount(enc(src), enc(target), enc(fstype), flags, enc(data)) != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"mount {target}: {os.strerror(err)}")


def unshare(flags: int) -> bool:
    """unshare(2); True on success."""
    return _libc.unshare(flags) == 0


def stage_for_bwrap(plan: Plan) -> None:
    """Child side, bubblewrap jail, still root: bind the Python installations (which may sit
    under a directory the sandbox uid cannot enter, like ``/root``) to a private staging
    directory that bubblewrap, started as the sandbox uid, can read from."""
    if not unshare(CLONE_NEWNS):
        raise OSError(ctypes.get_errno(), "unshare failed")
    mount(None, "/", None, MS_REC | MS_PRIVATE)
    mount("tmpfs", plan.staging, "tmpfs", MS_NOSUID | MS_NODEV, "mode=755,size=16k")
    for i, path in enumerate(plan.expose):
        st = os.path.join(plan.staging, str(i))
        if os.path.isdir(path):
            os.mkdir(st)
        else:
            open(st, "w").close()
        mount(path, st, None, MS_BIND | MS_REC)


def jail_filesystem(plan: Plan, uid: int | None) -> None:
    """Child side of the fallback jail: new mount/net/ipc/uts namespaces and the filesystem view."""
    if not unshare(CLONE_NEWNS | CLONE_NEWNET | CLONE_NEWIPC | CLONE_NEWUTS):
        raise OSError(ctypes.get_errno(), "unshare failed")
    mount(None, "/", None, MS_REC | MS_PRIVATE)
    # Bind what must stay visible to a staging tmpfs, cover the hidden paths, move the binds back.
    mount("tmpfs", plan.staging, "tmpfs", MS_NOSUID | MS_NODEV, "mode=700,size=4k")
    staged = []
    for i, path in enumerate(plan.expose):
        st = os.path.join(plan.staging, str(i))
        os.mkdir(st)
        mount(path, st, None, MS_BIND | MS_REC)
        staged.append(st)
    for h in plan.hide:  # root-owned and empty: nothing to read, nothing writable (/run/lock...)
        mount("tmpfs", h, "tmpfs", MS_NOSUID | MS_NODEV, "mode=755,size=1m")
    # The child's private /tmp is prepared inside the staging area (which itself lives under
    # the host's /tmp), so that exposed paths under /tmp can be moved into it first.
    new_tmp = os.path.join(plan.staging, "tmp")
    os.mkdir(new_tmp)
    mount("tmpfs", new_tmp, "tmpfs", MS_NOSUID | MS_NODEV, f"mode=1777,size={plan.disk_mb}m")
    for st, path in zip(staged, plan.expose):
        target = os.path.join(new_tmp, os.path.relpath(path, "/tmp")) if under(path, "/tmp") else path
        os.makedirs(target, exist_ok=True)
        mount(st, target, None, MS_MOVE)
    mount(new_tmp, "/tmp", None, MS_MOVE)
    for c in plan.cover:  # after the move: a covered package may live under /tmp too
        if os.path.isdir(c):
            mount("tmpfs", c, "tmpfs", MS_NOSUID | MS_NODEV, "mode=755,size=4k")
        elif os.path.exists(c):
            mount("/dev/null", c, None, MS_BIND)
    if os.path.isdir("/dev/shm"):
        mount("tmpfs", "/dev/shm", "tmpfs", MS_NOSUID | MS_NODEV, f"mode=1777,size={plan.shm_mb}m")
    os.mkdir(JAIL_WORKDIR, 0o700)
    if plan.fontlist:
        os.mkdir(MPL_DIR, 0o700)
        with open(os.path.join(MPL_DIR, f"fontlist-v{json.loads(plan.fontlist).get('_version', 0)}.json"), "wb") as f:
            f.write(plan.fontlist)
    if uid is not None:
        for d in (JAIL_WORKDIR, MPL_DIR):
            if os.path.isdir(d):
                os.chown(d, uid, uid)
