"""Alias of :mod:`grader.problems.smallcases`, kept for the documented command ``python -m
grader.smallcases --write``.

``grader.smallcases`` is the very module object ``grader.problems.smallcases`` (names read or
monkeypatched through either are the same); ``python -m grader.smallcases ...`` runs its command. See
"Upgrading a course deployed before the move" in ``grader/README.md``.
"""

from ._alias import alias

alias(__name__, "grader.problems.smallcases")
