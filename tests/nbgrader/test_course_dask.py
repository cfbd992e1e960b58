"""The course's class autograde on a local Dask cluster (``grade --nbgrader --scheduler``).

Three students of the timed exam (right, wrong, hostile) collected into a course, judged on a
local cluster of 2 worker processes, then ``nbgrader autograde`` from the stored results. Checks:
the gradebook's scores equal ``python -m grader judge``'s on each notebook, the hostile code got
its security verdict on the workers too (the jail is on there), autograde judged nobody again
(one stored submission per student, under the key autograde looks up), and a second run judges
nobody.

Run: .venv/bin/python -m pytest tests/nbgrader/test_course_dask.py -q   (about a minute; as root)
"""

from __future__ import annotations

import contextlib
import io
import os
import sqlite3

import pytest

from fake_class import HOSTILE, WRONG_EMPTY, Student, _solution, collected_class, gradebook_scores, judge_json
from grader.cli import main as grader_main
from grader.course.nbgrader_autograde import STORE_NAME, grade_course
from grader.jail import jail_kind

PROBLEM = "bowyer-watson-timed"
pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(os.geteuid() != 0 and jail_kind() == "none",
                                 reason="this account has no kernel jail (no bubblewrap or user namespaces): grading "
                                        "refuses")]


def test_course_on_a_local_dask_cluster(tmp_path):
    distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed (pip install "
                                                            "'delaunay-course[dist]')")
    klass = [Student("right", _solution("accepted_scan.py")), Student("wrong", WRONG_EMPTY),
             Student("hostile", HOSTILE)]
    course = collected_class(tmp_path, PROBLEM, klass)
    submitted = course.root / "submitted"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            assert grader_main(["grade", PROBLEM, str(submitted), "--nbgrader", "--scheduler",
                                cluster.scheduler_address, "--counterexample-seconds", "0"]) == 0
        assert "notebook(s) sent to the Dask cluster at" in err.getvalue(), err.getvalue()
        again = grade_course(PROBLEM, submitted, autograde=False, scheduler=cluster.scheduler_address)
    judged = {s.name: judge_json(PROBLEM, submitted / s.name / PROBLEM / f"{PROBLEM}.ipynb") for s in klass}
    assert {s: j["verdict"] for s, j in judged.items()} == {"right": "AC", "wrong": "WA", "hostile": "SV"}
    got = gradebook_scores(course.root, PROBLEM)
    assert {s: g["score"] for s, g in got.items()} == {s: j["score"] for s, j in judged.items()} \
        == {"right": 100, "wrong": 0, "hostile": 0}
    assert all(g["manual"] == [] for g in got.values())
    assert {r["student"]: r["verdict"] for r in again} == {s: j["verdict"] for s, j in judged.items()}
    with contextlib.closing(sqlite3.connect(course.root / STORE_NAME)) as db:
        rows = db.execute("SELECT student, status FROM submissions WHERE problem=?", (PROBLEM,)).fetchall()
        tests = db.execute("SELECT COUNT(*) FROM results WHERE student='right'").fetchone()[0]
    assert sorted(rows) == [("hostile", "done"), ("right", "done"), ("wrong", "done")]  # nobody judged twice
    assert tests == len(judged["right"]["tests"])
