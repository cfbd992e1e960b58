"""Per-test cost of starting a compiled program in the run jail: the C launcher against the Python bootstrap.

A trivial C++ program (reads one number, prints it) is compiled once in the compile jail, then run
``--runs`` times in one run sandbox (as the judge runs a C++ submission's tests), first started by
the Python bootstrap (``GRADER_LAUNCHER=python``), then by the C launcher. Printed per starter:
the CPU charged to the program per test (``time_s``: the sandbox's cgroup, or its process tree),
the grader process's own CPU per test, the CPU of its reaped children per test (bubblewrap and the
program when no cgroup catches them, the ``kill_all`` sweep's forked helper) and the wall time.

Run (as root or an ordinary account; the worktree's code via PYTHONPATH):
    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_cpp_start.py [--runs 30]

Example output:
    python bootstrap: charged 39.8 ms/test (median), grader 5.4 ms, children 12.0 ms, wall 225 ms
    C launcher:       charged  9.1 ms/test (median), grader 5.3 ms, children 12.2 ms, wall 143 ms
"""
from __future__ import annotations

import argparse
import os
import resource
import statistics
import tempfile
import time

from grader.jail import Limits, Sandbox, launcher
from grader.judging.compile import compile_source
from grader.judging.languages import CPP
from grader.judging.runner import run_stdio

PROGRAM = '#include <cstdio>\nint main(){int x; if(std::scanf("%d",&x)==1) std::printf("%d\\n",x); return 0;}\n'


def _cpu(who: int) -> float:
    ru = resource.getrusage(who)
    return ru.ru_utime + ru.ru_stime


def measure(binary: str, runs: int, starter: str) -> str:
    """One line: what a test costs with ``starter`` (``python`` or ``c``)."""
    os.environ[launcher.LAUNCHER_ENV] = starter
    charged, walls = [], []
    with Sandbox(Limits(cpu_s=2, memory_mb=256), program=binary) as box:
        run_stdio(box, "", "0\n", 2.0, [], program=True)  # first-time costs out of the way
        s0, c0 = _cpu(resource.RUSAGE_SELF), _cpu(resource.RUSAGE_CHILDREN)
        for i in range(runs):
            t0 = time.monotonic()
            out = run_stdio(box, "", f"{i}\n", 2.0, [], program=True)
            walls.append(time.monotonic() - t0)
            if out.status != "ok" or out.value.strip() != str(i):
                raise SystemExit(f"run {i}: {out.status} {out.message} {out.value!r}")
            charged.append(out.time_s)
        s1, c1 = _cpu(resource.RUSAGE_SELF), _cpu(resource.RUSAGE_CHILDREN)
        used = "C launcher" if box.launcher else "python bootstrap"
    return (f"{used + ':':18}charged {statistics.median(charged) * 1000:5.1f} ms/test (median), grader "
            f"{(s1 - s0) / runs * 1000:.1f} ms, children {(c1 - c0) / runs * 1000:.1f} ms, wall "
            f"{statistics.median(walls) * 1000:.0f} ms")


def main() -> None:
    """The command line (see the module's docstring)."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--runs", type=int, default=30)
    a = ap.parse_args()
    built = compile_source(PROGRAM, CPP, tempfile.mkdtemp(prefix="bench-cpp-start-"))
    if not built.ok:
        raise SystemExit(built.message)
    print(f"load average {' '.join(f'{x:.1f}' for x in os.getloadavg())}, uid {os.getuid()}, {a.runs} runs each")
    for starter in ("python", "c"):
        print(measure(built.binary, a.runs, starter), flush=True)


if __name__ == "__main__":
    main()
