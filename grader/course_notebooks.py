"""Alias of :mod:`grader.course.course_notebooks`, kept for courses deployed before the move: their
``nbgrader_config.py`` imports ``CODE_STUB`` from it.

``grader.course_notebooks`` is the very module object ``grader.course.course_notebooks`` (names read or
monkeypatched through either are the same); ``python -m grader.course_notebooks ...`` runs its command.
See "Upgrading a course deployed before the move" in ``grader/README.md``.
"""

from ._alias import alias

alias(__name__, "grader.course.course_notebooks")
