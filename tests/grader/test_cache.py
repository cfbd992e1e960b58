"""The test cache trusts only what no other account can write, and only what was made for this package.

    .venv/bin/python -m pytest tests/grader/test_cache.py -q

On the fixture problem ``tiny-delaunay`` (a sample and two generated tests), with ``$GRADER_CACHE`` and
``$HOME`` in a temporary folder: a cache that is filled once is reused; a cache folder writable by
group or others, owned by another account, a symbolic link, a tampered file, or a folder made
for another answer key or by an older grader is refused and the tests are generated again (into
the account's own ``~/.cache/grader`` when the shared one cannot be trusted, with a warning
saying how to fix it). The last test does the same as an ordinary account
(``tests/grader/ordinary_user.py``). ``python -m grader warm`` fills it.

Example:
    >>> sorted(testcache.manifest_for("x", "0" * 16))
    ['answer_key', 'digest', 'format', 'problem']
"""
from __future__ import annotations

import json
import os
import re
import shutil
import sys
import tempfile
from pathlib import Path

import pytest

from grader.cli import main as grader_main
from grader.problems import Problem, cache as testcache

from . import ordinary_user

HERE = Path(__file__).resolve().parent
FIXTURE = HERE / "fixtures" / "tiny-delaunay"
NOBODY = 65534


