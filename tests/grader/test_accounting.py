"""The per-test fixed cost's parts: counters read through kept descriptors, a child that starts lean.

Run: .venv/bin/python -m pytest tests/grader/test_accounting.py -q

What is checked: :class:`grader.jail.cgroups.ControlFile` reads a whole file however it changes and
writes from its start; the cgroup-v2 accounting (not delegated on every machine, so on a stand-in
directory of plain files) reads CPU, peak and OOM kills through the same descriptors and closes
them; a sandbox leaves no descriptor open after many tests; the jailed child starts without
``re`` (the ``json`` package, ``traceback`` and ``linecache`` all import it) and still has its
site-packages, ``exit`` and source lines in the tracebacks a student prints.
"""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from grader.jail import cgroups
from grader.jail.cgroups import ControlFile
from grader.jail.sandbox import Limits, Sandbox
from grader.judging.runner import FunctionWorker


def _open_fds() -> set[str]:
    return set(os.listdir("/proc/self/fd"))


def test_control_file_reads_everything_and_follows_rewrites(tmp_path: Path):
    p = tmp_path / "counter"
    p.write_bytes(b"x" * 10_000 + b"\n")
    f = ControlFile(str(p), writable=True)
    assert f.read(4096) == b"x" * 10_000 + b"\n"  # more than one chunk
    p.write_text("12\n")  # the same file rewritten (a counter moving on)
    assert f.read() == b"12\n"
    f.write(b"7")
    assert p.read_text() == "72\n"  # written from the start
    f.close()
    assert f.fd == -1
    with pytest.raises(OSError):
        ControlFile(str(tmp_path / "missing")).read()  # opened on first use: the error comes then


def test_cgroup_v2_reads_through_kept_descriptors(tmp_path: Path):
    (tmp_path / "cpu.stat").write_text("usage_usec 2500000\nuser_usec 2000000\n")
    (tmp_path / "memory.peak").write_text(str(300 << 20) + "\n")
    (tmp_path / "memory.events").write_text("low 0\nhigh 0\nmax 3\noom 1\noom_kill 1\n")
    (tmp_path / "cgroup.procs").write_text("")
    before = _open_fds()
    g = cgroups._V2(tmp_path, memory_mb=256, processes=8)
    assert (tmp_path / "memory.max").read_text() == str(256 << 20) and (tmp_path / "pids.max").read_text() == "8"
    assert g.cpu_seconds() == 2.5
    assert not g.memory_limit_hit()  # the kills before the reset do not count
    (tmp_path / "memory.events").write_text("low 0\nhigh 0\nmax 4\noom 2\noom_kill 2\n")
    assert g.memory_limit_hit()
    g.reset_peak()
    assert not g.memory_limit_hit()
    (tmp_path / "cpu.stat").write_text("usage_usec 3000000\n")
    assert g.usage(fallback=os.getpid())[0] == 3.0
    assert g.peak_memory_mb() > 0
    assert _open_fds() - before  # the counters' descriptors are kept open...
    g.close()
    assert _open_fds() == before  # ...and closed with the group


def test_many_tests_leave_no_descriptor_open():
    before = _open_fds()
    with Sandbox(Limits(memory_mb=256)) as box:
        w = FunctionWorker(box, "def f(x):\n    return x\n", "f", forbidden=[])
        assert [w.call([k], time_limit=2).value for k in range(50)] == list(range(50))
        during = _open_fds()
        assert w.call([1], time_limit=2).value == 1 and _open_fds() == during  # steady: nothing opened a test
        w.stop()
    assert _open_fds() == before


CHILD = """
import sys
LOADED = sorted(m for m in ("re", "json", "traceback", "linecache") if m in sys.modules)
import numpy
def f(x):
    import io, traceback
    try:
        {}[x]
    except KeyError:
        buf = io.StringIO()
        traceback.print_exc(file=buf)
    return [LOADED, callable(exit), int(numpy.int64(x)), buf.getvalue()]
"""


def test_child_starts_without_re_and_keeps_site_packages():
    with Sandbox(Limits(memory_mb=1024)) as box:
        w = FunctionWorker(box, CHILD, "f", forbidden=[])
        out = w.call([3], time_limit=5)
        w.stop()
    assert out.status == "ok", out
    loaded, has_exit, three, printed = out.value
    assert loaded == [] and has_exit and three == 3
    assert "\n    {}[x]\n" in printed  # the student's own traceback shows its source line
