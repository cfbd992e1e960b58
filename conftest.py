"""Repository-wide pytest settings: which files are not test or doctest modules.

`make test` runs pytest with --doctest-modules over tests/, reference_impl/ and grader/;
the files below are data for the tests (hostile student submissions, fixtures) or
programs that talk on stdin (the sandbox's child bootstrap), never modules to import.
"""
collect_ignore_glob = [
    "tests/grader/hostile/*",
    "tests/grader/fixtures/*",
    "grader/jail/child_bootstrap.py",
    "solutions/*",
    "assignments/*",
    "build/*",
]


def pytest_configure(config):
    """Drop numba machine code compiled against since-edited library modules (importing the
    package never does; ``make test`` has already run the warm-up, which does the same)."""
    if not hasattr(config, "workerinput"):  # once, in the controlling process
        from reference_impl._jitcache import purge_stale_cache
        purge_stale_cache()
