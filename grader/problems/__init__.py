"""Room 3, problems: the problem packages and what is made from them without judging.

========================  =================================================================
``package``               a package ``assignments/<id>/``: load, list, validate, materialise tests
``smallcases``            exhaustive small cases (``python -m grader.smallcases --write``)
``families``              small inputs at every scale (scaled, shifted, one-ulp nudges, far out) for the counterexample search
``statements``            the statements' generated "Limits and scoring" block
``cache``                 the cache of generated tests and parsed YAML: whom it trusts; ``python -m grader warm``
========================  =================================================================

Imports: :mod:`grader.judging` (the checker runtime and protocol) and :mod:`grader.jail`, never
the contest, classroom or course rooms. ``from grader.problems import load_problem, ...`` names
the package module's public names, re-exported here.

Example:
    >>> load_problem("delaunay").entry
    'delaunay'
"""

from .package import (ALWAYS_FORBIDDEN, COURSE_CONFIG, REPO, Group, Problem, TestCase, check_course, course_folder,
                      list_problems, load_problem, problems_root, using_course)
from .cache import cache_root

__all__ = ["ALWAYS_FORBIDDEN", "COURSE_CONFIG", "REPO", "Group", "Problem", "TestCase", "cache_root", "check_course",
           "course_folder", "list_problems", "load_problem", "problems_root", "using_course"]
