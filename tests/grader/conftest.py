"""Shared fixtures for the grader tests (run: .venv/bin/python -m pytest tests/grader -q)."""
from __future__ import annotations

import hashlib
import os
import time
from pathlib import Path

import pytest

from grader.contest.judge import Judge
from grader.problems import Problem
from grader.jail.procs import parent
from grader.jail import uidpool
from grader.jail.sandbox import Sandbox

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
FIXTURE_PROBLEM = HERE / "fixtures" / "tiny-delaunay"


@pytest.fixture(scope="session")
def tiny_judge() -> Judge:
    """A Judge for a one-group Delaunay problem with a 1 s limit, 256 MB, 1 MB of output."""
    return Judge(Problem.load(FIXTURE_PROBLEM))


#: Sandbox uids this test process has used (recorded by the autouse fixture below).
USED_UIDS: set[int] = set()


@pytest.fixture(autouse=True, scope="session")
def _record_sandbox_uids():
    """Remember the uid of every sandbox this run enters, so leftovers are looked for only there."""
    original = Sandbox.__enter__

    def enter(self):
        box = original(self)
        if getattr(box, "uid", None) is not None:
            USED_UIDS.add(box.uid)
        return box

    Sandbox.__enter__ = enter
    yield
    Sandbox.__enter__ = original


def sandbox_processes() -> list[int]:
    """PIDs of live processes of the sandbox uids this run used (there should be none between
    judgings). Each uid is checked while holding its slot lock, so processes of another grader
    on the same host, which may use the same uids, are never counted. Not root (the sandboxes
    run as this account): every process of this uid but this one and its ancestors that is
    still alive 3 s later (bubblewrap's reaper may still be exiting when the judge returns)."""
    if os.geteuid() != 0:
        mine, pid = {os.getpid()}, os.getpid()
        while (pid := parent(pid)) > 1:
            mine.add(pid)
        deadline = time.monotonic() + 3.0
        while (left := [p for p in _processes_of(os.getuid()) if p not in mine]) and time.monotonic() < deadline:
            time.sleep(0.05)
        return left
    pids = []
    dir_fd = uidpool.open_private_dir(uidpool.LOCK_DIR)
    try:
        for uid in sorted(USED_UIDS):
            slot = uidpool.hold(uid, dir_fd)
            if slot is None:
                continue  # another grader holds this slot now: what runs under it is not ours
            try:
                pids += _processes_of(uid)
            finally:
                slot.close()
    finally:
        os.close(dir_fd)
    return pids


def _processes_of(uid: int) -> list[int]:
    """Live processes of ``uid``. Zombies are dead, not live: bubblewrap leaves its reaper to
    the host's init to collect."""
    pids = []
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                with open(f"/proc/{d}/status") as f:
                    fields = dict(line.split(":", 1) for line in f if ":" in line)
                real = int(fields["Uid"].split()[0])
                zombie = fields["State"].split()[0] == "Z"
            except (OSError, KeyError, ValueError, IndexError):
                continue
            if real == uid and not zombie:
                pids.append(int(d))
    return pids


def tree_digest(*dirs: str) -> str:
    """A digest of every file under the given checkout directories (to prove nothing changed)."""
    h = hashlib.sha256()
    for d in dirs:
        for p in sorted((REPO / d).rglob("*")):
            if p.is_file() and "__pycache__" not in p.parts and ".pytest_cache" not in p.parts:
                h.update(str(p).encode())
                h.update(p.read_bytes())
    return h.hexdigest()
