"""Room 2, judging: one submission run in the jail and its answers checked.

========================  =================================================================
``runner``                the parent side of a jailed run: function mode and stdio mode
``frames``                a long float answer as a binary frame: the parent's checked decoder
``languages``             languages as data: suffixes, how a file becomes code, compile and run rules
``submissions``           reading a ``.py``/``.ipynb`` safely; function or stdio mode
``verdicts``              verdicts, per-test and overall results, the table
``text``                  sanitising text that comes from a submission
``check_budget``          the checker's CPU budget
``checker_runtime``       the one checker loader (stdlib only: exported validators load it by path)
``checker_protocol``      the checker protocol ``validate`` checks
``checker_attacks``       hostile answers every checker must survive
``hidden_feedback``       what a student sees of a hidden test
``feedback_policy``       how much of a failing test a student sees, per group (``feedback:``)
========================  =================================================================

Imports: the standard library, :mod:`grader.jail` and :mod:`reference_impl` only; never the
problems, contest, classroom or course rooms (the judging loop, which uses problems, is
:mod:`grader.contest.judge`). A new language is one entry in :mod:`grader.judging.languages`.
"""
