"""Hostile C++ submissions: the compile jail and the run jail of a compiled program.

Every file in tests/grader/hostile_cpp/ states its verdict on its first line (``// expect: VERDICT``)
and is judged once per test run (a module-level cache) on the tiny closest-pair fixture
(tests/grader/fixtures/tiny-closest-pair: 1 s, 256 MB, 1 MB of output), stopping at the first
failure, with small compile limits (:data:`COMPILE`) so that the compiler bombs end in seconds.
Each must get its verdict (never JE), leave no process behind, and no byte of the instructor's
secret (a file the grader can read, created here) may appear in any output. In the sources,
``/work/main`` stands for this checkout, ``/grader-secret`` for the secret file and
``/grader-cache-file`` for a file of the grader's test cache (answers). As root,
:func:`test_as_an_ordinary_account` runs this file again as an ordinary account (bubblewrap
without root, no cgroup): the same verdicts.

Run: .venv/bin/python -m pytest tests/grader/test_hostile_cpp.py -q -p no:cacheprovider
"""
from __future__ import annotations

import json
import os
import shutil
import sys
from pathlib import Path

import pytest

from grader.contest.judge import Judge
from grader.jail import Limits
from grader.judging.verdicts import Verdict, format_table
from grader.problems import Problem, cache_root

from . import ordinary_user
from .conftest import HERE, sandbox_processes
from .test_hostile import shows_safely

CORPUS = sorted((HERE / "hostile_cpp").glob("*.cpp"))
FIXTURE = HERE / "fixtures" / "tiny-closest-pair"
#: Small compile limits: a bomb is stopped within seconds (the judge's own are 30 s and 1 GiB).
COMPILE = Limits(cpu_s=4.0, memory_mb=384, output_mb=64, open_files=128, processes=16, disk_mb=48, shm_mb=1)
SECRET = "SECRET-c0ffee-7e11 instructor only; grades: mallory 0\n"
_results: dict[str, object] = {}


def expected(path: Path) -> str:
    first = path.read_text().splitlines()[0]
    assert first.startswith("// expect: "), f"{path.name} must start with '// expect: VERDICT'"
    return first.split(":", 1)[1].strip()


@pytest.fixture(scope="module")
def secret():
    """The instructor's secret file (in the account's home, readable by the grader)."""
    top = Path.home() / f".grader-secret-{os.getpid()}"
    top.mkdir(exist_ok=True)
    path = top / "secret.txt"
    path.write_text(SECRET)
    yield path
    shutil.rmtree(top, ignore_errors=True)


@pytest.fixture(scope="module")
def judge():
    return Judge(Problem.load(FIXTURE), stop_at_first_failure=True, compile_limits=COMPILE)


def _aimed(path: Path, tmp: Path, secret: Path, judge: Judge) -> Path:
    judge.problem.tests()  # the cache holds this fixture's answers from here on
    cached = sorted(p for p in (cache_root() / FIXTURE.name).rglob("*.ans"))
    text = path.read_text()
    for stand_in, real in (("/work/main", HERE.parent.parent), ("/grader-secret", secret),
                           ("/grader-cache-file", cached[0] if cached else "/nonexistent")):
        text = text.replace(stand_in, str(real))
    out = tmp / path.name
    out.write_text(text)
    return out


def judged(name: str, judge: Judge, secret: Path, tmp_path_factory) -> object:
    """The result of one source of the corpus, judged once per run."""
    if name not in _results:
        src = _aimed(HERE / "hostile_cpp" / name, tmp_path_factory.mktemp("cpp"), secret, judge)
        _results[name] = judge.judge_path(src)
    return _results[name]


@pytest.mark.parametrize("path", CORPUS, ids=[p.stem for p in CORPUS])
def test_hostile_cpp_gets_its_verdict(path: Path, judge, secret, tmp_path_factory):
    result = judged(path.name, judge, secret, tmp_path_factory)
    verdicts = [t.verdict for t in result.tests]
    assert Verdict.JE not in verdicts, [t.message for t in result.tests if t.verdict == Verdict.JE]
    assert result.verdict == expected(path), [(t.name, str(t.verdict), t.message[:300]) for t in result.tests]
    assert sandbox_processes() == [], "processes of the sandbox uid survived the judging"
    shows_safely(result)
    everything = json.dumps(result.to_json(), ensure_ascii=False) + format_table(result) + \
        "".join(t.message + t.hidden_message + t.stderr for t in result.tests)
    for line in SECRET.split(";"):
        assert line.strip() not in everything, f"the secret leaked through {path.name}"


@pytest.mark.parametrize("name", ["include_passwd.cpp", "include_secret.cpp", "include_relative.cpp",
                                  "include_checkout.cpp", "include_tests.cpp", "include_dev_zero.cpp",
                                  "include_proc.cpp"])
def test_files_outside_the_submission_are_not_in_the_compile_jail(name, judge, secret, tmp_path_factory):
    message = judged(name, judge, secret, tmp_path_factory).tests[0].message
    assert "No such file or directory" in message, message
    assert "submission.cpp:3:10: fatal error" in message, message


def test_compiler_messages_are_capped_and_escaped(judge, secret, tmp_path_factory):
    flood = judged("error_flood.cpp", judge, secret, tmp_path_factory).tests[0].message
    assert "invalid conversion" in flood and "more than 4 MiB of compiler messages" in flood, flood[:300]
    assert len(flood) < 4200, len(flood)
    escaped = judged("escape_in_error.cpp", judge, secret, tmp_path_factory).tests[0].message
    assert "\x1b" not in escaped and "\\x1b" in escaped, escaped


@pytest.mark.parametrize("name", ["template_bomb.cpp", "preprocessor_bomb.cpp"])
def test_compiler_bombs_stop_at_a_limit(name, judge, secret, tmp_path_factory):
    message = judged(name, judge, secret, tmp_path_factory).tests[0].message
    signs = ("more than", "memory exhausted", "out of memory", "signal terminated", "CPU")
    assert any(s in message for s in signs), message


def test_run_time_failures_are_explained(judge, secret, tmp_path_factory):
    def msg(name: str) -> str:
        return next(t.message for t in judged(name, judge, secret, tmp_path_factory).tests if t.verdict != Verdict.AC)

    assert "exited with code 3" in msg("read_files.cpp"), msg("read_files.cpp")  # 4: an allowed file unreadable
    assert "exited with code 3" in msg("network.cpp")
    assert "exited with code 3" in msg("launcher_tamper.cpp")  # launcher, program read-only; no fd above 2
    assert "SIGSEGV" in msg("segfault.cpp")
    assert "forbidden system call" in msg("fork.cpp")


def test_a_correct_deep_recursion_is_accepted(judge, secret, tmp_path_factory):
    result = judged("deep_recursion.cpp", judge, secret, tmp_path_factory)
    assert result.score == 100 and all(t.verdict == Verdict.AC for t in result.tests), result.tests


@pytest.mark.slow
def test_as_an_ordinary_account():
    """The whole corpus again as an ordinary account (bubblewrap without root)."""
    why = ordinary_user.can_run()
    if why:
        pytest.skip(why)
    r = ordinary_user.run_as_user([sys.executable, "-m", "pytest", "tests/grader/test_hostile_cpp.py", "-q", "-n", "0",
                                   "-p", "no:cacheprovider", "-k", "not ordinary_account"], timeout=600)
    tail = (r.stdout + r.stderr)[-6000:]
    assert r.returncode == 0, tail
    assert "passed" in r.stdout and "failed" not in r.stdout.splitlines()[-1], tail
