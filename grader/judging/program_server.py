"""One jail per compiled submission: the C launcher's server mode runs every test in a fresh process.

A compiled program's test used to start its own bubblewrap jail (about 17 ms of CPU in the jail's
set-up and 5 ms in the grader, per test). Here one jail is started per sandbox, on its first test,
with the C launcher in its ``serve`` mode as the jail's pid 1 (``grader/jail/launcher.c`` says what
it does and why the student's process cannot reach it). Per test the grader sends one request on
a Unix socket with the test's stdin, stdout and stderr attached; the server forks a fresh process,
applies the limits and the seccomp filter the per-test jail had (plus no IPC objects that would
outlive the process), execs the binary, waits, kills whatever the test left, measures and empties
``/tmp`` and ``/dev/shm`` and reports the exit status, the process's CPU and peak memory.

The grader keeps the measures it had: the cgroup's CPU and memory peak (reset per test), or the
process tree's samples for an ordinary account, and takes the larger of those and the server's
``wait4`` figures; TLE by CPU (sampled while the test runs), by idle and by wall time. A timeout,
a server that died, a report that is not exactly the protocol's or a jail left unclean ends the
jail: the test gets its verdict and the next test starts a fresh jail. A server that cannot start
at all (no ``ready`` in time) sends the sandbox's remaining tests through the per-test jail.
``GRADER_LAUNCHER=per-test`` (or ``python``) keeps one jail per test (A/B, a fallback).

Nothing hidden goes to the jail: the test's input only; the answer is checked in the grader.

Run: nothing to run; the judge runs a compiled submission's tests with :func:`run_compiled`.

Example:
    >>> with Sandbox(Limits(cpu_s=2, memory_mb=256), program=binary, no_processes=True) as box:  # doctest: +SKIP
    ...     run_compiled(box, "3\\n", 2.0).status
    'ok'
"""

from __future__ import annotations

import os
import re
import select
import signal
import socket
import subprocess
import time
from types import SimpleNamespace
from typing import Sequence

from ..jail import Sandbox, launcher, seccomp
from ..jail.cgroups import ProcTree
from .runner import (RunOutcome, _bad_alloc, _cpu_seconds, _memory_limit_hit, _peak_rss_mb, _reset_peak,
                     _runqueue_seconds, _sample_s, _stdio_outcome, output_paths, run_stdio, sleep_limit_for,
                     wall_limit_for)

#: The name the server is attached under (:meth:`Sandbox.attach`).
ATTACH_NAME = "program-server"
#: Wall seconds a server may take to say ``ready`` (a loaded machine starts a jail in well under 1 s).
READY_S = 20.0
#: RLIMIT_CPU of the server itself (each test's process gets the test's own).
SERVER_CPU_S = 3600
_REPORT = re.compile(rb"done (exit|signal) (\d{1,3}) (\d{1,15}) (\d{1,15}) (\d{1,15}) (\d{1,15}) (\d{1,15}) ([01])\n")


class _Failed:
    """Attached instead of a server whose start failed: the sandbox's tests use the per-test jail."""

    def __init__(self, why: str):
        self.why = why  #: what went wrong (for a debugger; the tests are judged all the same)

    def close(self) -> None:
        """Nothing to close."""


def usable(box: Sandbox) -> bool:
    """True when ``box``'s compiled program runs through a server: the bubblewrap jail, the C
    launcher, a seccomp filter, not switched off, and no server of this sandbox failed to start."""
    return (box.kind == "bwrap" and bool(box.launcher_path) and box.profile == "run" and launcher.serves()
            and seccomp.program() is not None and not isinstance(box.attach(ATTACH_NAME), _Failed))


