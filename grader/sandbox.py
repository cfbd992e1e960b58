"""Old import name of :mod:`grader.jail.sandbox` (the jail's modules live in ``grader/jail/``).

``import grader.sandbox`` gives the very module object ``grader.jail.sandbox``, so attributes read or
monkeypatched through either name are the same.
"""
import sys

from .jail import sandbox as _module

sys.modules[__name__] = _module
if __name__ == "__main__":  # python -m grader.sandbox: the doctor
    from .jail.doctor import main
    sys.exit(main(sys.argv[1:]))
