"""A light command stays light: what ``python -m grader`` imports, and YAML read the fast way with the same data.

    .venv/bin/python -m pytest tests/grader/test_startup.py -q

Structural, not timed (benchmarks/bench_judge_overhead.py --startup-only prints the times): a
fresh interpreter imports ``grader.cli`` (or runs ``list`` / ``--help``) and reports which of the
heavy modules it loaded: none may be there. The YAML tests check that libyaml's loader and the
parsed-YAML cache give exactly what ``yaml.safe_load`` gives, on every problem's YAML files.

Example:
    >>> "numba" in HEAVY
    True
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from grader.problems import cache as testcache, list_problems

REPO = Path(__file__).resolve().parents[2]

#: modules a command that judges nothing must not load: the answer key and its JIT, notebook and
#: plotting stacks, the jail, the judging loop, the class tools and their SQLite store
HEAVY = ("numpy", "numba", "scipy", "reference_impl", "nbformat", "nbconvert", "matplotlib", "IPython", "sqlite3",
         "dask", "copydetect", "grader.jail", "grader.judging.runner", "grader.contest", "grader.classroom",
         "grader.course")
#: of the jail, only its package (whose names load on first use) and the trust rule (standard
#: library only, shared with the test cache) may load in a command that judges nothing
LIGHT = ("grader.jail", "grader.jail.trust")

REPORT = ("import json, sys\n"
          "heavy = {heavy!r}\n"
          "light = {light!r}\n"
          "print(json.dumps(sorted(m for m in sys.modules if m not in light and (m in heavy or "
          "m.startswith(tuple(h + '.' for h in heavy))))))\n")


def _loaded(code: str, extra_heavy: tuple[str, ...] = ()) -> list[str]:
    """Run ``code`` in a fresh interpreter, then list the heavy modules it left in ``sys.modules``."""
    script = code + "\n" + REPORT.format(heavy=HEAVY + extra_heavy, light=LIGHT)
    env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": str(REPO), "HOME": str(Path.home())}
    env.update({k: os.environ[k] for k in ("GRADER_CACHE", "GRADER_PROBLEMS", "NUMBA_CACHE_DIR") if k in os.environ})
    r = subprocess.run([sys.executable, "-c", script], cwd=REPO, capture_output=True, text=True, timeout=120, env=env)
    assert r.returncode == 0, r.stderr[-2000:]
    return json.loads(r.stdout.strip().splitlines()[-1])


def test_importing_the_cli_loads_nothing_heavy():
    assert _loaded("import grader.cli", ("yaml",)) == []


def test_import_grader_is_light_and_its_names_still_work():
    assert _loaded("import grader", ("yaml", "grader.problems")) == []
    # the public names are imported on first use
    code = "import grader\nassert grader.Judge.__module__ == 'grader.contest.judge'\nassert 'Judge' in dir(grader)"
    assert "grader.contest" in _loaded(code)
    with pytest.raises(AttributeError):
        import grader

        grader.no_such_name  # noqa: B018


@pytest.mark.parametrize("argv", [["--help"], ["list"], ["list", "--json"]])
def test_light_commands_load_nothing_heavy(argv):
    code = ("import contextlib, io\nfrom grader.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            f"    try:\n        assert main({argv!r}) == 0\n    except SystemExit as e:\n        assert e.code == 0\n")
    assert _loaded(code) == []


def test_a_judge_command_loads_the_jail_but_not_the_answer_key(tmp_path):
    """A judge that stops at CE (a syntax error) loads the judging loop; the answer key, numba and
    the notebook stacks stay out (tests are read from the cache, never generated here)."""
    list_problems()[0].tests()  # any problem: its tests are in the cache once
    sub = tmp_path / "bad.py"
    sub.write_text("def delaunay(points):\n    return [\n")
    pid = list_problems()[0].id
    code = ("import contextlib, io\nfrom grader.cli import main\n"
            f"with contextlib.redirect_stdout(io.StringIO()):\n    assert main(['judge', {pid!r}, {str(sub)!r}]) == 1\n")
    loaded = _loaded(code)
    assert "grader.contest.judge" in loaded and "grader.jail.sandbox" in loaded
    assert not [m for m in loaded if m.split(".")[0] in ("numpy", "numba", "reference_impl", "matplotlib", "nbformat")]


# -- YAML ---------------------------------------------------------------------------------------
def _yaml_files() -> list[Path]:
    files = sorted(REPO.glob("assignments/*/problem.yaml")) + sorted(REPO.glob("assignments/*/course.yaml"))
    files += sorted(REPO.glob("tests/grader/fixtures/*/*.yaml")) + sorted(REPO.glob("solutions/*/expected*.yaml"))
    assert len(files) >= 24
    return files


def _shape(x):
    """The value with every type made visible (1 == 1.0 == True would hide a changed type)."""
    if isinstance(x, dict):
        return {(type(k).__name__, k): _shape(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_shape(v) for v in x]
    return (type(x).__name__, repr(x))


@pytest.mark.skipif(not hasattr(yaml, "CSafeLoader"), reason="PyYAML without libyaml: the pure loader is used")
@pytest.mark.parametrize("path", _yaml_files(), ids=lambda p: str(p.relative_to(REPO)))
def test_libyaml_reads_the_same_data(path):
    text = path.read_text()
    assert _shape(yaml.load(text, Loader=yaml.CSafeLoader)) == _shape(yaml.safe_load(text))  # noqa: S506


@pytest.mark.parametrize("path", _yaml_files(), ids=lambda p: str(p.relative_to(REPO)))
def test_the_parsed_yaml_cache_gives_the_same_data(path, tmp_path, monkeypatch):
    monkeypatch.setenv("GRADER_CACHE", str(tmp_path / "cache"))
    expected = _shape(yaml.safe_load(path.read_text()))
    assert _shape(testcache.load_yaml(path)) == expected  # parsed, then kept
    kept = list((tmp_path / "cache" / "yaml").glob("*.json"))
    assert len(kept) == 1
    monkeypatch.setattr(testcache, "load_yaml_text", lambda text: pytest.fail("parsed again"))
    assert _shape(testcache.load_yaml(path)) == expected  # from the cache


def test_yaml_json_cannot_hold_is_parsed_every_time(tmp_path, monkeypatch):
    """Dates and integer keys do not survive JSON: such a file is never cached (read right each time)."""
    monkeypatch.setenv("GRADER_CACHE", str(tmp_path / "cache"))
    f = tmp_path / "x.yaml"
    f.write_text("when: 2024-06-01\n1: one\n")
    assert testcache.load_yaml(f) == yaml.safe_load(f.read_text())
    assert testcache.load_yaml(f) == yaml.safe_load(f.read_text())
    assert not list((tmp_path / "cache" / "yaml").glob("*.json"))


def test_an_untrusted_parsed_yaml_is_not_read(tmp_path, monkeypatch):
    """A cached parse that others may write is ignored: the file is parsed again."""
    monkeypatch.setenv("GRADER_CACHE", str(tmp_path / "cache"))
    f = tmp_path / "p.yaml"
    f.write_text("entry: delaunay\n")
    testcache.load_yaml(f)
    (kept,) = (tmp_path / "cache" / "yaml").glob("*.json")
    kept.write_text(json.dumps({"entry": "forged"}))
    kept.chmod(0o666)
    assert testcache.load_yaml(f) == {"entry": "delaunay"}
