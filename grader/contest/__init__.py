"""Room 4, contest: the judging loop over a problem's tests, and the tools built on it.

========================  =================================================================
``judge``                 :class:`Judge`: every test of a problem, groups, scores, the verdict
``report``                one submission's HTML report (``judge --report``)
``stress``                the smallest input a submission gets wrong
``kattis``                export of a problem as a Kattis package (and its expected verdicts)
``sample_check``          the notebooks' sample check (``%check_samples``)
========================  =================================================================

``stress`` and ``kattis`` are problem tools and ``sample_check`` a course tool, but all three run
the judging loop, so they sit here, above it. Imports: :mod:`grader.problems`,
:mod:`grader.judging`, :mod:`grader.jail`; never the classroom or course rooms.
"""
