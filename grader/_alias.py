"""How an old module name stays an alias of its new module (``grader/README.md``, "Upgrading a
course deployed before the move").

An alias module calls :func:`alias` with its own ``__name__``: imported, it becomes the very module
object it names (``sys.modules`` holds the new module under the old name, so names read or
monkeypatched through either are the same); run with ``python -m``, it runs the new module's
``main``.
"""
from __future__ import annotations

import importlib
import sys
from types import ModuleType
from typing import Callable


def alias(name: str, target: str, command: Callable[[ModuleType], int | None] | None = None) -> ModuleType:
    """Make the module ``name`` (the caller's ``__name__``) an alias of ``target``; as ``__main__``,
    exit with ``command(module)`` (default: the module's ``main()``).

    >>> import grader.nbgrader_autograde as old
    >>> old.__name__
    'grader.course.nbgrader_autograde'
    """
    module = importlib.import_module(target)
    if name == "__main__":
        sys.exit((command or (lambda m: m.main()))(module))
    sys.modules[name] = module
    return module
