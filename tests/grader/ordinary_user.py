"""Running part of the suite as an ordinary (non-root) account, from a root test run (CI is root).

:func:`run_as_user` starts a command as ``USER`` (created with ``useradd`` when missing) in a
private mount namespace of its own, where

* the directories it must read but cannot enter (the interpreter under ``/root/.pyenv``, mode
  0700 above it, or a checkout cloned under a 0700 directory) are re-bound under an empty,
  world-traversable tmpfs laid over the blocking directory, read-only as before: nothing on the
  host changes mode or owner;
* the checkout's numba caches (``__pycache__`` with ``.nbi`` files) are replaced by writable
  copies owned by the user, and the same files are copied into the user's ``NUMBA_CACHE_DIR``
  (where numba looks first when it is set: :func:`seed_numba_cache_dir`), so numba loads what
  ``make warm`` compiled instead of compiling everything again (about 60 s of 2 CPUs; numba
  itself checks each file's source stamp and its own version, and compiles what does not match);
* the grader's test cache (``GRADER_CACHE``) is a copy the user owns: the "instructor's"
  ``.cache/grader``.

The account is an ordinary one in every way the jail cares about: a uid without capabilities,
its own home, ``os.geteuid() != 0``.

Example:
    >>> run_as_user(["id", "-u"]).stdout.strip() != "0"          # doctest: +SKIP
    True
"""
from __future__ import annotations

import fcntl
import os
import pwd
import shutil
import stat
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Sequence

from grader.jail import uidpool
from grader.jail.mounts import CLONE_NEWNS, MS_BIND, MS_PRIVATE, MS_RDONLY, MS_REC, MS_REMOUNT, mount, unshare
from grader.jail.paths import outermost, python_roots

REPO = Path(__file__).resolve().parents[2]
USER = "grader-instructor"


