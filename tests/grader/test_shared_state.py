"""Root's grader state shared between its runs (the sandbox-uid locks) is root's alone
(hardening round 4, item 1).

The lock folder used to be ``/tmp/grader-sandbox-uids``: any account could make it first and hold
all 512 locks (every root ``judge``/``grade`` failed with a traceback) or make each lock a
symbolic link (root created files wherever they pointed). Now it is ``/run/grader/sandbox-uids``,
checked before use (:mod:`grader.jail.uidpool`); an unsafe folder, or a pool whose every uid
stays taken, is a one-line refusal with exit code 2.

* as root: an unprivileged uid (``nobody``) attacks in a private mount namespace (fresh tmpfs on
  ``/tmp`` and ``/run``; :mod:`tests.grader.shared_state_attack`), root's CLI judges there; the
  in-process tests move the lock folder (``uidpool.LOCK_DIR``) into ``tmp_path`` and shrink the
  pool and its wait, so no test holds the host's locks or waits long;
* as the ordinary account (``user_only``, run by ``test_jail_user.test_as_an_ordinary_user``):
  the account's sandboxes never touch the pool, so a hostile lock folder changes nothing.

Run: .venv/bin/python -m pytest tests/grader/test_shared_state.py -q -n 0
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile

import pytest

from grader.cli import main as grader_main

from .conftest import HERE, REPO
from .shared_state_attack import SCENARIOS

ATTACK = HERE / "shared_state_attack.py"
ACCEPTED = REPO / "solutions" / "delaunay" / "accepted_walk.py"
NOBODY = 65534
root_only = pytest.mark.skipif(os.geteuid() != 0, reason="root's uid pool (this run is not root)")
user_only = pytest.mark.skipif(os.geteuid() == 0, reason="runs as the ordinary account, started by "
                                                          "test_jail_user.test_as_an_ordinary_user (this run is root)")


def attack(scenario: str) -> dict:
    """Play one scenario of :mod:`tests.grader.shared_state_attack` (its own mount namespace)."""
    r = subprocess.run([sys.executable, str(ATTACK), scenario], capture_output=True, text=True, timeout=600,
                       cwd=REPO, env={**os.environ, "PYTHONPATH": str(REPO)})
    assert r.returncode == 0, r.stdout + r.stderr
    out = json.loads(r.stdout)
    assert "error" not in out, out
    return out


def one_line(stderr: str, starts: str) -> str:
    """The single line of a refusal (no traceback), checked to start with ``starts``."""
    assert "Traceback" not in stderr, stderr
    lines = stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(starts), stderr
    return lines[0]


@pytest.fixture
def pool(tmp_path, monkeypatch):
    """:mod:`grader.jail.uidpool` with its lock folder in ``tmp_path`` (root-owned, 0700), three
    uids outside the real pool (62600-62602: a sandbox run here never shares a uid with another
    grader on the host), a 0.3 s wait and no legacy folder: what a test holds is no other grader's."""
    from grader.jail import uidpool

    os.chmod(tmp_path, 0o700)
    monkeypatch.setattr(uidpool, "LOCK_DIR", tmp_path / "locks")
    monkeypatch.setattr(uidpool, "LEGACY_LOCK_DIR", None)
    monkeypatch.setattr(uidpool, "UID_BASE", 62600)
    monkeypatch.setattr(uidpool, "UID_COUNT", 3)
    monkeypatch.setattr(uidpool, "SLOT_WAIT_S", 0.3)
    monkeypatch.setenv("GRADER_PROBLEMS", str(HERE / "fixtures"))
    return uidpool


def hold_all(uidpool) -> list:
    """Hold every uid of the (shrunk) pool, as another grader would."""
    fd = uidpool.open_private_dir(uidpool.LOCK_DIR)
    try:
        slots = [uidpool.hold(uidpool.UID_BASE + k, fd) for k in range(uidpool.UID_COUNT)]
    finally:
        os.close(fd)
    assert all(slots)
    return slots


# -- as root: an account's folder, the old place and the new ---------------------------------------

