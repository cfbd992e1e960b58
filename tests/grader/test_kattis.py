"""Exported Kattis packages pass problemtools' verifyproblem (0 errors) with their accepted,
wrong-answer and too-slow submissions, using a languages.yaml that runs CPython.

Hidden data is exported for a subset of groups (enough to give every submission its verdict)
to keep verifyproblem's many validator runs short. Both problems are verified in parallel.

Run: .venv/bin/python -m pytest tests/grader/test_kattis.py -q
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from grader.kattis import LANGUAGES_YAML, export, shortname

VERIFY = Path(sys.executable).with_name("verifyproblem")
EXPORTS = {"delaunay": ["tiny", "degenerate", "large"], "bowyer-watson-timed": ["tiny", "degenerate", "random"]}


@pytest.mark.slow
@pytest.mark.skipif(not VERIFY.exists(), reason="problemtools is not installed")
def test_verifyproblem_reports_no_errors(tmp_path):
    (tmp_path / "config" / "problemtools").mkdir(parents=True)
    (tmp_path / "config" / "problemtools" / "languages.yaml").write_text(LANGUAGES_YAML)
    env = {**os.environ, "XDG_CONFIG_HOME": str(tmp_path / "config"),
           "PATH": f"{Path(sys.executable).parent}:{os.environ.get('PATH', '')}"}
    procs = {}
    for pid, groups in EXPORTS.items():
        dest = export(pid, tmp_path / "kattis", groups=groups)
        assert dest.name == shortname(pid) and re.fullmatch(r"[a-z0-9]+", dest.name)
        assert (dest / "output_validator" / "checker.py").read_text().count("EMBEDDED_VERIFY_SOURCE = ") == 1
        assert {p.name for p in (dest / "submissions").iterdir()} == {"accepted", "wrong_answer", "time_limit_exceeded"}
        procs[pid] = subprocess.Popen([str(VERIFY), str(dest), "-p", "config", "data", "validators", "submissions"],
                                      cwd=tmp_path, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    for pid, proc in procs.items():
        out, _ = proc.communicate(timeout=900)
        summary = [ln for ln in out.splitlines() if " tested: " in ln]
        assert summary and re.search(r"tested: 0 errors", summary[-1]), out[-3000:]
        for kind in ("accepted", "wrong_answer", "time_limit_exceeded"):
            assert re.search(rf"{kind}/\S+ .*OK: (AC|WA|TLE)", out), (kind, out[-3000:])
