"""One jail per compiled submission (grader/judging/program_server.py, the C launcher's serve mode).

Every test here runs one probe program (compiled once per run), which does what its input asks,
in one sandbox, test after test, as the judge runs a C++ submission's tests. What must hold:

* nothing carries from one test to the next: files left in ``/tmp``, the working directory and
  ``/dev/shm`` are gone (a link is removed, never followed), memory is fresh (a new process), the
  IPC objects that would outlive a process cannot be made; a filled ``/tmp`` is still an MLE;
* a background process cannot be started (the seccomp filter kills the test's process) and so
  cannot write into the next test's output;
* the student's process cannot kill, stop or ptrace the server, nor open its memory or its
  descriptors; closing or writing the descriptor numbers the server uses changes nothing;
* a test that times out, or a server that dies, gives a verdict, and the next test gets a fresh jail;
  a server that cannot start leaves the tests to a jail per test;
* ``GRADER_LAUNCHER=per-test`` switches back to one jail per test (``run_compiled`` then uses ``run_stdio``).

As root, :func:`test_as_an_ordinary_account` runs this file again as an ordinary account.

Run: .venv/bin/python -m pytest tests/grader/test_program_server.py -q -p no:cacheprovider
"""
from __future__ import annotations

import os
import signal
import sys
import threading
import time

import pytest

from grader.jail import Limits, Sandbox, launcher
from grader.jail.procs import children
from grader.judging import program_server
from grader.judging.program_server import run_compiled

from . import ordinary_user
from .cpp_probe import compiled_probe

#: The probe: its first input word says what to do; it prints what it saw.
PROBE = r"""
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <fcntl.h>
#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/ptrace.h>
#include <sys/sem.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>
static int counter = 0;
static const char *exists(const char *p) { struct stat st; return lstat(p, &st) == 0 ? "present" : "absent"; }
int main() {
    char what[64] = "";
    if (std::scanf("%63s", what) != 1) return 2;
    std::string w = what;
    if (w == "hello") { std::printf("hello\n"); return 0; }
    if (w == "leave") {
        FILE *f = std::fopen("/tmp/left", "w"); std::fputs("state", f); std::fclose(f);
        f = std::fopen("left-in-work", "w"); std::fputs("state", f); std::fclose(f);
        f = std::fopen("/dev/shm/left", "w"); std::fputs("state", f); std::fclose(f);
        mkdir("/tmp/locked", 0700); f = std::fopen("/tmp/locked/inner", "w"); std::fclose(f); chmod("/tmp/locked", 0);
        symlink("/submission", "/tmp/link"); symlink("/tmp/work", "/tmp/work-link");
        std::printf("left\n"); return 0;
    }
    if (w == "look") {
        char cwd[256];
        std::printf("%s %s %s %s %s %s cwd=%s\n", exists("/tmp/left"), exists("left-in-work"), exists("/dev/shm/left"),
                    exists("/tmp/locked"), exists("/tmp/link"), exists("/submission/program"), getcwd(cwd, sizeof cwd));
        FILE *f = std::fopen("new-file", "w");
        std::printf("work writable %d\n", f != nullptr);
        return 0;
    }
    if (w == "count") { std::printf("counter %d\n", ++counter); return 0; }
    if (w == "ipc") {
        int q = msgget(IPC_PRIVATE, IPC_CREAT | 0600); int e1 = errno;
        int s = semget(IPC_PRIVATE, 1, IPC_CREAT | 0600); int e2 = errno;
        long m = syscall(SYS_mq_open, "state", O_CREAT | O_RDWR, 0600, nullptr); int e3 = errno;
        std::printf("msgget %d %d semget %d %d mq_open %ld %d\n", q, e1 == EPERM, s, e2 == EPERM, m, e3 == EPERM);
        return 0;
    }
    if (w == "fork") {  // a background writer into the next test's output, if it could start
        std::printf("before\n"); std::fflush(stdout);
        pid_t p = fork();
        if (p == 0) { for (int i = 0; i < 200; ++i) { std::printf("LEAK\n"); std::fflush(stdout); usleep(10000); } _exit(0); }
        std::printf("fork returned %d\n", (int)p);
        return 0;
    }
    if (w == "attack") {  // the server is pid 1 of the jail
        int r[6];
        r[0] = ptrace(PTRACE_ATTACH, 1, nullptr, nullptr);
        r[1] = open("/proc/1/mem", O_RDWR);
        r[2] = open("/proc/1/fd/3", O_RDWR);
        char buf[64]; r[3] = (int)readlink("/proc/1/fd/3", buf, sizeof buf);
        r[4] = open("/proc/1/environ", O_RDONLY);
        r[5] = kill(1, SIGSTOP);
        kill(1, SIGKILL); kill(1, SIGTERM); kill(1, SIGSEGV); kill(-1, SIGKILL); kill(0, SIGCONT);
        std::printf("ptrace %d mem %d fd %d link %d environ %d\n", r[0], r[1], r[2], r[3], r[4]);
        return 0;
    }
    if (w == "fds") {  // the numbers a server might use: closed, written, reopened as something else
        for (int fd = 3; fd < 64; ++fd) { (void)!write(fd, "done exit 0 0 0 0 0 0 1\n", 24); close(fd); }
        for (int fd = 3; fd < 10; ++fd) open("/dev/null", O_RDONLY);
        std::printf("fds\n"); return 0;
    }
    if (w == "fill") {  // /tmp to the brim: its files are memory
        static char block[1 << 16]; std::memset(block, 'x', sizeof block);
        for (int i = 0; i < 64; ++i) {  // files of up to 4 MB (RLIMIT_FSIZE is the output limit)
            std::string name = "/tmp/fill" + std::to_string(i);
            FILE *f = std::fopen(name.c_str(), "w");
            int n = 0;
            while (f && n < 64 && std::fwrite(block, 1, sizeof block, f) == sizeof block) ++n;
            if (!f || std::fclose(f) != 0 || n < 64) break;
        }
        std::printf("filled\n"); return 0;
    }
    if (w == "spin") { volatile unsigned long x = 0; for (;;) ++x; }
    if (w == "sleep") { std::printf("sleeping\n"); std::fflush(stdout); sleep(3); std::printf("woke\n"); return 0; }
    return 1;
}
"""


