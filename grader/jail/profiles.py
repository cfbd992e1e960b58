"""The jail's profiles besides the run jail of a Python submission: the compile jail and a
compiled program's run jail.

* **compile** (:func:`compile_bwrap_options`): a compiler (``g++`` and the processes it starts:
  ``cc1plus``, ``as``, ``collect2``, ``ld``) runs as untrusted as the program it builds. Its
  bubblewrap view holds only what the compiler needs: ``/usr`` (the compiler, its headers and
  libraries) with the ``/bin``, ``/lib*`` links, the dynamic loader's files of ``/etc`` (none of the
  account files: ``#include "/etc/passwd"`` is "No such file"), a ``/dev`` with ``/dev/null`` alone
  (``#include "/dev/zero"`` cannot hang), no ``/proc``, a sized ``/tmp`` for the compiler's
  temporary files, and one writable folder, :data:`COMPILE_WORKDIR`, bound from the host, that
  holds the source and receives the binary. The checkout, the problems' tests and answers, home
  folders and the host's ``/tmp`` are not in it; the paths a judge hides are covered where they lie
  under ``/usr``. New processes are allowed (no "no new processes" seccomp filter), the network,
  IPC, UTS and pid namespaces are new (no network), the rest of the seccomp deny-list applies;
* **a compiled program's run** (:data:`JAIL_PROGRAM`): the run jail of a Python submission, plus
  the binary bound read-only at :data:`JAIL_PROGRAM` and the C launcher that starts it
  (:mod:`grader.jail.launcher`) at :data:`JAIL_LAUNCHER`; the sandbox is asked to refuse new
  processes (``Sandbox(no_processes=True)``) as root too, since no audit hook watches a binary.

Run: nothing to run here; ``python -m grader.jail`` shows what the machine gives.

Example:
    >>> opts = compile_bwrap_options(["/usr", "/bin"], "/tmp/grader-build-x", 128, [])
    >>> opts[opts.index("--bind") + 1:opts.index("--bind") + 3]
    ['/tmp/grader-build-x', '/tmp/work']
"""

from __future__ import annotations

import os
from typing import Sequence

from .paths import under

#: Where the compile jail's writable folder (source in, binary out) is seen by the compiler.
COMPILE_WORKDIR = "/tmp/work"
#: Where a compiled program's binary is seen in its run jail (read-only).
JAIL_PROGRAM = "/submission/program"
#: Where the C launcher of compiled programs is seen in their run jail (read-only).
JAIL_LAUNCHER = "/submission/launcher"
#: The only ``/etc`` entries the compile jail shows: the dynamic loader's (the compiler's own
#: programs are dynamically linked).
COMPILE_ETC = ("/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives")
SYSTEM_TREES = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32")


def base_bwrap_options(trees: Sequence[str], etc: Sequence[str]) -> list[str]:
    """The options every jail starts with: all namespaces new, no capabilities, a new session, the
    system ``trees`` read-only (a link kept as a link, a missing tree skipped) and the ``etc`` files
    that exist.

    >>> base_bwrap_options((), ("/etc/ld.so.cache",))[-3:]
    ['--ro-bind-try', '/etc/ld.so.cache', '/etc/ld.so.cache']
    """
    a = ["--unshare-all", "--unshare-user", "--disable-userns", "--die-with-parent", "--new-session",
         "--cap-drop", "ALL", "--hostname", "sandbox"]
    for d in trees:
        if os.path.islink(d):
            a += ["--symlink", os.readlink(d), d]
        elif os.path.isdir(d):
            a += ["--ro-bind", d, d]
    for e in etc:
        a += ["--ro-bind-try", e, e]
    return a


def compile_bwrap_options(trees: Sequence[str], scratch: str, disk_mb: int, hidden: Sequence[str]) -> list[str]:
    """bubblewrap's options for the compile jail: ``trees`` (the system trees that exist, links
    kept as links), the loader's ``/etc`` files, ``/dev/null``, a ``disk_mb`` MiB ``/tmp``, the host
    folder ``scratch`` (staged for root) bound writable at :data:`COMPILE_WORKDIR`, every path of
    ``hidden`` that lies under ``/usr`` covered by an empty tmpfs, the new root read-only."""
    a = base_bwrap_options(trees, COMPILE_ETC)
    a += ["--size", "65536", "--perms", "0755", "--tmpfs", "/dev", "--dev-bind", "/dev/null", "/dev/null",
          "--remount-ro", "/dev",
          "--size", str(disk_mb << 20), "--perms", "1777", "--tmpfs", "/tmp",
          "--bind", scratch, COMPILE_WORKDIR]
    inside = [h for h in hidden if any(under(h, t) for t in trees if not os.path.islink(t))]
    for h in inside:
        a += ["--size", "4096", "--perms", "0755", "--tmpfs", h]
    for path in ["/", *inside]:
        a += ["--remount-ro", path]
    a += ["--chdir", COMPILE_WORKDIR]
    return a