class ProgramServer:
    """The jail of one compiled submission and its launcher in ``serve`` mode (started here)."""

    def __init__(self, box: Sandbox):
        self.box = box
        self.sock, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        per_test = seccomp.program(no_processes=box.no_processes, shared_jail=True)
        base = seccomp.program(no_processes=False)
        if per_test is None or base is None:
            raise ValueError("a compiled program's server needs a seccomp filter (x86-64)")
        filter_fd = seccomp.program_fd(per_test)
        null = os.open(os.devnull, os.O_RDONLY)
        log = os.open(os.path.join(box.private_dir, "server.log"), os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o600)
        argv = [box.launcher_path, "serve", str(theirs.fileno()), str(filter_fd), str(box.inner_nproc() or 0),
                str(box.limits.memory_mb << 20), box.child_workdir, box.program_path]
        try:
            self.proc = box.spawn(argv, null, log, log, pass_fds=(theirs.fileno(), filter_fd), cpu_s=SERVER_CPU_S,
                                  seccomp_filter=base)
        finally:
            theirs.close()
            for fd in (filter_fd, null, log):
                os.close(fd)
        self.pid = self.proc.pid
        self.sock.setblocking(False)
        self.alive = self._wait_ready()

    def _wait_ready(self) -> bool:
        deadline = time.monotonic() + READY_S
        while time.monotonic() < deadline and self.proc.poll() is None:
            r, _, _ = select.select([self.sock], [], [], 0.05)
            if r:
                try:
                    return self.sock.recv(64) == b"ready\n"
                except OSError:
                    return False
        return False

    def close(self) -> None:
        """End the jail: its pid 1 first (the kernel then kills the whole pid namespace), then bubblewrap."""
        if self.proc.poll() is None:
            self.box.terminate(self.pid)
            try:
                self.proc.wait(timeout=5)
            except Exception:  # noqa: BLE001 - a bubblewrap that would not die: SIGKILL its group
                os.killpg(self.pid, signal.SIGKILL)
                self.proc.wait()
        self.sock.close()
        self.alive = False

    def run(self, input_text: str, time_limit: float, idle_left: float) -> RunOutcome | None:
        """One test: ``input_text`` on stdin, the program's stdout in ``.value``; None when the
        request could not be sent (the jail had ended: nothing ran)."""
        box = self.box
        in_path = os.path.join(box.private_dir, "input.txt")
        out_path, err_path = output_paths(box)
        with open(in_path, "w") as f:
            f.write(input_text)
        fds = [os.open(in_path, os.O_RDONLY), os.open(out_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600),
               os.open(err_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)]
        _reset_peak(box, 0)
        cpu0 = _cpu_seconds(box, self.pid)
        cpu_limit = int(time_limit + 1) + 1  # RLIMIT_CPU as the per-test jail set it
        try:
            socket.send_fds(self.sock, [b"run %d\n" % cpu_limit], fds)
        except OSError:  # the jail ended since the last test: the caller starts a fresh one
            self.close()
            return None
        finally:
            for fd in fds:
                os.close(fd)
        sent, started = True, False
        wall0 = time.monotonic()
        deadline = wall0 + wall_limit_for(time_limit)
        waited = peak = 0.0
        report = b""
        cpu_exceeded = idle_exceeded = False
        while sent and time.monotonic() < deadline:
            r, _, _ = select.select([self.sock], [], [], max(0.0, min(_sample_s(box), deadline - time.monotonic())))
            if r:
                try:
                    report = self.sock.recv(256)
                except BlockingIOError:
                    continue
                except OSError:
                    report = b""
                if report == b"started\n" and not started:
                    started, report = True, b""
                    continue
                break
            box.sample_files(self.pid)
            peak = max(peak, _peak_rss_mb(box, self.pid)) if box.group is not None else 0.0
            if self.proc.poll() is not None:
                break
            used = _cpu_seconds(box, self.pid) - cpu0
            if used > time_limit + 0.05:
                cpu_exceeded = True
                break
            waited = max(waited, _runqueue_seconds(box, self.pid) if box.group is not None else 0.0)
            if time.monotonic() - wall0 - used - waited > min(idle_left, sleep_limit_for(time_limit)):
                idle_exceeded = True
                break
        wall = time.monotonic() - wall0
        m = _REPORT.fullmatch(report) if started else None
        if not started and not (cpu_exceeded or idle_exceeded):
            self.close()  # the jail ended (or broke the protocol) before the test's process started: nothing ran
            return None
        if m is None:  # a timeout, or the server is gone or said something else: this jail ends here
            self.close()
        elif m.group(8) != b"1":  # the jail could not be emptied: not reused
            self.close()
        cpu = mem = 0.0
        status = -signal.SIGKILL
        if m is not None:
            code = int(m.group(2))
            status = -code if m.group(1) == b"signal" else code
            cpu = (int(m.group(3)) + int(m.group(4))) / 1e6
            mem = int(m.group(5)) / 1024
            box.files.note("/tmp", int(m.group(6)) / 1024)
            box.files.note("/dev/shm", int(m.group(7)) / 1024)
        if box.group is not None:  # the whole sandbox, as the per-test jail measured it
            cpu = max(cpu, _cpu_seconds(box, self.pid) - cpu0)
            rss = mem + (0.0 if box.files_charged() else box.files.peak_mb())
            mem = max(peak, _peak_rss_mb(box, self.pid), rss if isinstance(box.group, ProcTree) else 0.0)
        time_s = round(cpu, 4)
        timed_out = m is None and (cpu_exceeded or idle_exceeded or time.monotonic() >= deadline)
        if m is None and not timed_out:
            outcome = _jail_died(box, time_s, mem)
        else:
            child = SimpleNamespace(violation=None, replies=[], exit_status=status)
            outcome = _stdio_outcome(box, child, time_limit, time_s, mem, timed_out, False, out_path, err_path)  # type: ignore[arg-type]
            if outcome.status == "crash" and status in (-signal.SIGABRT, -signal.SIGSEGV) and _bad_alloc(err_path):
                outcome = RunOutcome("memory", message="std::bad_alloc: the program could not get more memory "
                                     "(aborted)", time_s=time_s, memory_mb=mem)
        outcome.idle_s = max(0.0, wall - cpu - waited)
        return outcome


