"""Benchmark of the judge's own cost (target: under 1.5 s of overhead for 30 tests).

1. Judge overhead: a trivial-compute submission on a 30-test function-mode problem; overhead =
   judge wall time minus the submission's own measured time, in-process and via the CLI.
2. Class grading: ``grade --jobs 1`` vs ``--jobs 2`` on a small class (prints the speed-up).

Run: .venv/bin/python benchmarks/bench_grader.py [--students 6]
Prints numbers only; nothing is asserted (tests assert behaviour, not timings).
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from grader.classroom.classgrade import grade_class  # noqa: E402
from grader.contest.judge import Judge  # noqa: E402
from grader.problems import Problem  # noqa: E402

TRIVIAL = "def delaunay(points):\n    return []\n"  # all tests are collinear: no triangles is right


def make_problem(root: Path, n_tests: int = 30) -> Path:
    p = root / "bench30"
    (p / "statement").mkdir(parents=True)
    (p / "input_validators").mkdir()
    (p / "statement" / "problem.en.md").write_text("# benchmark\n")
    (p / "problem.yaml").write_text("problem_format_version: 2023-07-draft\nname: bench\nlimits: {time_limit: 2, memory: 512, output: 8}\n")
    cases = "\n".join(f"      - {{kind: collinear, n: {3 + k}}}" for k in range(n_tests))
    (p / "course.yaml").write_text(
        f"entry: delaunay\nforbidden: [scipy.spatial]\nchecker: {REPO}/assignments/delaunay/output_validator/checker.py\n"
        f"generator: {REPO}/assignments/delaunay/generators/generator.py\nseed: 1\n"
        f"groups:\n  - name: all\n    points: 30\n    cases:\n{cases}\n")
    return p


def bench_overhead(tmp: Path, repeats: int = 3) -> None:
    prob = make_problem(tmp)
    sub = tmp / "trivial.py"
    sub.write_text(TRIVIAL)
    judge = Judge(Problem.load(prob))
    judge.judge_path(sub)  # warm caches (tests generated, checker loaded)
    rows = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        r = judge.judge_path(sub)
        wall = time.perf_counter() - t0
        own = sum(t.time_s for t in r.tests)
        rows.append((wall, own, r.verdict, len(r.tests)))
    best = min(rows)
    print(f"judge, in process: {best[3]} tests, verdict {best[2]}: wall {best[0]:.3f} s, submission's own time "
          f"{best[1]:.3f} s, overhead {best[0] - best[1]:.3f} s ({1000 * (best[0] - best[1]) / best[3]:.1f} ms/test, "
          f"target < 1.5 s)")
    env = {**os.environ, "GRADER_PROBLEMS": str(tmp)}
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "grader", "judge", "bench30", str(sub), "--json"], cwd=REPO, env=env,
                   check=True, capture_output=True)
    cli = time.perf_counter() - t0
    print(f"judge, whole CLI process (python start, imports, judging): {cli:.3f} s")


def bench_jobs(tmp: Path, students: int) -> None:
    src = (REPO / "solutions" / "bowyer-watson-timed" / "accepted_scan.py").read_text()
    root = tmp / "class"
    for k in range(students):
        (root / f"s{k:02d}").mkdir(parents=True)
        (root / f"s{k:02d}" / "sol.py").write_text(src + f"\n# student {k}\n")
    Judge("bowyer-watson-timed")  # materialise tests once
    times = {}
    for jobs in (1, 2):
        db = tmp / f"jobs{jobs}.sqlite"
        t0 = time.perf_counter()
        out = grade_class("bowyer-watson-timed", root, db, jobs=jobs, progress=False)
        times[jobs] = time.perf_counter() - t0
        assert all(s["verdict"] == "AC" for s in out), out
    print(f"grade bowyer-watson-timed, {students} students: --jobs 1 {times[1]:.2f} s, --jobs 2 {times[2]:.2f} s, "
          f"speed-up {times[1] / times[2]:.2f}x on {os.cpu_count()} cores (load average now "
          f"{os.getloadavg()[0]:.1f})")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--students", type=int, default=6)
    a = ap.parse_args()
    tmp = Path(tempfile.mkdtemp(prefix="bench-grader-"))
    try:
        bench_overhead(tmp)
        bench_jobs(tmp, a.students)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
