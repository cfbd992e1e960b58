"""The course on a running JupyterHub (deploy/jupyterhub/), with an instructor and four students.

One hub for the module (xdist group "hub"). The instructor, in chromium, clicks formgrader's
Generate and Release for `delaunay` and `closest-pair`. Two students (in chromium, through the
pages: login form, Assignments tab, the notebook, the sample check's output read in the page)
and two more (through the HTTP APIs the same pages call) fetch, write a solution into the first
solution cell (for each problem one accepted, one wrong on degenerate input) and submit; the
instructor clicks Collect, Autograde (the course's jailed judge, as the instructor's ordinary
account) and Generate/Release Feedback; each student fetches the feedback and opens it. Every
score equals `python -m grader judge <id> <notebook>`. Then isolation: student code, run as that
student (a process, and the student's own kernel on the hub), cannot read another student's home,
the exchange's submitted copies or the instructor's course; judged, such code gets a security
violation and no data. And what every account can read of the problems is enough for the sample
check but holds nothing a hidden test is built from (no generators, seed or hidden cases).

    .venv/bin/python -m pytest tests/hub/test_hub.py -n 0 -x -q      (as root)
"""
from __future__ import annotations

import json
import os
import pwd
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
import requests

sys.path.insert(0, str(Path(__file__).parent))
import contents_race as cr  # noqa: E402
import hub_browser as hb  # noqa: E402
import hub_session as hs  # noqa: E402

pytestmark = [pytest.mark.xdist_group("hub"),
              pytest.mark.skipif(bool(hs.can_run()), reason=hs.can_run() or "runs")]

REPO = hs.REPO
S1, S2, S3, S4 = hs.STUDENTS  # this run's accounts (hubtest<pid>-student1 ...)
SOLUTIONS = {  # student -> problem -> the solution they write
    S1: {"delaunay": "accepted_walk.py", "closest-pair": "accepted_sweep.py"},
    S2: {"delaunay": "wrong_prefix_collinear.py", "closest-pair": "wrong_x_neighbours.py"},
    S3: {"delaunay": "accepted_walk.py", "closest-pair": "wrong_x_neighbours.py"},
    S4: {"delaunay": "wrong_prefix_collinear.py", "closest-pair": "accepted_sweep.py"},
}
API_STUDENTS = (S1, S2)   # through the HTTP APIs the pages call
BROWSER_STUDENTS = (S3, S4)  # through the pages, in chromium
PROBLEMS = ("delaunay", "closest-pair")
SHOTS = REPO / "build" / "screenshots"


@pytest.fixture(scope="module")
def hub():
    h = hs.start_hub()
    try:
        yield h
    finally:
        h.stop()


@pytest.fixture(scope="module")
def browser():
    if not Path(hb.CHROMIUM).exists():
        pytest.skip("Debian chromium is not installed (apt-get install chromium)")
    pytest.importorskip("playwright.sync_api", reason="playwright is not installed (pip install '.[test]')")
    with hb.student_browser() as b:
        yield b


def _report(e: BaseException, tab: hb.HubTab, hub: hs.Hub, shot: str, account: str = "") -> None:
    """A screenshot of ``tab``, and a note on ``e``: the page's open dialogs and the hub log's last
    lines (those of ``account``, when one is named)."""
    tab.shot(shot)
    e.add_note(f"{tab.name}'s open dialogs: {tab.dialogs() or '(none)'}\n"
               f"hub log (kept in build/hub-test.log){', ' + account + ' only' if account else ''}:\n"
               f"{hub.log_tail(80, account)}")


