"""Alias of :mod:`grader.course.student_edition`, kept for the documented command ``python -m
grader.student_edition OUTDIR``.

``grader.student_edition`` is the very module object ``grader.course.student_edition`` (names read or
monkeypatched through either are the same); ``python -m grader.student_edition ...`` runs its command.
See "Upgrading a course deployed before the move" in ``grader/README.md``.
"""

from ._alias import alias

alias(__name__, "grader.course.student_edition")
