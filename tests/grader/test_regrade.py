"""Per-group store keys: upgrading a store written with whole-package keys, on-demand regrades
that resume, the nbgrader path's keys, and bad input.

* a store from before per-group keys (``<content>-<package digest>``, no fingerprints) whose
  package did not change: its results are adopted, no test is judged again;
* the same store after the package changed: each student is judged again (nobody can tell which
  group changed) and the diff says "graded under the previous store keys"; the old rows stay;
* ``regrade --student``: judged again from scratch, the old score noted first; a regrade
  interrupted after that note resumes on the next run and still reports the old score;
* the nbgrader path: a statement edit changes no key; a result stored under the previous key of
  the same code and package is taken over, not judged again.

Run: .venv/bin/python -m pytest tests/grader/test_regrade.py -q
"""
from __future__ import annotations

import shutil
import sqlite3
import subprocess
import sys

import pytest

from grader.classroom import regrade
from grader.classroom.classgrade import grade_class
from grader.classroom.store import ResultStore
from grader.problems import load_problem

from .conftest import HERE, REPO

ACCEPTED = (REPO / "solutions" / "delaunay" / "accepted_walk.py").read_text()


@pytest.fixture
def problems(monkeypatch, tmp_path):
    root = tmp_path / "problems"
    shutil.copytree(HERE / "fixtures" / "tiny-delaunay", root / "tiny-delaunay")
    course = root / "tiny-delaunay" / "course.yaml"
    course.write_text(course.read_text().replace("../../../../", f"{REPO}/"))
    monkeypatch.setenv("GRADER_PROBLEMS", str(root))
    return root


def klass(root, names=("ada", "bob")):
    for n in names:
        (root / n).mkdir(parents=True)
        (root / n / "tiny-delaunay.py").write_text(ACCEPTED if n == "ada" else "def delaunay(points):\n    return []\n")
    return root


def to_legacy(db, digest: str) -> None:
    """Rewrite a store as the grader before per-group keys wrote it: key content-digest, no fingerprints."""
    con = sqlite3.connect(db)
    for (sha,) in con.execute("SELECT DISTINCT sha FROM submissions").fetchall():
        old = f"{sha.split('-')[0]}-{digest[:8]}"
        con.execute("UPDATE submissions SET sha=?, groups='' WHERE sha=?", (old, sha))
        con.execute("UPDATE results SET sha=? WHERE sha=?", (old, sha))
    con.commit()


def judged_at(db) -> set[float]:
    return {t for (t,) in sqlite3.connect(db).execute("SELECT judged_at FROM results")}


def test_legacy_store_unchanged_package_is_adopted(tmp_path, problems, capsys):
    root, db = klass(tmp_path / "class"), tmp_path / "r.sqlite"
    grade_class("tiny-delaunay", root, db, progress=False)
    to_legacy(db, load_problem("tiny-delaunay").digest())
    before = judged_at(db)
    out = {s["student"]: s for s in grade_class("tiny-delaunay", root, db, progress=False)}
    assert out["ada"]["score"] == 100 and out["bob"]["score"] == 0
    assert judged_at(db) == before  # every result taken over, none judged again
    assert "ada: 100 (unchanged)" in capsys.readouterr().err
    assert all(s.get("skipped") for s in grade_class("tiny-delaunay", root, db, progress=False))


def test_legacy_store_changed_package_is_judged_again_and_said(tmp_path, problems, capsys):
    root, db = klass(tmp_path / "class"), tmp_path / "r.sqlite"
    grade_class("tiny-delaunay", root, db, progress=False)
    old_digest = load_problem("tiny-delaunay").digest()
    to_legacy(db, old_digest)
    course = problems / "tiny-delaunay" / "course.yaml"
    course.write_text(course.read_text() + "      - {kind: uniform, n: 6}\n")
    capsys.readouterr()
    grade_class("tiny-delaunay", root, db, progress=False)
    err = capsys.readouterr().err
    assert "ada: 100 (unchanged); tiny: graded under the previous store keys and the package changed since" in err
    con = sqlite3.connect(db)
    assert con.execute("SELECT COUNT(*) FROM results WHERE sha LIKE ?", (f"%-{old_digest[:8]}",)).fetchone()[0] == 6  # kept
    assert con.execute("SELECT COUNT(*) FROM results WHERE test='tiny/03'").fetchone()[0] == 2  # the new case, both