@pytest.fixture(scope="module")
def graded(hub, browser):
    """The whole round trip, the instructor in formgrader's pages; returns {student: {problem:
    formgrader score}}, the API students and the browser students (with what their sample checks
    showed in the page)."""
    teacher = hb.BrowserInstructor(browser, hub, hs.INSTRUCTOR, SHOTS)   # formgrader's buttons
    in_pages = {name: hb.BrowserStudent(browser, hub, name, SHOTS) for name in BROWSER_STUDENTS}
    try:
        teacher.log_in()
        for a in PROBLEMS:
            teacher.assignment(a, "assign")                  # Generate
            teacher.assignment(a, "release")
    except Exception as e:
        _report(e, teacher, hub, "failed-instructor")
        raise
    instructor = hs.HubUser(hub, hs.INSTRUCTOR)              # reads the scores formgrader shows
    for name, in_page in in_pages.items():
        try:
            in_page.log_in()
            in_page.checks = {}
            for a in PROBLEMS:
                in_page.fetch(a)
                code = (REPO / "solutions" / a / SOLUTIONS[name][a]).read_text()
                in_page.checks[a] = in_page.write_and_check(a, code, f"judged {a}.ipynb")
                in_page.submit(a)
        except Exception as e:
            _report(e, in_page, hub, "failed", name)
            raise
    students = {u: hs.HubUser(hub, u) for u in API_STUDENTS}
    for name, st in students.items():
        listed = {x["assignment_id"]: x["status"] for x in st.assignments()}
        assert listed == {a: "released" for a in PROBLEMS}, listed
        for a in PROBLEMS:
            st.assignments("fetch", assignment_id=a)
            path = f"/api/contents/{a}/{a}.ipynb"
            nb = st.call("GET", path).json()["content"]
            cell = next(c for c in nb["cells"] if c["cell_type"] == "code"
                        and c.get("metadata", {}).get("nbgrader", {}).get("solution"))
            cell["source"] = (REPO / "solutions" / a / SOLUTIONS[name][a]).read_text()
            st.call("PUT", path, json={"type": "notebook", "format": "json", "content": nb})
            st.assignments("submit", assignment_id=a)
    scores = {}
    for a in PROBLEMS:
        try:
            teacher.assignment(a, "collect")
            for name in SOLUTIONS:
                teacher.autograde(a, name)
            teacher.assignment(a, "generate-feedback")
            teacher.assignment(a, "release-feedback")
        except Exception as e:
            _report(e, teacher, hub, "failed-instructor")
            raise
        for row in instructor.call("GET", f"/formgrader/api/submissions/{a}").json():
            scores.setdefault(row["student"], {})[a] = row["score"]
    return scores, students, in_pages


def _judge(problem: str, notebook: Path) -> float:
    out = subprocess.run([sys.executable, "-m", "grader", "judge", problem, str(notebook), "--json"],
                         cwd=REPO, capture_output=True, text=True, timeout=600)
    return float(json.loads(out.stdout)["score"])


def test_scores_equal_the_judge(graded, hub):
    scores, _, _ = graded
    course = hub.home / "course"
    for name in hs.STUDENTS:
        for a in PROBLEMS:
            nb = course / "submitted" / name / a / f"{a}.ipynb"
            assert scores[name][a] == pytest.approx(_judge(a, nb)), (name, a)
    assert scores[S1]["delaunay"] > scores[S2]["delaunay"]


def test_students_fetch_their_feedback(graded):
    scores, students, _ = graded
    for name, st in students.items():
        for a in PROBLEMS:
            st.assignments("fetch_feedback", assignment_id=a)
            listed = st.call("GET", f"/api/contents/{a}/feedback").json()["content"]
            html = [f for stamp in listed for f in st.call("GET", f"/api/contents/{stamp['path']}").json()["content"]
                    if f["name"].endswith(".html")]
            assert html, (name, a)
            text = st.call("GET", f"/files/{html[0]['path']}").content.decode("utf-8")
            assert "Score" in text or "score" in text
            assert "≤" in text and "\\le" not in text, "the statement's maths reads as text (no MathJax offline)"


