"""Alias of :mod:`grader.contest.sample_check`, kept for released notebooks: their first cell runs
``%load_ext grader.sample_check``.

``grader.sample_check`` is the very module object ``grader.contest.sample_check`` (names read or
monkeypatched through either are the same). See "Upgrading a course deployed before the move" in
``grader/README.md``.
"""

from ._alias import alias

alias(__name__, "grader.contest.sample_check")
