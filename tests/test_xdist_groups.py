"""`make test` keeps a module's expensive fixture on one worker with `--dist loadgroup` and an
`xdist_group` mark (the hub, the lab servers, the nbgrader class). This checks that the installed
pytest and pytest-xdist still honour the mark: pytest 9.2 renamed the attribute xdist 3.8 writes
the group into, and every grouped module then built its fixture on both workers at once, in the
same folders (two npm installs into deploy/jupyterhub/node/ broke the hub test).

    .venv/bin/python -m pytest tests/test_xdist_groups.py -q
"""
from __future__ import annotations

import os
import subprocess
import sys
import textwrap


def test_an_xdist_group_runs_on_one_worker(tmp_path):
    (tmp_path / "test_grouped.py").write_text(textwrap.dedent("""
        import os, pytest
        pytestmark = [pytest.mark.xdist_group("g"), pytest.mark.skipif(False, reason="-")]
        def _log():
            with open(os.environ["GROUP_LOG"], "a") as f:
                f.write(os.environ.get("PYTEST_XDIST_WORKER", "none") + "\\n")
        def test_a(): _log()
        def test_b(): _log()
        def test_c(): _log()
        def test_d(): _log()
    """))
    log = tmp_path / "workers.txt"
    out = subprocess.run([sys.executable, "-m", "pytest", "-n", "2", "--dist", "loadgroup", "-q",
                          "-p", "no:cacheprovider", "--rootdir", str(tmp_path), str(tmp_path)],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120,
                         env={**os.environ, "GROUP_LOG": str(log)})
    assert out.returncode == 0, out.stdout + out.stderr
    workers = log.read_text().split()
    assert len(workers) == 4
    assert len(set(workers)) == 1, f"one xdist_group ran on several workers: {workers}"