def test_the_deploy_seeded_each_students_numba_cache(graded, hub):
    """Each student's server started with the install's numba seed in its ``~/.cache/numba``:
    copied by the hub at spawn (its log says so), the student's own and private."""
    from grader.course.numba_seed import untrusted
    seed = Path(hub.env["HUB_VENV"]) / "numba-seed"
    assert untrusted(seed) == ""
    seeded = {p.relative_to(seed) for p in seed.rglob("*.nbi")}
    assert seeded, "the install compiled no kernel into the seed"
    log = hub.log.read_text()
    for name in SOLUTIONS:
        pw = pwd.getpwnam(name)
        cache = Path(pw.pw_dir) / ".cache" / "numba"
        assert f"numba seed: {sum(p.is_file() for p in seed.rglob('*'))} files copied into {cache}" in log, name
        assert seeded <= {p.relative_to(cache) for p in cache.rglob("*.nbi")}, name
        st = os.stat(cache)
        assert (st.st_uid, st.st_mode & 0o777) == (pw.pw_uid, 0o700), name


def test_the_shared_venv_saves_widget_state(hub):
    """A lesson reopened on the hub without its kernel shows its widgets' last pictures."""
    overrides = REPO / "build" / "hub-venv" / "share" / "jupyter" / "lab" / "settings" / "overrides.json"
    assert json.loads(overrides.read_text())["@jupyter-widgets/jupyterlab-manager:plugin"]["saveState"] is True
    assert overrides.stat().st_mode & 0o004, "every account's JupyterLab reads it"


def test_saves_through_the_hub_replace_the_notebook_and_lose_nothing(graded, hub):
    """Every account's server reads deploy/jupyterhub/jupyter_server_config.py from the shared venv:
    a save through the hub replaces the notebook by a new file (a new inode, the old mode and owner;
    jupyter_server's own save writes in place), and 40 saves while a reader polls the same notebook
    through the hub lose none (tests/hub/test_saves.py races 200 on a plain server)."""
    installed = REPO / "build" / "hub-venv" / "etc" / "jupyter" / "jupyter_server_config.py"
    assert installed.read_text() == (REPO / "deploy" / "jupyterhub" / "jupyter_server_config.py").read_text()
    name = API_STUDENTS[0]
    st = graded[1][name]
    path = Path(pwd.getpwnam(name).pw_dir) / "save-race.ipynb"
    url = f"{st.base}/api/contents/{path.name}"
    headers = {"X-XSRFToken": st.xsrf}
    nb = cr.big_notebook(cells=4, lines=3000)
    st.call("PUT", f"/api/contents/{path.name}", json={"type": "notebook", "format": "json", "content": nb})
    os.chmod(path, 0o640)
    with open(path, "rb") as old:          # held open, its inode cannot be reused by a later save
        before = os.fstat(old.fileno())
        with requests.Session() as reader:
            reader.cookies.update(st.s.cookies)
            seen = cr.race(lambda body: st.s.put(url, json=body, headers=headers, timeout=120),
                           lambda: reader.get(url + "?content=1", headers=headers, timeout=120),
                           path, nb, saves=40, readers=1)
        assert cr.marker(old.read().decode()) == 0, "a reader of the old file reads it whole"
    assert not seen.lost and seen.torn_disk_reads == 0, seen.summary()
    assert seen.answers["read answered 200"] > 0, seen.summary()
    after = path.stat()
    assert after.st_ino != before.st_ino, "the save wrote in place: the course's contents manager is not in use"
    assert (after.st_mode & 0o777, after.st_uid, after.st_gid) == (0o640, before.st_uid, before.st_gid)


def _as(user: str, code: str) -> subprocess.CompletedProcess:
    """``code`` in the shared venv's python as ``user`` (what their kernel runs as)."""
    return subprocess.run(["runuser", "-u", user, "--", str(REPO / "build" / "hub-venv" / "bin" / "python"), "-c", code],
                          capture_output=True, text=True, timeout=120, cwd="/")


