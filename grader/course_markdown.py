"""Alias of :mod:`grader.course.course_markdown`, kept for the documented command ``python -m
grader.course_markdown``.

``grader.course_markdown`` is the very module object ``grader.course.course_markdown`` (names read or
monkeypatched through either are the same); ``python -m grader.course_markdown ...`` runs its command.
See "Upgrading a course deployed before the move" in ``grader/README.md``.
"""

from ._alias import alias

alias(__name__, "grader.course.course_markdown")
