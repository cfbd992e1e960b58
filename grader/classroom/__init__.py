"""Room 5, classroom: a whole class's submissions.

========================  =================================================================
``classgrade``            ``grade``: every student's folder, in parallel, resumable
``store``                 the SQLite results store
``scoreboard``            the contest scoreboard from a store
``timed``                 timed attempts (start, status, submit)
``regrade``               per-group store keys, carried-over results, regrade diffs
``extensions``            per-student extensions (``extensions.yaml`` of the course)
``similarity``            who shares code: fingerprints of every pair and of references
``similarity_report``     the similarity pages and ``run()``
``code_from_data``        code carried as data, decoded statically (never run)
``data_decoders``         the whitelist of pure decoders ``code_from_data`` may evaluate
========================  =================================================================

Imports: :mod:`grader.contest`, :mod:`grader.problems`, :mod:`grader.judging`,
:mod:`grader.jail`; never the course room.
"""
