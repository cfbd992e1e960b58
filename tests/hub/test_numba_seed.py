"""The course server's numba seed (``grader.course.numba_seed``), checked without a hub.

What it checks, as root, in temporary folders (the "student" is the unprivileged uid 65534, whose
"home" is a 0700 folder it owns; the copy runs as that uid through ``/usr/bin/python3``, as the
hub's ``pre_spawn`` runs it through the course venv's interpreter):

* an account with no cache, or an empty one, gets the seed: every file, its own, folders 0700,
  files 0600, contents unchanged;
* a cache with files in it is left alone (nothing added, nothing overwritten);
* a seed with a file or folder writable by others, a symbolic link, a part owned by another
  account, or a folder above it writable by others, is refused (logged, nothing copied);
* a home whose ``.cache`` is a symbolic link to a root-owned folder makes root write nothing
  there (the copy runs as the account).

Run: PYTHONPATH=$PWD .venv/bin/python -m pytest tests/hub/test_numba_seed.py -q
"""
from __future__ import annotations

import os
import shutil
import stat
import sys
import tempfile
from pathlib import Path

import pytest

from grader.course.numba_seed import copy_seed, seed_account, untrusted

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tests" / "grader"))
import ordinary_user  # noqa: E402

STUDENT, OTHER = 65534, 65533
PYTHON = "/usr/bin/python3"
pytestmark = pytest.mark.skipif(bool(ordinary_user.can_run()) or not os.access(PYTHON, os.X_OK),
                                reason=ordinary_user.can_run() or f"{PYTHON} is missing")
FILES = {"reference_impl/exact/predicates.orient2d-10.py311.nbi": b"index",
         "reference_impl/exact/predicates.orient2d-10.py311.1.nbc": b"\x00code" * 1000,
         "checkers.nbi": b"top"}


@pytest.fixture
def tmp():
    """A root-owned 0755 folder under /tmp (readable by the student, unlike pytest's tmp_path)."""
    path = Path(tempfile.mkdtemp(prefix="numba-seed-test-"))
    os.chmod(path, 0o755)
    yield path
    shutil.rmtree(path, ignore_errors=True)


def make_seed(tmp: Path) -> Path:
    seed = tmp / "seed"
    for rel, data in FILES.items():
        (seed / rel).parent.mkdir(parents=True, exist_ok=True, mode=0o755)
        (seed / rel).write_bytes(data)
        os.chmod(seed / rel, 0o644)
    for d in [seed, *(p for p in seed.rglob("*") if p.is_dir())]:
        os.chmod(d, 0o755)
    return seed


def make_home(tmp: Path) -> Path:
    home = tmp / "home"
    home.mkdir(mode=0o700)
    os.chown(home, STUDENT, STUDENT)
    return home


def seed(seed_dir: Path, dest: Path, log: list[str]) -> int:
    return seed_account(seed_dir, dest, STUDENT, STUDENT, log=log.append, python=PYTHON)


@pytest.mark.parametrize("empty_dir", [False, True])
def test_seeds_a_missing_or_empty_cache_privately(tmp, empty_dir):
    src, home, log = make_seed(tmp), make_home(tmp), []
    dest = home / ".cache" / "numba"
    if empty_dir:
        dest.mkdir(parents=True)
        shutil.chown(dest.parent, STUDENT, STUDENT)
        shutil.chown(dest, STUDENT, STUDENT)
    assert untrusted(src) == ""
    assert seed(src, dest, log) == len(FILES), log
    for rel, data in FILES.items():
        assert (dest / rel).read_bytes() == data
    for p in [*([] if empty_dir else [dest.parent]), dest, *dest.rglob("*")]:
        st = os.lstat(p)
        assert (st.st_uid, st.st_gid) == (STUDENT, STUDENT), p
        assert stat.S_IMODE(st.st_mode) == (0o700 if p.is_dir() else 0o600), p


def test_leaves_a_cache_with_files_alone(tmp):
    src, home, log = make_seed(tmp), make_home(tmp), []
    dest = home / ".cache" / "numba"
    dest.mkdir(parents=True)
    (dest / "checkers.nbi").write_bytes(b"mine")
    for p in (dest.parent, dest, dest / "checkers.nbi"):
        os.chown(p, STUDENT, STUDENT)
    assert seed(src, dest, log) == 0
    assert [p.name for p in dest.iterdir()] == ["checkers.nbi"]
    assert (dest / "checkers.nbi").read_bytes() == b"mine"
    assert "left alone" in log[-1]


@pytest.mark.parametrize("spoil", ["file 0666", "folder 0777", "symlink", "other owner", "parent 0777"])
def test_refuses_an_untrusted_seed(tmp, spoil):
    src, home, log = make_seed(tmp), make_home(tmp), []
    target = src / "reference_impl" / "exact" / "predicates.orient2d-10.py311.nbi"
    if spoil == "file 0666":
        os.chmod(target, 0o666)
    elif spoil == "folder 0777":
        os.chmod(target.parent, 0o777)
    elif spoil == "symlink":
        (src / "evil.nbi").symlink_to("/etc/shadow")
    elif spoil == "other owner":
        os.chown(target, OTHER, OTHER)
    else:
        os.chmod(tmp, 0o777)                  # anyone could replace the seed folder itself
    dest = home / ".cache" / "numba"
    assert untrusted(src) != ""
    assert seed(src, dest, log) == 0
    assert not dest.exists()
    assert "not used" in log[-1], log


def test_a_missing_seed_is_skipped(tmp):
    log: list[str] = []
    assert seed(tmp / "no-seed", make_home(tmp) / ".cache" / "numba", log) == 0
    assert "missing" in log[-1]


def test_copy_never_follows_a_symlink_in_the_seed(tmp):
    src = make_seed(tmp)
    (src / "evil.nbi").symlink_to(src / "checkers.nbi")
    dest = tmp / "dest"
    assert copy_seed(src, dest) == len(FILES)
    assert not (dest / "evil.nbi").exists()


def test_a_planted_symlink_in_the_home_makes_root_write_nothing(tmp):
    src, home, log = make_seed(tmp), make_home(tmp), []
    victim = tmp / "root-owned"
    victim.mkdir(mode=0o755)                  # root's: the student cannot write in it
    (home / ".cache").symlink_to(victim)
    os.lchown(home / ".cache", STUDENT, STUDENT)
    assert seed(src, home / ".cache" / "numba", log) == 0
    assert list(victim.iterdir()) == []
    assert "not copied" in log[-1], log
