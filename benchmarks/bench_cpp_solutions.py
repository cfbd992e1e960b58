"""The C++ reference solutions' verdicts, proved outside the judge (issue 41 "C++ submissions").

What it is: for each problem with C++ solutions (``solutions/<id>/*.cpp``) it compiles each file
once into a temporary folder (``g++ -std=gnu++17 -O2 -pipe -static -s``, the flags Kattis, DOMjudge
and CMS use), runs each binary on every test of the problem in stdio mode (the test's text input on
stdin, a per-test CPU-time cap: the problem's C++ limit, course.yaml ``time_limits: {cpp: X}``), and
converts and checks each output with the problem's own checker through the public API
(``problem.checker.read_output`` and ``check``, as the judge does in stdio mode). Per solution it
prints the groups passed and failed, the overall verdict (the first non-AC test's: AC, WA, PE, TLE
above the cap, RE, or CE when it does not compile), the slowest test's CPU time (a run goes on to
4 x the cap, so a too-slow solution's margin is measured), and for comparison the Python accepted
solution's slowest test time on the same tests (judged by the sandboxed judge, ``grader.judge_file``).
Per problem it prints the C++ limit and its margins (limit / the accepted slowest, the quadratic
slowest / limit), and at the end a summary table (C++ against Python, slowest and total; the compile
cost per file). Every verdict is checked against ``solutions/<id>/expected_cpp.yaml``
(``file: VERDICT [group ...]``, the groups being exactly the failed ones when given); a mismatch
makes the exit status 1.

The C++ limit (``cpp_time_limit``, the one place the rule is written): the accepted C++ solution's
slowest test's CPU time x 5 (Kattis's time_multiplier is 2 to 5), rounded up to 0.5 s, at least
1 s. ``--write-limits`` runs the accepted solution first (under the Python limit), writes the rule's
limit into course.yaml (editing the text: comments and layout stay) and judges the rest with it.

The binaries run outside the jail: they are the course's own reference files, not students' code.

Run (from the checkout, with the course's venv):
    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_cpp_solutions.py
    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_cpp_solutions.py --problems delaunay --quick
    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_cpp_solutions.py --write-limits   # re-measure the limits
    options: --cap SECONDS (one cap for every problem instead of its C++ limit), --json OUT (the rows
    as JSON), --quick (no Python comparison, and a group's remaining tests are skipped once it fails)

Example output (the full run with `--write-limits`, 2026-12-06 01:02, load average 13.7 falling to
7.3 on 2 cores; the delaunay block and the summary; all of it in benchmarks/README.md):
    compiler: /usr/bin/g++ -std=gnu++17 -O2 -pipe -static -s
    g++ (Debian 12.2.0-14+deb12u1) 12.2.0
    2026-12-06 01:02, load average 13.7 14.1 12.7, 2 cores
    == delaunay: 200 tests in 6 groups; Python accepted_walk.py: AC, slowest test 0.93 s, total 1.5 s
    compile accepted.cpp            10.23 s  ok
    compile compile_error.cpp        6.14 s  failed: ‘orient2d’ was not declared in this scope; did you mean ‘exact::orient2d’?
    compile quadratic.cpp           10.38 s  ok
    compile wrong_double.cpp         9.79 s  ok
    C++ limit 1 s per test (written: max(1, 5 x 0.048 s rounded up to 0.5 s)); a run is stopped at 4 x the limit
    solution               verdict  expected         groups passed / failed               slowest   python  ok
    accepted.cpp           AC       AC               6/6 -                                0.048 s   0.93 s  yes
    compile_error.cpp      CE       CE               0/6 (does not compile)                     -   0.93 s  yes
    quadratic.cpp          TLE      TLE large        5/6 large                            >4.73 s   0.93 s  yes
        first failure: large/01: TLE after 4.73 s CPU
    wrong_double.cpp       WA       WA degenerate    5/6 degenerate                       >4.78 s   0.93 s  yes
        first failure: degenerate/03: edge 42-63 is not Delaunay: point 17 is strictly inside the circumcircle of triangle (42, 63, 35)
    margins: limit 1 s = 20.9 x the accepted slowest (0.048 s); quadratic slowest >4.73 s = >4.7 x the limit
    ...
    == summary: C++ limit per problem and its margins (CPU times; quadratic '>' = stopped at 4 x the limit)
    problem                limit acc slowest acc total py slowest  py total limit/acc quad slowest quad/limit compile/file
    bowyer-watson-timed      1 s     0.003 s    0.37 s     0.09 s     0.2 s    320.8x       0.00 s    0.0x AC       14.4 s
    closest-pair             1 s     0.177 s    0.92 s     0.60 s     1.7 s      5.7x      >4.81 s  >4.8x TLE       15.2 s
    delaunay                 1 s     0.048 s    0.72 s     0.93 s     1.5 s     20.9x      >4.73 s  >4.7x TLE        9.1 s
    delaunay-3d              1 s     0.101 s    0.47 s     3.58 s     6.3 s      9.9x       2.38 s   2.4x TLE       14.2 s
    dynamic-network          1 s     0.116 s    0.39 s     0.88 s     1.7 s      8.7x      >4.84 s  >4.8x TLE       10.7 s
    edge-flip                1 s     0.033 s    0.65 s     1.06 s     2.0 s     30.6x      >4.87 s  >4.9x TLE       10.7 s
    emst                   1.5 s     0.292 s    1.16 s     0.92 s     1.8 s      5.1x      >6.62 s  >4.4x TLE       11.7 s
    largest-empty-circle     1 s     0.027 s    0.51 s     0.53 s     1.2 s     37.3x       2.79 s   2.8x TLE       10.3 s
    navmesh                  1 s     0.054 s    0.85 s     0.83 s     2.2 s     18.7x      >4.75 s  >4.7x TLE        8.1 s
    obstacle-clearance       1 s     0.046 s    1.22 s     1.10 s     2.3 s     21.8x      >4.79 s  >4.8x TLE       10.4 s
    proximity-network        1 s     0.058 s    1.28 s     0.95 s     1.8 s     17.2x      >4.91 s  >4.9x TLE        6.5 s
    voronoi                  1 s     0.039 s    1.31 s     0.48 s     1.2 s     25.5x       2.15 s   2.2x TLE        8.5 s
    load average at the end 7.3 9.3 11.5
    48 C++ solutions on 12 problems: every verdict as expected
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from grader import judge_file, load_problem  # noqa: E402 - after the path set-up

SOLUTIONS = ROOT / "solutions"
CXX = shutil.which("g++") or "g++"
CXXFLAGS = ["-std=gnu++17", "-O2", "-pipe", "-static", "-s"]
COMPILE_TIMEOUT_S = 120.0

# The C++ time limit rule (the one place it is written down), as Kattis sets a limit from its judges'
# accepted solutions: the slowest test's CPU time of the accepted C++ solution times a multiplier
# (Kattis: time_multiplier, 2 to 5), rounded up to half a second, and never below one second.
CPP_TIME_MULTIPLIER = 5.0
CPP_LIMIT_STEP_S = 0.5
CPP_LIMIT_FLOOR_S = 1.0
# A run is stopped at MEASURE_FACTOR times the cap (its verdict is TLE above the cap), so a too-slow
# solution's margin over the limit is measured up to that factor.
MEASURE_FACTOR = 4.0


def cpp_time_limit(accepted_slowest_s: float) -> float:
    """The C++ limit for a problem whose accepted C++ solution's slowest test took this CPU time.

    >>> cpp_time_limit(0.05), cpp_time_limit(0.3), cpp_time_limit(0.61)
    (1.0, 1.5, 3.5)
    """
    stepped = math.ceil(CPP_TIME_MULTIPLIER * accepted_slowest_s / CPP_LIMIT_STEP_S - 1e-9) * CPP_LIMIT_STEP_S
    return max(CPP_LIMIT_FLOOR_S, stepped)


TIME_LIMITS_LINE = re.compile(r"^time_limits:.*\n", re.M)


def write_cpp_limit(problem: str, limit_s: float) -> Path:
    """Write ``time_limits: {cpp: X}`` into the problem's course.yaml by editing its text (comments
    and formatting kept): the line is replaced when present, else inserted before ``groups:``."""
    f = ROOT / "assignments" / problem / "course.yaml"
    text = f.read_text()
    line = (f"time_limits: {{cpp: {limit_s:g}}}".ljust(36)
            + "# C++ per test, s (Python: problem.yaml's); bench_cpp_solutions.py --write-limits\n")
    if TIME_LIMITS_LINE.search(text):
        text = TIME_LIMITS_LINE.sub(lambda _m: line, text, count=1)
    else:
        at = re.search(r"^groups:", text, re.M)
        if at is None:
            raise ValueError(f"problem {problem!r}: course.yaml has no 'groups:' line to put time_limits before")
        text = text[:at.start()] + line + text[at.start():]
    if yaml.safe_load(text).get("time_limits", {}).get("cpp") != limit_s:
        raise ValueError(f"problem {problem!r}: writing time_limits into course.yaml failed")
    f.write_text(text)
    return f


@dataclass
class Compiled:
    source: Path
    binary: Path | None
    seconds: float
    message: str  # the compiler's first lines on failure


@dataclass
class SolutionResult:
    problem: str
    file: str
    verdict: str
    groups_passed: list[str] = field(default_factory=list)
    groups_failed: list[str] = field(default_factory=list)
    slowest_s: float = 0.0
    slowest_test: str = ""
    total_s: float = 0.0
    killed: bool = False  # stopped at MEASURE_FACTOR x the cap: slowest_s is a lower bound
    compile_s: float = 0.0
    first_failure: str = ""
    expected: str = ""
    matches: bool = True


def cpp_problems() -> list[str]:
    """Problem ids that have C++ solutions, in folder order."""
    return sorted(d.name for d in SOLUTIONS.iterdir() if d.is_dir() and any(d.glob("*.cpp")) and d.name != "cpp")


def expected_verdicts(problem: str) -> dict[str, tuple[str, list[str]]]:
    """``expected_cpp.yaml``: file -> (verdict, the groups it must fail; empty: not checked)."""
    f = SOLUTIONS / problem / "expected_cpp.yaml"
    if not f.is_file():
        return {}
    out = {}
    for name, value in (yaml.safe_load(f.read_text()) or {}).items():
        words = str(value).split()
        out[str(name)] = (words[0], words[1:])
    return out


def compile_cpp(source: Path, outdir: Path) -> Compiled:
    binary = outdir / source.stem
    t0 = time.monotonic()
    try:
        run = subprocess.run([CXX, *CXXFLAGS, "-o", str(binary), str(source)], capture_output=True, text=True,
                             timeout=COMPILE_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return Compiled(source, None, time.monotonic() - t0, f"compiler timed out after {COMPILE_TIMEOUT_S:g} s")
    seconds = time.monotonic() - t0
    if run.returncode != 0:
        return Compiled(source, None, seconds, "\n".join(run.stderr.strip().splitlines()[:3]))
    return Compiled(source, binary, seconds, "")


def _limit_cpu(seconds: int):
    def set_limits() -> None:  # in the child: a hard CPU limit
        resource.setrlimit(resource.RLIMIT_CPU, (seconds, seconds))
    return set_limits


def run_test(binary: Path, input_text: str, cap_s: float) -> tuple[str, float, str, bool]:
    """One run: (outcome 'ok'/'TLE'/'RE', CPU seconds, stdout, killed). The run may go on to
    MEASURE_FACTOR x the cap (so a too-slow program's time is measured), its outcome is TLE above
    the cap; the wall clock allows for a loaded machine."""
    hard = math.ceil(MEASURE_FACTOR * cap_s)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    killed = False
    try:
        run = subprocess.run([str(binary)], input=input_text, capture_output=True, text=True,
                             timeout=max(60.0, 20 * hard), preexec_fn=_limit_cpu(hard + 1))
        outcome = "ok" if run.returncode == 0 else "RE"
        stdout = run.stdout
        if run.returncode < 0 and -run.returncode in (9, 24):  # SIGKILL / SIGXCPU from the CPU limit
            outcome, killed = "TLE", True
    except subprocess.TimeoutExpired:
        outcome, stdout, killed = "TLE", "", True
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if cpu > cap_s:
        outcome = "TLE"
    return outcome, cpu, stdout, killed


def check_output(problem: Any, chk: Any, test: Any, args: list, stdout: str) -> tuple[str, str]:
    """The checker's verdict on one program output, as the judge gives it in stdio mode."""
    try:
        answer = chk.read_output(stdout, args)
    except chk.PresentationError as exc:
        return "PE", str(exc)
    except getattr(chk, "WrongAnswer", ()) as exc:
        return "WA", str(exc)
    ok, message = chk.check(args, answer, problem.read_answer(test, args))
    return ("AC", "") if ok else ("WA", message)


def judge_solution(problem: Any, compiled: Compiled, cap_s: float, quick: bool,
                   parsed: dict[str, tuple[list, Any]]) -> SolutionResult:
    groups = [g.name for g in problem.present_groups]
    res = SolutionResult(problem.id, compiled.source.name, "AC", compile_s=compiled.seconds)
    if compiled.binary is None:
        res.verdict, res.groups_failed, res.first_failure = "CE", groups, compiled.message
        return res
    chk = problem.checker
    failed: set[str] = set()
    for test in problem.tests():
        if quick and test.group in failed:
            continue
        outcome, cpu, stdout, killed = run_test(compiled.binary, test.input_text, cap_s)
        res.total_s += cpu
        if cpu > res.slowest_s:
            res.slowest_s, res.slowest_test, res.killed = cpu, test.name, killed
        if outcome == "ok":
            if test.name not in parsed:
                parsed[test.name] = (problem.parse_args(test), None)
            verdict, message = check_output(problem, chk, test, parsed[test.name][0], stdout)
        else:
            verdict, message = outcome, f"{outcome} after {cpu:.2f} s CPU"
        if verdict != "AC":
            failed.add(test.group)
            if res.verdict == "AC":
                res.verdict, res.first_failure = verdict, f"{test.name}: {message[:200]}"
    res.groups_failed = [g for g in groups if g in failed]
    res.groups_passed = [g for g in groups if g not in failed]
    return res


def python_accepted(problem: str) -> Path | None:
    """The Python accepted solution (first ``accepted*.py`` expected AC in ``expected.yaml``)."""
    f = SOLUTIONS / problem / "expected.yaml"
    table = yaml.safe_load(f.read_text()) if f.is_file() else {}
    for name, value in (table or {}).items():
        if str(name).startswith("accepted") and str(name).endswith(".py") and str(value).split()[0] == "AC":
            return SOLUTIONS / problem / str(name)
    return None


def python_time(problem: str) -> tuple[str, str, float, float]:
    """(file, verdict, slowest test's time_s, total time_s) of the Python accepted solution, judged by
    the judge."""
    path = python_accepted(problem)
    if path is None:
        return "-", "-", float("nan"), float("nan")
    result = judge_file(problem, path)
    times = [t.time_s for t in result.tests]
    return path.name, str(result.verdict), max(times, default=0.0), sum(times)


@dataclass
class ProblemSummary:
    problem: str
    limit_s: float
    limit_source: str                      # "course.yaml", "--cap" or "written: rule(...)"
    accepted_slowest_s: float = float("nan")
    accepted_total_s: float = float("nan")
    python_slowest_s: float = float("nan")
    python_total_s: float = float("nan")
    quadratic_slowest_s: float = float("nan")
    quadratic_killed: bool = False
    quadratic_verdict: str = "-"
    compile_mean_s: float = float("nan")


def _fmt(x: float, unit: str = " s", digits: int = 3) -> str:
    return "-" if x != x else f"{x:.{digits}f}{unit}"


def bench_problem(problem_id: str, cap_s: float | None, quick: bool,
                  write_limits: bool = False) -> tuple[list[SolutionResult], ProblemSummary]:
    """Compile and judge every C++ solution of one problem. The cap: ``cap_s`` when given, else the
    problem's C++ limit (course.yaml ``time_limits``); with ``write_limits`` the accepted solutions run
    first under the Python limit, and the rule's limit is written into course.yaml and used as the cap."""
    problem = load_problem(problem_id)
    tests = problem.tests()
    expected = expected_verdicts(problem_id)
    sources = sorted((SOLUTIONS / problem_id).glob("*.cpp"), key=lambda p: (not p.name.startswith("accepted"), p.name))
    if quick:
        py = ("-", "skipped (--quick)", float("nan"), float("nan"))
    else:
        py = python_time(problem_id)
    py_text = f"Python {py[0]}: {py[1]}" + (f", slowest test {py[2]:.2f} s, total {py[3]:.1f} s" if py[2] == py[2] else "")
    if write_limits:
        cap, source = problem.time_limit, "to be written"
    elif cap_s is not None:
        cap, source = cap_s, "--cap"
    else:
        cap, source = problem.time_limit_for("cpp"), "course.yaml" if "cpp" in problem.time_limits else \
            "problem.yaml (no C++ limit yet)"
    print(f"== {problem_id}: {len(tests)} tests in {len(problem.present_groups)} groups; {py_text}", flush=True)
    results = []
    parsed: dict[str, tuple[list, Any]] = {}
    with tempfile.TemporaryDirectory(prefix="bench-cpp-") as tmp:
        compiled = []
        for src in sources:
            c = compile_cpp(src, Path(tmp))
            errors = [line for line in c.message.splitlines() if "error: " in line] or c.message.splitlines() or [""]
            status = "ok" if c.binary else "failed: " + errors[0].split("error: ", 1)[-1][:100]
            print(f"compile {src.name:<22} {c.seconds:6.2f} s  {status}", flush=True)
            compiled.append(c)
        accepted = [c for c in compiled if c.source.name.startswith("accepted")]
        others = [c for c in compiled if not c.source.name.startswith("accepted")]
        done = [judge_solution(problem, c, cap, quick, parsed) for c in accepted]
        if write_limits:
            slowest = max((r.slowest_s for r in done), default=0.0)
            cap = cpp_time_limit(slowest)
            source = (f"written: max({CPP_LIMIT_FLOOR_S:g}, {CPP_TIME_MULTIPLIER:g} x {slowest:.3f} s "
                      f"rounded up to {CPP_LIMIT_STEP_S:g} s)")
            write_cpp_limit(problem_id, cap)
            for r in done:  # the accepted runs were capped by the Python limit: re-verdict against the new cap
                if r.verdict == "AC" and r.slowest_s > cap:
                    r.verdict, r.first_failure = "TLE", f"{r.slowest_test}: TLE after {r.slowest_s:.2f} s CPU"
        print(f"C++ limit {cap:g} s per test ({source}); a run is stopped at {MEASURE_FACTOR:g} x the limit",
              flush=True)
        done += [judge_solution(problem, c, cap, quick, parsed) for c in others]
        for r in done:
            want = expected.get(r.file)
            if want is None:
                r.expected, r.matches = "(none)", False
            else:
                r.expected = " ".join([want[0], *want[1]])
                r.matches = r.verdict == want[0] and (not want[1] or sorted(want[1]) == sorted(r.groups_failed))
            results.append(r)
    header = f"{'solution':<22} {'verdict':<8} {'expected':<16} {'groups passed / failed':<34} {'slowest':>9} " \
             f"{'python':>8}  ok"
    print(header)
    for r in results:
        groups = f"{len(r.groups_passed)}/{len(r.groups_passed) + len(r.groups_failed)} " + \
                 (" ".join(r.groups_failed) if r.verdict != "CE" else "(does not compile)") if r.groups_failed \
                 else f"{len(r.groups_passed)}/{len(r.groups_passed)} -"
        slowest = "-" if r.verdict == "CE" else (f">{r.slowest_s:.2f} s" if r.killed else f"{r.slowest_s:.3f} s")
        pyt = f"{py[2]:.2f} s" if py[2] == py[2] else "-"
        print(f"{r.file:<22} {r.verdict:<8} {r.expected:<16} {groups:<34} {slowest:>9} {pyt:>8}  "
              f"{'yes' if r.matches else 'NO'}")
        if r.first_failure and (not r.matches or r.verdict not in ("AC", "CE")):
            print(f"    first failure: {r.first_failure.splitlines()[0][:160]}")
    summary = ProblemSummary(problem_id, cap, source, python_slowest_s=py[2], python_total_s=py[3])
    acc = [r for r in results if r.file.startswith("accepted") and r.verdict != "CE"]
    if acc:
        summary.accepted_slowest_s = max(r.slowest_s for r in acc)
        summary.accepted_total_s = sum(r.total_s for r in acc)
    quad = next((r for r in results if r.file == "quadratic.cpp"), None)
    if quad is not None:
        summary.quadratic_slowest_s, summary.quadratic_killed = quad.slowest_s, quad.killed
        summary.quadratic_verdict = quad.verdict
    if results:
        summary.compile_mean_s = sum(r.compile_s for r in results) / len(results)
    print(f"margins: limit {cap:g} s = {cap / summary.accepted_slowest_s:.1f} x the accepted slowest "
          f"({_fmt(summary.accepted_slowest_s)}); quadratic slowest "
          f"{'>' if summary.quadratic_killed else ''}{_fmt(summary.quadratic_slowest_s, ' s', 2)} = "
          f"{'>' if summary.quadratic_killed else ''}{summary.quadratic_slowest_s / cap:.1f} x the limit"
          if acc and summary.accepted_slowest_s > 0 else f"margins: - (C++ limit {cap:g} s)")
    print(flush=True)
    return results, summary


def print_summary(rows: list[ProblemSummary]) -> None:
    """One line per problem: the C++ limit and its margins, C++ against Python, the compile cost."""
    print("== summary: C++ limit per problem and its margins (CPU times; quadratic '>' = stopped at "
          f"{MEASURE_FACTOR:g} x the limit)")
    print(f"{'problem':<21} {'limit':>6} {'acc slowest':>11} {'acc total':>9} {'py slowest':>10} {'py total':>9} "
          f"{'limit/acc':>9} {'quad slowest':>12} {'quad/limit':>10} {'compile/file':>12}")
    for s in rows:
        ratio = s.limit_s / s.accepted_slowest_s if s.accepted_slowest_s > 0 else float("nan")
        gt = ">" if s.quadratic_killed else ""
        quad = "-" if s.quadratic_slowest_s != s.quadratic_slowest_s else f"{gt}{s.quadratic_slowest_s:.2f} s"
        qr = "-" if s.quadratic_slowest_s != s.quadratic_slowest_s else \
            f"{gt}{s.quadratic_slowest_s / s.limit_s:.1f}x {s.quadratic_verdict}"
        print(f"{s.problem:<21} {s.limit_s:>4g} s {_fmt(s.accepted_slowest_s):>11} {_fmt(s.accepted_total_s, ' s', 2):>9} "
              f"{_fmt(s.python_slowest_s, ' s', 2):>10} {_fmt(s.python_total_s, ' s', 1):>9} "
              f"{_fmt(ratio, 'x', 1):>9} {quad:>12} {qr:>10} {_fmt(s.compile_mean_s, ' s', 1):>12}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--problems", nargs="+", default=None, help="problem ids (default: all with .cpp files)")
    parser.add_argument("--cap", type=float, default=None,
                        help="per-test CPU-time cap in seconds (default: each problem's C++ limit, course.yaml "
                             "time_limits.cpp)")
    parser.add_argument("--write-limits", action="store_true",
                        help="measure the accepted C++ solution, write the rule's limit into course.yaml "
                             "(time_limits: {cpp: X}) and judge the others with it")
    parser.add_argument("--quick", action="store_true",
                        help="skip the Python comparison; skip a group's remaining tests once it fails")
    parser.add_argument("--json", type=Path, default=None, help="write the rows as JSON here")
    args = parser.parse_args(argv)
    if args.write_limits and args.cap is not None:
        parser.error("--write-limits measures its own cap; leave out --cap")
    problems = args.problems or cpp_problems()
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    print(f"compiler: {CXX} {' '.join(CXXFLAGS)}")
    print(subprocess.run([CXX, "--version"], capture_output=True, text=True).stdout.splitlines()[0])
    print(f"{time.strftime('%Y-%m-%d %H:%M')}, load average {' '.join(f'{x:.1f}' for x in os.getloadavg())}, "
          f"{os.cpu_count()} cores", flush=True)
    all_results: list[SolutionResult] = []
    summaries: list[ProblemSummary] = []
    for pid in problems:
        results, summary = bench_problem(pid, args.cap, args.quick, args.write_limits)
        all_results += results
        summaries.append(summary)
    print_summary(summaries)
    bad = [f"{r.problem}/{r.file}: {r.verdict}, expected {r.expected}" for r in all_results if not r.matches]
    if args.json:
        args.json.write_text(json.dumps({"results": [r.__dict__ for r in all_results],
                                         "problems": [s.__dict__ for s in summaries]}, indent=1))
    print(f"load average at the end {' '.join(f'{x:.1f}' for x in os.getloadavg())}")
    print(f"{len(all_results)} C++ solutions on {len(problems)} problems: "
          + ("every verdict as expected" if not bad else f"{len(bad)} unexpected: " + "; ".join(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
