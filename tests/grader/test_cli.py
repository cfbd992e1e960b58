"""The command line as a student and an instructor meet it: exit codes, messages instead of
tracebacks, stores that are never created by a typo, a closed pipe, and the feedback a failing
submission gets (print() output, the input of every failing small test).

Run: .venv/bin/python -m pytest tests/grader/test_cli.py -q
"""
from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from grader.problems import list_problems
from grader.judging.verdicts import JudgeResult, TestResult, Verdict, format_table

from .conftest import HERE, REPO

ACCEPTED = REPO / "solutions" / "delaunay" / "accepted_walk.py"


def grader(*args: str, problems: str | None = None, cwd=REPO) -> subprocess.CompletedProcess:
    env = {**os.environ, **({"GRADER_PROBLEMS": problems} if problems else {})}
    return subprocess.run([sys.executable, "-m", "grader", *args], capture_output=True, text=True, cwd=cwd, env=env)


def test_list_shows_time_memory_and_points():
    r = grader("list", "--json")
    assert r.returncode == 0
    rows = {row["id"]: row for row in json.loads(r.stdout)}
    for p in list_problems():
        assert rows[p.id]["memory"] == f"{p.memory_mb}MB" and rows[p.id]["time_limit"] == f"{p.time_limit:g}s"
    text = grader("list").stdout.splitlines()
    assert text[0].split()[:5] == ["id", "entry", "time", "memory", "points"]


def test_list_shows_the_cpp_limit_and_flags_once():
    """A column per compiled language (its own time limit, course.yaml ``time_limits``) after the
    columns scripts read; the compile command once, on stderr, read from ``languages.CPP``."""
    from grader.judging.languages import CPP

    r = grader("list", "--json")
    rows = {row["id"]: row for row in json.loads(r.stdout)}
    for p in list_problems():
        assert rows[p.id]["time_limit_cpp"] == f"{p.time_limit_for('cpp'):g}s"
    r = grader("list")
    lines = r.stdout.splitlines()
    assert lines[0].split()[:7] == ["id", "entry", "time", "memory", "points", "cpp", "title"]
    problems = list_problems()
    assert len(lines) == 1 + len(problems)  # stdout is the table alone
    for line, p in zip(lines[1:], problems):
        assert line.split()[:6] == [p.id, p.entry, f"{p.time_limit:g}s", f"{p.memory_mb}MB", str(p.points),
                                    f"{p.time_limit_for('cpp'):g}s"] and line.endswith(p.title)
    command = " ".join(CPP.compile_command("main.cpp", "main"))
    assert r.stderr.count(command) == 1 and "-std=gnu++17" in command


