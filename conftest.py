"""Repository-wide pytest settings: which files are not test or doctest modules, and the order
in which the tests start.

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


def pytest_collection_modifyitems(items):
    """The tests marked ``slow`` start first (a stable sort: otherwise in collection order).

    ``make test`` runs ``pytest -n 2 --dist loadgroup``: pytest-xdist hands out the groups of
    several tests first (largest first), then single tests in collection order, so a long test
    collected late (``tests/nbgrader/test_docs.py``, minutes) would start when the other worker
    has nothing left and make the run's tail. Started early, the many short tests fill in beside it.
    """
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)
