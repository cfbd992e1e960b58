"""The course on a running JupyterHub (deploy/jupyterhub/), with an instructor and two students.

One hub for the module (xdist group "hub"): the instructor releases `delaunay` and `closest-pair`
through formgrader's API, two students fetch them through the Assignments tab's API, write a
solution into the first solution cell (one accepted, one wrong on degenerate input) and submit;
the instructor collects, autogrades (the course's jailed judge, as the instructor's ordinary
account) and releases feedback; each student fetches it. Every score equals
`python -m grader judge <id> <notebook>`. Then isolation: student code, run as that student,
cannot read the other student's home or the exchange's submitted copies.

    .venv/bin/python -m pytest tests/hub/test_hub.py -n 0 -x -q      (as root)
"""
from __future__ import annotations

import json
import pwd
import subprocess
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
import hub_session as hs  # noqa: E402

pytestmark = [pytest.mark.xdist_group("hub"),
              pytest.mark.skipif(bool(hs.can_run()), reason=hs.can_run() or "runs")]

REPO = hs.REPO
SOLUTIONS = {  # student -> problem -> the solution they write
    "hubtest-student1": {"delaunay": "accepted_walk.py", "closest-pair": "accepted_sweep.py"},
    "hubtest-student2": {"delaunay": "wrong_prefix_collinear.py", "closest-pair": "wrong_x_neighbours.py"},
}
PROBLEMS = ("delaunay", "closest-pair")


@pytest.fixture(scope="module")
def hub():
    h = hs.start_hub()
    try:
        yield h
    finally:
        h.stop()


@pytest.fixture(scope="module")
def graded(hub):
    """The whole round trip; returns {student: {problem: formgrader score}} and the users."""
    instructor = hs.HubUser(hub, hs.INSTRUCTOR)
    for a in PROBLEMS:
        instructor.formgrader(f"assignment/{a}/assign")
        instructor.formgrader(f"assignment/{a}/release")
    students = {u: hs.HubUser(hub, u) for u in hs.STUDENTS}
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
        instructor.formgrader(f"assignment/{a}/collect")
        for name in students:
            instructor.formgrader(f"submission/{a}/{name}/autograde")
        instructor.formgrader(f"assignment/{a}/generate_feedback")
        instructor.formgrader(f"assignment/{a}/release_feedback")
        for row in instructor.call("GET", f"/formgrader/api/submissions/{a}").json():
            scores.setdefault(row["student"], {})[a] = row["score"]
    return scores, students


def _judge(problem: str, notebook: Path) -> float:
    out = subprocess.run([sys.executable, "-m", "grader", "judge", problem, str(notebook), "--json"],
                         cwd=REPO, capture_output=True, text=True, timeout=600)
    return float(json.loads(out.stdout)["score"])


def test_scores_equal_the_judge(graded, hub):
    scores, _ = graded
    course = hub.home / "course"
    for name in hs.STUDENTS:
        for a in PROBLEMS:
            nb = course / "submitted" / name / a / f"{a}.ipynb"
            assert scores[name][a] == pytest.approx(_judge(a, nb)), (name, a)
    assert scores["hubtest-student1"]["delaunay"] > scores["hubtest-student2"]["delaunay"]


def test_students_fetch_their_feedback(graded):
    scores, students = graded
    for name, st in students.items():
        for a in PROBLEMS:
            st.assignments("fetch_feedback", assignment_id=a)
            listed = st.call("GET", f"/api/contents/{a}/feedback").json()["content"]
            html = [f for stamp in listed for f in st.call("GET", f"/api/contents/{stamp['path']}").json()["content"]
                    if f["name"].endswith(".html")]
            assert html, (name, a)
            text = st.call("GET", f"/files/{html[0]['path']}").text
            assert "Score" in text or "score" in text


def _as(user: str, code: str) -> subprocess.CompletedProcess:
    """``code`` in the shared venv's python as ``user`` (what their kernel runs as)."""
    return subprocess.run(["runuser", "-u", user, "--", str(REPO / "build" / "hub-venv" / "bin" / "python"), "-c", code],
                          capture_output=True, text=True, timeout=120, cwd="/")


def test_isolation_between_students(graded, hub):
    other = pwd.getpwnam("hubtest-student1").pw_dir
    inbound = hub.home / "exchange" / "delaunay-course" / "inbound"
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
    r = _as("hubtest-student2", probe)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]", r.stdout
    # the probe is real: the owner reads their own notebook
    mine = _as("hubtest-student1", f"print(len(open({other!r} + '/delaunay/delaunay.ipynb').read()) > 0)")
    assert mine.stdout.strip() == "True", mine.stderr