def test_isolation_between_students(graded, hub):
    other = pwd.getpwnam(S1).pw_dir
    inbound = hub.home / "exchange" / "delaunay-course" / "inbound"
    # after the round trip's release, submit and collect: deploy.sh's modes are kept (test_exchange.py)
    assert oct(os.stat(hub.home / "exchange").st_mode & 0o7777) == "0o1777"
    assert oct(os.stat(inbound).st_mode & 0o7777) == "0o3733"
    probe = f"""
import os, glob
leaks = []
for p in [{other!r} + "/delaunay/delaunay.ipynb", {other!r}]:
    try:
        open(p).read() if os.path.isfile(p) else os.listdir(p)
        leaks.append(p)
    except OSError:
        pass
try:
    leaks += os.listdir({str(inbound)!r})
except OSError:
    pass
leaks += glob.glob({str(inbound)!r} + "/*/*.ipynb")
print(leaks)
"""
    r = _as(S2, probe)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]", r.stdout
    # the probe is real: the owner reads their own notebook
    mine = _as(S1, f"print(len(open({other!r} + '/delaunay/delaunay.ipynb').read()) > 0)")
    assert mine.stdout.strip() == "True", mine.stderr


LEAK_PROBE = """
import glob, os
leaks = []
for p in {paths!r}:
    try:
        open(p, "rb").read(1) if os.path.isfile(p) else os.listdir(p)
        leaks.append(p)
    except OSError:
        pass
leaks += glob.glob({inbound!r} + "/*/*.ipynb")
print("LEAKS", leaks)
"""


def _private_paths(hub) -> tuple[list[str], str]:
    """What a student must not read: the other student's home and work, the instructor's course
    (sources with solutions, gradebook, submissions), the exchange's inbound."""
    other = pwd.getpwnam(S1).pw_dir
    course = hub.home / "course"
    paths = [other, other + "/delaunay/delaunay.ipynb", str(course), str(course / "gradebook.db"),
             str(course / "source" / "delaunay" / "delaunay.ipynb"), str(course / "delaunay" / "course.yaml"),
             str(course / "submitted")]
    return paths, str(hub.home / "exchange" / "delaunay-course" / "inbound")


def test_a_students_own_kernel_reads_nothing_private(graded, hub):
    _, students, _ = graded
    paths, inbound = _private_paths(hub)
    out = students[S2].run_in_kernel(LEAK_PROBE.format(paths=paths, inbound=inbound))
    assert "LEAKS []" in out, out
    # the probe is real: in student1's own kernel the same code reads student1's files
    mine = students[S1].run_in_kernel(LEAK_PROBE.format(paths=paths[:2], inbound="/nonexistent"))
    assert "LEAKS " + repr(paths[:2]) in mine, mine


def test_judged_code_that_reads_private_files_gets_a_violation(graded, hub):
    paths, _ = _private_paths(hub)
    where = Path(tempfile.mkdtemp(prefix="hubtest-probe-"))      # pytest's tmp_path is root's, 0700
    probe = where / "probe.py"
    probe.write_text("LEAKED = []\n" + "\n".join(f"LEAKED.append(open({p!r}, 'rb').read())" for p in paths[1:2])
                     + "\ndef delaunay(points):\n    return [len(x) for x in LEAKED]\n")
    os.chmod(where, 0o755)
    os.chmod(probe, 0o644)
    instructor = pwd.getpwnam(hs.INSTRUCTOR)
    # the instructor's own caches, in this private folder: not a guessable /tmp name that another
    # account could make first (a numba cache is code); numba's a copy of the instructor's (CI time)
    (where / "cache").mkdir(mode=0o700)
    os.chown(where / "cache", instructor.pw_uid, instructor.pw_gid)
    if hs.seed_numba_cache(hs.INSTRUCTOR, where / "numba") is None:
        (where / "numba").mkdir(mode=0o700)
        os.chown(where / "numba", instructor.pw_uid, instructor.pw_gid)
    env = [f"{k}={v}" for k, v in {"GRADER_PROBLEMS": str(hub.home / "course"),
                                    "GRADER_CACHE": str(where / "cache"),
                                    "NUMBA_CACHE_DIR": str(where / "numba"),
                                    "HOME": instructor.pw_dir}.items()]
    try:
        r = subprocess.run(["runuser", "-u", hs.INSTRUCTOR, "--", "env", *env,
                            str(REPO / "build" / "hub-venv" / "bin" / "python"),
                            "-m", "grader", "judge", "delaunay", str(probe), "--json"],
                           capture_output=True, text=True, timeout=600, cwd="/")
    finally:
        shutil.rmtree(where, ignore_errors=True)
    assert r.stdout.strip(), r.stderr
    result = json.loads(r.stdout)
    assert result["verdict"] == "SV" and result["score"] == 0, result
    assert paths[1] in json.dumps(result), result                  # the message names what it tried


