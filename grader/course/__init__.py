"""Room 6, course: the nbgrader course built on the judge.

========================  =================================================================
``nbgrader_autograde``    nbgrader's autograde by the judge (``JudgeCells``, the late penalty)
``course_notebooks``      the assignment notebooks generated from the problem packages
``course_markdown``       statement markdown as nbgrader and formgrader render it
``student_edition``       what a student receives (``python -m grader.student_edition OUTDIR``)
``public_problems``       the problems without their hidden tests, for students' machines
``grades_export``         the course's grades for Canvas and Moodle (``export-grades``)
``numba_seed``            the course server's compiled kernels, copied into each new account's cache
========================  =================================================================

Imports: every room below (classroom, contest, problems, judging, jail). The old module names
``grader.nbgrader_autograde``, ``grader.course_notebooks``, ``grader.course_markdown``,
``grader.student_edition`` and ``grader.public_problems`` are aliases of these modules, kept for
courses deployed before the move (see ``grader/README.md``).
"""
