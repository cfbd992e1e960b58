"""The jail without root: an ordinary instructor account grades as safely as root (issue 21).

Two halves:

* as root (CI): :func:`test_as_an_ordinary_user` creates an ordinary account and runs, as that
  account (:mod:`tests.grader.ordinary_user`), the whole hostile corpus (test_hostile.py: the
  instructor's home through cffi and ctypes, sqlite3 on a gradebook, ``.cache/grader/``, a
  classmate's submission, forked helpers, a sleeping orphan, and every older attack), the
  nbgrader end-to-end test (tests/nbgrader/test_course_e2e.py: forgeries gain nothing, every
  score equals ``python -m grader judge``'s), the account's half of test_shared_state.py (a
  hostile lock folder changes nothing: the account never uses root's uid pool) and this file's
  ordinary-user tests below;
* as that account (the tests marked ``user_only``): the jail is bubblewrap's, the attacks are real
  (without a jail each one succeeds), and where no user namespace can be made grading refuses
  while the trusted mode judges a student's own code.

The refusal and the trusted mode are also tested in-process as root (``is_root`` patched), so
they are covered where no ordinary account can be made.

Run: .venv/bin/python -m pytest tests/grader/test_jail_user.py -q -n 0   (as root: ~4 min)
"""
from __future__ import annotations

import json
import os
import sys

import pytest

import grader.jail.sandbox as sandbox
from grader.cli import main as grader_main
from grader.jail import JAIL_ENV, TRUSTED_ENV, JailUnavailable, jail_kind, mechanism
from grader.problems import cache_root

from . import ordinary_user
from .conftest import HERE
from .test_hostile import aimed_at_this_checkout, instructor_files

HOSTILE = HERE / "hostile"
#: The attacks of issue 21 that a kernel jail stops and the audit hook does not.
NATIVE_ATTACKS = ["instructor_home_cffi", "instructor_home_ctypes", "gradebook_sqlite", "grader_cache_ctypes",
                  "classmate_submission"]
#: Run as the ordinary account: the corpus, the nbgrader course, the user half of this file.
USER_RUN = ["tests/grader/test_hostile.py", "tests/nbgrader/test_course_e2e.py", "tests/grader/test_jail_user.py",
            "tests/grader/test_shared_state.py::test_the_accounts_judge_never_uses_the_uid_pool"]
user_only = pytest.mark.skipif(os.geteuid() == 0, reason="runs as the ordinary account, started by "
                                                          "test_as_an_ordinary_user (this run is root)")


@pytest.mark.slow
@pytest.mark.xdist_group("ordinary-user")
def test_as_an_ordinary_user():
    why = ordinary_user.can_run()
    if why:
        pytest.skip(why)
    r = ordinary_user.run_as_user([sys.executable, "-m", "pytest", *USER_RUN, "-q", "-n", "0", "-p", "no:cacheprovider",
                                   "-rs"])
    tail = (r.stdout + r.stderr)[-6000:]
    assert r.returncode == 0, tail
    summary = r.stdout.strip().splitlines()[-1]
    assert "failed" not in summary and "error" not in summary, tail
    # nothing the ordinary account must run was skipped (root-only tests of test_hostile: none)
    skipped = [ln for ln in r.stdout.splitlines() if ln.startswith("SKIPPED")]
    assert not [s for s in skipped if "needs root to create" not in s], tail


# -- as the ordinary account ---------------------------------------------------------------------

@user_only
def test_the_account_gets_the_bubblewrap_jail(tiny_judge):
    assert os.geteuid() != 0 and jail_kind() == "bwrap"
    r = tiny_judge.judge_path(HOSTILE / "wrong_type.py")
    assert r.to_json()["sandbox"] == "bwrap+proc-tree+seccomp-noproc"


@user_only
def test_the_account_loads_the_checkouts_numba_cache():
    """The account's numba cache holds every kernel ``make warm`` compiled (ordinary_user copies
    it where numba looks, ``NUMBA_CACHE_DIR``): nothing here compiles a kernel again."""
    from reference_impl import warmup
    assert os.environ.get("NUMBA_CACHE_DIR") and warmup.not_cached() == []


@user_only
@pytest.mark.parametrize("name", NATIVE_ATTACKS)
def test_without_a_jail_the_attacks_succeed(name, tiny_judge, tmp_path, monkeypatch):
    """The trusted mode (no jail) on a copy of the account's files: each attack does what it says
    (its own RuntimeError: RE), so the WA it gets in the jail is the jail's doing."""
    home = instructor_files(tmp_path / "home")
    assert (cache_root() / "tiny-delaunay").is_dir()
    monkeypatch.setenv(JAIL_ENV, "none")
    monkeypatch.setenv(TRUSTED_ENV, "1")
    r = tiny_judge.judge_path(aimed_at_this_checkout(HOSTILE / f"{name}.py", tmp_path, home))
    assert r.to_json()["sandbox"] == "trusted"
    t = r.tests[0]
    assert t.verdict == "RE" and "RuntimeError" in t.message, (t.verdict, t.message)


