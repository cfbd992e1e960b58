"""The runner measures per-test memory and CPU time and reuses one worker across tests.

Run: .venv/bin/python -m pytest tests/grader/test_runner.py -q
"""
from __future__ import annotations

from grader.judging.runner import FunctionWorker
from grader.jail.sandbox import Limits, Sandbox, is_root

SOURCE = """
import os
def f(mb, spin):
    if mb:
        x = bytearray(mb << 20)
        x[::4096] = b"x" * len(x[::4096])
    s = 0
    for i in range(spin):
        s += i
    return [os.getpid(), os.getuid(), os.getcwd(), sorted(os.environ)]
"""


def test_worker_is_reused_and_measures_each_test():
    with Sandbox(Limits(memory_mb=512)) as box:
        w = FunctionWorker(box, SOURCE, "f", forbidden=[])
        big = w.call([150, 0], time_limit=2)
        small = w.call([0, 3_000_000], time_limit=2)
        assert big.status == small.status == "ok"
        assert big.value[0] == small.value[0] and w.starts == 1  # one worker for both tests
        assert big.memory_mb > 140 > small.memory_mb  # the peak is reset between tests
        assert small.time_s > 0.01 and big.time_s > 0
        assert "GRADER_PROBLEMS" not in small.value[3] and "HOME" in small.value[3]  # scrubbed environment
        if is_root():
            assert small.value[1] != 0 and small.value[2] == "/tmp/work"  # unprivileged, private directory
        w.stop()


def test_worker_restarts_after_a_crash():
    # a per-process identity: in the bubblewrap jail (its own pid namespace) every worker is pid 2
    src = "import os, time\nSTART = time.time_ns()\ndef f(crash):\n    if crash:\n        os._exit(3)\n    return START\n"
    with Sandbox(Limits()) as box:
        w = FunctionWorker(box, src, "f", forbidden=[])
        first = w.call([False], 1).value
        assert w.call([True], 1).status == "crash"
        again = w.call([False], 1)
        assert again.status == "ok" and again.value != first and w.starts == 2
        w.stop()


CHANNEL = """
import json, os, time
def _fd():
    return json.loads(open("/proc/self/cmdline", "rb").read().split(b"\\0")[4])["ctl_out"]
def f(kind):
    fd = _fd()
    if kind == "idless":
        for _ in range(5000):
            os.write(fd, b'{"x": 1}\\n')
    elif kind == "wrong_id":
        os.write(fd, b'{"id": 999, "ok": 1}\\n')
    elif kind == "twice":
        os.write(fd, json.dumps({"id": 1, "ok": 1}).encode() + b"\\n" + json.dumps({"id": 1, "ok": 2}).encode() + b"\\n")
        time.sleep(5)
    elif kind == "huge_line":
        os.write(fd, b"[" * (3 << 20))
        time.sleep(5)
    return 0
"""


def test_control_channel_junk_ends_the_call_at_once():
    with Sandbox(Limits(output_mb=1)) as box:
        for kind, status in (("idless", "bad_type"), ("wrong_id", "bad_type"), ("huge_line", "output_limit")):
            w = FunctionWorker(box, CHANNEL, "f", forbidden=[])
            out = w.call([kind], time_limit=2)
            assert out.status == status, (kind, out)
            assert out.time_s < 2 and len(w.child.replies if w.child else []) <= 1
            w.stop()
        w = FunctionWorker(box, CHANNEL, "f", forbidden=[])
        first = w.call(["twice"], time_limit=2)  # its own forged reply with the right id is its answer
        assert first.status == "ok" and first.value == 1
        second = w.call(["plain"], time_limit=2)  # the duplicate was junk: the next call is PE at once
        assert second.status == "bad_type" and "judge's channel" in second.message
        w.stop()


def test_sleeping_is_stopped_early_and_spends_the_idle_budget():
    src = "import time\ndef f(s):\n    time.sleep(s)\n    return s\n"
    with Sandbox(Limits()) as box:
        w = FunctionWorker(box, src, "f", forbidden=[])
        nap = w.call([0.6], time_limit=1)
        assert nap.status == "ok" and nap.idle_s >= 0.5  # the idle time is measured...
        assert w.call([0.6], time_limit=1, idle_left=0.3).status == "timeout"  # ...and charged to the budget
        assert w.call([0.1], time_limit=1, idle_left=0.0).status == "timeout"  # spent: TLE at once
        slept = w.call([60], time_limit=1)  # idle cap 0.5 x 1 s + 1 s, far below the 20 s backstop
        assert slept.status == "timeout" and "idle" in slept.message
        w.stop()


def test_busy_machine_is_not_idle_time():
    """Waiting for a CPU (run queue, from schedstat) is not idleness: a CPU-bound call is never
    stopped as idle, however loaded the machine (this one usually is)."""
    src = "def f(n):\n    s = 0\n    for i in range(n):\n        s += i\n    return s\n"
    with Sandbox(Limits()) as box:
        w = FunctionWorker(box, src, "f", forbidden=[])
        out = w.call([2_000_000], time_limit=5, idle_left=0.5)
        assert out.status == "ok", out
        w.stop()


def test_the_child_has_sites_builtins_and_reads_large_and_many_requests():
    """The child starts without ``site`` (``-S``) but gives a submission the builtins ``site``
    would (``exit`` and ``quit`` end a test like ``sys.exit``; ``help``, ``copyright``, ``credits``,
    ``license`` exist); requests larger than a pipe's 64 KiB and many small ones in a row arrive whole."""
    src = ("import builtins\n"
           "def f(kind, data):\n"
           "    if kind in ('exit', 'quit'):\n"
           "        getattr(builtins, kind)(3)\n"
           "    if kind == 'names':\n"
           "        return [n for n in ('help', 'copyright', 'credits', 'license', 'exit', 'quit')"
           " if callable(getattr(builtins, n, None))]\n"
           "    return [len(data), sum(data)]\n")
    with Sandbox(Limits(memory_mb=512)) as box:
        w = FunctionWorker(box, src, "f", forbidden=[])
        names = w.call(["names", []], time_limit=2)
        assert names.status == "ok" and names.value == ["help", "copyright", "credits", "license", "exit", "quit"]
        for kind in ("exit", "quit"):
            ended = w.call([kind, []], time_limit=2)
            assert ended.status == "error" and "sys.exit(3)" in ended.message, ended
        big = list(range(100_000))  # about 600 KB of JSON: many pipe-fulls
        assert w.call(["sum", big], time_limit=5).value == [len(big), sum(big)]
        for k in range(50):
            assert w.call(["sum", [k, 1]], time_limit=2).value == [2, k + 1]
        assert w.starts == 1
        w.stop()
