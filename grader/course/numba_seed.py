"""The course server's numba seed: kernels compiled once at install, copied into each new account's cache.

On the course server every account's server gives numba a private cache (``~/.cache/numba``: the
shared venv is read-only), so without a seed each student's first sample check compiles the
checkers' kernels again (tens of CPU-seconds). ``deploy/jupyterhub/deploy.sh install`` compiles
them once into a seed folder owned by root (``build``), and the hub's ``pre_spawn`` hook copies the
seed into an account's cache when that cache is missing or empty (``seed_account``).

Safety: the seed is used only when every part of it, and every folder above it, is owned by root
(or the hub's own uid) and writable by no one else (``untrusted``); it is copied by a process
running as the account (so nothing the account planted in its home can make root write elsewhere),
regular files only, into private folders (0700) and files (0600); an existing, non-empty cache is
left alone. numba itself checks each cached function's source stamp and its own version before
using it, so a stale seed costs only a compile.

Run (root; the hub does the copy itself):
    python -m grader.course.numba_seed build SEED_DIR "2d predicates,checkers"   # as the compiling account
    python -m grader.course.numba_seed check SEED_DIR                             # '' or why untrusted
    python -m grader.course.numba_seed copy SEED_DIR DEST                         # as the account
    python -m grader.course.numba_seed seed SEED_DIR DEST ACCOUNT                 # root: as the hub does

Example:
    >>> untrusted("/nonexistent-seed")
    '/nonexistent-seed: missing'
"""
from __future__ import annotations

import os
import stat
import subprocess
import sys
from pathlib import Path
from typing import Callable

__all__ = ["untrusted", "copy_seed", "seed_account", "build"]


def _bad_mode(path: Path, st: os.stat_result, owners: tuple[int, ...]) -> str:
    """Why ``path`` (already lstat'ed) cannot be trusted as part of a seed, or ''."""
    if st.st_uid not in owners:
        return f"{path}: owned by uid {st.st_uid}, not by root or the hub"
    if st.st_mode & 0o022:
        return f"{path}: writable by its group or by others (mode {stat.S_IMODE(st.st_mode):04o})"
    return ""


def untrusted(seed: str | os.PathLike[str], owners: tuple[int, ...] | None = None) -> str:
    """'' when the seed folder ``seed`` may be given to accounts, else the reason why not.

    Trusted means: every folder above it is owned by one of ``owners`` (default: root and this
    process's uid) and not writable by group or others, unless it is sticky (like ``/tmp``: no one
    can then rename what root owns in it); the seed and everything in it is a folder or a regular
    file (no symbolic link, no device) owned by one of ``owners`` and not group/other-writable.
    """
    owners = owners if owners is not None else tuple({0, os.getuid()})
    seed = Path(os.path.abspath(seed))
    try:
        top = os.lstat(seed)
    except FileNotFoundError:
        return f"{seed}: missing"
    for parent in reversed(seed.parents):
        st = os.lstat(parent)
        if stat.S_ISLNK(st.st_mode):
            return f"{parent}: a symbolic link above the seed"
        why = _bad_mode(parent, st, owners)
        if why and not (st.st_uid in owners and st.st_mode & stat.S_ISVTX):
            return why
    if not stat.S_ISDIR(top.st_mode):
        return f"{seed}: not a folder"
    for root, dirs, files in os.walk(seed, followlinks=False):
        for name in [".", *dirs, *files]:
            path = Path(root, name) if name != "." else Path(root)
            st = os.lstat(path)
            if not (stat.S_ISDIR(st.st_mode) or stat.S_ISREG(st.st_mode)):
                return f"{path}: not a regular file or folder (a symbolic link?)"
            why = _bad_mode(path, st, owners)
            if why:
                return why
    return ""


