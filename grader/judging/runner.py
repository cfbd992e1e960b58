"""Parent side of running student code: a persistent function-mode worker and one-shot stdio runs.

Both return a :class:`RunOutcome` (raw facts: what came back, how long, how much memory, how it
ended); :mod:`grader.contest.judge` turns outcomes into verdicts. Nothing here trusts the child: replies
are read with bounded, non-blocking reads under a wall-clock deadline, parsed as JSON only, and
time and memory are measured by the parent from ``/proc`` and ``wait4``.

Why one module: the function-mode worker and the stdio run share the one protocol with the
jail's child (:mod:`grader.jail.child_bootstrap`: its reply framing, the deadline loop, the
measurement of time and memory); split, the two halves of that protocol would be read apart.

Example:
    >>> with Sandbox(Limits()) as box:                                   # doctest: +SKIP
    ...     w = FunctionWorker(box, "def f(x): return x", "f", forbidden=[])
    ...     w.call([3], time_limit=1.0).value
    3
"""

from __future__ import annotations

import json
import marshal
import os
import select
import signal
import time
from dataclasses import dataclass
from typing import Any, Sequence

from ..jail import BOOTSTRAP_PATH, Sandbox, python_roots
from ..jail.paths import interpreter, site_paths
from ..jail.cgroups import SAMPLE_S, ProcTree
from ..jail.engines import ENGINE_API, IMPORTED_BY_LIBRARIES, engine_libraries, engine_modules
from .frames import decode as decode_frame
from .text import clean

#: The child's program (the grader's directory is not visible in the jail). It is compiled once
#: here and sent first on the child's control pipe as ``marshal`` data behind its length in 12
#: digits (the grader's data to the child, never the other way; the same interpreter on both
#: sides); the child's ``-c`` program is only :data:`LOADER`. Compiled in every child, the source
#: cost 4 ms of CPU a start.
BOOTSTRAP_SOURCE = BOOTSTRAP_PATH.read_text()
LOADER = """import marshal, os
def _take(n, fd={fd}):
    data = b""
    while len(data) < n:
        chunk = os.read(fd, n - len(data))
        if not chunk:
            os._exit(1)
        data += chunk
    return data
exec(marshal.loads(_take(int(_take(12)))))
"""
_bootstrap: list[bytes] = []


def bootstrap_code() -> bytes:
    """What the child's loader reads first: the length in 12 digits, then the compiled bootstrap."""
    if not _bootstrap:
        code = marshal.dumps(compile(BOOTSTRAP_SOURCE, "<string>", "exec", dont_inherit=True, optimize=0))
        _bootstrap.append(b"%012d" % len(code) + code)
    return _bootstrap[0]
CLK_TCK = os.sysconf("SC_CLK_TCK")


#: At most this many control lines per run beyond the protocol's own (load reply, one reply per call).
MAX_CONTROL_LINES = 4
_REPLY_KEYS = ("ok", "error", "bad_type")


def wall_limit_for(time_limit: float) -> float:
    """Backstop wall-clock cap of one test, reached only on a machine so loaded that the submission
    hardly gets a CPU (a 2-core machine at load 9 gives it about a fifth of one). A submission
    that sleeps is stopped much earlier (:func:`sleep_limit_for`); TLE is decided on CPU time.

    >>> wall_limit_for(2.0)
    30.0
    """
    return 10 * time_limit + 10.0


def sleep_limit_for(time_limit: float) -> float:
    """Wall time a test may spend *idle*: neither running nor waiting for a busy CPU (sleeping,
    blocked on a lock or a pipe). Time spent waiting in the run queue of a loaded machine does not
    count (it is read from ``/proc/<pid>/schedstat``), so this is slack, not a sleeping allowance.

    >>> sleep_limit_for(2.0)
    2.0
    """
    return 0.5 * time_limit + 1.0


def idle_budget_for(time_limit: float) -> float:
    """Idle wall time (see :func:`sleep_limit_for`) a whole submission may spend, summed over its
    tests: once spent, the remaining tests are TLE at once, so a sleeper holds a judge for at most
    this long.

    >>> idle_budget_for(6.0)
    30.0
    """
    return 2 * time_limit + 18.0