def test_regrade_on_demand_resumes(tmp_path, problems):
    root, db = klass(tmp_path / "class"), tmp_path / "r.sqlite"
    grade_class("tiny-delaunay", root, db, progress=False)
    store = ResultStore(db)
    sha = store.latest("tiny-delaunay")["ada"]["sha"]
    regrade.force(store, "tiny-delaunay", "ada", sha, "regraded on demand")  # then the run is killed
    regrade.force(store, "tiny-delaunay", "ada", sha, "again")  # a second call changes nothing
    assert regrade.pending(store, "tiny-delaunay", "ada", sha) and not store.is_done("ada", "tiny-delaunay", sha)
    store.close()
    before = judged_at(db)
    out = {s["student"]: s for s in grade_class("tiny-delaunay", root, db, progress=False)}  # the rerun resumes
    assert out["ada"]["regrade"]["old_score"] == 100 == out["ada"]["regrade"]["new_score"]
    assert out["ada"]["regrade"]["changes"] == {"tiny": "regraded on demand"}
    assert out["bob"].get("skipped")
    assert len(judged_at(db) - before) == 3  # ada's three tests, judged again from scratch
    with pytest.raises(ValueError, match="no submission of zed"):
        grade_class("tiny-delaunay", root, db, progress=False, regrade_students=["zed"])


def test_regrade_cli_one_student(tmp_path, problems):
    root, db = klass(tmp_path / "class"), tmp_path / "r.sqlite"
    grade_class("tiny-delaunay", root, db, progress=False)
    r = subprocess.run([sys.executable, "-m", "grader", "regrade", "tiny-delaunay", str(root), "--db", str(db),
                        "--student", "bob", "--diff", str(tmp_path / "d.csv"), "--quiet"],
                       capture_output=True, text=True, cwd=REPO)
    assert r.returncode == 0, r.stderr
    assert "bob: 0 (unchanged); tiny: regraded on demand" in r.stdout
    assert "1 regraded, 0 scores moved" in r.stdout
    assert (tmp_path / "d.csv").read_text().splitlines()[1].startswith("bob,tiny-delaunay,0.0,0.0,0.0,WA,WA")


def test_nbgrader_keys_statement_edit_and_previous_key(tmp_path, problems):
    from grader.course import nbgrader_autograde as nba

    sub = tmp_path / "ada.py"
    sub.write_text(ACCEPTED)
    store = tmp_path / "judged.sqlite"
    nba._problems.clear(), nba._fps.clear()
    first = nba.judge_notebook_file("tiny-delaunay", sub, "ada", store)
    (problems / "tiny-delaunay" / "statement" / "problem.en.md").write_text("# reworded\n")
    nba._problems.clear(), nba._fps.clear()
    problem = nba._problem("tiny-delaunay")
    code = sub.read_text()
    key = nba.code_key(problem, code)
    assert ResultStore(store).is_done("ada", "tiny-delaunay", key)  # the same key: nothing to judge
    # a store written before per-group keys: ada's result under the previous key is taken over
    legacy = nba.legacy_code_key(problem, code)
    con = sqlite3.connect(store)
    con.execute("UPDATE submissions SET sha=?, groups='' WHERE sha=?", (legacy, key))
    con.execute("UPDATE results SET sha=? WHERE sha=?", (legacy, key))
    con.commit()
    before = judged_at(store)
    again = nba.judge_notebook_file("tiny-delaunay", sub, "ada", store)
    assert again.score == first.score == 100 and judged_at(store) == before


def test_bad_extensions_file_is_named(tmp_path, problems):
    from grader.classroom import extensions

    (problems / "extensions.yaml").write_text("ada:\n  tiny-delaunay: 3 weeks\n")
    with pytest.raises(ValueError, match="ada / tiny-delaunay: an extension is"):
        extensions.load()
    (problems / "extensions.yaml").write_text("ada:\n  delaunay-typo: 3 days\n")
    with pytest.raises(ValueError, match="no assignment 'delaunay-typo'"):
        extensions.load()