def test_students_can_check_samples_but_not_rebuild_hidden_tests(graded, hub):
    import yaml

    public = hub.home / "problems"
    listing = _as(S2, f"""
import json, os
files = [os.path.join(d, f) for d, _, fs in os.walk({str(public)!r}) for f in fs]
print(json.dumps({{f: open(f, errors="replace").read() if f.endswith(".yaml") else "" for f in files}}))
""")
    assert listing.returncode == 0, listing.stderr
    files = json.loads(listing.stdout)
    assert files, "the students' copy of the problems is empty"
    assert not [f for f in files if "/generators/" in f or "/secret/" in f or f.endswith(".ans") and "/sample/" not in f]
    full = hub.home / "course"
    for pid in PROBLEMS:
        mine = yaml.safe_load(files[str(public / pid / "course.yaml")])
        theirs = yaml.safe_load((full / pid / "course.yaml").read_text())
        assert "seed" in theirs and any(g.get("cases") for g in theirs["groups"])     # the probe is real
        assert "seed" not in mine and not [g for g in mine["groups"] if g.get("cases") and not g.get("withheld")], mine
        assert (full / pid / "generators").is_dir()
    # the sample check, as the student (the jailed judge, the student's own caches)
    home = pwd.getpwnam(S1).pw_dir
    check = _as(S1, f"""
import os
os.environ.update(GRADER_PROBLEMS={str(public)!r}, GRADER_CACHE={home!r} + "/.cache/grader",
                  NUMBA_CACHE_DIR={home!r} + "/.cache/numba")
from pathlib import Path
from grader.contest.sample_check import judge_samples
result, problem = judge_samples("delaunay", Path({home!r}) / "delaunay" / "delaunay.ipynb")
print("CHECK", result.verdict, [g.name for g in problem.groups])
""")
    assert "CHECK AC ['sample']" in check.stdout, check.stdout + check.stderr


def test_the_browser_students_checked_submitted_and_read_feedback(graded):
    """The students who used the pages: the sample check's table was shown in the page, the scores
    (in test_scores_equal_the_judge) are the judge's, and the feedback opens from the Assignments tab."""
    scores, _, in_pages = graded
    for name, in_page in in_pages.items():
        for a in PROBLEMS:
            assert f"judged {a}.ipynb" in in_page.checks[a] and "sample" in in_page.checks[a], in_page.checks[a]
            text = in_page.fetch_feedback(a)
            assert a in text and ("Score" in text or "score" in text), text[:500]
    # each problem: one of them right, one wrong on degenerate input, and formgrader tells them apart
    for a in PROBLEMS:
        assert scores[S3][a] != scores[S4][a], (a, scores)


def test_the_clean_up_removes_only_this_modules_accounts():
    """The accounts are this run's (named after its process) and the clean-up refuses any other name,
    the old shared ``hubtest-student1`` too (a run of an older checkout may be using it)."""
    assert all(hs.ACCOUNT_NAME.fullmatch(u) for u in (hs.INSTRUCTOR, *hs.STUDENTS))
    assert str(os.getpid()) in hs.INSTRUCTOR and len(set(hs.STUDENTS)) == 4
    for other in ("root", "hubtest-student1", "hub-student1", "hubtest12-student1x"):
        with pytest.raises(ValueError, match="not a hub test account"):
            hs.remove_accounts([other])
