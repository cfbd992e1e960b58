"""Does bubblewrap work here? The probe the jail's choice of mechanism rests on.

:func:`bwrap_status` starts ``bwrap --unshare-all ... true`` once per process and uid (root drops to
the uid first) and remembers the answer; :func:`bwrap_path` finds the binary. The sandbox
(:mod:`grader.jail.sandbox`) and ``python -m grader.jail`` (:mod:`grader.jail.doctor`) ask it.

Run: ``python -c "from grader.jail.bwrap_probe import bwrap_status; print(bwrap_status(None))"``

    >>> works, why = bwrap_status(None)
    >>> works or why != ""
    True
"""
from __future__ import annotations

import os
import shutil
import subprocess

#: (bwrap path, uid) -> (works, why not): one probe per process and uid
_bwrap_works: dict[tuple[str, int | None], tuple[bool, str]] = {}


def bwrap_path() -> str | None:
    """The bubblewrap binary, if installed."""
    return shutil.which("bwrap", path="/usr/bin:/bin:/usr/local/bin")


def bwrap_status(uid: int | None) -> tuple[bool, str]:
    """(works, why not) for bubblewrap started by ``uid`` (root drops to it first; None: this
    process as it is). Probed once per process and uid."""
    path = bwrap_path()
    if path is None:
        return False, "bubblewrap is not installed"
    if (path, uid) not in _bwrap_works:
        _bwrap_works[path, uid] = _probe_bwrap(path, uid)
    return _bwrap_works[path, uid]


def _probe_bwrap(path: str, uid: int | None) -> tuple[bool, str]:
    """Can bubblewrap create its namespaces here, started by ``uid`` (user namespaces enabled)?"""
    def drop() -> None:
        os.setgroups([])
        os.setresgid(uid, uid, uid)
        os.setresuid(uid, uid, uid)
    try:
        r = subprocess.run([path, "--unshare-all", "--die-with-parent", "--ro-bind", "/", "/", "true"],
                           preexec_fn=drop if uid is not None else None, timeout=30, stdin=subprocess.DEVNULL,
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    except (OSError, subprocess.SubprocessError) as exc:
        return False, f"bubblewrap could not be started: {exc}"
    why = r.stderr.decode(errors="replace").strip().splitlines()[-1:] or [f"exit code {r.returncode}"]
    return r.returncode == 0, "" if r.returncode == 0 else f"bubblewrap cannot create a user namespace ({why[0]})"
