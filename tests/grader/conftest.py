"""Shared fixtures for the grader tests (run: .venv/bin/python -m pytest tests/grader -q)."""
from __future__ import annotations

import hashlib
import os
from pathlib import Path

import pytest

from grader.judge import Judge
from grader.problems import Problem
from grader.sandbox import UID_BASE, UID_COUNT

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
FIXTURE_PROBLEM = HERE / "fixtures" / "tiny-delaunay"


@pytest.fixture(scope="session")
def tiny_judge() -> Judge:
    """A Judge for a one-group Delaunay problem with a 1 s limit, 256 MB, 1 MB of output."""
    return Judge(Problem.load(FIXTURE_PROBLEM))


def sandbox_processes() -> list[int]:
    """PIDs of live processes owned by a sandbox uid (there should be none between judgings).
    Zombies are dead, not live: bubblewrap leaves its reaper to the host's init to collect."""
    pids = []
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                with open(f"/proc/{d}/status") as f:
                    fields = dict(line.split(":", 1) for line in f if ":" in line)
                uid = int(fields["Uid"].split()[0])
                zombie = fields["State"].split()[0] == "Z"
            except (OSError, KeyError, ValueError, IndexError):
                continue
            if UID_BASE <= uid < UID_BASE + UID_COUNT and not zombie:
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
