"""A fresh account's first `grader judge PROBLEM`, with an empty numba cache and with the course server's seed.

The course server (deploy/jupyterhub/) gives every account a private numba cache; without a seed the
account's first judge compiles the checkers' kernels. This compiles a seed as the test account
(``grader-instructor``, as deploy.sh compiles it as the instructor), installs it root-owned, and judges
an accepted solution (default ``voronoi``'s ``accepted_clip.py``) as that account twice with an empty cache and twice with a
cache seeded by ``grader.course.numba_seed.seed_account`` (the hub's pre_spawn). CPU = user + system
of the command and the children it waits for (``getrusage(RUSAGE_CHILDREN)``). Root only.

    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_numba_seed.py ["GROUPS" [PROBLEM SOLUTION]]

Example output line:
    first judge voronoi, seeded cache: 2.0 CPU-s, 2.2 s wall (exit 0)
"""
from __future__ import annotations

import os
import resource
import shutil
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(REPO / "tests" / "grader"), str(REPO)]
import ordinary_user  # noqa: E402

from grader.course.numba_seed import copy_seed, seed_account, untrusted  # noqa: E402


def cpu_run(argv: list[str], env: dict[str, str]) -> tuple[float, float, int]:
    """CPU-s, wall s and exit code of ``argv`` run as the test account."""
    r0, t = resource.getrusage(resource.RUSAGE_CHILDREN), time.time()
    r = ordinary_user.run_as_user(argv, env={"PYTHONPATH": str(REPO), **env})
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime), time.time() - t, r.returncode


def main() -> int:
    if os.geteuid() != 0 or ordinary_user.can_run():
        print("needs root (it runs the judge as an ordinary account)", file=sys.stderr)
        return 2
    groups = sys.argv[1] if len(sys.argv) > 1 else "2d predicates,voronoi and hull,checkers"
    problem, solution = (sys.argv[2], sys.argv[3]) if len(sys.argv) > 3 else ("voronoi", "accepted_clip.py")
    pw = ordinary_user.ensure_user()
    base = Path(tempfile.mkdtemp(prefix="bench-numba-seed-"))
    os.chmod(base, 0o711)
    try:
        scratch = base / "scratch"
        scratch.mkdir(mode=0o700)
        os.chown(scratch, pw.pw_uid, pw.pw_gid)
        cpu, wall, rc = cpu_run([sys.executable, "-m", "grader.course.numba_seed", "build", str(scratch), groups], {})
        print(f"seed build ({groups!r}) as {pw.pw_name}: {cpu:.1f} CPU-s, {wall:.1f} s wall (exit {rc})")
        seed = base / "seed"
        n = copy_seed(scratch, seed)
        for p in [seed, *seed.rglob("*")]:
            os.chown(p, 0, 0)
            os.chmod(p, 0o755 if p.is_dir() else 0o644)
        size = sum(p.stat().st_size for p in seed.rglob("*") if p.is_file()) / 1e6
        print(f"seed: {n} files, {size:.1f} MB, untrusted={untrusted(seed)!r}")
        sol = str(REPO / "solutions" / problem / solution)
        for label in ("empty cache", "seeded cache"):
            home = base / label.split()[0]
            home.mkdir(mode=0o700)
            os.chown(home, pw.pw_uid, pw.pw_gid)
            cache = home / ".cache" / "numba"
            if label.startswith("seeded"):
                t = time.time()
                copied = seed_account(seed, cache, pw.pw_uid, pw.pw_gid, python="/usr/bin/python3", log=lambda m: None)
                print(f"seed_account copied {copied} files in {time.time() - t:.2f} s")
            for run in ("first", "second"):
                cpu, wall, rc = cpu_run([sys.executable, "-m", "grader", "judge", problem, sol],
                                        {"NUMBA_CACHE_DIR": str(cache)})
                print(f"{run} judge {problem}, {label}: {cpu:.1f} CPU-s, {wall:.1f} s wall (exit {rc})")
    finally:
        shutil.rmtree(base, ignore_errors=True)
    print("load average", " ".join(f"{x:.2f}" for x in os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