def copy_seed(seed: str | os.PathLike[str], dest: str | os.PathLike[str]) -> int:
    """Copy the seed's folders and regular files into ``dest`` when ``dest`` is missing or an
    empty folder; return the number of files copied (0: ``dest`` already had files, left alone).

    Meant to run as the account that owns ``dest`` (``seed_account`` starts it so): folders are
    made 0700, files 0600, symbolic links and other special files in the seed are skipped, and
    no existing file is ever overwritten (files are created with ``O_EXCL``).
    """
    seed, dest = Path(seed), Path(dest)
    if dest.is_dir() and any(dest.iterdir()):
        return 0
    dest.parent.mkdir(mode=0o700, parents=True, exist_ok=True)
    dest.mkdir(mode=0o700, exist_ok=True)
    os.chmod(dest, 0o700)                                 # (an empty folder the account made itself)
    copied = 0
    for root, dirs, files in os.walk(seed, followlinks=False):
        rel = Path(root).relative_to(seed)
        for d in dirs:
            if stat.S_ISDIR(os.lstat(Path(root, d)).st_mode):
                (dest / rel / d).mkdir(mode=0o700, exist_ok=True)
        for f in files:
            src = Path(root, f)
            try:
                fin = os.open(src, os.O_RDONLY | os.O_NOFOLLOW)
            except OSError:
                continue                                  # a symbolic link: never followed
            with os.fdopen(fin, "rb") as fi:
                if not stat.S_ISREG(os.fstat(fi.fileno()).st_mode):
                    continue
                fout = os.open(dest / rel / f, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600)
                with os.fdopen(fout, "wb") as fo:
                    while chunk := fi.read(1 << 20):
                        fo.write(chunk)
            copied += 1
    return copied


def seed_account(seed: str | os.PathLike[str], dest: str | os.PathLike[str], uid: int, gid: int,
                 log: Callable[[str], object] = print, python: str = sys.executable, timeout: float = 60) -> int:
    """Give the account ``uid``:``gid`` the seed as its numba cache ``dest`` (the hub's ``pre_spawn``).

    Checks the seed (``untrusted``) here, then copies it in a child process running as the account
    (``copy_seed``, this file run by ``python``, which the account must be able to run: the course
    venv's, built from ``/usr/bin/python3``). Returns the files copied; a missing or untrusted seed, or a failed copy, is
    logged through ``log`` and returns 0: the account's server starts all the same.
    """
    why = untrusted(seed)
    if why:
        log(f"numba seed not used for uid {uid}: {why}")
        return 0
    try:
        run = subprocess.run([python, "-I", os.path.abspath(__file__), "copy", os.fspath(seed), os.fspath(dest)],
                             user=uid, group=gid, extra_groups=[], cwd="/", env={"PATH": "/usr/bin:/bin"},
                             capture_output=True, text=True, timeout=timeout)
    except (OSError, subprocess.SubprocessError) as exc:
        log(f"numba seed not copied for uid {uid}: {exc}")
        return 0
    if run.returncode != 0:
        log(f"numba seed not copied for uid {uid}: {run.stderr.strip().splitlines()[-1:]}")
        return 0
    copied = int(run.stdout.strip() or 0)
    log(f"numba seed: {copied} files copied into {dest}" if copied else f"numba seed: {dest} not empty, left alone")
    return copied


def build(groups: list[str]) -> None:
    """Compile the kernels of ``reference_impl.warmup``'s feature groups ``groups`` (all when
    empty) into the cache numba uses here (``NUMBA_CACHE_DIR``); run as the compiling account."""
    from reference_impl import warmup
    unknown = [g for g in groups if g not in warmup.FEATURES]
    if unknown:
        raise ValueError(f"unknown warm-up groups {unknown}: choose among {sorted(warmup.FEATURES)}")
    if not groups:
        warmup.warm(progress=None)
        return
    for g in groups:
        warmup.FEATURES[g]()


def main(argv: list[str]) -> int:
    if len(argv) >= 2 and argv[0] == "build":
        os.environ["NUMBA_CACHE_DIR"] = os.path.abspath(argv[1])   # before numba is imported
        build([g.strip() for g in (argv[2] if len(argv) > 2 else "").split(",") if g.strip()])
        return 0
    if len(argv) == 2 and argv[0] == "check":
        why = untrusted(argv[1])
        print(why)
        return 1 if why else 0
    if len(argv) == 4 and argv[0] == "seed":
        import pwd
        pw = pwd.getpwnam(argv[3])
        seed_account(argv[1], argv[2], pw.pw_uid, pw.pw_gid)
        return 0
    if len(argv) == 3 and argv[0] == "copy":
        print(copy_seed(argv[1], argv[2]))
        return 0
    print(__doc__.split("Example:")[0].split("Run (root; the hub does the copy itself):")[1], file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
