"""JupyterHub configuration of the course server (local unix accounts, one shared course venv).

Written for `deploy/jupyterhub/deploy.sh`, which installs everything this file refers to, and run
by it (as root, the hub needs it to start servers as other accounts):
    /opt/delaunay-course/venv/bin/jupyterhub -f deploy/jupyterhub/jupyterhub_config.py

Settings come from the environment the deploy script exports (defaults in brackets):
    COURSE_HOME        [/opt/delaunay-course]  shared venv (venv/), course root (course/), configs
    HUB_PORT           [8000]                  public port of the proxy
    HUB_INSTRUCTORS    [hub-instructor]        comma-separated accounts that get formgrader
    HUB_AUTH           [pam]                   "pam" for a real course; "dummy" for tests and demos
    HUB_DUMMY_PASSWORD                         the shared password of the dummy authenticator
    HUB_STATE          [$COURSE_HOME/state]    cookie secret, sqlite database, pid files

Students get the Assignments tab (nbgrader's assignment_list) and nothing of formgrader: each
server reads `JUPYTER_CONFIG_PATH` = `$COURSE_HOME/jupyter/student` or `.../instructor` (written by
the deploy script), whose `jupyter_server_config.json` and `labconfig/page_config.json` switch
nbgrader's server and lab extensions on or off for that role.
"""

import os
import pwd

try:  # the course venv's grader (a venv installed before the seed existed has none: no seed then)
    from grader.course.numba_seed import seed_account
except ImportError:  # pragma: no cover - an old venv
    seed_account = None

c = get_config()  # noqa: F821 - provided by jupyterhub when it loads this file

COURSE_HOME = os.environ.get("COURSE_HOME", "/opt/delaunay-course")
STATE = os.environ.get("HUB_STATE", os.path.join(COURSE_HOME, "state"))
VENV = os.environ.get("HUB_VENV", os.path.join(COURSE_HOME, "venv"))
VENV_BIN = os.path.join(VENV, "bin")
INSTRUCTORS = {u for u in os.environ.get("HUB_INSTRUCTORS", "hub-instructor").split(",") if u}
STUDENTS = {u for u in os.environ.get("HUB_STUDENTS", "").split(",") if u}

c.JupyterHub.ip = "127.0.0.1"
c.JupyterHub.port = int(os.environ.get("HUB_PORT", "8000"))
c.JupyterHub.hub_port = int(os.environ.get("HUB_API_PORT", "8081"))
c.ConfigurableHTTPProxy.api_url = f"http://127.0.0.1:{int(os.environ.get('HUB_PROXY_API_PORT', '8001'))}"
c.ConfigurableHTTPProxy.command = [os.environ.get("HUB_PROXY", "configurable-http-proxy")]
c.JupyterHub.cookie_secret_file = os.path.join(STATE, "jupyterhub_cookie_secret")
c.JupyterHub.db_url = "sqlite:///" + os.path.join(STATE, "jupyterhub.sqlite")
c.JupyterHub.pid_file = os.path.join(STATE, "jupyterhub.pid")
c.ConfigurableHTTPProxy.pid_file = os.path.join(STATE, "proxy.pid")
c.JupyterHub.cleanup_servers = True          # stopping the hub stops every single-user server
c.JupyterHub.default_url = "/hub/home"

# --- who may log in --------------------------------------------------------------------------
if os.environ.get("HUB_AUTH", "pam") == "dummy":
    # tests and `make hub` demos only: one shared password, and only the course's accounts
    c.JupyterHub.authenticator_class = "dummy"
    c.DummyAuthenticator.password = os.environ["HUB_DUMMY_PASSWORD"]
else:
    c.JupyterHub.authenticator_class = "pam"  # the machine's own passwords (passwd/ldap/...)
c.Authenticator.allowed_users = INSTRUCTORS | STUDENTS if STUDENTS else set()
c.Authenticator.admin_users = INSTRUCTORS
if not STUDENTS:
    c.Authenticator.allow_all = True         # every unix account of this machine may log in

# --- how a server starts: the account's own process, from the shared venv ---------------------
c.JupyterHub.spawner_class = "jupyterhub.spawner.LocalProcessSpawner"
c.Spawner.cmd = [os.path.join(VENV_BIN, "jupyterhub-singleuser")]
c.Spawner.default_url = "/lab"
c.Spawner.start_timeout = 120
c.Spawner.http_timeout = 120


def pre_spawn(spawner) -> None:
    """Per account: role config, course root, private numba and grader caches (numba writes its
    cache beside the sources unless told otherwise, and the shared venv is read-only). A new
    account's numba cache starts as a copy of the install's seed (the kernels the checkers use,
    compiled once), so its first sample check does not compile them again."""
    name = spawner.user.name
    pw = pwd.getpwnam(name)
    home = pw.pw_dir
    role = "instructor" if name in INSTRUCTORS else "student"
    env = spawner.environment
    env["PATH"] = f"{VENV_BIN}:/usr/local/bin:/usr/bin:/bin"
    env["JUPYTER_CONFIG_PATH"] = os.path.join(COURSE_HOME, "jupyter", role)
    env["NUMBA_CACHE_DIR"] = os.path.join(home, ".cache", "numba")
    # copied as the account, only into a missing or empty cache, only from a root-owned seed
    if seed_account is not None:
        seed_account(os.path.join(VENV, "numba-seed"), env["NUMBA_CACHE_DIR"], pw.pw_uid, pw.pw_gid,
                     log=spawner.log.info, python=os.path.join(VENV_BIN, "python"))
    env["GRADER_CACHE"] = os.path.join(home, ".cache", "grader")
    env["GRADER_PROBLEMS"] = os.path.join(COURSE_HOME, "course" if role == "instructor" else "problems")
    env["OMP_NUM_THREADS"] = env["OPENBLAS_NUM_THREADS"] = "1"
    if role == "instructor":
        # formgrader reads the course's nbgrader_config.py from the directory the server starts in
        spawner.notebook_dir = os.path.join(COURSE_HOME, "course")
    else:
        spawner.notebook_dir = home


c.Spawner.pre_spawn_hook = pre_spawn
