"""A running course hub for tests: deploy/jupyterhub/deploy.sh in a temp COURSE_HOME, and logged-in users.

:func:`start_hub` installs the deployment (dummy authenticator, free ports, the shared venv in
build/hub-venv) and starts JupyterHub in its own session; :meth:`Hub.stop` stops it, the proxy
and every single-user server it started. :class:`HubUser` logs in through the hub's login form and
calls what the Assignments tab and formgrader call (their HTTP APIs, with the server's XSRF cookie).

Run by tests/hub/test_hub.py (as root); by hand:
    .venv/bin/python -c "import sys; sys.path[:0]=['tests/hub']; import hub_session as h; hub=h.start_hub(); print(hub.url)"
"""
from __future__ import annotations

import json
import os
import pwd
import re
import secrets
import shutil
import signal
import socket
import subprocess
import tempfile
import time
import uuid
from dataclasses import dataclass, field
from pathlib import Path

import requests

REPO = Path(__file__).resolve().parents[2]
DEPLOY = REPO / "deploy" / "jupyterhub" / "deploy.sh"
# Test accounts of their own (not make hub's hub-*), named after this process (``hubtest<pid>-...``):
# two checkouts' hub tests on one machine at once never share, empty or reinstall each other's
# accounts. Hub.stop removes them (userdel --remove: the home and the private group), and start_hub
# first removes those of earlier runs whose process is gone (a run killed before its clean-up).
PREFIX = f"hubtest{os.getpid()}-"
INSTRUCTOR = PREFIX + "instructor"
STUDENTS = tuple(f"{PREFIX}student{k}" for k in (1, 2, 3, 4))  # 3, 4: the browser
#: the names this module gives accounts (the clean-up removes no other account)
ACCOUNT_NAME = re.compile(r"hubtest([0-9]+)-(instructor|student[0-9])")


