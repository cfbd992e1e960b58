"""The jail's refusals: grading stops with one clear line (the CLI prints it and exits 2).

:class:`JailUnavailable` is the base: no kernel jail can be built for this user, or (root) the
shared state the jail depends on cannot be trusted or is exhausted (:mod:`grader.jail.uidpool`).
The message is the whole explanation; the CLI prints ``error: <message>`` without a traceback.

Example:
    >>> issubclass(UnsafeSharedState, JailUnavailable) and issubclass(NoFreeSlot, JailUnavailable)
    True
"""

from __future__ import annotations

__all__ = ["JailUnavailable", "UnsafeSharedState", "NoFreeSlot"]


class JailUnavailable(RuntimeError):
    """No kernel jail can be built for this user: grading refuses (the message names the fixes)."""


class UnsafeSharedState(JailUnavailable):
    """Root's folder of sandbox-uid locks is not root's alone (wrong owner, writable by others, a
    symbolic link, not a directory): another account could hold or redirect the locks."""


class NoFreeSlot(JailUnavailable):
    """Every sandbox uid of root's pool stayed taken for the whole wait (too many concurrent sandboxes)."""
