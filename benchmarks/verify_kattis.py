"""Export every problem whole as a Kattis package and run problemtools' verifyproblem on it, N times.

For each problem: ``grader.contest.kattis.export`` with all groups (the reference solutions placed by
judging them), then ``verifyproblem -p config data validators submissions`` ``--runs`` times on
the same package (``--jobs`` problems at once, so each run has a neighbour loading the machine).
Prints one row per problem and run: errors, warnings, every submission's directory and the
verdict problemtools gave it (``OK`` when it matched the directory), and the wall seconds; the
logs stay in ``--out``. Exit status 1 if any run had an error.

Run:
    .venv/bin/python benchmarks/verify_kattis.py --runs 3 --jobs 2            # all twelve
    .venv/bin/python benchmarks/verify_kattis.py delaunay emst --runs 1 --out /tmp/vk
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from grader.contest.kattis import LANGUAGES_YAML, export  # noqa: E402
from grader.problems import REPO, list_problems  # noqa: E402

VERIFY = Path(sys.executable).with_name("verifyproblem")


def parse(out: str) -> dict:
    """verifyproblem's output -> errors, warnings and ``{dir/file: (status, verdict text)}``.

    >>> parse("   accepted/a.py (Python 3) OK: AC (100) [CPU: 0.66s]\\nx tested: 0 errors, 2 warnings\\n")
    {'errors': 0, 'warnings': 2, 'subs': {'accepted/a.py': ('OK', 'AC (100)')}}
    """
    m = re.search(r"tested: (\d+) errors?, (\d+) warnings?", out)
    subs = {}
    for ln in out.splitlines():
        s = re.match(r"^\s*(\w+)/(\S+\.py) \(.*\) (OK|[A-Za-z]+): (.*)$", ln)
        if s and not ln.lstrip().startswith(("ERROR", "WARNING")):
            subs[f"{s.group(1)}/{s.group(2)}"] = (s.group(3) or "", s.group(4).split(" [")[0])
    for ln in out.splitlines():  # "ERROR in submission wrong_answer/x.py ... got TLE"
        e = re.search(r"ERROR .*?(\w+/\S+\.py).*", ln)
        if e:
            subs[e.group(1)] = ("ERROR", ln.strip()[:90])
    return {"errors": int(m.group(1)) if m else -1, "warnings": int(m.group(2)) if m else -1, "subs": subs}


def verify(dest: str, workdir: str, log: str) -> tuple[dict, float]:
    """One verifyproblem run on the package ``dest``; its output goes to ``log``."""
    env = {**os.environ, "XDG_CONFIG_HOME": str(Path(workdir) / "config"),
           "PATH": f"{Path(sys.executable).parent}:{os.environ.get('PATH', '')}"}
    t0 = time.monotonic()
    proc = subprocess.run([str(VERIFY), dest, "-p", "config", "data", "validators", "submissions"],
                          cwd=workdir, env=env, capture_output=True, text=True, timeout=3600)
    wall = time.monotonic() - t0
    out = proc.stdout + proc.stderr
    Path(log).write_text(out)
    return parse(out), wall


def one_problem(problem_id: str, workdir: str, runs: int) -> list[tuple[int, dict, float, float]]:
    """Export ``problem_id`` whole (placing the solutions by judging them), then verify it ``runs`` times."""
    t0 = time.monotonic()
    dest = export(problem_id, Path(workdir) / "kattis")
    export_s = time.monotonic() - t0
    rows = []
    for k in range(1, runs + 1):
        res, wall = verify(str(dest), workdir, str(Path(workdir) / f"{problem_id}.{k}.log"))
        rows.append((k, res, wall, export_s))
        print(f"{problem_id} run {k}: {res['errors']} errors, {res['warnings']} warnings, {wall:.0f} s",
              file=sys.stderr, flush=True)
    return rows


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("problems", nargs="*", help="problem ids (default: every problem under assignments/)")
    ap.add_argument("--runs", type=int, default=3, help="verifyproblem runs per problem (default 3)")
    ap.add_argument("--jobs", type=int, default=2, help="problems verified at once (default 2)")
    ap.add_argument("--out", default="", help="working folder for packages and logs (default: a temp folder)")
    a = ap.parse_args(argv)
    if not VERIFY.exists():
        raise SystemExit(f"{VERIFY} not found: install problemtools into this venv (make setup)")
    ids = a.problems or [p.id for p in list_problems(REPO / "assignments")]
    work = Path(a.out or tempfile.mkdtemp(prefix="verify-kattis-"))
    (work / "config" / "problemtools").mkdir(parents=True, exist_ok=True)
    (work / "config" / "problemtools" / "languages.yaml").write_text(LANGUAGES_YAML)
    t0 = time.monotonic()
    with ProcessPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pid: pool.submit(one_problem, pid, str(work), a.runs) for pid in ids}
        results = {pid: f.result() for pid, f in futures.items()}
    total = time.monotonic() - t0
    bad = 0
    print("| problem | run | errors | warnings | export s | verify s | submissions (dir/file: problemtools' verdict) |")
    print("|---|---|---|---|---|---|---|")
    for pid, rows in results.items():
        for k, res, wall, export_s in rows:
            bad += res["errors"] != 0
            subs = "; ".join(f"{name}: {v or s}" + ("" if s == "OK" else f" ({s})")
                             for name, (s, v) in sorted(res["subs"].items()))
            print(f"| {pid} | {k} | {res['errors']} | {res['warnings']} | {export_s:.0f} | {wall:.0f} | {subs} |")
    print(f"\n{len(ids)} problems x {a.runs} runs, --jobs {a.jobs}: {total:.0f} s wall; "
          f"{bad} run(s) with errors; logs in {work}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
