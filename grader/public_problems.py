"""Alias of :mod:`grader.course.public_problems`, kept for the documented command ``python -m
grader.public_problems`` (the hub's ``deploy.sh`` runs it).

``grader.public_problems`` is the very module object ``grader.course.public_problems`` (names read or
monkeypatched through either are the same); ``python -m grader.public_problems ...`` runs its command.
See "Upgrading a course deployed before the move" in ``grader/README.md``.
"""

from ._alias import alias

alias(__name__, "grader.course.public_problems")