@pytest.fixture
def cache(tmp_path, monkeypatch) -> Path:
    """An empty ``$GRADER_CACHE``, and a ``$HOME`` of this test's own (the private fallback)."""
    monkeypatch.setenv("GRADER_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    return tmp_path / "cache"


def _tests(problem: Problem | None = None) -> list[tuple[str, str, str]]:
    p = problem or Problem.load(FIXTURE)
    return [(t.name, t.input_text, t.answer_text) for t in p.tests()]


def _folder(root: Path) -> Path:
    p = Problem.load(FIXTURE)
    return root / p.id / p.digest()


def _no_generation(monkeypatch) -> None:
    monkeypatch.setattr(Problem, "_generate_into", lambda self, folder: pytest.fail("tests generated again"))


def test_filled_once_then_reused(cache, monkeypatch):
    first = _tests()
    folder = _folder(cache)
    assert json.loads((folder / testcache.MANIFEST).read_text()) == testcache.manifest_for("tiny-delaunay",
                                                                                           folder.name)
    assert testcache.tree_reason(folder) is None and oct(folder.stat().st_mode & 0o777) == "0o700"
    _no_generation(monkeypatch)
    assert _tests() == first


def test_a_group_writable_cache_is_refused_and_the_private_one_used(cache, tmp_path, capsys):
    good = _tests()
    shutil.rmtree(cache)
    cache.mkdir()
    cache.chmod(0o775)
    assert _tests() == good
    assert not list(cache.iterdir()), "nothing is written into a cache others can write"
    assert _folder(tmp_path / "home" / ".cache" / "grader").is_dir()
    err = capsys.readouterr().err
    assert f"the test cache {cache} is not trusted" in err and "writable by group" in err and "chmod go-w" in err


@pytest.mark.parametrize("tamper", ["answer made world-writable", "folder made group-writable",
                                    "answer owned by another account", "folder replaced by a link",
                                    "folder replaced by a file"])
def test_a_tampered_tests_folder_is_refused_and_made_again(tamper, cache, tmp_path, capsys):
    if "another account" in tamper and os.geteuid() != 0:
        pytest.skip("needs root to give a file to another account")
    good = _tests()
    folder = _folder(cache)
    answer = sorted(folder.rglob("*.ans"))[0]
    if tamper == "answer made world-writable":
        answer.write_text("[]\n")
        answer.chmod(0o666)
    elif tamper == "folder made group-writable":
        answer.write_text("[]\n")
        folder.chmod(0o770)
    elif tamper == "answer owned by another account":
        answer.write_text("[]\n")
        os.chown(answer, NOBODY, NOBODY)
    elif tamper == "folder replaced by a file":
        shutil.rmtree(folder)
        folder.write_text("not a folder\n")
    else:
        forged = tmp_path / "forged"
        shutil.copytree(folder, forged)
        next(forged.rglob("*.ans")).write_text("[]\n")
        shutil.rmtree(folder)
        folder.symlink_to(forged)
    assert _tests() == good
    if "file" not in tamper:  # a file is no tests folder at all (read as one made by an older grader)
        assert "refused the cached tests" in capsys.readouterr().err
    assert testcache.tree_reason(folder) is None and folder.is_dir() and not folder.is_symlink()


@pytest.mark.parametrize("change", ["another answer key", "another format", "no manifest (an older grader)"])
def test_tests_made_for_another_package_are_made_again(change, cache, capsys):
    good = _tests()
    folder = _folder(cache)
    manifest = folder / testcache.MANIFEST
    for f in folder.rglob("*.ans"):
        f.write_text("[]\n")
    if change == "no manifest (an older grader)":
        manifest.unlink()
    else:
        made_for = json.loads(manifest.read_text())
        made_for["answer_key" if "key" in change else "format"] = "0"
        manifest.write_text(json.dumps(made_for))
    assert _tests() == good
    assert "refused" not in capsys.readouterr().err  # no warning: nobody did anything wrong


def test_an_unusable_private_cache_too_is_a_clear_error(cache, tmp_path, monkeypatch):
    monkeypatch.setenv("GRADER_CACHE", str(tmp_path / "home" / ".cache" / "grader"))
    shared = tmp_path / "home" / ".cache" / "grader"
    shared.mkdir(parents=True)
    shared.chmod(0o777)
    with pytest.raises(ValueError, match="no usable cache.*Set GRADER_CACHE to a folder of your own"):
        _tests()


def test_warm_fills_the_cache_with_progress(cache, monkeypatch, capsys):
    monkeypatch.setenv("GRADER_PROBLEMS", str(FIXTURE.parent))
    assert grader_main(["warm"]) == 0
    out = capsys.readouterr().out
    n = len([d for d in FIXTURE.parent.iterdir() if (d / "course.yaml").is_file()])
    assert re.search(rf"\[\d+/{n}\] tiny-delaunay: 3 tests, generated in [\d.]+ s", out), out
    assert str(_folder(cache)) in out
    assert re.search(r"compiled programs: (started by the C launcher|started by the Python bootstrap \(no C)", out), out
    _no_generation(monkeypatch)
    assert grader_main(["warm", "tiny-delaunay"]) == 0
    assert "3 tests, cached" in capsys.readouterr().out


# -- as an ordinary account ---------------------------------------------------------------------
ACCOUNT_RUN = """
import json, sys
from grader.problems import Problem
p = Problem.load(sys.argv[1])
print(json.dumps({"folder": str(p._materialise()), "tests": [[t.name, t.answer_text] for t in p.tests()]}))
"""


@pytest.mark.skipif(bool(ordinary_user.can_run()), reason=ordinary_user.can_run() or "runs")
def test_as_an_ordinary_account(cache):
    """An account is given (1) a cache folder another account owns, (2) root's cache, which it may
    read but not write: it uses neither for writing, and judges from its own ``~/.cache/grader``."""
    good = _tests()
    user = ordinary_user.ensure_user()
    scratch = Path(tempfile.mkdtemp(prefix="grader-cache-test-"))
    try:
        scratch.chmod(0o755)
        home = scratch / "home"
        home.mkdir()
        os.chown(home, user.pw_uid, user.pw_gid)
        theirs = scratch / "nobodys-cache"
        theirs.mkdir()
        os.chown(theirs, NOBODY, NOBODY)
        roots = scratch / "roots-cache"
        roots.mkdir(mode=0o755)
        for shared, why in ((theirs, "is owned by uid 65534"), (roots, None)):
            r = ordinary_user.run_as_user([sys.executable, "-c", ACCOUNT_RUN, str(FIXTURE)],
                                          env={"HOME": str(home), "GRADER_CACHE": str(shared)}, timeout=600)
            assert r.returncode == 0, r.stderr[-3000:]
            got = json.loads(r.stdout.strip().splitlines()[-1])
            assert got["folder"].startswith(str(home / ".cache" / "grader")), (got["folder"], r.stderr)
            assert [tuple(t) for t in got["tests"]] == [(n, a) for n, _, a in good]
            assert not list(shared.iterdir()), "nothing written into a cache the account may not trust or write"
            if why:
                assert why in r.stderr and "not trusted" in r.stderr, r.stderr
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
