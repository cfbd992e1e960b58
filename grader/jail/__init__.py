"""The grader's jail: everything that keeps student code from the grader's machine, in one place.

One entry point: :class:`Sandbox` (with :class:`Limits`) starts jailed children; the runner
(:mod:`grader.judging.runner`) talks to them. The modules, none importing a module that imports it back:

========================  =================================================================
``sandbox``               the jail: which kind (:func:`jail_kind`), rlimits, cleanup
``uidpool``               root's pool of sandbox uids; its lock folder, checked to be root's alone
``errors``                the refusals (:class:`JailUnavailable` and its kinds): one line, exit 2
``mounts``                root's child side: staging for bubblewrap, the ``namespaces`` jail
``cgroups``               accounting of a whole sandbox: cgroup v1/v2, ``/proc`` sums
``tmpfs``                 the writable ``/tmp`` and ``/dev/shm``: sizes within the memory limit, use
``seccomp``               the seccomp-BPF filter (denied calls; no new processes, not root)
``engines``               every installed copy of the forbidden packages and engines
``fontcache``             matplotlib's font cache, built outside the jail
``paths``, ``procs``      path and process-table helpers
``doctor``                ``python -m grader.jail``: what this machine gives to root and to this user
``launcher``              the C launcher of compiled programs (``launcher.c``), built once into the trusted cache
``trust``                 whom a cached file must belong to (also the test cache's rule)
``child_bootstrap.py``    the child side (stdlib only, run by path, never imported)
========================  =================================================================

The jail is the bottom room of the grader (``grader/README.md``'s map): it imports the standard
library only, never another room. ``python -m grader.sandbox`` is kept as an alias of the doctor.

Example:
    >>> from grader.jail import Limits, Sandbox
    >>> Limits(cpu_s=1).cpu_s
    1
"""

from pathlib import Path

#: The child's program (run with ``python -IS -c``; the grader's directory is not visible in the jail).
BOOTSTRAP_PATH = Path(__file__).with_name("child_bootstrap.py")

#: Where each public name lives. They load on first use (PEP 562), so a module that needs one small
#: part of the jail (``grader.jail.trust``, the launcher's cache) does not load the sandbox.
_LAZY = {name: "errors" for name in ("JailUnavailable", "NoFreeSlot", "UnsafeSharedState")} | {
    name: "sandbox" for name in ("JAIL_ENV", "JAIL_WORKDIR", "LOCK_DIR", "TRUSTED_ENV", "UID_BASE",
                                 "Limits", "Sandbox", "bwrap_path", "is_root", "jail_kind", "mechanism",
                                 "python_roots", "refusal_message", "refuses_processes", "require_jail",
                                 "uid_processes")}


def __getattr__(name: str):
    if name in _LAZY:
        from importlib import import_module
        value = getattr(import_module(f".{_LAZY[name]}", __name__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["BOOTSTRAP_PATH", "JAIL_ENV", "JAIL_WORKDIR", "LOCK_DIR", "TRUSTED_ENV", "UID_BASE", "JailUnavailable",
           "NoFreeSlot", "UnsafeSharedState",
           "Limits", "Sandbox", "bwrap_path", "is_root", "jail_kind", "mechanism", "python_roots", "refusal_message",
           "refuses_processes", "require_jail", "uid_processes"]