@dataclass
class RunOutcome:
    """What happened in one run. ``status`` is one of: ok, error, bad_type, violation, timeout,
    crash, output_limit, memory, load_error, exit (stdio normal end)."""

    status: str
    value: Any = None
    message: str = ""
    time_s: float = 0.0
    memory_mb: float = 0.0
    where: tuple[str, ...] = ()
    idle_s: float = 0.0  #: wall time not spent computing (sleeping, blocked, waiting for a CPU)


def _cpu_seconds(box: Sandbox, pid: int) -> float:
    """CPU seconds used so far by the whole sandbox (its cgroup: forked helpers included), or
    by process ``pid`` when the sandbox has no group (not root)."""
    if box.group is not None:
        try:
            return box.group.cpu_seconds()
        except (OSError, ValueError):
            return 0.0
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            fields = f.read().rsplit(b")", 1)[1].split()
        ticks = (int(fields[11]) + int(fields[12])) / CLK_TCK
        with open(f"/proc/{pid}/schedstat", "rb") as f:
            precise = int(f.read().split()[0]) / 1e9
        return max(ticks, precise)
    except (OSError, IndexError, ValueError):
        return 0.0


def _runqueue_seconds(box: Sandbox, pid: int) -> float:
    """Time spent runnable but waiting for a CPU (``schedstat`` field 2): summed over the
    sandbox's processes when it has a group (the jail's own pid 1 and the student's helpers),
    else of process ``pid``."""
    if box.group is not None:
        return box.group.runqueue_seconds(box.group.pids() or [pid])
    try:
        with open(f"/proc/{pid}/schedstat", "rb") as f:
            return int(f.read().split()[1]) / 1e9
    except (OSError, IndexError, ValueError):
        return 0.0


def _usage(box: Sandbox, pid: int) -> tuple[float, float]:
    """(:func:`_cpu_seconds`, :func:`_runqueue_seconds`) in one pass over the sandbox's counters."""
    if box.group is not None:
        return box.group.usage(pid)
    return _cpu_seconds(box, pid), _runqueue_seconds(box, pid)


