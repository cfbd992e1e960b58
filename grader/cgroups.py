"""Old import name of :mod:`grader.jail.cgroups` (the jail's modules live in ``grader/jail/``).

``import grader.cgroups`` gives the very module object ``grader.jail.cgroups``, so attributes read or
monkeypatched through either name are the same.
"""
import sys

from .jail import cgroups as _module

sys.modules[__name__] = _module
if __name__ == "__main__":  # python -m grader.cgroups: the module's own command
    _module.main()
