"""Alias of :mod:`grader.course.nbgrader_autograde`, kept for courses deployed before the move: their
``nbgrader_config.py`` names ``grader.nbgrader_autograde.JudgeCells`` and ``CourseLatePolicy``.

``grader.nbgrader_autograde`` is the very module object ``grader.course.nbgrader_autograde`` (names read
or monkeypatched through either are the same); ``python -m grader.nbgrader_autograde ...`` runs its
command. See "Upgrading a course deployed before the move" in ``grader/README.md``.
"""

from ._alias import alias

alias(__name__, "grader.course.nbgrader_autograde")