def can_run() -> str:
    """'' when a hub can run here, else why not (the skip reason)."""
    if os.geteuid() != 0:
        return "the hub runs as root (it starts servers as other accounts); CI runs as root"
    for tool in ("useradd", "npm", "/usr/bin/python3"):
        if shutil.which(tool) is None:
            return f"{tool} is missing"
    if subprocess.run(["/usr/bin/python3", "-c", "import ensurepip"], capture_output=True).returncode:
        return "/usr/bin/python3 cannot make a venv (apt-get install python3-venv)"
    return ""


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@dataclass
class Hub:
    """A started hub: its URL, password, COURSE_HOME and process."""
    url: str
    password: str
    home: Path
    proc: subprocess.Popen
    log: Path
    env: dict = field(default_factory=dict)

    def stop(self) -> None:
        """SIGTERM the hub (it stops its servers and proxy), then kill what is left of its session
        and of the test accounts' processes it started; remove COURSE_HOME."""
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(30)
            except subprocess.TimeoutExpired:
                pass
        try:
            os.killpg(self.proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        uids = {pwd.getpwnam(u).pw_uid for u in (INSTRUCTOR, *STUDENTS)}
        for p in Path("/proc").iterdir():
            if p.name.isdigit():
                try:
                    if p.stat().st_uid in uids and str(self.home) in (p / "environ").read_text(errors="replace"):
                        os.kill(int(p.name), signal.SIGKILL)
                except (OSError, ProcessLookupError):
                    pass
        try:                                   # the log outlives COURSE_HOME: a failed run can be read
            keep = REPO / "build" / "hub-test.log"
            keep.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(self.log, keep)
        except OSError:
            pass
        shutil.rmtree(self.home, ignore_errors=True)
        remove_accounts((INSTRUCTOR, *STUDENTS))

    def log_tail(self, lines: int = 60, having: str = "") -> str:
        """The hub log's last ``lines`` lines (those that contain ``having``): the hub's and its
        single-user servers' messages, for a failure's report."""
        try:
            text = self.log.read_text(errors="replace").splitlines()
        except OSError as e:
            return f"(no hub log: {e})"
        return "\n".join([t for t in text if having in t][-lines:])


def remove_accounts(names) -> list[str]:
    """Remove the accounts ``names`` that exist and are this module's (:data:`ACCOUNT_NAME`): their
    processes killed, then ``userdel --remove`` (home, mail spool, private group); return those removed."""
    removed = []
    for name in names:
        if not ACCOUNT_NAME.fullmatch(name):
            raise ValueError(f"{name!r} is not a hub test account (hubtest<pid>-instructor or -student<k>)")
        try:
            uid = pwd.getpwnam(name).pw_uid
        except KeyError:
            continue
        for p in Path("/proc").iterdir():
            if p.name.isdigit():
                try:
                    if p.stat().st_uid == uid:
                        os.kill(int(p.name), signal.SIGKILL)
                except (OSError, ProcessLookupError):
                    pass
        subprocess.run(["userdel", "--remove", "--force", name], capture_output=True, timeout=60)
        removed.append(name)
    return removed


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def remove_stale_accounts() -> list[str]:
    """Remove the hub test accounts of runs whose process is gone; return their names."""
    stale = []
    for pw in pwd.getpwall():
        m = ACCOUNT_NAME.fullmatch(pw.pw_name)
        if m and int(m.group(1)) != os.getpid() and not _alive(int(m.group(1))):
            stale.append(pw.pw_name)
    return remove_accounts(stale)


def _own(tree: Path, pw: pwd.struct_passwd) -> None:
    """``tree`` and everything in it owned by ``pw``'s account and private to it (0700 / 0600)."""
    for p in [tree, *tree.rglob("*")]:
        os.lchown(p, pw.pw_uid, pw.pw_gid)
        os.chmod(p, 0o700 if p.is_dir() else 0o600)


def _account(name: str) -> pwd.struct_passwd:
    """The account ``name``, made as deploy.sh makes it when missing (it keeps an existing one)."""
    try:
        return pwd.getpwnam(name)
    except KeyError:
        subprocess.run(["useradd", "--create-home", "--shell", "/bin/bash", name], check=True)
        return pwd.getpwnam(name)


def seed_grader_cache(account: str) -> Path | None:
    """Copy the checkout's generated tests (``.cache/grader``, filled by ``make warm``) into
    ``~account/.cache/grader``, owned by the account and private to it; return it, or None when the
    checkout has none.

    Test set-up only, to save CI time: deploy.sh's ``grader warm`` as the instructor then checks
    these tests instead of generating every problem's again through the shared venv (which compiled
    every numba kernel the generators use, minutes of CPU). The grader's own rules decide: a tests
    folder is used only when its manifest names this problem's digest (a hash of the package and of
    the code its tests come from) and this answer key (a hash of the venv's ``reference_impl``
    sources), so the venv uses them only where it would generate the same tests; any other problem
    is generated as before.
    """
    src = REPO / ".cache" / "grader"
    if not src.is_dir():
        return None
    pw = _account(account)
    cache = Path(pw.pw_dir) / ".cache"
    cache.mkdir(mode=0o700, exist_ok=True)
    os.chown(cache, pw.pw_uid, pw.pw_gid)
    dest = cache / "grader"
    shutil.rmtree(dest, ignore_errors=True)
    shutil.copytree(src, dest, symlinks=False)
    _own(dest, pw)
    return dest


def seed_numba_cache(account: str, dest: Path | None = None) -> Path | None:
    """Copy the instructor's numba cache (``~/.cache/numba``: the install's numba seed, which
    deploy.sh starts it from, and what its ``grader warm`` compiled) to ``dest`` (default
    ``~account/.cache/numba``), owned by ``account`` and private to it (0700); return ``dest``, or
    None when the instructor has none.

    Test set-up only, for a judge run outside the hub (the probe test) that should not compile
    every kernel again; the students' caches are seeded by the deployment itself (the hub's
    ``pre_spawn``, ``grader.course.numba_seed``). numba checks each cached function's source stamp
    and its own version before using it, so a copy never runs code compiled from other sources.
    """
    src = Path(pwd.getpwnam(INSTRUCTOR).pw_dir) / ".cache" / "numba"
    if not src.is_dir():
        return None
    pw = pwd.getpwnam(account)
    if dest is None:
        cache = Path(pw.pw_dir) / ".cache"
        cache.mkdir(mode=0o700, exist_ok=True)
        os.chown(cache, pw.pw_uid, pw.pw_gid)
        dest = cache / "numba"
    shutil.rmtree(dest, ignore_errors=True)
    shutil.copytree(src, dest, symlinks=False)
    _own(dest, pw)
    return dest


def start_hub(timeout: float = 240) -> Hub:
    """Install the deployment into a fresh COURSE_HOME and start the hub; return when it answers."""
    remove_stale_accounts()
    home = Path(tempfile.mkdtemp(prefix="course-hub-"))
    os.chmod(home, 0o755)
    port = _free_port()
    password = secrets.token_urlsafe(12)
    env = {**os.environ, "COURSE_HOME": str(home), "HUB_VENV": str(REPO / "build" / "hub-venv"),
           "HUB_INSTRUCTORS": INSTRUCTOR, "HUB_STUDENTS": ",".join(STUDENTS), "HUB_AUTH": "dummy",
           "HUB_DUMMY_PASSWORD": password, "HUB_PORT": str(port), "HUB_API_PORT": str(_free_port()),
           "HUB_PROXY_API_PORT": str(_free_port()),
           # CI time: a small seed (not every group), kept with build/hub-venv between runs
           "HUB_NUMBA_SEED": "2d predicates,checkers"}
    for u in (INSTRUCTOR, *STUDENTS):
        # a fresh class: nothing fetched, submitted or cached by an earlier run (nbgrader lists an
        # assignment as "submitted" from the student's own nbgrader_cache under ~/.local). Emptied
        # before the install, so the class then finds what the install leaves: the instructor's
        # test and numba caches that deploy.sh fills, and the numba seed the hub copies into each
        # student's empty cache at spawn, as on a real deployment (for CI time the instructor's
        # tests are seeded from the checkout's first: seed_grader_cache).
        try:
            h = Path(pwd.getpwnam(u).pw_dir)
        except KeyError:  # the install makes the account
            continue
        if h.name == u and h.parent == Path("/home") and h.is_dir():
            for entry in h.iterdir():
                if entry.is_dir() and not entry.is_symlink():
                    shutil.rmtree(entry, ignore_errors=True)
                else:
                    entry.unlink(missing_ok=True)
    seed_grader_cache(INSTRUCTOR)
    subprocess.run([str(DEPLOY), "install"], env=env, check=True, timeout=900)
    log = home / "hub.log"
    with open(log, "w") as f:
        proc = subprocess.Popen([str(DEPLOY), "start"], env=env, stdout=f, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, start_new_session=True)
    hub = Hub(f"http://127.0.0.1:{port}", password, home, proc, log, env)
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            raise RuntimeError("the hub exited:\n" + log.read_text()[-3000:])
        try:
            if requests.get(hub.url + "/hub/api", timeout=5).ok:
                return hub
        except requests.ConnectionError:
            pass
        time.sleep(0.5)
    hub.stop()
    raise RuntimeError("the hub did not answer:\n" + log.read_text()[-3000:])


class HubUser:
    """One account logged in to ``hub``, with its single-user server started."""

    def __init__(self, hub: Hub, name: str):
        self.hub, self.name = hub, name
        self.s = requests.Session()
        form = self.s.get(hub.url + "/hub/login", timeout=30)
        xsrf = self.s.cookies.get("_xsrf", path="/hub/") or form.text.split('name="_xsrf" value="')[1].split('"')[0]
        r = self.s.post(hub.url + "/hub/login", data={"username": name, "password": hub.password, "_xsrf": xsrf},
                        timeout=30)
        r.raise_for_status()
        self.base = f"{hub.url}/user/{name}"
        self.s.get(hub.url + "/hub/spawn", timeout=150)
        deadline = time.monotonic() + 150
        while True:  # the server's page, through the hub's OAuth (sets the server's _xsrf cookie)
            r = self.s.get(self.base + "/lab", timeout=60)
            if r.ok and r.url.startswith(self.base + "/lab"):
                break
            if time.monotonic() > deadline:
                raise RuntimeError(f"{name}'s server did not start: {r.status_code} {r.url}\n" + hub.log.read_text()[-3000:])
            time.sleep(1)
        self.xsrf = self.s.cookies.get("_xsrf", path=f"/user/{name}/")

    def call(self, method: str, path: str, **kw) -> requests.Response:
        """``method`` on the user's server at ``path`` (XSRF header added); raises on HTTP errors."""
        r = self.s.request(method, self.base + path, headers={"X-XSRFToken": self.xsrf}, timeout=600, **kw)
        r.raise_for_status()
        return r

    def run_in_kernel(self, code: str, timeout: float = 180) -> str:
        """Run ``code`` in a new kernel of the user's own server (the kernel REST API and its
        websocket, as JupyterLab does); return what it printed (errors as ``ERROR name: value``)."""
        import websocket

        kernel = self.call("POST", "/api/kernels", json={"name": "python3"}).json()
        try:
            url = "ws" + self.base[len("http"):] + f"/api/kernels/{kernel['id']}/channels"
            cookie = "; ".join(f"{c.name}={c.value}" for c in self.s.cookies)
            ws = websocket.create_connection(url, header=[f"Cookie: {cookie}", f"X-XSRFToken: {self.xsrf}"],
                                             origin=self.hub.url, timeout=timeout)
            try:
                msg_id = uuid.uuid4().hex
                ws.send(json.dumps({
                    "header": {"msg_id": msg_id, "msg_type": "execute_request", "username": self.name,
                               "session": uuid.uuid4().hex, "version": "5.3"},
                    "parent_header": {}, "metadata": {}, "channel": "shell", "buffers": [],
                    "content": {"code": code, "silent": False, "store_history": False, "user_expressions": {},
                                "allow_stdin": False, "stop_on_error": True}}))
                out = []
                deadline = time.monotonic() + timeout
                while time.monotonic() < deadline:
                    msg = json.loads(ws.recv())
                    if msg.get("parent_header", {}).get("msg_id") != msg_id:
                        continue
                    kind, content = msg["msg_type"], msg["content"]
                    if kind == "stream":
                        out.append(content["text"])
                    elif kind == "error":
                        out.append(f"ERROR {content['ename']}: {content['evalue']}")
                    elif kind == "status" and content["execution_state"] == "idle":
                        return "".join(out)
                raise TimeoutError(f"{self.name}'s kernel did not finish in {timeout:.0f} s: {''.join(out)[-2000:]}")
            finally:
                ws.close()
        finally:
            self.call("DELETE", f"/api/kernels/{kernel['id']}")

    def formgrader(self, path: str) -> dict:
        """POST to formgrader's API (what its buttons do); the JSON answer, which must say success."""
        out = self.call("POST", "/formgrader/api/" + path).json()
        if not out.get("success", True):
            raise AssertionError(f"formgrader {path}: {out.get('error') or out.get('log')}")
        return out

    def assignments(self, action: str = "", **data) -> list | dict:
        """The Assignments tab's API: list (no action), or fetch / submit / fetch_feedback."""
        if not action:
            out = self.call("GET", "/assignments", params={"course_id": "delaunay-course"}).json()
        else:
            out = self.call("POST", "/assignments/" + action, data={"course_id": "delaunay-course", **data}).json()
        if not out.get("success"):
            raise AssertionError(f"{self.name}: assignments {action or 'list'}: {out.get('value') or out}")
        return out["value"]
