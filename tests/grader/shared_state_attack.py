"""An account's attack on root's shared grader state, replayed in a private mount namespace.

``python tests/grader/shared_state_attack.py SCENARIO`` (as root) makes a mount namespace of its
own with a fresh tmpfs on ``/tmp`` (mode 1777, like the host's) and on ``/run`` (0755, or 1777 for
the scenarios where ``/run`` is world-writable), so nothing the host or another grader uses is
touched. In it, an unprivileged uid (``nobody``) or root prepares the scenario's lock folder, then
root runs the CLI, ``grader.cli.main(["judge", "tiny-delaunay", <accepted solution>, "--json"])``
as ``python -m grader`` does, with one change: the pool's uids start at :data:`BASE` (62700),
outside the real pool (62000-62511), since the namespace's lock folders are not the host's and a
uid shared with another grader on the host would get its processes killed. The result is printed
as one JSON object: ``rc``, ``stderr``, ``seconds`` and ``created`` (files that appeared in
``/tmp/victim``, a root-owned folder the attacker's symbolic links point into).

Scenarios (``SCENARIOS``): the old location ``/tmp/grader-sandbox-uids`` made by the attacker
with every lock held (``tmp-held``) or every lock a symbolic link (``tmp-links``); the same under
a world-writable ``/run`` (``run-held``, ``run-links``); and unsafe folders made by root
(``run-world-writable``, ``run-symlink``, ``run-not-a-dir``, ``run-parent-not-root``).

Example:
    >>> sorted(SCENARIOS)[0]
    'run-held'
"""
from __future__ import annotations

import fcntl
import json
import os
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
ACCEPTED = REPO / "solutions" / "delaunay" / "accepted_walk.py"
NOBODY = 65534
#: First uid of the pool in the namespace (the real one starts at 62000); the attacker takes all 512.
BASE = 62700
UIDS = range(BASE, BASE + 512)
#: The CLI as ``python -m grader`` runs it, the pool moved to BASE (a grader from before
#: ``grader.jail.uidpool`` kept it in ``grader.jail.sandbox``: the tests show its behaviour too).
JUDGE = """
import sys
try:
    from grader.jail import uidpool as pool
except ImportError:
    from grader.jail import sandbox as pool
pool.UID_BASE = int(sys.argv[1])
from grader.cli import main
sys.exit(main(sys.argv[2:]))
"""
#: scenario -> (mode of the namespace's /run, lock folder, who makes it, what it is)
SCENARIOS = {
    "tmp-held": ("0755", "/tmp/grader-sandbox-uids", "nobody", "held"),
    "tmp-links": ("0755", "/tmp/grader-sandbox-uids", "nobody", "links"),
    "run-held": ("1777", "/run/grader/sandbox-uids", "nobody", "held"),
    "run-links": ("1777", "/run/grader/sandbox-uids", "nobody", "links"),
    "run-world-writable": ("0755", "/run/grader/sandbox-uids", "root", "mode-0777"),
    "run-symlink": ("0755", "/run/grader/sandbox-uids", "root", "symlink"),
    "run-not-a-dir": ("0755", "/run/grader/sandbox-uids", "root", "file"),
    "run-parent-not-root": ("0755", "/run/grader/sandbox-uids", "root", "parent-nobody"),
}
VICTIM = "/tmp/victim"


