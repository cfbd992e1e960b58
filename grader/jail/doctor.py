"""``python -m grader.jail`` (also ``python -m grader.sandbox``): what this machine gives to root
and to this user, and why.

It probes bubblewrap (as this user, and as root for an unprivileged uid too), reads the kernel's
user-namespace settings and the cgroup accounting root would get, and prints one line for each
account with the jail it gets (or that grading refuses there, and the fixes), and where root's
sandbox uid locks are and whether that folder is root's alone (:mod:`grader.jail.uidpool`), and
what starts compiled programs in the run jail: the C launcher or the Python bootstrap
(:mod:`grader.jail.launcher`).

Example:
    >>> "this user" in report()                                    # doctest: +SKIP
    True
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

from . import cgroups, launcher, seccomp, uidpool
from .sandbox import bwrap_path, bwrap_status, is_root, jail_kind

#: The kernel settings that allow or forbid unprivileged user namespaces (where they exist).
USERNS_SETTINGS = ("/proc/sys/user/max_user_namespaces", "/proc/sys/kernel/unprivileged_userns_clone",
                   "/proc/sys/kernel/apparmor_restrict_unprivileged_userns")
#: The uid root probes bubblewrap with, standing for any ordinary account.
NOBODY = 65534

USER_JAIL = ("bwrap+proc-tree+seccomp-noproc: the same allow-list as root (/usr, the Python installations, "
             "private /tmp), new user/pid/net/ipc/uts namespaces, dies with the grader; no new processes "
             "(seccomp), so the student process's own CPU and memory limits are the whole sandbox's (its "
             "address space leaves room for the sized /tmp and /dev/shm, the only writable mounts)")


def userns_settings() -> str:
    """The user-namespace sysctls of this kernel, e.g. ``max_user_namespaces=96363``."""
    found = []
    for path in USERNS_SETTINGS:
        try:
            found.append(f"{Path(path).name}={Path(path).read_text().strip()}")
        except OSError:
            pass
    return ", ".join(found) or "no settings found"


def _root_line() -> str:
    kind = jail_kind()
    group = cgroups.open_group(f"grader-probe-{os.getpid()}", 64, 8, None)
    acct = group.mechanism
    group.close()
    sec = "seccomp filter" if seccomp.program() else "no seccomp (unsupported architecture)"
    jail = ("bubblewrap allow-list jail (user/pid/net/ipc/uts/cgroup namespaces)" if kind == "bwrap" else
            "hand-written namespace jail (top-level directories covered)")
    return (f"root: {kind}+{acct}+seccomp: {jail}, dedicated uid per sandbox, NO_NEW_PRIVS, {sec}, "
            f"whole-sandbox accounting and limits by {acct}, private sized /tmp and /dev/shm, rlimits")


def _user_line(who: str, ok: bool, why: str) -> str:
    if ok:
        return f"{who}: {USER_JAIL}"
    return (f"{who}: NO kernel jail ({why}): grading refuses; only the trusted mode (--trusted, GRADER_TRUSTED=1, "
            "a student's own code) runs, without a jail. Fixes: install bubblewrap, allow unprivileged user "
            "namespaces, or grade as root")


def report() -> str:
    """The doctor's text: bubblewrap, the kernel's settings, then root's and this user's jail."""
    lines = [f"bubblewrap: {bwrap_path() or 'not installed (apt-get install bubblewrap)'}",
             f"user namespaces: {userns_settings()}"]
    if is_root():
        lines.append(_root_line())
        lines.append(uidpool.describe())
        lines.append(_user_line(f"an ordinary user (probed as uid {NOBODY})", *bwrap_status(NOBODY)))
    else:
        lines.append("root: not probed from this account (run this as root); root gets bubblewrap or the "
                     "namespaces jail, with cgroup accounting where it can create a cgroup")
        lines.append(_user_line(f"this user (uid {os.getuid()})", *bwrap_status(None)))
        lines.append(uidpool.describe())
    lines.append(launcher.status())
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """Print :func:`report`; exit 0 when this account can grade (a kernel jail; root: a safe lock
    folder), else 1."""
    text = report()
    print(text)
    return 0 if (is_root() and "UNSAFE" not in text) or (not is_root() and bwrap_status(None)[0]) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