@pytest.fixture(scope="module")
def probe(tmp_path_factory) -> str:
    return compiled_probe(PROBE, tmp_path_factory)


@pytest.fixture
def box(probe, monkeypatch):
    monkeypatch.delenv(launcher.LAUNCHER_ENV, raising=False)
    with Sandbox(Limits(cpu_s=1, memory_mb=256), program=probe, no_processes=True) as b:
        yield b


def run(box: Sandbox, what: str, limit: float = 1.0):
    return run_compiled(box, what + "\n", limit)


def server(box: Sandbox) -> program_server.ProgramServer:
    s = box.attach(program_server.ATTACH_NAME)
    assert isinstance(s, program_server.ProgramServer) and s.alive, s
    return s


def test_files_left_by_a_test_are_gone_at_the_next(box):
    assert run(box, "leave").value == "left\n"
    first = server(box)
    out = run(box, "look")
    assert out.status == "ok", (out.status, out.message)
    assert out.value == "absent absent absent absent absent present cwd=/tmp/work\nwork writable 1\n", out.value
    assert server(box) is first  # the same jail: emptied, not replaced
    assert os.path.exists(box.program or "")  # the link to the program was removed, not followed


def test_a_filled_tmp_is_an_mle_and_is_emptied_for_the_next_test(box):
    out = run(box, "fill")
    assert out.status == "memory" and "/tmp" in out.message, (out.status, out.message)
    assert run(box, "look").value.startswith("absent absent absent absent absent present")


def test_memory_and_ipc_do_not_carry_between_tests(box):
    assert [run(box, "count").value for _ in range(3)] == ["counter 1\n"] * 3
    out = run(box, "ipc")
    assert out.value == "msgget -1 1 semget -1 1 mq_open -1 1\n", out.value


def test_a_background_process_cannot_write_into_the_next_test(box):
    out = run(box, "fork")
    assert out.status == "violation", (out.status, out.message, out.value)
    time.sleep(0.1)
    assert [run(box, "hello").value for _ in range(2)] == ["hello\n"] * 2


