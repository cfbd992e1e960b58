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


def python_roots() -> list[str]:
    """Directories the child interpreter needs to read (installation prefixes, realpaths)."""
    roots = {os.path.realpath(p) for p in (sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix)}
    roots.add(os.path.realpath(os.path.dirname(sys.executable)))
    return sorted(r for r in roots if os.path.isdir(r))