def _prepare(folder: str, kind: str, ready: int, release: int) -> None:
    """Make ``folder`` as the scenario says, tell ``ready``, then hold what it holds until
    ``release`` is closed (runs in a forked child; never returns)."""
    held = []
    try:
        if kind in ("held", "links"):
            os.setgroups([])
            os.setresgid(NOBODY, NOBODY, NOBODY)
            os.setresuid(NOBODY, NOBODY, NOBODY)
            os.makedirs(folder, mode=0o755)
            for uid in UIDS:
                path = os.path.join(folder, f"{uid}.lock")
                if kind == "links":
                    os.symlink(f"{VICTIM}/created-by-root-{uid}", path)
                else:
                    fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
                    fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
                    held.append(fd)
        elif kind == "mode-0777":
            os.makedirs(folder)
            os.chmod(folder, 0o777)
        elif kind == "symlink":
            os.makedirs("/run/elsewhere", mode=0o700)
            os.makedirs(os.path.dirname(folder))
            os.symlink("/run/elsewhere", folder)
        elif kind == "file":
            os.makedirs(os.path.dirname(folder))
            Path(folder).write_text("")
        elif kind == "parent-nobody":
            os.makedirs(folder, mode=0o700)
            os.chown(os.path.dirname(folder), NOBODY, NOBODY)
        os.write(ready, b"ok")
        os.read(release, 1)  # until the judge is done
    except BaseException as exc:  # noqa: BLE001 - reported to the parent, which fails the scenario
        os.write(ready, f"error: {exc!r}".encode())
    os._exit(0)


def _fresh_tmp() -> None:
    """A fresh tmpfs on this namespace's ``/tmp``, with the checkout and the venv still where they were
    when they live under ``/tmp`` (a clone in ``/tmp``, as CI may make): the host's ``/tmp`` is first
    bound on ``/var/tmp`` (in this namespace only), then each such path is bound back in place."""
    from grader.jail.mounts import MS_BIND, MS_REC, mount
    from grader.jail.paths import under

    keep = sorted({p for p in (str(REPO), os.path.realpath(sys.prefix), os.path.realpath(sys.base_prefix))
                   if under(p, "/tmp")})
    if keep:
        mount("/tmp", "/var/tmp", None, MS_BIND | MS_REC)
    mount("tmpfs", "/tmp", "tmpfs", 0, "mode=1777,size=256m")
    for path in keep:
        os.makedirs(path, exist_ok=True)
        mount(os.path.join("/var/tmp", os.path.relpath(path, "/tmp")), path, None, MS_BIND | MS_REC)


def run(scenario: str, timeout: float = 300) -> dict:
    """Play ``scenario`` (this process enters a new mount namespace: call it in a child)."""
    from grader.jail.mounts import CLONE_NEWNS, MS_PRIVATE, MS_REC, mount, unshare

    run_mode, folder, _who, kind = SCENARIOS[scenario]
    if not unshare(CLONE_NEWNS):
        raise OSError("unshare(CLONE_NEWNS) failed")
    mount(None, "/", None, MS_REC | MS_PRIVATE)
    _fresh_tmp()
    mount("tmpfs", "/run", "tmpfs", 0, f"mode={run_mode},size=16m")
    os.mkdir(VICTIM, 0o755)
    ready_r, ready_w = os.pipe()
    release_r, release_w = os.pipe()
    pid = os.fork()
    if pid == 0:  # pragma: no cover - child
        os.close(ready_r)
        os.close(release_w)
        _prepare(folder, kind, ready_w, release_r)
    os.close(ready_w)
    os.close(release_r)
    try:
        said = os.read(ready_r, 4096).decode()
        if said != "ok":
            return {"error": said or "the scenario's process died"}
        env = {**os.environ, "GRADER_PROBLEMS": str(REPO / "tests" / "grader" / "fixtures")}
        t0 = time.monotonic()
        r = subprocess.run([sys.executable, "-c", JUDGE, str(BASE), "judge", "tiny-delaunay", str(ACCEPTED), "--json"],
                           cwd=REPO, env=env, capture_output=True, text=True, timeout=timeout)
        return {"rc": r.returncode, "stderr": r.stderr, "seconds": round(time.monotonic() - t0, 1),
                "created": sorted(os.listdir(VICTIM)),
                "verdict": json.loads(r.stdout)["verdict"] if r.returncode in (0, 1) and r.stdout.strip() else ""}
    except subprocess.TimeoutExpired as exc:
        return {"rc": None, "stderr": f"timed out after {exc.timeout} s", "seconds": timeout,
                "created": sorted(os.listdir(VICTIM)), "verdict": ""}
    finally:
        os.close(release_w)
        os.waitpid(pid, 0)


if __name__ == "__main__":
    print(json.dumps(run(sys.argv[1])))