def test_the_server_cannot_be_killed_stopped_traced_or_read(box):
    out = run(box, "attack")
    assert out.status == "ok", (out.status, out.message)
    assert out.value == "ptrace -1 mem -1 fd -1 link -1 environ -1\n", out.value
    first = server(box)
    assert run(box, "hello").value == "hello\n"
    assert server(box) is first and first.proc.poll() is None


def test_writing_or_closing_the_servers_descriptor_numbers_changes_nothing(box):
    out = run(box, "fds")
    assert (out.status, out.value) == ("ok", "fds\n"), (out.status, out.message)
    first = server(box)
    assert run(box, "hello").value == "hello\n" and server(box) is first


def test_a_timeout_ends_the_jail_and_the_next_test_gets_a_fresh_one(box):
    assert run(box, "hello").value == "hello\n"
    first = server(box)
    out = run(box, "spin", limit=0.3)
    assert out.status == "timeout", (out.status, out.message)
    assert run(box, "hello").value == "hello\n"
    assert server(box) is not first and first.proc.poll() is not None


def test_a_server_that_dies_gives_a_verdict_and_a_fresh_jail(box):
    assert run(box, "hello").value == "hello\n"
    first = server(box)
    inner = children(first.pid)  # the server, pid 1 of the jail, seen from the host

    def kill_it() -> None:
        time.sleep(0.3)
        for pid in inner:
            os.kill(pid, signal.SIGKILL)

    killer = threading.Thread(target=kill_it)
    killer.start()
    out = run(box, "sleep", limit=5.0)
    killer.join()
    assert out.status == "crash" and "jail ended" in out.message, (out.status, out.message)
    assert run(box, "hello").value == "hello\n" and server(box) is not first
    # killed between two tests: the next test runs in a fresh jail, not judged on the dead one
    second = server(box)
    for pid in children(second.pid):
        os.kill(pid, signal.SIGKILL)
    time.sleep(0.1)
    assert run(box, "hello").value == "hello\n"
    assert server(box) is not second


def test_a_server_that_cannot_start_leaves_the_tests_to_the_per_test_jail(box, monkeypatch):
    def broken(self, box):
        raise OSError("no room for another jail")

    monkeypatch.setattr(program_server.ProgramServer, "__init__", broken)
    assert [run(box, "hello").value for _ in range(2)] == ["hello\n"] * 2
    assert not program_server.usable(box)  # tried once per sandbox, not once per test


def test_the_per_test_jail_is_kept_as_a_switch(probe, monkeypatch):
    monkeypatch.setenv(launcher.LAUNCHER_ENV, "per-test")
    with Sandbox(Limits(cpu_s=1, memory_mb=256), program=probe, no_processes=True) as b:
        assert run(b, "leave").value == "left\n"
        assert run(b, "look").value.startswith("absent absent absent absent absent present")
        assert b.attach(program_server.ATTACH_NAME) is None


@pytest.mark.slow
def test_as_an_ordinary_account():
    """This file again as an ordinary account (bubblewrap without root, no cgroup)."""
    why = ordinary_user.can_run()
    if why:
        pytest.skip(why)
    r = ordinary_user.run_as_user([sys.executable, "-m", "pytest", "tests/grader/test_program_server.py", "-q", "-n",
                                   "0", "-p", "no:cacheprovider", "-k", "not ordinary_account"], timeout=600)
    tail = (r.stdout + r.stderr)[-6000:]
    assert r.returncode == 0, tail
    last = r.stdout.splitlines()[-1]
    assert "passed" in last and "failed" not in last and "skipped" not in last, tail


def test_a_compiled_programs_jail_binds_no_python(probe, monkeypatch):
    """The static launcher and the program are all a compiled submission's jail binds: no Python
    installation. A checkout cloned under /tmp (as CI's is) has its venv there, and a venv bound
    into the jail's /tmp made every test's clean-up fail (the server then quit after each test)."""
    from grader.jail.paths import python_roots, under
    monkeypatch.delenv(launcher.LAUNCHER_ENV, raising=False)
    with Sandbox(Limits(cpu_s=1, memory_mb=256), program=probe, no_processes=True) as b:
        assert b.launcher, "the C launcher starts compiled programs here"
        exposed = b._make_plan().expose
    assert len(exposed) == 2 and not [p for p in exposed for r in python_roots() if under(p, r) or under(r, p)], exposed
