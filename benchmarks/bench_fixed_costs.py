"""The judge's fixed costs, one checkout against another under the same load (issue 42, item 2).

Grades two empty-work classes (``bench-empty-1`` and ``bench-empty-200``: ``return []`` on
collinear points, every test AC) with each checkout in turn, round after round, each ``grade``
command's CPU counted with everything it starts (the cgroup or ``/proc`` meter of
``bench_judge_overhead.py``). A later student's CPU (mean of students 2..n) gives, by difference,

* the fixed cost of one function-mode test: (200-test student - 1-test student) / 199;
* the fixed cost of one submission (jail, child start, bookkeeping): the 1-test student minus one test.

Alternating the checkouts puts both under the same machine load, so the comparison holds where
a lone run's CPU moves by tens of percent with the load. Round 0 only warms the caches.

Run (``before`` a copy of another commit, e.g. ``git archive main | tar -x -C /tmp/main-src``)::

    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_fixed_costs.py --rounds 2 --students 5 \\
        before=/tmp/main-src after=$PWD

Example output::

    before: later student CPU s: 1 test 0.0722, 200 tests 0.3597 (8 samples); per-test 1.444 ms, per-submission 0.0708 s
    after: later student CPU s: 1 test 0.0400, 200 tests 0.1345 (8 samples); per-test 0.475 ms, per-submission 0.0396 s
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_judge_overhead as bench  # noqa: E402  (the meter, the empty-work problems, grade runs)

SIZES = (1, 200)


def _checkout(text: str) -> tuple[str, Path]:
    name, sep, path = text.partition("=")
    root = Path(path)
    if not sep or not name or not (root / "grader" / "__init__.py").is_file():
        raise argparse.ArgumentTypeError(f"{text!r}: expected NAME=CHECKOUT, a folder holding grader/ (e.g. after=$PWD)")
    return name, root.resolve()


def measure(checkouts: dict[str, Path], rounds: int, students: int, method: str = "auto") -> dict[str, dict]:
    """Per checkout: the later students' CPU (s) in the 1-test and 200-test classes, and the two
    fixed costs derived from them (``per_test_s``, ``per_submission_s``)."""
    if rounds < 1 or students < 2:
        raise ValueError(f"need rounds >= 1 and students >= 2 (got {rounds}, {students})")
    meter = bench.Meter(method)
    tmp = Path(tempfile.mkdtemp(prefix="bench-fixed-costs-"))
    problems = tmp / "problems"
    ids = bench.make_empty_problems(problems, SIZES)
    samples: dict[str, dict[str, list[float]]] = {name: {i: [] for i in ids} for name in checkouts}
    for r in range(rounds + 1):
        for name, root in checkouts.items():
            env = dict(os.environ, PYTHONPATH=str(root), GRADER_PROBLEMS=str(problems))
            for eid in ids:
                cdir = tmp / f"class-{name}-{eid}-{r}"
                bench.make_class(cdir, eid, bench.TRIVIAL, students, bench.LANGUAGES["python"])
                # python -m puts its working directory first on sys.path: the checkout's own
                cmd = [sys.executable, "-m", "grader", "grade", eid, str(cdir), "--db", str(tmp / f"{name}-{eid}-{r}.db"),
                       "--jobs", "1", "--json"]
                m = meter.run(cmd, env, cwd=root,
                              on_line=lambda s, eid=eid: s.startswith(f"{eid}: ") and "student folders" in s
                              or s.startswith("graded "))
                m.ok()
                marks = [mk for mk in m.marks if "student folders" in mk[0] or mk[0].startswith("graded ")]
                totals = [b[1] - a[1] for a, b in zip(marks, marks[1:])]
                if r and len(totals) == students:
                    samples[name][eid] += totals[1:]  # students 2..n
    out = {}
    for name in checkouts:
        one, many = (statistics.mean(samples[name][i]) for i in ids)
        per_test = (many - one) / (SIZES[1] - SIZES[0])
        out[name] = {"one": one, "many": many, "n": len(samples[name][ids[0]]), "per_test_s": per_test,
                     "per_submission_s": one - per_test}
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("checkouts", nargs="+", type=_checkout, help="NAME=CHECKOUT (a folder holding grader/)")
    ap.add_argument("--rounds", type=int, default=2, help="measured rounds (after one warm-up round)")
    ap.add_argument("--students", type=int, default=5, help="students per class (the first is not counted)")
    ap.add_argument("--method", default="auto", choices=["auto", "cgroup-v1", "cgroup-v2", "proc"])
    a = ap.parse_args()
    load0 = os.getloadavg()[0]
    res = measure(dict(a.checkouts), a.rounds, a.students, a.method)
    for name, r in res.items():
        print(f"{name}: later student CPU s: 1 test {r['one']:.4f}, 200 tests {r['many']:.4f} ({r['n']} samples); "
              f"per-test {1000 * r['per_test_s']:.3f} ms, per-submission {r['per_submission_s']:.4f} s")
    print(f"load average {load0:.1f} at the start, {os.getloadavg()[0]:.1f} at the end")


if __name__ == "__main__":
    main()