@root_only
@pytest.mark.parametrize("scenario", ["tmp-held", "tmp-links"])
def test_an_accounts_folder_at_the_old_place_changes_nothing(scenario):
    """``nobody`` made ``/tmp/grader-sandbox-uids`` first, every lock held or a symbolic link:
    root's judge neither follows a link (no file at their targets) nor fails; it judges."""
    out = attack(scenario)
    assert out["created"] == [], out
    assert out["rc"] == 0 and out["verdict"] == "AC", out


@root_only
@pytest.mark.parametrize("scenario", ["run-held", "run-links", "run-world-writable", "run-symlink", "run-not-a-dir",
                                      "run-parent-not-root"])
def test_an_unsafe_lock_folder_is_a_one_line_refusal(scenario):
    """Under a world-writable ``/run`` (``nobody`` made ``/run/grader`` first), or a folder that is
    world-writable, a symbolic link, a file, or under a folder of another owner: exit 2, one line
    naming the folder, no file created at a link's target."""
    out = attack(scenario)
    assert SCENARIOS[scenario][1] == "/run/grader/sandbox-uids"
    assert out["created"] == [], out
    assert out["rc"] == 2, out
    line = one_line(out["stderr"], "error: unsafe sandbox lock folder /run/grader/sandbox-uids: /run/grader")
    assert "grading refuses" in line


@root_only
def test_every_uid_taken_is_a_one_line_refusal(pool, capsys):
    slots = hold_all(pool)
    try:
        code = grader_main(["judge", "tiny-delaunay", str(ACCEPTED)])
    finally:
        for s in slots:
            s.close()
    assert code == 2
    line = one_line(capsys.readouterr().err, "error: no free sandbox uid: all 3 uids of root's pool (62600-62602")
    assert str(pool.LOCK_DIR) in line
    assert grader_main(["judge", "tiny-delaunay", str(ACCEPTED)]) == 0  # freed: it judges


@root_only
def test_grade_stops_in_one_line_when_every_uid_is_taken(pool, tmp_path, capsys):
    """Class grading (two workers) stops at the first refusal instead of a JE for every student."""
    for name in ("ada", "bob", "cy"):
        (tmp_path / "class" / name).mkdir(parents=True)
        (tmp_path / "class" / name / "solution.py").write_text(ACCEPTED.read_text())
    slots = hold_all(pool)
    try:
        code = grader_main(["grade", "tiny-delaunay", str(tmp_path / "class"), "--db", str(tmp_path / "r.sqlite"),
                            "--jobs", "2", "--quiet"])
    finally:
        for s in slots:
            s.close()
    out = capsys.readouterr()
    assert code == 2 and "JE" not in out.out, out
    one_line(out.err, "error: no free sandbox uid")


@root_only
@pytest.mark.parametrize("command", ["judge", "grade"])
def test_a_world_writable_lock_folder_is_refused_before_judging(pool, tmp_path, capsys, command):
    pool.LOCK_DIR.mkdir()
    os.chmod(pool.LOCK_DIR, 0o777)
    (tmp_path / "class" / "ada").mkdir(parents=True)
    (tmp_path / "class" / "ada" / "solution.py").write_text(ACCEPTED.read_text())
    argv = (["judge", "tiny-delaunay", str(ACCEPTED)] if command == "judge" else
            ["grade", "tiny-delaunay", str(tmp_path / "class"), "--db", str(tmp_path / "r.sqlite"), "--quiet"])
    assert grader_main(argv) == 2
    line = one_line(capsys.readouterr().err, f"error: unsafe sandbox lock folder {pool.LOCK_DIR}")
    assert "writable by group or others (mode 0777)" in line


@root_only
def test_lock_files_are_opened_without_following_links(pool, tmp_path):
    """A symbolic link in the folder (only root could put it there) is refused, never followed."""
    fd = pool.open_private_dir(pool.LOCK_DIR)
    os.close(fd)
    target = tmp_path / "target"
    os.symlink(target, pool.LOCK_DIR / f"{pool.UID_BASE}.lock")
    from grader.jail.errors import UnsafeSharedState

    with pytest.raises(UnsafeSharedState, match="cannot be opened"):
        pool.acquire(start=0)
    assert not target.exists()