def _jail_died(box: Sandbox, time_s: float, mem: float) -> RunOutcome:
    """The server ended (or broke the protocol) during a test: MLE when the sandbox's memory limit
    was hit, else a run-time error; the next test gets a fresh jail."""
    if _memory_limit_hit(box):
        return RunOutcome("memory", message="the program's processes together went over the memory limit",
                          time_s=time_s, memory_mb=max(mem, float(box.limits.memory_mb)))
    return RunOutcome("crash", message="the program's jail ended during the test (the next test gets a fresh one)",
                      time_s=time_s, memory_mb=mem)


def run_program(box: Sandbox, input_text: str, time_limit: float, idle_left: float) -> RunOutcome | None:
    """One test of ``box``'s compiled program through its server (started on the first test, again
    after a jail ended), or None when no server can run here (the caller uses the per-test jail)."""
    for _ in range(2):  # a jail found dead before the request was sent: once more in a fresh one
        if not usable(box):
            return None
        server = box.attach(ATTACH_NAME)
        if not isinstance(server, ProgramServer) or not server.alive or server.proc.poll() is not None:
            if isinstance(server, ProgramServer):
                server.close()  # replaced below
            try:
                server = ProgramServer(box)
            except (OSError, ValueError, subprocess.SubprocessError) as exc:  # the jail could not start
                box.attach(ATTACH_NAME, _Failed(f"{type(exc).__name__}: {exc}"))
                return None
            if not server.alive:
                server.close()
                box.attach(ATTACH_NAME, _Failed("no 'ready' from the server"))
                return None
            box.attach(ATTACH_NAME, server)
        outcome = server.run(input_text, time_limit, idle_left)
        if outcome is not None:
            return outcome
    return None


def run_compiled(box: Sandbox, input_text: str, time_limit: float, forbidden: Sequence[str] = (),
                 filename: str = "submission.cpp", idle_left: float = float("inf")) -> RunOutcome:
    """One test of ``box``'s compiled program (``Sandbox(program=...)``): in the sandbox's one jail
    through its server where that can run (:func:`run_program`), else in a jail of its own
    (:func:`grader.judging.runner.run_stdio`); the program's stdout is in ``.value``."""
    served = run_program(box, input_text, time_limit, idle_left)
    if served is not None:
        return served
    return run_stdio(box, "", input_text, time_limit, forbidden, filename=filename, idle_left=idle_left, program=True)
