"""Old import name of :mod:`grader.jail.engines` (the jail's modules live in ``grader/jail/``).

``import grader.engines`` gives the very module object ``grader.jail.engines``, so attributes read or
monkeypatched through either name are the same.
"""
import sys

from .jail import engines as _module

sys.modules[__name__] = _module
if __name__ == "__main__":  # python -m grader.engines: the module's own command
    _module.main()
