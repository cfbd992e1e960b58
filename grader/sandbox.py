"""Alias: ``python -m grader.sandbox`` is the jail doctor (``python -m grader.jail``), kept because
refusal messages, the READMEs and deployed courses' notes name it.

``import grader.sandbox`` still gives the very module object :mod:`grader.jail.sandbox` (names read
or monkeypatched through either are the same). See "Upgrading a course deployed before the move"
in ``grader/README.md``.
"""

import sys
from types import ModuleType

from ._alias import alias


def _doctor(_module: ModuleType) -> int:
    """The jail doctor, as ``python -m grader.jail`` runs it."""
    from .jail.doctor import main
    return main(sys.argv[1:])


alias(__name__, "grader.jail.sandbox", _doctor)