def _refuses(tiny_judge, capsys, tmp_path) -> None:
    with pytest.raises(JailUnavailable) as exc:
        tiny_judge.judge_path(HOSTILE / "wrong_type.py")
    msg = str(exc.value)
    for fix in ("install bubblewrap", "user namespaces", "as root", "--trusted"):
        assert fix in msg, msg
    sub = HERE.parent.parent / "solutions" / "delaunay" / "accepted_walk.py"
    assert grader_main(["judge", "delaunay", str(sub)]) == 2
    assert "no kernel jail can be built" in capsys.readouterr().err
    # the trusted mode: a student's own code, judged without a jail, and the output says so
    assert grader_main(["judge", "delaunay", str(sub), "--trusted"]) == 0
    out = capsys.readouterr().out
    assert "judged in the trusted mode" in out and "AC" in out
    assert grader_main(["judge", "delaunay", str(sub), "--trusted", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["sandbox"] == "trusted"
    # a class is refused once, before any student is judged (not JE per student)
    klass = tmp_path / "class" / "alice"
    klass.mkdir(parents=True)
    (klass / "delaunay.py").write_text(sub.read_text())
    assert grader_main(["grade", "delaunay", str(klass.parent), "--db", str(tmp_path / "r.sqlite"), "--quiet"]) == 2
    assert "no kernel jail can be built" in capsys.readouterr().err
    assert not (tmp_path / "r.sqlite").exists() or "alice" not in (tmp_path / "r.sqlite").read_bytes().decode("latin-1")


@user_only
def test_without_user_namespaces_grading_refuses_and_the_trusted_mode_judges(tiny_judge, monkeypatch, capsys, tmp_path):
    monkeypatch.setenv(JAIL_ENV, "none")  # as a kernel without unprivileged user namespaces
    assert jail_kind() == "none"
    _refuses(tiny_judge, capsys, tmp_path)


# -- as root, simulated ----------------------------------------------------------------------------

def test_not_root_without_a_jail_refuses_and_trusted_judges_simulated(tiny_judge, monkeypatch, capsys, tmp_path):
    monkeypatch.setattr(sandbox, "is_root", lambda: False)
    monkeypatch.setenv(JAIL_ENV, "none")
    monkeypatch.delenv(TRUSTED_ENV, raising=False)
    _refuses(tiny_judge, capsys, tmp_path)
    assert mechanism() == "trusted"


def test_the_doctor_names_both_accounts(capsys):
    from grader.jail.doctor import main
    code = main([])
    out = capsys.readouterr().out
    assert "bubblewrap:" in out and "root" in out and ("ordinary user" in out or "this user" in out)
    assert code == (0 if os.geteuid() == 0 or jail_kind() == "bwrap" else 1)


# -- the account's jail, as root too (is_root patched: the same bubblewrap command, uid 0 mapped) --

def _as_account(monkeypatch) -> None:
    if os.geteuid() == 0:
        monkeypatch.setattr(sandbox, "is_root", lambda: False)
    if jail_kind() != "bwrap":
        pytest.skip("bubblewrap cannot create a user namespace here (the ordinary-account run covers it)")


def test_a_stdio_run_is_charged_its_cpu_in_the_account_jail(monkeypatch, tiny_judge, tmp_path):
    """bubblewrap's reaper, not the grader, collects the student's process, so ``wait4`` does not
    see its CPU: the process tree's samples do (the time was 0.004 s for 0.39 s of work)."""
    _as_account(monkeypatch)
    sub = tmp_path / "burn.py"
    sub.write_text("import sys, time\nsys.stdin.read()\nwhile time.process_time() < 0.4:\n    pass\nprint(0)\n")
    r = tiny_judge.judge_path(sub)
    assert r.to_json()["sandbox"] == "bwrap+proc-tree+seccomp-noproc"
    # the program computes until it has used 0.4 CPU-seconds (a fixed loop count is machine-speed
    # bound); the samples every 0.02 s may miss the last of it
    assert r.tests[0].time_s >= 0.3, r.tests[0]
    sub.write_text("import sys\nsys.stdin.read()\nwhile True:\n    pass\n")
    assert tiny_judge.judge_path(sub).tests[0].verdict == "TLE"


def test_threads_are_capped_inside_the_account_jail(monkeypatch, tiny_judge, tmp_path):
    """RLIMIT_NPROC set inside the sandbox's user namespace counts its threads only: a few work,
    thousands do not (RE), whatever else the account runs."""
    _as_account(monkeypatch)
    sub = tmp_path / "threads.py"
    sub.write_text("import threading\n\ndef delaunay(points):\n    ts = [threading.Thread(target=len, args=([],)) "
                   "for _ in range(4)]\n    [t.start() for t in ts]\n    [t.join() for t in ts]\n    return []\n")
    assert tiny_judge.judge_path(sub).verdict == "WA"
    assert tiny_judge.judge_path(HOSTILE / "thread_bomb.py").verdict == "RE"
