"""The C++ reference solutions' verdicts, proved outside the judge (issue 41 "C++ submissions").

What it is: for each problem with C++ solutions (``solutions/<id>/*.cpp``) it compiles each file
once into a temporary folder (``g++ -std=gnu++17 -O2 -pipe -static -s``, the flags Kattis, DOMjudge
and CMS use), runs each binary on every test of the problem in stdio mode (the test's text input on
stdin, a per-test CPU-time cap), and converts and checks each output with the problem's own checker
through the public API (``problem.checker.read_output`` and ``check``, as the judge does in stdio
mode). Per solution it prints the groups passed and failed, the overall verdict (the first non-AC
test's: AC, WA, PE, TLE against the cap, RE, or CE when it does not compile), the slowest test's CPU
time, and for comparison the Python accepted solution's slowest test time on the same tests (judged
by the sandboxed judge, ``grader.judge_file``). Every verdict is checked against
``solutions/<id>/expected_cpp.yaml`` (``file: VERDICT [group ...]``, the groups being exactly the
failed ones when given); a mismatch makes the exit status 1.

The binaries run outside the jail: they are the course's own reference files, not students' code.

Run (from the checkout, with the course's venv):
    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_cpp_solutions.py
    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_cpp_solutions.py --problems delaunay --quick
    options: --cap SECONDS (per-test CPU cap, default 1.0), --json OUT (the rows as JSON),
    --quick (no Python comparison, and a group's remaining tests are skipped once it fails)

Example output (`--problems delaunay`, 2026-12-05, load average 4-6 on 2 cores; the compile lines
from a `--quick` run just after, once the compiler's message was shortened to its first error):
    compiler: /usr/bin/g++ -std=gnu++17 -O2 -pipe -static -s
    g++ (Debian 12.2.0-14+deb12u1) 12.2.0
    == delaunay: 200 tests in 6 groups, cap 1 s CPU per test; Python accepted_walk.py: AC, slowest test 1.26 s
    compile accepted.cpp             3.87 s  ok
    compile compile_error.cpp        2.33 s  failed: 'orient2d' was not declared in this scope; did you mean ...
    compile quadratic.cpp            3.91 s  ok
    compile wrong_double.cpp         3.40 s  ok
    solution               verdict  expected         groups passed / failed               slowest   python  ok
    accepted.cpp           AC       AC               6/6 -                                0.058 s   1.26 s  yes
    compile_error.cpp      CE       CE               0/6 (does not compile)                     -   1.26 s  yes
    quadratic.cpp          TLE      TLE large        5/6 large                               >1 s   1.26 s  yes
        first failure: large/01: TLE after 2.98 s CPU
    wrong_double.cpp       WA       WA degenerate    5/6 degenerate                          >1 s   1.26 s  yes
        first failure: degenerate/03: edge 42-63 is not Delaunay: point 17 is strictly inside the circumcircle ...

    4 C++ solutions on 1 problems: every verdict as expected
"""
from __future__ import annotations

import argparse
import json
import os
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


def _limit_cpu(cap_s: float):
    def set_limits() -> None:  # in the child: a hard CPU limit a little above the cap
        secs = int(cap_s) + 2
        resource.setrlimit(resource.RLIMIT_CPU, (secs, secs))
    return set_limits


def run_test(binary: Path, input_text: str, cap_s: float) -> tuple[str, float, str]:
    """One run: (outcome 'ok'/'TLE'/'RE', CPU seconds, stdout). The wall clock allows for load."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        run = subprocess.run([str(binary)], input=input_text, capture_output=True, text=True,
                             timeout=max(10.0, 4 * cap_s), preexec_fn=_limit_cpu(cap_s))
        outcome = "ok" if run.returncode == 0 else "RE"
        stdout = run.stdout
        if run.returncode < 0 and -run.returncode in (9, 24):  # SIGKILL / SIGXCPU from the CPU limit
            outcome = "TLE"
    except subprocess.TimeoutExpired:
        outcome, stdout = "TLE", ""
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if cpu > cap_s:
        outcome = "TLE"
    return outcome, cpu, stdout


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
        outcome, cpu, stdout = run_test(compiled.binary, test.input_text, cap_s)
        if cpu > res.slowest_s:
            res.slowest_s, res.slowest_test = cpu, test.name
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


def python_time(problem: str) -> tuple[str, str, float]:
    """(file, verdict, slowest test's time_s) of the Python accepted solution, judged by the judge."""
    path = python_accepted(problem)
    if path is None:
        return "-", "-", float("nan")
    result = judge_file(problem, path)
    slowest = max((t.time_s for t in result.tests), default=0.0)
    return path.name, str(result.verdict), slowest


def bench_problem(problem_id: str, cap_s: float, quick: bool) -> list[SolutionResult]:
    problem = load_problem(problem_id)
    tests = problem.tests()
    expected = expected_verdicts(problem_id)
    sources = sorted((SOLUTIONS / problem_id).glob("*.cpp"), key=lambda p: (not p.name.startswith("accepted"), p.name))
    if quick:
        py = ("-", "skipped (--quick)", float("nan"))
    else:
        py = python_time(problem_id)
    py_text = f"Python {py[0]}: {py[1]}" + (f", slowest test {py[2]:.2f} s" if py[2] == py[2] else "")
    print(f"== {problem_id}: {len(tests)} tests in {len(problem.present_groups)} groups, cap {cap_s:g} s CPU "
          f"per test; {py_text}", flush=True)
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
        for c in compiled:
            r = judge_solution(problem, c, cap_s, quick, parsed)
            want = expected.get(c.source.name)
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
        slowest = "-" if r.verdict == "CE" else (f">{cap_s:g} s" if r.slowest_s > cap_s else f"{r.slowest_s:.3f} s")
        pyt = f"{py[2]:.2f} s" if py[2] == py[2] else "-"
        print(f"{r.file:<22} {r.verdict:<8} {r.expected:<16} {groups:<34} {slowest:>9} {pyt:>8}  "
              f"{'yes' if r.matches else 'NO'}")
        if r.first_failure and (not r.matches or r.verdict not in ("AC", "CE")):
            print(f"    first failure: {r.first_failure.splitlines()[0][:160]}")
    print(flush=True)
    return results


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--problems", nargs="+", default=None, help="problem ids (default: all with .cpp files)")
    parser.add_argument("--cap", type=float, default=1.0, help="per-test CPU-time cap in seconds (default 1.0)")
    parser.add_argument("--quick", action="store_true",
                        help="skip the Python comparison; skip a group's remaining tests once it fails")
    parser.add_argument("--json", type=Path, default=None, help="write the rows as JSON here")
    args = parser.parse_args(argv)
    problems = args.problems or cpp_problems()
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    print(f"compiler: {CXX} {' '.join(CXXFLAGS)}")
    print(subprocess.run([CXX, "--version"], capture_output=True, text=True).stdout.splitlines()[0])
    all_results: list[SolutionResult] = []
    for pid in problems:
        all_results += bench_problem(pid, args.cap, args.quick)
    bad = [f"{r.problem}/{r.file}: {r.verdict}, expected {r.expected}" for r in all_results if not r.matches]
    if args.json:
        args.json.write_text(json.dumps([r.__dict__ for r in all_results], indent=1))
    print(f"{len(all_results)} C++ solutions on {len(problems)} problems: "
          + ("every verdict as expected" if not bad else f"{len(bad)} unexpected: " + "; ".join(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
