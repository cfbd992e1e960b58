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
from pathlib import Path


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


def test_slow_tests_are_collected_first(tmp_path):
    """The root conftest starts the tests marked ``slow`` first, the rest keeping their order."""
    (tmp_path / "conftest.py").write_text(textwrap.dedent(f"""
        import importlib.util
        spec = importlib.util.spec_from_file_location("repo_conftest", {str(Path(__file__).parents[1] / "conftest.py")!r})
        repo_conftest = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(repo_conftest)
        pytest_collection_modifyitems = repo_conftest.pytest_collection_modifyitems
    """))
    (tmp_path / "test_order.py").write_text(textwrap.dedent("""
        import pytest
        def test_a(): pass
        @pytest.mark.slow
        def test_b(): pass
        def test_c(): pass
        @pytest.mark.slow
        def test_d(): pass
    """))
    out = subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider",
                          "-p", "no:randomly", "--rootdir", str(tmp_path), "-W", "ignore::pytest.PytestUnknownMarkWarning",
                          str(tmp_path)], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stdout + out.stderr
    order = [ln.split("::")[-1] for ln in out.stdout.splitlines() if "::test_" in ln]
    assert order == ["test_b", "test_d", "test_a", "test_c"], out.stdout
