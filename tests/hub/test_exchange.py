"""nbgrader's exchange as deploy.sh makes it (``deploy.sh exchange``, part of ``install``): the
properties that protect a world-writable folder, checked without a hub.

What it checks, in a temporary ``COURSE_HOME`` (as root; the "instructor" is the test account
``grader-instructor``, the "students" are the unprivileged uids 65534 and 65533):

* the exchange root is root's, mode 1777 (sticky), and nbgrader's own ``release_assignment``
  check of the root (it compares only the 0777 bits) keeps the sticky bit;
* the course folder and its ``outbound`` are the instructor's, 0755; ``inbound`` the
  instructor's, 3733 (nbgrader's 0733 + setgid, plus sticky);
* a student can neither rename nor remove the course folder, nor list ``inbound``; a student
  can submit (make an entry in ``inbound``), and a classmate cannot remove or rename it;
* a course folder a student made first is refused by ``deploy.sh exchange``, which changes nothing.

What it does not check: nbgrader's submit and collect themselves (the hub test's round trip
does), nor the hub.

Run: .venv/bin/python -m pytest tests/hub/test_exchange.py -q -n 0
"""
from __future__ import annotations

import errno
import pwd
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tests" / "grader"))
import ordinary_user  # noqa: E402

DEPLOY = REPO / "deploy" / "jupyterhub" / "deploy.sh"
STUDENT, CLASSMATE = 65534, 65533
pytestmark = pytest.mark.skipif(bool(ordinary_user.can_run()), reason=ordinary_user.can_run() or "runs")


def as_uid(uid: int, action) -> int:
    """``action()`` in a forked child running as ``uid``: 0 when it succeeded, else its errno."""
    pid = os.fork()
    if pid == 0:  # pragma: no cover - child
        code = 0
        try:
            os.setgroups([])
            os.setresgid(uid, uid, uid)
            os.setresuid(uid, uid, uid)
            action()
        except OSError as exc:
            code = exc.errno or 255
        except BaseException:  # noqa: BLE001
            code = 255
        os._exit(code)
    return os.waitstatus_to_exitcode(os.waitpid(pid, 0)[1])


@pytest.fixture
def home():
    path = Path(tempfile.mkdtemp(prefix="exchange-test-"))
    os.chmod(path, 0o755)
    yield path
    shutil.rmtree(path, ignore_errors=True)


def deploy_exchange(home: Path) -> subprocess.CompletedProcess:
    instructor = ordinary_user.ensure_user().pw_name
    return subprocess.run(["bash", str(DEPLOY), "exchange"], capture_output=True, text=True, timeout=60,
                          env={**os.environ, "COURSE_HOME": str(home), "HUB_INSTRUCTORS": instructor})


def mode(path: Path) -> tuple[str, str]:
    st = os.lstat(path)
    return oct(st.st_mode & 0o7777), pwd.getpwuid(st.st_uid).pw_name


def test_the_exchange_deploy_makes(home):
    r = deploy_exchange(home)
    assert r.returncode == 0, r.stderr
    instr = ordinary_user.USER
    ex, course = home / "exchange", home / "exchange" / "delaunay-course"
    assert mode(ex) == ("0o1777", "root")
    assert mode(course) == ("0o755", instr) and mode(course / "outbound") == ("0o755", instr)
    assert mode(course / "inbound") == ("0o3733", instr)
    # the student cannot take the course folder away or read inbound's names
    assert as_uid(STUDENT, lambda: os.rename(course, ex / "taken")) == errno.EPERM
    assert as_uid(STUDENT, lambda: shutil.rmtree(course)) in (errno.EPERM, errno.EACCES)
    assert as_uid(STUDENT, lambda: os.listdir(course / "inbound")) == errno.EACCES
    # a submission (nbgrader names it student+assignment+timestamp+random) stays the student's
    sub = course / "inbound" / "student+delaunay+2026-01-01 00:00:00.000000 UTC+AbCdEfGhIjKl"
    assert as_uid(STUDENT, lambda: os.mkdir(sub, 0o777)) == 0
    assert as_uid(CLASSMATE, lambda: os.rmdir(sub)) == errno.EPERM
    assert as_uid(CLASSMATE, lambda: os.rename(sub, course / "inbound" / "classmate+x")) == errno.EPERM
    assert sub.is_dir()
    # nbgrader's release checks the root's 0777 bits only: the sticky bit stays
    from nbgrader.auth import Authenticator
    from nbgrader.coursedir import CourseDirectory
    from nbgrader.exchange.default.release_assignment import ExchangeReleaseAssignment
    from traitlets.config import Config

    cfg = Config()
    cfg.Exchange.root = str(ex)
    ExchangeReleaseAssignment(coursedir=CourseDirectory(config=cfg), authenticator=Authenticator(config=cfg),
                              config=cfg).ensure_root()
    assert mode(ex) == ("0o1777", "root")
    assert deploy_exchange(home).returncode == 0 and sub.is_dir()  # installing again keeps submissions


def test_a_course_folder_a_student_made_first_is_refused(home):
    ex = home / "exchange"
    ex.mkdir(mode=0o777)
    os.chmod(ex, 0o777)  # an exchange from before: no sticky bit
    assert as_uid(STUDENT, lambda: os.makedirs(ex / "delaunay-course" / "inbound")) == 0
    r = deploy_exchange(home)
    assert r.returncode == 1 and "is not grader-instructor's folder" in r.stderr, r.stderr
    assert mode(ex / "delaunay-course") == ("0o755", "nobody")  # unchanged: not given to anyone
