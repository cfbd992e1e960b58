"""Old import name of :mod:`grader.jail.fontcache` (the jail's modules live in ``grader/jail/``).

``import grader.fontcache`` gives the very module object ``grader.jail.fontcache``, so attributes read or
monkeypatched through either name are the same.
"""
import sys

from .jail import fontcache as _module

sys.modules[__name__] = _module
if __name__ == "__main__":  # python -m grader.fontcache: the module's own command
    _module.main()
