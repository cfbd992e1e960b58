"""The benchmark scripts stay runnable: every script under benchmarks/ compiles, and the Delaunay
benchmark prints its table on small sizes (timings are printed, never asserted).

Run: .venv/bin/python -m pytest tests/test_benchmarks.py -q
"""
from __future__ import annotations

import py_compile
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCRIPTS = sorted((ROOT / "benchmarks").glob("*.py"))


@pytest.mark.parametrize("script", SCRIPTS, ids=[s.name for s in SCRIPTS])
def test_script_compiles(script, tmp_path):
    py_compile.compile(str(script), cfile=str(tmp_path / "out.pyc"), doraise=True)


def test_bench_delaunay_prints_its_table():
    run = subprocess.run([sys.executable, "benchmarks/bench_delaunay.py", "--quick", "--sizes", "100", "2000",
                          "--kinds", "uniform", "grid", "--repeat", "1"],
                         cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-3000:]
    rows = [line.split("|") for line in run.stdout.splitlines() if line.startswith(("uniform", "grid"))]
    assert [r[0].split()[0] for r in rows] == ["uniform", "uniform", "grid", "grid"], run.stdout
    for r in rows:
        ours, tri, ratio = float(r[1]), float(r[2]), float(r[4])
        assert ours > 0 and tri > 0, r
        # The times are printed rounded to 0.001 ms and the ratio (to 0.01) comes from the unrounded
        # times, so the ratio must lie in the interval the printed times allow, not at their quotient.
        low, high = max(ours - 5e-4, 0) / (tri + 5e-4), (ours + 5e-4) / max(tri - 5e-4, 1e-12)
        assert low - 0.005 <= ratio <= high + 0.005, (r, low, high)