@root_only
def test_a_uid_an_older_grader_holds_in_its_folder_is_skipped(pool, tmp_path, monkeypatch):
    """While an older grader (locks in ``/tmp/grader-sandbox-uids``) may still run, a uid is taken
    only when free in both folders; an older folder not root's alone is ignored."""
    legacy = tmp_path / "legacy"
    legacy.mkdir(mode=0o700)
    monkeypatch.setattr(pool, "LEGACY_LOCK_DIR", legacy)
    fd = pool.open_private_dir(legacy)
    old = pool.hold(pool.UID_BASE, fd)  # the older grader's lock on the first uid
    os.close(fd)
    try:
        slot = pool.acquire(start=0)
        assert slot.uid == pool.UID_BASE + 1 and len(slot.fds) == 2
        slot.close()
        os.chown(legacy, NOBODY, NOBODY)  # not root's: never used, whatever it holds
        slot = pool.acquire(start=0)
        assert slot.uid == pool.UID_BASE and len(slot.fds) == 1
        slot.close()
    finally:
        old.close()


@root_only
def test_the_doctor_says_where_the_locks_are_and_whether_they_are_safe(pool):
    assert f"sandbox uid locks: {pool.LOCK_DIR} (root's, not writable by others" in pool.describe()
    os.chmod(pool.LOCK_DIR, 0o770)
    assert pool.describe().startswith(f"sandbox uid locks: UNSAFE: unsafe sandbox lock folder {pool.LOCK_DIR}")


@root_only
def test_the_test_accounts_lock_never_follows_a_link_in_tmp(pool, tmp_path, monkeypatch):
    """``ordinary_user.run_as_user`` (root) locks the account's runs in root's state folder; the
    older ``/tmp/<user>.lock`` is taken only as a regular file of root's, never created through
    a link (it used to be opened with ``open(..., "w")``: a link truncated or made its target)."""
    from . import ordinary_user

    fake_tmp = tmp_path / "tmp"
    fake_tmp.mkdir(mode=0o777)
    os.chmod(fake_tmp, 0o1777)
    monkeypatch.setattr(tempfile, "tempdir", str(fake_tmp))
    target = tmp_path / "etc-nologin"
    os.symlink(target, fake_tmp / "someone.lock")
    fds = ordinary_user.account_lock("someone")
    try:
        assert not target.exists() and len(fds) == 1
        assert (pool.LOCK_DIR.parent / "test-accounts" / "someone.lock").is_file()
    finally:
        for fd in fds:
            os.close(fd)
    os.unlink(fake_tmp / "someone.lock")
    (fake_tmp / "someone.lock").write_text("")  # an older checkout's lock: held too
    fds = ordinary_user.account_lock("someone")
    assert len(fds) == 2
    for fd in fds:
        os.close(fd)


def test_the_lock_folder_is_under_run_or_var_lib():
    from grader.jail import uidpool

    assert str(uidpool.default_lock_dir()) == ("/run/grader/sandbox-uids" if os.path.isdir("/run")
                                               else "/var/lib/grader/sandbox-uids")
    assert not str(uidpool.LOCK_DIR).startswith(("/tmp", "/var/tmp", "/dev/shm"))


# -- as the ordinary account ---------------------------------------------------------------------

@user_only
def test_the_accounts_judge_never_uses_the_uid_pool(tiny_judge, tmp_path, monkeypatch):
    """A hostile lock folder (every lock a symbolic link, the pool refusing) changes nothing for an
    ordinary account: its sandboxes run as itself and never take a pool uid."""
    from grader.jail import uidpool

    hostile = tmp_path / "grader-sandbox-uids"
    hostile.mkdir()
    for k in range(uidpool.UID_COUNT):
        os.symlink(tmp_path / f"created-{k}", hostile / f"{uidpool.UID_BASE + k}.lock")
    monkeypatch.setattr(uidpool, "LOCK_DIR", hostile)
    monkeypatch.setattr(uidpool, "LEGACY_LOCK_DIR", hostile)

    def refuse(*a, **k):
        raise AssertionError("an ordinary account took a uid of root's pool")

    monkeypatch.setattr(uidpool, "acquire", refuse)
    r = tiny_judge.judge_path(ACCEPTED)
    assert r.verdict == "AC" and r.to_json()["sandbox"] == "bwrap+proc-tree+seccomp-noproc"
    assert not list(tmp_path.glob("created-*"))
    assert "root only" in uidpool.describe()
