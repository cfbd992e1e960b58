"""The runner measures per-test memory and CPU time and reuses one worker across tests.

Run: .venv/bin/python -m pytest tests/grader/test_runner.py -q
"""
from __future__ import annotations

from grader.runner import FunctionWorker
from grader.sandbox import Limits, Sandbox, is_root

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
