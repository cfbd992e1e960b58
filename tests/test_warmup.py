"""The warm-up (`python -m reference_impl warm`, run by `make setup`) leaves numba's cache
holding every kernel, so that no lesson, problem or judge run waits for a compile.

Two fresh processes: the first warms (compiling only what is stale, e.g. after an edit), the
second runs the same features and must compile nothing (no cache miss in any kernel), and every
kernel that is not ``inline="always"`` has its index file in the cache directory numba uses.
On a fresh clone (CI) ``make test`` runs the warm-up on an empty cache first, and the warm-up
fails when some kernel is left out of the cache: that is where a feature missing from
``warmup.FEATURES`` is caught.

Run: .venv/bin/python -m pytest tests/test_warmup.py -q
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

from reference_impl import warmup

ROOT = Path(__file__).resolve().parents[1]

PROBE = textwrap.dedent("""
    import json
    from reference_impl import warmup
    seconds = warmup.warm(progress=None)
    misses = {name: sum(disp.stats.cache_misses.values()) for name, disp in warmup.kernels().items()}
    print(json.dumps({"seconds": seconds, "misses": {k: v for k, v in misses.items() if v},
                      "unindexed": warmup.not_cached(),
                      "kernels": len(warmup.kernels())}))
""")


def _probe() -> dict:
    run = subprocess.run([sys.executable, "-c", PROBE], cwd=ROOT, capture_output=True, text=True, timeout=1800)
    assert run.returncode == 0, run.stderr[-3000:]
    return json.loads(run.stdout.strip().splitlines()[-1])


def test_after_warming_nothing_compiles_and_every_kernel_is_cached():
    _probe()                       # warm: compiles whatever is stale
    second = _probe()
    assert second["kernels"] > 100, second   # the package's kernels were found
    assert second["misses"] == {}, f"compiled again in a warmed process: {second['misses']}"
    assert second["unindexed"] == [], f"kernels the warm-up never reached: {second['unindexed']}"
    assert set(second["seconds"]) == {"2d predicates", "3d predicates", "2d delaunay", "2d updates",
                                      "voronoi and hull", "proximity", "meshes and paths",
                                      "flips and quality", "dynamic network", "3d delaunay", "checkers"}
    assert {name for phase in warmup.PHASES for name in phase} == set(warmup.FEATURES)


def test_an_empty_cache_is_reported(tmp_path):
    """not_cached() is the warm-up's own check (``python -m reference_impl warm`` fails when it
    is not empty): with an empty cache directory it names every kernel."""
    code = "from reference_impl import warmup; print(len(warmup.not_cached()), len(warmup.kernels()))"
    run = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=600,
                         env={**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)})
    assert run.returncode == 0, run.stderr[-3000:]
    missing, total = map(int, run.stdout.split())
    assert missing > 100 and missing <= total, run.stdout


def test_warm_command_reports_every_feature():
    run = subprocess.run([sys.executable, "-m", "reference_impl", "warm"], cwd=ROOT,
                         capture_output=True, text=True, timeout=1800)
    assert run.returncode == 0, run.stderr[-3000:]
    lines = run.stdout.splitlines()
    assert lines[0].startswith("warming numba's cache")
    assert any(line.split()[:2] == ["2d", "delaunay"] for line in lines), run.stdout
    assert lines[-1].startswith("done in ") and "not reached" not in lines[-1], run.stdout


def test_side_by_side_compile_runs_every_phase_in_worker_processes():
    """The cold-start path (``warm`` uses it when most kernels are missing) on a warm cache:
    each phase's features run in spawned workers and report their seconds."""
    lines = []
    assert warmup._compile_side_by_side(2, lines.append)
    assert len(lines) == len(warmup.PHASES), lines
    for phase, line in zip(warmup.PHASES, lines):
        assert all(f"{name} " in line for name in phase), line
