"""Path helpers shared by the jail's modules (no jail logic, no imports from the jail).

Example:
    >>> under("/usr/lib/x", "/usr"), under("/usrx", "/usr")
    (True, False)
    >>> outermost(["/a", "/a/b", "/c"])
    ['/a', '/c']
"""

from __future__ import annotations

import os
import sys
from typing import Sequence


def under(path: str, root: str) -> bool:
    """True when ``path`` is ``root`` or lies below it (string test on normalised paths)."""
    return path == root or path.startswith(root.rstrip("/") + "/")


def outermost(paths: Sequence[str]) -> list[str]:
    """The paths that lie below no other path of the list (order kept)."""
    return [p for p in paths if not any(p != o and under(p, o) for o in paths)]


def interpreter() -> str:
    """This interpreter's path as a jailed child can run it: ``sys.executable`` with its directory
    resolved and its own name kept. ``python`` found through ``PATH=$PWD/../.venv/bin`` (as the
    course's instructor steps set it, in ``assignments/``) is ``.../assignments/../.venv/bin/python``,
    and the jail covers the course folder that ``..`` passes through; the name stays unresolved
    because a venv's ``python`` link is what makes the interpreter that venv's.

    >>> import os, sys
    >>> interpreter() == os.path.join(os.path.realpath(os.path.dirname(sys.executable)), os.path.basename(sys.executable))
    True
    """
    return os.path.join(os.path.realpath(os.path.dirname(sys.executable)), os.path.basename(sys.executable))


def python_roots() -> list[str]:
    """Directories the child interpreter needs to read (installation prefixes, realpaths)."""
    roots = {os.path.realpath(p) for p in (sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix)}
    roots.add(os.path.realpath(os.path.dirname(sys.executable)))
    return sorted(r for r in roots if os.path.isdir(r))
