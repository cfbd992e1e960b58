"""ruff over the whole repository, with the configuration in pyproject.toml ([tool.ruff]).

Run: .venv/bin/python -m pytest tests/test_lint.py -q      (or: .venv/bin/python -m ruff check .)

ruff is in the dev extras (``pip install -e '.[dev]'``, what ``make setup`` does), so CI runs
this; without ruff installed the test is skipped and says so.
"""
from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.skipif(importlib.util.find_spec("ruff") is None,
                    reason="ruff is not installed (it is in the dev extras: pip install -e '.[dev]')")
def test_ruff_check_passes():
    out = subprocess.run([sys.executable, "-m", "ruff", "check", "--no-cache", "--output-format", "concise", "."],
                         cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, f"ruff check found problems:\n{out.stdout}{out.stderr}"
