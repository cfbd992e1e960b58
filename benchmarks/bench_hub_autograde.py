"""Students per minute: a synthetic class of one problem autograded the course's way vs nbgrader's kernel way.

The class: N submissions of `bowyer-watson-timed` (tests/nbgrader/fake_class.py's released notebook,
alternating the accepted scan and the tutorial's wrong code in the first solution cell), collected
into two identical course roots. Side by side:
  * the course's path: `grade_course` (the sandboxed judge, `--jobs` workers, then `nbgrader autograde`
    from the stored results), what formgrader's Autograde runs on the course server;
  * nbgrader's plain autograde: the same notebooks executed in a kernel each, one by one (the
    course config with nbgrader's own `Execute` step put back).

Run (as root, or as the instructor's account):
    .venv/bin/python benchmarks/bench_hub_autograde.py [--students 200] [--jobs 2]
"""
from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "nbgrader"))

from fake_class import Student, _solution, collected_class, gradebook_scores  # noqa: E402

from grader.course.nbgrader_autograde import grade_course, run_nbgrader  # noqa: E402
from grader.problems import load_problem  # noqa: E402

PROBLEM = "bowyer-watson-timed"
PLAIN = """
# benchmark only: nbgrader's own kernel execution instead of the course's judge
from nbgrader.preprocessors import Execute
c.Autograde.autograde_preprocessors = [Execute, LimitOutput, SaveAutoGrades, AssignLatePenalties, CheckCellMetadata]
"""


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--students", type=int, default=200)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    if a.students < 1:
        raise ValueError("--students must be at least 1")
    load_problem(PROBLEM).tests()
    right, wrong = _solution("accepted_scan.py"), _solution("wrong_tutorial.py")
    klass = [Student(f"s{k:03d}", right if k % 2 == 0 else wrong) for k in range(a.students)]
    with tempfile.TemporaryDirectory(prefix="bench-hub-") as tmp:
        course = collected_class(Path(tmp), PROBLEM, klass)
        plain = Path(tmp) / "plain"
        shutil.copytree(course.root, plain)
        with open(plain / "nbgrader_config.py", "a") as f:
            f.write(PLAIN)
        t0 = time.perf_counter()
        grade_course(PROBLEM, course.root / "submitted", jobs=a.jobs, autograde=True)
        ours = time.perf_counter() - t0
        t0 = time.perf_counter()
        run_nbgrader(plain, "autograde", PROBLEM, check=False)
        theirs = time.perf_counter() - t0
        graded = [gradebook_scores(r, PROBLEM) for r in (course.root, plain)]
    n = len(klass)
    print(f"{n} submissions of {PROBLEM} on this machine:\n"
          f"  course path (sandboxed judge, --jobs {a.jobs}, then nbgrader autograde): {ours:7.1f} s  "
          f"{60 * n / ours:6.1f} students/min\n"
          f"  nbgrader plain kernel autograde (one by one):                 {theirs:7.1f} s  "
          f"{60 * n / theirs:6.1f} students/min\n"
          f"  scored in the gradebook: course {len(graded[0])}, plain {len(graded[1])}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