def ensure_user(name: str = USER) -> pwd.struct_passwd:
    """The account ``name``, created (with a home directory) when missing; root only."""
    try:
        return pwd.getpwnam(name)
    except KeyError:
        subprocess.run(["useradd", "--create-home", "--shell", "/bin/sh", name], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        return pwd.getpwnam(name)


def can_run() -> str:
    """'' when :func:`run_as_user` can work here, else why not (for a skip message)."""
    if os.geteuid() != 0:
        return "needs root to create the ordinary account (CI runs as root)"
    if shutil.which("useradd") is None:
        return "useradd is missing"
    return ""


def _blocker(path: str) -> str | None:
    """The outermost ancestor of ``path`` that other users cannot enter (mode without o+x)."""
    parts = Path(path).parts
    for k in range(2, len(parts) + 1):
        d = os.path.join(*parts[:k])
        if not os.stat(d).st_mode & stat.S_IXOTH:
            return d
    return None


def _numba_caches() -> list[Path]:
    return sorted({p.parent for p in (REPO / "reference_impl").rglob("*.nbi")})


def seed_numba_cache_dir(cache_dir: Path) -> int:
    """Copy the checkout's compiled numba code (``.nbi``/``.nbc`` and the ``.deps.sha1`` stamps of
    :mod:`reference_impl._jitcache`) into ``cache_dir`` laid out as numba's own locator for
    ``NUMBA_CACHE_DIR`` expects it (``<folder>_<sha1 of the folder's path>``); return the files copied.

    With ``NUMBA_CACHE_DIR`` set numba never reads ``__pycache__``: without this the account compiled
    every kernel again. A copy, not a link: the account owns and may rewrite it; numba recompiles any
    function whose source stamp or numba version differs, so a copy never runs stale code.
    """
    from numba.core.caching import UserProvidedCacheLocator
    copied = 0
    for cache in _numba_caches():
        src_dir = cache.parent  # the sources whose kernels __pycache__ holds
        dest = cache_dir / UserProvidedCacheLocator.get_suitable_cache_subpath(str(src_dir / "x.py"))
        for f in cache.iterdir():
            if f.suffix in (".nbi", ".nbc") or f.name.endswith(".deps.sha1"):
                dest.mkdir(parents=True, exist_ok=True)
                shutil.copy2(f, dest / f.name)
                copied += 1
    return copied


def run_as_user(argv: Sequence[str], env: dict[str, str] | None = None, timeout: float = 1800,
                user: str = USER) -> subprocess.CompletedProcess:
    """Run ``argv`` as ``user`` (see the module docstring) with cwd = the checkout; output captured.
    One run at a time per account (a lock, :func:`account_lock`): the account's tests count its processes."""
    fds = account_lock(user)
    try:
        return _run_as_user(argv, env, timeout, user)
    finally:
        for fd in fds:
            os.close(fd)


def account_lock(user: str) -> list[int]:
    """Wait for, and hold, the host-wide lock of ``user``'s test runs (every checkout's): the file
    ``<user>.lock`` in root's state folder (``/run/grader/test-accounts``, checked like the sandbox
    locks by :func:`grader.jail.uidpool.open_private_dir`), opened without following links. The
    lock older checkouts took, ``/tmp/<user>.lock``, is held too when it is a regular file of
    root's (it is never created, truncated or followed: any account can make names in ``/tmp``).
    Returns the locked descriptors (closing them releases the lock)."""
    flags = os.O_RDWR | os.O_NOFOLLOW | os.O_CLOEXEC
    dir_fd = uidpool.open_private_dir(uidpool.LOCK_DIR.parent / "test-accounts")
    try:
        fds = [os.open(f"{user}.lock", flags | os.O_CREAT, 0o600, dir_fd=dir_fd)]
    finally:
        os.close(dir_fd)
    tmp_fd = os.open(tempfile.gettempdir(), os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
    try:
        old = os.open(f"{user}.lock", flags, dir_fd=tmp_fd)
        st = os.fstat(old)
        if stat.S_ISREG(st.st_mode) and st.st_uid == 0:
            fds.append(old)
        else:
            os.close(old)
    except OSError:  # missing, or a symbolic link (ELOOP): not an older checkout's lock
        pass
    finally:
        os.close(tmp_fd)
    for fd in fds:
        fcntl.flock(fd, fcntl.LOCK_EX)
    return fds


def _run_as_user(argv: Sequence[str], env: dict[str, str] | None, timeout: float, user: str) -> subprocess.CompletedProcess:
    pw = ensure_user(user)
    uid, gid = pw.pw_uid, pw.pw_gid
    scratch = Path(tempfile.mkdtemp(prefix="grader-as-user-"))
    os.chmod(scratch, 0o711)
    need = outermost(sorted({*python_roots(), str(REPO)}))
    blocked = {p: b for p in need if (b := _blocker(p))}
    copies = []
    for k, cache in enumerate(_numba_caches()):
        copy = scratch / "numba" / str(k)
        shutil.copytree(cache, copy)
        copies.append((copy, cache))
    seed_numba_cache_dir(scratch / "numba-user")
    grader_cache = scratch / "grader-cache"
    if (REPO / ".cache" / "grader").is_dir():
        shutil.copytree(REPO / ".cache" / "grader", grader_cache)
    else:
        grader_cache.mkdir()
    for d in (scratch / "numba", grader_cache, scratch / "numba-user"):
        d.mkdir(exist_ok=True)
        for p in [d, *d.rglob("*")]:
            os.lchown(p, uid, gid)
    staging = scratch / "staging"
    staging.mkdir()

    def enter() -> None:  # runs as root in the forked child, before exec
        if not unshare(CLONE_NEWNS):
            raise OSError("unshare(CLONE_NEWNS) failed")
        mount(None, "/", None, MS_REC | MS_PRIVATE)
        mount("tmpfs", str(staging), "tmpfs", 0, "mode=700")
        staged = {}
        for k, p in enumerate(blocked):
            st = os.path.join(staging, str(k))
            os.mkdir(st)
            mount(p, st, None, MS_BIND | MS_REC)
            staged[p] = st
        for b in outermost(sorted(set(blocked.values()))):
            mount("tmpfs", b, "tmpfs", 0, "mode=755")
        for p, st in staged.items():
            os.makedirs(p, exist_ok=True)
            mount(st, p, None, MS_BIND | MS_REC)
            mount(None, p, None, MS_BIND | MS_REMOUNT | MS_RDONLY)
        for copy, cache in copies:
            mount(str(copy), str(cache), None, MS_BIND)
        os.setgroups([])
        os.setresgid(gid, gid, gid)
        os.setresuid(uid, uid, uid)

    base = {"PATH": "/usr/local/bin:/usr/bin:/bin", "HOME": pw.pw_dir, "USER": user, "LANG": "C.UTF-8",
            "PYTHONDONTWRITEBYTECODE": "1", "GRADER_CACHE": str(grader_cache),
            "NUMBA_CACHE_DIR": str(scratch / "numba-user"), "TMPDIR": "/tmp"}
    try:
        return subprocess.run(list(argv), cwd=REPO, env={**base, **(env or {})}, preexec_fn=enter, timeout=timeout,
                              stdin=subprocess.DEVNULL, capture_output=True, text=True)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":  # python tests/grader/ordinary_user.py CMD...: try a command as the user
    r = run_as_user(sys.argv[1:])
    print(r.stdout, r.stderr, sep="", end="")
    sys.exit(r.returncode)
