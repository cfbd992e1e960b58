"""Students per minute: a synthetic class of one problem autograded the course's way vs nbgrader's kernel way.

The class: N submissions of one problem (`--problem`, default `bowyer-watson-timed`; the course's
released notebook, alternating an accepted solution and a wrong one (`--wrong`; default: the
tutorial's code on `bowyer-watson-timed`, which fails every group, one by a TLE of the 6 s limit;
on `delaunay` `wrong_super_float.py`, a WA on one group: the tutorial's code there TLEs on three
groups, 18 CPU-s a student whatever the grader does) in the first solution cell), collected into
identical course roots. Side by side:
  * the course's path: `grade_course` (the sandboxed judge, `--jobs` workers, then `nbgrader autograde`
    from the stored results), what formgrader's Autograde runs on the course server;
  * with `--dask N`, the same path on a local Dask distributed cluster of N worker processes
    (`python -m grader grade --nbgrader --scheduler ADDRESS`);
  * nbgrader's plain autograde: the same notebooks executed in a kernel each, one by one (the
    course config with nbgrader's own `Execute` step put back).
The rates are scores only (no counterexample search); `--searches` then runs the searches for the
failed notebooks (the problem's `course.yaml` budget, `--jobs` at a time) and reports their cost apart.

Run (as root, or as the instructor's account):
    .venv/bin/python benchmarks/bench_hub_autograde.py [--students 200] [--jobs 2] [--problem delaunay] [--dask 2]
"""
from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "nbgrader"))

from fake_class import Student, _solution, collected_class, gradebook_scores  # noqa: E402

from grader.course.nbgrader_autograde import STORE_NAME, grade_course, run_nbgrader  # noqa: E402
from grader.problems import load_problem  # noqa: E402

#: per problem: (accepted, wrong) under solutions/<problem>/
CLASSES = {"bowyer-watson-timed": ("accepted_scan.py", "wrong_tutorial.py"),
           "delaunay": ("accepted_walk.py", "wrong_super_float.py")}
PLAIN = """
# benchmark only: nbgrader's own kernel execution instead of the course's judge
from nbgrader.preprocessors import Execute
c.Autograde.autograde_preprocessors = [Execute, LimitOutput, SaveAutoGrades, AssignLatePenalties, CheckCellMetadata]
"""


def _searches(problem_id: str, root: Path, jobs: int) -> tuple[int, float, float]:
    """The counterexample searches of the failed notebooks in ``root``: (how many, their seconds, wall)."""
    from grader.classroom.class_counterexamples import pending, run_searches
    from grader.classroom.store import ResultStore

    problem = load_problem(problem_id)
    collected = {d.name: str(d / problem_id / f"{problem_id}.ipynb") for d in (root / "submitted").iterdir()}
    store = ResultStore(root / STORE_NAME)
    try:
        todo = pending(store, problem, collected)
    finally:
        store.close()
    t0 = time.perf_counter()
    n, seconds = run_searches(problem_id, todo, root / STORE_NAME, None, jobs)
    return n, seconds, time.perf_counter() - t0


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--students", type=int, default=200)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--problem", default="bowyer-watson-timed", choices=sorted(CLASSES))
    ap.add_argument("--wrong", help="the wrong solution under solutions/PROBLEM/ (default: see above)")
    ap.add_argument("--dask", type=int, default=0, metavar="N",
                    help="also grade the class on a local Dask cluster of N worker processes")
    ap.add_argument("--searches", action="store_true", help="then time the counterexample searches (reported apart)")
    ap.add_argument("--no-plain", action="store_true", help="skip nbgrader's plain kernel autograde")
    a = ap.parse_args()
    if a.students < 1:
        raise ValueError("--students must be at least 1")
    if a.dask < 0:
        raise ValueError("--dask must be 0 (no Dask run) or a number of workers")
    problem = a.problem
    load_problem(problem).tests()
    names = (CLASSES[problem][0], a.wrong or CLASSES[problem][1])
    right, wrong = (_solution(name, problem) for name in names)
    klass = [Student(f"s{k:03d}", right if k % 2 == 0 else wrong) for k in range(a.students)]
    print(f"load average at the start: {' '.join(f'{x:.2f}' for x in os.getloadavg())}", flush=True)
    times: dict[str, float] = {}
    with tempfile.TemporaryDirectory(prefix="bench-hub-") as tmp:
        course = collected_class(Path(tmp), problem, klass)
        roots = {"course": course.root}
        for name in ["plain"] * (not a.no_plain) + ["dask"] * bool(a.dask):
            roots[name] = Path(tmp) / name
            shutil.copytree(course.root, roots[name])
        if "plain" in roots:
            with open(roots["plain"] / "nbgrader_config.py", "a") as f:
                f.write(PLAIN)
        t0 = time.perf_counter()
        grade_course(problem, course.root / "submitted", jobs=a.jobs, autograde=True)
        times["course"] = time.perf_counter() - t0
        if a.dask:
            from distributed import LocalCluster

            with LocalCluster(n_workers=a.dask, threads_per_worker=1, processes=True, dashboard_address=None) as cl:
                t0 = time.perf_counter()
                grade_course(problem, roots["dask"] / "submitted", autograde=True, scheduler=cl.scheduler_address)
                times["dask"] = time.perf_counter() - t0
        if "plain" in roots:
            t0 = time.perf_counter()
            run_nbgrader(roots["plain"], "autograde", problem, check=False)
            times["plain"] = time.perf_counter() - t0
        graded = {name: gradebook_scores(r, problem) for name, r in roots.items()}
        found = _searches(problem, course.root, a.jobs) if a.searches else None
    n = len(klass)
    rate = {k: 60 * n / v for k, v in times.items()}
    labels = {"course": f"course path (sandboxed judge, --jobs {a.jobs}, then nbgrader autograde)",
              "dask": f"course path on a local Dask cluster ({a.dask} worker processes)",
              "plain": "nbgrader plain kernel autograde (one by one)"}
    print(f"{n} submissions of {problem} on this machine ({names[0]} and {names[1]} alternating):")
    for k, v in times.items():
        ratio = f"  x{rate[k] / rate['plain']:.2f} stock" if "plain" in rate and k != "plain" else ""
        print(f"  {labels[k]:70} {v:7.1f} s  {rate[k]:6.1f} students/min{ratio}")
    print("  scored in the gradebook: " + ", ".join(f"{k} {len(g)}" for k, g in graded.items()))
    if "dask" in graded:
        same = {s: g["score"] for s, g in graded["dask"].items()} == {s: g["score"] for s, g in graded["course"].items()}
        print(f"  Dask gradebook scores {'equal' if same else 'DIFFER FROM'} the pool path's")
    if found is not None:
        k, seconds, wall = found
        print(f"  counterexample searches after the scores: {k} searches, {seconds:.1f} s of searching, "
              f"{wall:.1f} s wall with {a.jobs} at a time (not in the rates above)")
    print(f"load average at the end: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