def _peak_rss_mb(box: Sandbox, pid: int) -> float:
    """Peak memory since the last :func:`_reset_peak`: of the whole sandbox (cgroup) when it has
    a group, else the peak RSS of process ``pid``; plus, where no cgroup charges them, the files
    kept in the jail's tmpfs mounts (:meth:`Sandbox.sample_files`)."""
    if box.group is not None:
        files = 0.0 if box.files_charged() else box.files.peak_mb()
        try:
            return box.group.peak_memory_mb() + files
        except (OSError, ValueError):
            return files
    try:
        with open(f"/proc/{pid}/status", "rb") as f:
            for line in f:
                if line.startswith(b"VmHWM:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    return 0.0


def _reset_peak(box: Sandbox, pid: int) -> None:
    box.files.reset()
    if box.group is not None:
        try:
            box.group.reset_peak()
        except (OSError, ValueError):
            pass
        return
    try:
        with open(f"/proc/{pid}/clear_refs", "w") as f:
            f.write("5")
    except OSError:
        pass


def _memory_limit_hit(box: Sandbox) -> bool:
    """Did the kernel kill a process of the sandbox for memory (its cgroup's OOM killer) since
    the last :func:`_reset_peak`? (A forked helper can die that way while the worker answers.)"""
    try:
        return box.group is not None and box.group.memory_limit_hit()
    except (OSError, ValueError):
        return False


def _sample_s(box: Sandbox) -> float:
    """How often a running test's CPU and idle time are sampled: 0.2 s, or
    :data:`grader.jail.cgroups.SAMPLE_S` where the accounting is by samples of a process tree
    (an ordinary account: the exiting process's last CPU is only known from them)."""
    return SAMPLE_S if isinstance(box.group, ProcTree) else 0.2


def _describe_signal(sig: int) -> str:
    try:
        name = signal.Signals(sig).name
    except ValueError:
        name = f"signal {sig}"
    hint = {"SIGSEGV": " (segmentation fault: very deep recursion?)", "SIGABRT": " (aborted)",
            "SIGXCPU": " (CPU time limit)", "SIGKILL": " (killed)"}.get(name, "")
    return f"killed by {name}{hint}"


class _Child:
    """A started child with its control pipes; reads replies with a deadline.

    The control channel is bounded: a line must be one of the protocol's messages (for a call,
    exactly one reply carrying the id that was asked for), at most the problem's output limit in
    bytes, and at most :data:`MAX_CONTROL_LINES` lines beyond the protocol's own. The first line
    that is not (no id, a wrong or repeated id, not JSON, unknown keys) ends the reading: it is
    recorded as ``{"garbled": ...}`` and everything after it is discarded unread.
    """

    def __init__(self, box: Sandbox, config: dict, source: str, stdin: int, stdout: int, stderr: int,
                 cpu_s: float):
        self.box = box
        c_in_r, self.ctl_in = os.pipe()
        self.ctl_out, c_out_w = os.pipe()
        config = dict(config, ctl_in=c_in_r, ctl_out=c_out_w)
        self.launched = config["mode"] == "exec" and bool(box.launcher_path)
        if self.launched:  # a compiled program: the C launcher, no interpreter
            argv = [box.launcher_path, str(config["nproc"] or 0), str(config.get("stack_bytes") or 0),
                    str(c_in_r), str(c_out_w), config["program"]]
        else:
            sites = site_paths()  # -S: no .pth code in the child (see site_paths), its packages all the same
            if sites is not None:
                config["site_paths"] = list(sites)
            argv = [interpreter(), "-I" if sites is None else "-IS", "-c", LOADER.format(fd=c_in_r), json.dumps(config)]
        try:
            self.proc = box.spawn(argv, stdin, stdout, stderr, pass_fds=(c_in_r, c_out_w), cpu_s=cpu_s)
        finally:
            os.close(c_in_r)
            os.close(c_out_w)
        self.pid = self.proc.pid
        self.pidfd = os.pidfd_open(self.pid)
        os.set_blocking(self.ctl_in, False)
        os.set_blocking(self.ctl_out, False)
        self.buf = bytearray()
        self.max_bytes = (box.limits.output_mb << 20) + (1 << 16)  # the answer plus its JSON envelope
        self.line_budget = MAX_CONTROL_LINES + 1  # the load reply, then one per request sent
        self.want_id: int | None = None
        #: the reply keys a call may carry: "frame" only where the worker asked for frames
        self.reply_keys = _REPLY_KEYS + ("frame",) if config.get("frames") else _REPLY_KEYS
        self.junk = False
        self.replies: list[dict] = []
        self.exit_status: int | None = None
        self.rusage = None
        self.pending = (b"" if self.launched else bootstrap_code()) + (json.dumps({"source": source, "filename": config["filename"]}) + "\n").encode()
        self.violation: str | None = None

    def send(self, obj: dict, args_json: str | None = None) -> None:
        if "id" in obj:
            self.want_id = obj["id"]
            self.line_budget += 1
        line = json.dumps(obj, allow_nan=True, separators=(",", ":"))  # + args encoded by the judge, once a test
        self.pending += (line if args_json is None else f'{line[:-1]},"args":{args_json}}}').encode() + b"\n"

    def wait_reply(self, deadline: float, want: str | None = None) -> dict | None:
        """Pump I/O until a reply (with key ``want`` or any key if None) arrives, the child ends,
        or the deadline passes (checked on every read). Returns the reply or None."""
        while True:
            for i, r in enumerate(self.replies):
                if "violation" in r:
                    self.violation = self.violation or r["violation"]
                    return r
                if want is None or want in r or "garbled" in r or "output_limit" in r:
                    return self.replies.pop(i)
            if self.exit_status is not None and self.ctl_out < 0:
                return None
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            poller = select.poll()
            if self.pending and self.ctl_in >= 0:
                poller.register(self.ctl_in, select.POLLOUT)
            if self.ctl_out >= 0:
                poller.register(self.ctl_out, select.POLLIN)
            if self.exit_status is None:
                poller.register(self.pidfd, select.POLLIN)
            for fd, ev in poller.poll(max(1, int(left * 1000))):
                if fd == self.ctl_in:
                    try:
                        n = os.write(self.ctl_in, self.pending[: 1 << 16])
                        self.pending = self.pending[n:]
                    except BlockingIOError:
                        pass
                    except OSError:  # child closed its end
                        self.pending = b""
                elif fd == self.ctl_out:
                    self._read()
                elif fd == self.pidfd:
                    self._reap()
                    self._read()

    def _read(self) -> None:
        if self.ctl_out < 0:
            return
        try:
            chunk = os.read(self.ctl_out, 1 << 20)
        except BlockingIOError:
            return
        if not chunk:
            os.close(self.ctl_out)
            self.ctl_out = -1
            return
        if self.junk:
            return  # after a protocol violation everything is discarded unread
        self.buf += chunk
        start = 0
        while not self.junk:
            nl = self.buf.find(b"\n", start)
            if nl < 0:
                break
            self._accept(bytes(self.buf[start:nl]))
            start = nl + 1
        del self.buf[:start]
        if self.junk:
            self.buf.clear()
        elif len(self.buf) > self.max_bytes:
            self.buf.clear()
            self.junk = True
            self.replies.append({"output_limit": True})

    def _accept(self, line: bytes) -> None:
        """Keep ``line`` if it is a protocol message we expect now, else mark the channel as junk."""
        self.line_budget -= 1
        if len(line) > self.max_bytes:
            self.junk = True
            self.replies.append({"output_limit": True})
            return
        try:
            obj = json.loads(line) if self.line_budget >= 0 else None
        except (ValueError, RecursionError):
            obj = None
        if not isinstance(obj, dict):
            obj = None
        elif len(obj) == 1 and "violation" in obj:
            obj = {"violation": clean(obj["violation"], 500)}
        elif len(obj) == 1 and next(iter(obj)) in ("loaded", "load_error", "exit"):
            pass
        elif (len(obj) == 2 and type(obj.get("id")) is int and obj["id"] == self.want_id
              and any(k in obj for k in self.reply_keys)):
            self.want_id = None  # a second reply with the same id is junk
        else:
            obj = None
        if obj is None:
            self.junk = True
            what = "too many lines" if self.line_budget < 0 else clean(line[:200], 200)
            self.replies.append({"garbled": what})
        else:
            self.replies.append(obj)

    def _reap(self) -> None:
        if self.exit_status is None:
            try:
                _, status, self.rusage = os.wait4(self.pid, os.WNOHANG)
            except ChildProcessError:
                status = 0
            else:
                if _ == 0:
                    return
            self.exit_status = self.box.decode_exit(os.waitstatus_to_exitcode(status))
            self.proc.returncode = self.exit_status

    def release(self) -> None:
        """Close ``ctl_in`` once everything was sent: a stdio child waits for that before it exits."""
        if self.ctl_in >= 0 and not self.pending:
            os.close(self.ctl_in)
            self.ctl_in = -1

    def kill(self) -> None:
        """Kill the process group, reap the child, then sweep every process of the sandbox uid."""
        if self.exit_status is None:
            self.box.terminate(self.pid)
            _, status, self.rusage = os.wait4(self.pid, 0)
            self.exit_status = self.box.decode_exit(os.waitstatus_to_exitcode(status))
            self.proc.returncode = self.exit_status
        self.box.kill_all()
        self.close()

    def close(self) -> None:
        for name in ("ctl_in", "ctl_out", "pidfd"):
            fd = getattr(self, name)
            if fd >= 0:
                os.close(fd)
                setattr(self, name, -1)

    def drain_after_exit(self, seconds: float = 0.5) -> None:
        """After the child exited, read what is left on the pipe (grandchildren may hold it)."""
        end = time.monotonic() + seconds
        while self.ctl_out >= 0 and time.monotonic() < end:
            r, _, _ = select.select([self.ctl_out], [], [], max(0.0, end - time.monotonic()))
            if not r:
                break
            self._read()


def _child_config(box: Sandbox, mode: str, entry: str, forbidden: Sequence[str], filename: str) -> dict:
    work = box.child_workdir
    read_roots = python_roots() + [work, "/dev/null", "/dev/urandom", "/dev/zero", "/proc/self",
                                   "/usr/share/zoneinfo", "/etc/localtime"]
    return {"mode": mode, "entry": entry, "forbidden": list(forbidden), "filename": filename,
            "read_roots": read_roots, "write_roots": [work], "engines": engine_modules(forbidden),
            "engine_api": ENGINE_API, "engine_libs": engine_libraries(forbidden),
            "library_imports": list(IMPORTED_BY_LIBRARIES), "nproc": box.inner_nproc()}


def _classify_death(child: _Child, memory_mb: float, limit_mb: int) -> RunOutcome:
    code = child.exit_status
    if code is not None and code < 0:
        sig = -code
        if sig == signal.SIGXCPU:
            return RunOutcome("timeout", message="CPU time limit exceeded")
        if sig == signal.SIGSYS:  # the seccomp filter of a non-root jail: a new process
            return RunOutcome("violation", message="a forbidden system call (this jail lets a submission start no "
                                                   "other process: fork, vfork, clone, posix_spawn)", memory_mb=memory_mb)
        if sig == signal.SIGKILL and memory_mb >= 0.9 * limit_mb:
            return RunOutcome("memory", message="killed near the memory limit", memory_mb=memory_mb)
        return RunOutcome("crash", message=_describe_signal(sig), memory_mb=memory_mb)
    return RunOutcome("crash", message=f"the process exited with code {code} during the test", memory_mb=memory_mb)


def _output_overflow(box: Sandbox, paths: Sequence[str]) -> bool:
    limit = box.limits.output_mb << 20
    for p in paths:
        try:
            if os.stat(p).st_size >= limit:
                return True
        except OSError:  # not there (yet)
            pass
    return False


def output_paths(box: Sandbox) -> list[str]:
    """The files a run's stdout and stderr go to, in the sandbox's private directory."""
    return [os.path.join(box.private_dir, n) for n in ("stdout.txt", "stderr.txt")]


def _error_outcome(err: object, time_s: float = 0.0, memory_mb: float = 0.0) -> RunOutcome:
    """An error report from the child (any JSON: it may be forged) as a sanitised outcome."""
    err = err if isinstance(err, dict) else {}
    kind = clean(err.get("type", "Error"), 100)
    msg = clean(err.get("message", kind))
    frames = err.get("where")
    where = tuple(clean(w, 300) for w in frames[:4] if isinstance(w, str)) if isinstance(frames, list) else ()
    status = "memory" if kind == "MemoryError" else "error"
    if "[Errno 28]" in msg:  # ENOSPC: a tmpfs of the jail is full, and its files are memory
        status, msg = "memory", f"a file system of the jail is full (files there count as memory): {msg}"
    return RunOutcome(status, message=msg, time_s=time_s, memory_mb=memory_mb, where=where)


class FunctionWorker:
    """One worker process per submission; reused across tests, restarted after a crash or timeout."""

    def __init__(self, box: Sandbox, source: str, entry: str, forbidden: Sequence[str],
                 filename: str = "submission.py", load_timeout: float = 10.0, total_cpu_s: float = 60.0,
                 frames: bool = False):
        """``frames``: a long answer of float rows comes back as a ``FloatRows`` (a binary
        frame, :mod:`grader.judging.frames`) instead of nested lists; the caller takes both."""
        self.box, self.source, self.entry = box, source, entry
        self.config = _child_config(box, "function", entry, forbidden, filename)
        if frames:
            self.config["frames"] = True
        self.load_timeout = load_timeout
        self.total_cpu_s = total_cpu_s
        self.child: _Child | None = None
        self.out_paths = output_paths(box)
        self.load_failure: RunOutcome | None = None
        self._next_id = 0
        self.starts = 0

    def start(self) -> RunOutcome | None:
        """Start the worker and load the submission; returns a failure outcome or None."""
        self.stop()
        fds = [os.open(p, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600) for p in self.out_paths]
        null = os.open(os.devnull, os.O_RDONLY)
        try:
            self.child = _Child(self.box, self.config, self.source, null, fds[0], fds[1], self.total_cpu_s)
        finally:
            for fd in (*fds, null):
                os.close(fd)
        self.starts += 1
        t0 = time.monotonic()
        reply = self.child.wait_reply(t0 + self.load_timeout, want="loaded")
        outcome = None
        if reply is None and self.child.exit_status is None:
            outcome = RunOutcome("timeout", message=f"loading the submission took over {self.load_timeout:g} s")
        elif reply is None:
            self.child.drain_after_exit()
            reply = next((r for r in self.child.replies if "load_error" in r or "violation" in r), None)
        if outcome is None and reply is not None and "violation" in reply:
            outcome = RunOutcome("violation", message=reply["violation"])
        elif outcome is None and reply is not None and ("garbled" in reply or "output_limit" in reply):
            outcome = RunOutcome("bad_type", message="while loading, the submission wrote on the judge's channel")
        elif outcome is None and reply is not None and "load_error" in reply:
            outcome = _error_outcome(reply["load_error"])
            outcome.status = "memory" if outcome.status == "memory" else "load_error"
        elif outcome is None and reply is None:
            outcome = _classify_death(self.child, 0.0, self.box.limits.memory_mb)
            outcome.message = "while loading: " + outcome.message
        if outcome is not None:
            if _output_overflow(self.box, self.out_paths):
                outcome = RunOutcome("output_limit", message="too much output while loading")
            self.stop()
            self.load_failure = outcome
        return outcome

    def stop(self) -> None:
        if self.child is not None:
            self.child.kill()
            self.child = None

    def call(self, args: list, time_limit: float, idle_left: float = float("inf"), args_json: str | None = None) -> RunOutcome:
        """Run the entry function on ``args`` (JSON-native; ``args_json``: the same, encoded) under
        ``time_limit`` CPU seconds, stopping early once it has spent ``idle_left`` s of wall time not computing."""
        if idle_left <= 0:
            return RunOutcome("timeout", message="the submission's wall-time budget is used up (it spent it "
                                                 "sleeping or blocked)", time_s=time_limit)
        if self.child is None or self.child.exit_status is not None:
            failure = self.start()
            if failure is not None:
                return failure
        child = self.child
        assert child is not None
        self._next_id += 1
        rid = self._next_id
        _reset_peak(self.box, child.pid)
        cpu0, rq0 = _usage(self.box, child.pid)
        wall0 = time.monotonic()
        child.send({"id": rid} if args_json is not None else {"id": rid, "args": args}, args_json)
        wall_limit = wall_limit_for(time_limit)
        deadline = wall0 + wall_limit
        cpu_exceeded = idle_exceeded = False
        while True:
            reply = child.wait_reply(min(time.monotonic() + _sample_s(self.box), deadline), want="id")
            self.box.sample_files(child.pid)
            if reply is not None:  # the reply to this call, a violation, or junk (see _Child)
                break
            if child.exit_status is not None or time.monotonic() >= deadline:
                break
            cpu, rq = _usage(self.box, child.pid)
            used = cpu - cpu0
            if used > time_limit + 0.05:
                cpu_exceeded = True
                break
            idle = time.monotonic() - wall0 - used - (rq - rq0)
            if idle > min(idle_left, sleep_limit_for(time_limit)):
                idle_exceeded = True
                break
        wall = time.monotonic() - wall0
        alive = child.exit_status is None
        if alive:
            cpu, waited = _usage(self.box, child.pid)
            cpu, waited = cpu - cpu0, waited - rq0
        else:
            cpu, waited = _cpu_seconds(self.box, child.pid) - cpu0 if self.box.group else wall, 0.0
        mem = _peak_rss_mb(self.box, child.pid)
        time_s = round(max(cpu, 0.0), 4)
        idle = max(0.0, wall - max(cpu, 0.0) - waited)
        outcome = self._outcome(child, reply, time_limit, time_s, mem, cpu_exceeded, idle_exceeded)
        outcome.idle_s = idle
        return outcome

    def _outcome(self, child: _Child, reply: dict | None, time_limit: float, time_s: float, mem: float,
                 cpu_exceeded: bool, idle_exceeded: bool) -> RunOutcome:
        overflow = _output_overflow(self.box, self.out_paths)
        if _memory_limit_hit(self.box) and not (reply is not None and "violation" in reply):
            self.stop()
            return RunOutcome("memory", message="the submission's processes together went over the memory limit",
                              time_s=time_s, memory_mb=max(mem, float(self.box.limits.memory_mb)))
        if self.box.files.full_message() and not (reply is not None and "violation" in reply):
            self.stop()  # its files go with its jail
            return RunOutcome("memory", message=self.box.files.full_message(), time_s=time_s, memory_mb=mem)
        if reply is not None and "violation" in reply:
            self.stop()
            return RunOutcome("violation", message=reply["violation"], time_s=time_s, memory_mb=mem)
        if overflow or (reply is not None and "output_limit" in reply):
            self.stop()
            return RunOutcome("output_limit", message=f"more than {self.box.limits.output_mb} MiB of output",
                              time_s=time_s, memory_mb=mem)
        if reply is None:
            if cpu_exceeded:
                self.stop()
                return RunOutcome("timeout", message=f"over {time_limit:g} s of CPU time (stopped)",
                                  time_s=max(time_s, time_limit), memory_mb=mem)
            if idle_exceeded:
                self.stop()
                return RunOutcome("timeout", message="stopped: it was idle (sleeping or blocked, not computing) for "
                                                     f"over {sleep_limit_for(time_limit):g} s, or the submission's "
                                                     "idle budget is used up", time_s=max(time_s, time_limit),
                                  memory_mb=mem)
            if child.exit_status is None:
                self.stop()
                return RunOutcome("timeout", message=f"no answer within {wall_limit_for(time_limit):g} s of wall time",
                                  time_s=max(time_s, time_limit), memory_mb=mem)
            child.drain_after_exit()
            late = [r for r in child.replies if "violation" in r]
            if late:
                self.stop()
                return RunOutcome("violation", message=late[0]["violation"], time_s=time_s)
            outcome = _classify_death(child, mem, self.box.limits.memory_mb)
            outcome.time_s = time_s
            self.stop()
            return outcome
        if time_s > time_limit:
            return RunOutcome("timeout", message=f"used {time_s:.2f} s of CPU time (limit {time_limit:g} s)",
                              time_s=time_s, memory_mb=mem)
        if "garbled" in reply:
            self.stop()
            return RunOutcome("bad_type", message="the submission wrote on the judge's channel (protocol "
                                                  f"violation: {reply['garbled'][:80]})", time_s=time_s, memory_mb=mem)
        if "error" in reply:
            return _error_outcome(reply["error"], time_s, mem)
        if "bad_type" in reply:
            return RunOutcome("bad_type", message=f"returned a value of type {clean(reply['bad_type'], 200)}",
                              time_s=time_s, memory_mb=mem)
        if "frame" in reply:  # only where asked for (_Child.reply_keys); checked part by part
            try:
                value: Any = decode_frame(reply["frame"])
            except ValueError as exc:
                return RunOutcome("bad_type", message=f"the answer's binary frame is malformed: {exc}",
                                  time_s=time_s, memory_mb=mem)
            return RunOutcome("ok", value=value, time_s=time_s, memory_mb=mem)
        if "ok" not in reply:
            return RunOutcome("bad_type", message="the worker sent an unreadable answer", time_s=time_s, memory_mb=mem)
        return RunOutcome("ok", value=reply["ok"], time_s=time_s, memory_mb=mem)


def run_stdio(box: Sandbox, source: str, input_text: str, time_limit: float, forbidden: Sequence[str],
              filename: str = "submission.py", idle_left: float = float("inf"), program: bool = False) -> RunOutcome:
    """Run the submission once as a program with ``input_text`` on stdin; output in ``.value``.
    It is stopped once it has spent ``idle_left`` seconds of wall time not computing.
    ``program``: run the sandbox's compiled binary (``Sandbox(program=...)``) instead of ``source``;
    its stack may grow up to the memory limit; this runs it in a jail of its own (the judge runs a
    compiled program's tests in one jail, :func:`grader.judging.program_server.run_compiled`)."""
    if idle_left <= 0:
        return RunOutcome("timeout", message="the submission's wall-time budget is used up (it spent it "
                                             "sleeping or blocked)", time_s=time_limit)
    config = _child_config(box, "exec" if program else "stdio", "", forbidden, filename)
    if program:
        config.update(program=box.program_path, stack_bytes=box.limits.memory_mb << 20)
        source = ""
    in_path = os.path.join(box.private_dir, "input.txt")
    out_path, err_path = output_paths(box)
    with open(in_path, "w") as f:
        f.write(input_text)
    fin = os.open(in_path, os.O_RDONLY)
    fout = os.open(out_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    ferr = os.open(err_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    _reset_peak(box, 0)
    cpu0 = _cpu_seconds(box, 0)
    try:
        child = _Child(box, config, source, fin, fout, ferr, time_limit + 1)
    finally:
        for fd in (fin, fout, ferr):
            os.close(fd)
    wall0 = time.monotonic()
    waited = 0.0  # run-queue wait of the new process, as last seen while it was alive
    deadline = wall0 + wall_limit_for(time_limit)
    reply = None
    peak = 0.0
    cpu_exceeded = junk = False
    while child.exit_status is None and time.monotonic() < deadline:
        reply = child.wait_reply(min(time.monotonic() + _sample_s(box), deadline), want="exit")
        box.sample_files(child.pid)
        peak = max(peak, _peak_rss_mb(box, child.pid)) if box.group is not None else 0.0  # a tree is sampled
        if reply is not None and "exit" in reply:  # the program ended: its files are measured, it may go
            child.release()
            reply = None
        if reply is not None and "violation" in reply:
            break
        if reply is not None and ("garbled" in reply or "output_limit" in reply):
            junk = True
            break
        if child.exit_status is not None:
            break
        used = _cpu_seconds(box, child.pid) - (cpu0 if box.group else 0.0)
        if used > time_limit + 0.05:
            cpu_exceeded = True
            break
        waited = max(waited, _runqueue_seconds(box, child.pid))
        if time.monotonic() - wall0 - used - waited > min(idle_left, sleep_limit_for(time_limit)):
            break
    wall = time.monotonic() - wall0
    timed_out = cpu_exceeded or (not junk and child.exit_status is None and (reply is None or "violation" not in reply))
    child.kill() if child.exit_status is None else None
    child.drain_after_exit(0.2)
    box.kill_all()
    child.close()
    ru = child.rusage
    cpu = (ru.ru_utime + ru.ru_stime) if ru is not None else 0.0
    mem = (ru.ru_maxrss / 1024) if ru is not None else 0.0
    if box.group is not None:  # the whole sandbox, forked helpers included; not ru_maxrss: it keeps the
        # RSS of the grader forked before exec (measured: 249 MB reported for a program of 17 MB)
        cpu, mem = max(cpu, _cpu_seconds(box, 0) - cpu0), max(peak, _peak_rss_mb(box, 0))
    time_s = round(cpu, 4)
    outcome = _stdio_outcome(box, child, time_limit, time_s, mem, timed_out, junk, out_path, err_path)
    # abort() in the namespace's pid 1 (the jail runs the program as pid 1): its own SIGABRT is
    # ignored, as for any init, and glibc's abort() falls back to a faulting instruction (SIGSEGV)
    if program and outcome.status == "crash" and child.exit_status in (-signal.SIGABRT, -signal.SIGSEGV) \
            and _bad_alloc(err_path):
        outcome = RunOutcome("memory", message="std::bad_alloc: the program could not get more memory (aborted)",
                             time_s=time_s, memory_mb=mem)
    outcome.idle_s = max(0.0, wall - cpu - waited)
    return outcome


def _bad_alloc(err_path: str) -> bool:
    """Did a C++ program end on an uncaught ``std::bad_alloc`` (its message is the last of stderr)?"""
    try:
        with open(err_path, "rb") as f:
            f.seek(max(0, os.path.getsize(err_path) - 4096))
            return b"std::bad_alloc" in f.read()
    except OSError:
        return False


def _stdio_outcome(box: Sandbox, child: _Child, time_limit: float, time_s: float, mem: float, timed_out: bool,
                   junk: bool, out_path: str, err_path: str) -> RunOutcome:
    cpu = time_s
    violation = child.violation or next((r["violation"] for r in child.replies if "violation" in r), None)
    if violation:
        return RunOutcome("violation", message=violation, time_s=time_s, memory_mb=mem)
    if junk:
        return RunOutcome("bad_type", message="the program wrote on the judge's channel (protocol violation)",
                          time_s=time_s, memory_mb=mem)
    if _memory_limit_hit(box):
        return RunOutcome("memory", message="the program's processes together went over the memory limit",
                          time_s=time_s, memory_mb=max(mem, float(box.limits.memory_mb)))
    if box.files.full_message():
        return RunOutcome("memory", message=box.files.full_message(), time_s=time_s, memory_mb=mem)
    if _output_overflow(box, [out_path, err_path]):
        return RunOutcome("output_limit", message=f"more than {box.limits.output_mb} MiB of output",
                          time_s=time_s, memory_mb=mem)
    if timed_out or cpu > time_limit or (child.exit_status or 0) == -signal.SIGXCPU:
        return RunOutcome("timeout", message=f"time limit {time_limit:g} s exceeded", time_s=max(time_s, time_limit),
                          memory_mb=mem)
    errors = [r["load_error"] for r in child.replies if isinstance(r.get("load_error"), dict)]
    if errors:
        outcome = _error_outcome(errors[0], time_s, mem)
        if errors[0].get("type") == "SyntaxError":
            outcome.status = "load_error"
        return outcome
    if child.exit_status != 0:
        outcome = _classify_death(child, mem, box.limits.memory_mb)
        outcome.time_s = time_s
        if child.exit_status and child.exit_status > 0:
            outcome.message = f"the program exited with code {child.exit_status}"
        return outcome
    with open(out_path, "rb") as f:
        data = f.read(box.limits.output_mb << 20)
    return RunOutcome("ok", value=data.decode("utf-8", errors="replace"), time_s=time_s, memory_mb=mem)