@pytest.mark.parametrize("args", [["list"], ["scoreboard", "--db", "{store}"], ["judge", "delaunay", "--help"]])
def test_a_closed_pipe_ends_quietly(tmp_path, args):
    """`python -m grader list | head -0`: the reader is gone before anything is written."""
    store = tmp_path / "s.sqlite"
    from grader.classroom.store import ResultStore

    ResultStore(store).close()
    argv = [a.format(store=store) for a in args]
    proc = subprocess.Popen([sys.executable, "-m", "grader", *argv], cwd=REPO, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    proc.stdout.close()
    err = proc.stderr.read()
    assert proc.wait() == 0 and "Traceback" not in err and "BrokenPipe" not in err, err


@pytest.mark.parametrize("args", [
    ["scoreboard", "--db", "{tmp}/typo.sqlite"],
    ["timed", "status", "bowyer-watson-timed", "ada", "--db", "{tmp}/typo.sqlite"],
    ["timed", "submit", "bowyer-watson-timed", "ada", str(ACCEPTED), "--db", "{tmp}/typo.sqlite"],
])
def test_commands_that_read_a_store_refuse_a_missing_one(tmp_path, args):
    r = grader(*[a.format(tmp=tmp_path) for a in args])
    assert r.returncode == 2 and "no results store at" in r.stderr and "Traceback" not in r.stderr
    assert not (tmp_path / "typo.sqlite").exists()  # not silently created


@pytest.mark.parametrize("args, message", [
    (["grade", "delaunay", "{tmp}/no-such-class"], "does not exist"),
    (["judge", "delaunay", "{tmp}/missing.py"], "does not exist"),
    (["judge", "no-such-problem", str(ACCEPTED)], "unknown problem"),
    (["export-kattis", "delaunay", "{tmp}/out", "--groups", "nope"], "no hidden group nope"),
])
def test_bad_input_is_a_message_and_exit_2(tmp_path, args, message):
    r = grader(*[a.format(tmp=tmp_path) for a in args])
    assert r.returncode == 2 and message in r.stderr and "Traceback" not in r.stderr, r.stderr


CHATTY_WRONG = '''
def delaunay(points):
    print("debug: got", len(points), "points")
    print("x" * 5000)
    return [[0, 2, 1]] if len(points) >= 3 else []
'''


def test_judge_exit_code_and_print_output(tmp_path):
    fixtures = str(HERE / "fixtures")
    ok = grader("judge", "tiny-delaunay", str(ACCEPTED), problems=fixtures)
    assert ok.returncode == 0, ok.stdout + ok.stderr
    bad = tmp_path / "chatty.py"
    bad.write_text(CHATTY_WRONG)
    # no counterexample search (10 s a judging by default; tested in test_counterexample.py): the print output is the point
    r = grader("judge", "tiny-delaunay", str(bad), "--counterexample-seconds", "0", problems=fixtures)
    assert r.returncode == 1, r.stdout + r.stderr
    assert "--- your print() output in this test ---" in r.stdout
    assert "debug: got 4 points" in r.stdout  # the first failing test is the 4-point sample
    assert "more bytes not shown" in r.stdout and "x" * 5000 not in r.stdout  # capped
    js = json.loads(grader("judge", "tiny-delaunay", str(bad), "--json", "--counterexample-seconds", "0",
                           problems=fixtures).stdout)
    assert js["verdict"] == "WA" and "debug: got 4 points" in js["tests"][0]["message"]


def _t(name: str, verdict: Verdict, preview: str = "", message: str = "wrong") -> TestResult:
    return TestResult(name, name.split("/")[0], verdict, message=message, input_preview=preview)


def test_table_shows_the_input_of_every_failing_small_test():
    tests = [_t("a/1", Verdict.WA, "3\n0 0\n1 0\n0 1\n", "bad a"), _t("a/2", Verdict.SKIPPED),
             _t("b/1", Verdict.AC), _t("b/2", Verdict.TLE, "1\n5 5\n", "slow b"),
             _t("c/1", Verdict.WA, "", "too big to show")]
    text = format_table(JudgeResult("p", "x.py", tests, {"a": 1, "b": 1, "c": 1}))
    assert "first failure: a/1: bad a\nits input:\n3\n0 0\n1 0\n0 1" in text
    assert "also failed: b/2: slow b\nits input:\n1\n5 5" in text
    assert "also failed: c/1: too big to show" in text


def test_timed_cli_messages(tmp_path):
    db = str(tmp_path / "c.sqlite")
    first = grader("timed", "start", "bowyer-watson-timed", "ada", "--db", db)
    assert first.returncode == 0 and " started at " in first.stdout and "already" not in first.stdout
    assert "minutes left" in first.stdout and "epoch" not in first.stdout
    again = grader("timed", "start", "bowyer-watson-timed", "ada", "--db", db)
    assert "already started at" in again.stdout
    clock = first.stdout.split(" started at ")[1].split(";")[0]
    assert clock in again.stdout  # the same start, shown as local clock time
    st = grader("timed", "status", "bowyer-watson-timed", "ada", "--db", db)
    assert st.returncode == 0 and "minutes left" in st.stdout and "deadline" in st.stdout
    untimed = grader("timed", "start", "delaunay", "ada", "--db", str(tmp_path / "u.sqlite"))
    assert untimed.returncode == 2 and "no timed settings" in untimed.stderr
    assert not (tmp_path / "u.sqlite").exists()


def test_judge_from_the_course_folder_with_the_readme_path():
    """``assignments/README.md`` runs the judge from ``assignments/`` with ``PATH=$PWD/../.venv/bin``:
    the interpreter's path then goes through the course folder, which the jail covers; the child
    must still start (it once failed every test as RE: ``execvp .../assignments/../.venv/bin/python``)."""
    via = os.path.join("..", os.path.relpath(sys.executable, REPO))  # sys.executable: .../assignments/../.venv/...
    r = subprocess.run([via, "-m", "grader", "judge", "delaunay", str(ACCEPTED), "--json"],
                       capture_output=True, text=True, cwd=REPO / "assignments", timeout=600)
    assert r.returncode == 0, r.stdout[-1500:] + r.stderr[-1500:]
    assert json.loads(r.stdout)["verdict"] == "AC"
