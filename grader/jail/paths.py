"""Path helpers shared by the jail's modules (no jail logic, no imports from the jail).

Example:
    >>> under("/usr/lib/x", "/usr"), under("/usrx", "/usr")
    (True, False)
    >>> outermost(["/a", "/a/b", "/c"])
    ['/a', '/c']
"""

from __future__ import annotations

import functools
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
    """Directories the child interpreter needs to read (installation prefixes, realpaths; found
    once a process: the interpreter does not move)."""
    return list(_python_roots())


@functools.lru_cache(maxsize=1)
def _python_roots() -> tuple[str, ...]:
    roots = {os.path.realpath(p) for p in (sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix)}
    roots.add(os.path.realpath(os.path.dirname(sys.executable)))
    return tuple(sorted(r for r in roots if os.path.isdir(r)))


@functools.lru_cache(maxsize=1)
def site_paths() -> tuple[str, ...] | None:
    """The directories ``site`` puts on ``sys.path`` for this interpreter started with ``-I``
    (its site-packages and the directory lines of their ``.pth`` files), for a child started with
    ``-I -S``: it gets the same installed packages without running the ``.pth`` files' code (an
    editable install's import finder costs more CPU than the interpreter's own start). None when
    this interpreter itself runs without ``site`` (``-S``): the child then keeps its ``site``.

    >>> paths = site_paths()
    >>> paths is None or all(os.path.isdir(p) for p in paths)
    True
    """
    if sys.flags.no_site:
        return None
    import site

    out: list[str] = []
    for base in site.getsitepackages():
        if not os.path.isdir(base) or base in out:
            continue
        out.append(base)
        try:
            names = sorted(n for n in os.listdir(base) if n.endswith(".pth") and not n.startswith("."))
        except OSError:
            continue
        for name in names:
            try:
                with open(os.path.join(base, name), encoding="utf-8") as f:
                    lines = f.read().splitlines()
            except (OSError, UnicodeDecodeError):
                continue
            for line in lines:
                line = line.rstrip()
                if not line or line.startswith(("#", "import ", "import\t")):
                    continue
                path = os.path.abspath(os.path.join(base, line))
                if os.path.isdir(path) and path not in out:
                    out.append(path)
    return tuple(out)
