"""Time autograding the nbgrader fake class: nbgrader's one-by-one autograde vs the parallel path.

Both start from the same collected class (tests/nbgrader/fake_class.py: 11 students of
`bowyer-watson-timed`) in two fresh course copies, with the hidden tests already generated.

Run (as root, like the course server):
    .venv/bin/python benchmarks/bench_nbgrader.py [--jobs 2]
"""

from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "nbgrader"))

from fake_class import collected_class, gradebook_scores, students  # noqa: E402

from grader.course.nbgrader_autograde import grade_course, run_nbgrader  # noqa: E402
from grader.problems import load_problem  # noqa: E402

PROBLEM = "bowyer-watson-timed"


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    load_problem(PROBLEM).tests()
    with tempfile.TemporaryDirectory(prefix="bench-nbgrader-") as tmp:
        klass = students()
        course = collected_class(Path(tmp), PROBLEM, klass)
        twin = Path(tmp) / "twin"
        shutil.copytree(course.root, twin)
        t0 = time.perf_counter()
        course.nbgrader("autograde", PROBLEM)
        one = time.perf_counter() - t0
        t0 = time.perf_counter()
        grade_course(PROBLEM, twin / "submitted", jobs=a.jobs, autograde=False)  # the pool
        pool = time.perf_counter() - t0
        run_nbgrader(twin, "autograde", PROBLEM, "--force")  # what grade_course runs next
        par = time.perf_counter() - t0
        same = gradebook_scores(course.root, PROBLEM) == gradebook_scores(twin, PROBLEM)
    print(f"{len(klass)} students of {PROBLEM}: nbgrader autograde one by one {one:.1f} s; "
          f"python -m grader grade --nbgrader --jobs {a.jobs} {par:.1f} s ({one / par:.2f}x; judging pool {pool:.1f} s, "
          f"then nbgrader autograde from the stored results {par - pool:.1f} s); same gradebook: {same}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
