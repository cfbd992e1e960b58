"""The kernels' one status convention, and the one place a status becomes an exception.

A numba kernel cannot raise a useful exception, so every kernel that can end in
more than one way says how in one integer.  All statuses are negative, so a
kernel may return either a vertex or triangle index (>= 0) or a status:

=========  ==========================================================  ==========================
status     meaning                                                     the caller
=========  ==========================================================  ==========================
OK         done (``insert``: the point became a new vertex)             goes on
GROW       the scratch or mesh arrays are too small; nothing changed    enlarges them, calls again
FLAT       what is left is degenerate (collinear in 2D, coplanar in     switches to its flat
           3D): nothing built or changed                               representation
CROSSING   two input segments properly cross: the user's input          raises ``ValueError``
                                                                        naming the two segments
LOST       a walk or a sanity check failed: never expected, and the     ``check`` raises
           mesh is left as it was                                      ``KernelError``
BUDGET     a build in a cheap but risky order ran past its work cap     builds again in the safe
           (``kernel.build``; the mesh is unfinished)                  (BRIO) order
=========  ==========================================================  ==========================

Used by ``kernel`` and ``removal`` (2D), ``kernel3d`` (3D) and the constrained
triangulation's segment insertion.

>>> check(OK, "insert")
-1
>>> check(LOST, "constrained Delaunay: the segment walk")
Traceback (most recent call last):
    ...
reference_impl.mesh.status.KernelError: constrained Delaunay: the segment walk failed (status LOST); please report this input
"""
from __future__ import annotations

OK = -1
GROW = -3
FLAT = -4
CROSSING = -5
LOST = -6
BUDGET = -7

NAMES = {OK: "OK", GROW: "GROW", FLAT: "FLAT", CROSSING: "CROSSING", LOST: "LOST", BUDGET: "BUDGET"}


class KernelError(RuntimeError):
    """A kernel reported a failure that correct code never meets (status LOST)."""


def check(status: int, what: str) -> int:
    """Return ``status`` (as an int) if it is one a caller handles; raise ``KernelError`` for LOST
    or for a code that is not a status at all."""
    status = int(status)
    if status == LOST:
        raise KernelError(f"{what} failed (status LOST); please report this input")
    if status not in NAMES:
        raise KernelError(f"{what}: unknown status {status}")
    return status
