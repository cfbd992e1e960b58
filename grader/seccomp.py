"""Old import name of :mod:`grader.jail.seccomp` (the jail's modules live in ``grader/jail/``).

``import grader.seccomp`` gives the very module object ``grader.jail.seccomp``, so attributes read or
monkeypatched through either name are the same.
"""
import sys

from .jail import seccomp as _module

sys.modules[__name__] = _module
if __name__ == "__main__":  # python -m grader.seccomp: the module's own command
    _module.main()
