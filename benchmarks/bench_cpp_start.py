"""Per-test cost of starting a compiled program in the run jail: one jail per submission, one per test, the Python bootstrap.

A trivial C++ program (reads one number, prints it) is compiled once in the compile jail, then run
``--runs`` times in one run sandbox (as the judge runs a C++ submission's tests), started by the
Python bootstrap in a jail per test (``GRADER_LAUNCHER=python``), by the C launcher in a jail per
test (``GRADER_LAUNCHER=per-test``), then by the C launcher's server in one jail for all the tests
(the default). Printed per starter: the CPU charged to the program per test (``time_s``: the
sandbox's cgroup, or its process tree), the grader process's own CPU per test, the CPU of its
reaped children per test (bubblewrap and the program when no cgroup catches them, the
``kill_all`` sweep's forked helper), the CPU of everything in the sandbox's cgroup per test
(``jail``: bubblewrap's set-up, the server, the program; root only) and the wall time.

Run (as root or an ordinary account; the worktree's code via PYTHONPATH):
    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_cpp_start.py [--runs 30]

Example output (as root, load 5.4):
    python bootstrap: charged  23.2 ms/test (median), grader 5.1 ms, children 25.6 ms, jail 22.4 ms, wall 109 ms
    C launcher:       charged  11.5 ms/test (median), grader 5.0 ms, children 13.6 ms, jail 10.3 ms, wall 64 ms
    C server:         charged   0.9 ms/test (median), grader 0.6 ms, children  0.0 ms, jail  1.0 ms, wall 6 ms
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
from grader.judging.program_server import run_compiled

PROGRAM = '#include <cstdio>\nint main(){int x; if(std::scanf("%d",&x)==1) std::printf("%d\\n",x); return 0;}\n'


def _cpu(who: int) -> float:
    ru = resource.getrusage(who)
    return ru.ru_utime + ru.ru_stime


def measure(binary: str, runs: int, starter: str) -> str:
    """One line: what a test costs with ``starter`` (``python``, ``per-test`` or ``serve``)."""
    os.environ[launcher.LAUNCHER_ENV] = starter
    charged, walls = [], []
    with Sandbox(Limits(cpu_s=2, memory_mb=256), program=binary) as box:
        run_compiled(box, "0\n", 2.0)  # first-time costs out of the way
        s0, c0 = _cpu(resource.RUSAGE_SELF), _cpu(resource.RUSAGE_CHILDREN)
        j0 = box.group.cpu_seconds() if box.group is not None and box.root_mode else 0.0
        for i in range(runs):
            t0 = time.monotonic()
            out = run_compiled(box, f"{i}\n", 2.0)
            walls.append(time.monotonic() - t0)
            if out.status != "ok" or out.value.strip() != str(i):
                raise SystemExit(f"run {i}: {out.status} {out.message} {out.value!r}")
            charged.append(out.time_s)
        s1, c1 = _cpu(resource.RUSAGE_SELF), _cpu(resource.RUSAGE_CHILDREN)
        j1 = box.group.cpu_seconds() if box.group is not None and box.root_mode else 0.0
        used = ("C server" if starter == "serve" else "C launcher") if box.launcher else "python bootstrap"
    jail = f"jail {(j1 - j0) / runs * 1000:4.1f} ms, " if box.root_mode else ""
    return (f"{used + ':':18}charged {statistics.median(charged) * 1000:5.1f} ms/test (median), grader "
            f"{(s1 - s0) / runs * 1000:.1f} ms, children {(c1 - c0) / runs * 1000:4.1f} ms, {jail}wall "
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
    for starter in ("python", "per-test", "serve"):
        print(measure(built.binary, a.runs, starter), flush=True)


if __name__ == "__main__":
    main()
