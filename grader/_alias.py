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

    The alias's own module object (if something holds it already, as a test runner importing the
    file by its path does) gets the target's names too.

    >>> alias("grader.example_alias", "grader.judging.languages").SUFFIXES
    ('.py', '.ipynb', '.cpp', '.cc', '.cxx')
    >>> sys.modules.pop("grader.example_alias").__name__
    'grader.judging.languages'
    """
    module = importlib.import_module(target)
    if name == "__main__":
        sys.exit((command or (lambda m: m.main()))(module))
    own = sys.modules.get(name)
    if own is not None and own is not module:
        own.__dict__.update({k: v for k, v in vars(module).items() if not k.startswith("__")})
    sys.modules[name] = module
    return module
