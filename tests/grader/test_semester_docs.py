"""The docs test of ``assignments/README.md``'s "A semester": its files and commands, as written.

In a copy of the course (``assignments/`` with the venv beside it), the README's ``roster.csv``,
``lms-map.csv`` and ``extensions.yaml`` blocks are written as the files they name, three students'
files are put in ``submissions/``, and every line of the section's ``sh`` block runs in order, each
in a bash that first runs the block's first line (``cd assignments && export PATH=...``). Before
the first ``regrade`` the test fixes a test as the README says (a case added to a group of
``delaunay/course.yaml``). Every line has a check; a line without one fails here.

Run: .venv/bin/python -m pytest tests/grader/test_semester_docs.py -q   (about 2 minutes)
"""
from __future__ import annotations

import csv
import re
import shutil
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest

from .conftest import REPO

pytestmark = pytest.mark.slow
SECTION = "## A semester"


def files_of(markdown: str) -> dict[str, str]:
    """The fenced blocks whose info string names a file: ```` ```csv roster.csv ```` -> its text.

    >>> files_of("x\\n```yaml ext.yaml\\na: 1\\n```\\n")
    {'ext.yaml': 'a: 1\\n'}
    """
    return {name: text for name, text in re.findall(r"```\w+ ([\w.-]+)\n(.*?)```", markdown, re.S)}


def section(readme: str) -> str:
    text = readme[readme.index(SECTION):]
    return text[:text.index("\n## ", 1)] if "\n## " in text[1:] else text


def solution(problem: str, name: str) -> str:
    return (REPO / "solutions" / problem / name).read_text()


def test_semester_section_as_written(tmp_path):
    text = section((REPO / "assignments" / "README.md").read_text())
    block = [ln.strip() for ln in re.findall(r"```sh\n(.*?)```", text, re.S)[0].splitlines() if ln.strip()]
    prelude, steps = block[0], block[1:]
    assert prelude.startswith("cd assignments &&"), prelude
    root = tmp_path / "course"
    shutil.copytree(REPO / "assignments", root / "assignments", symlinks=True,
                    ignore=shutil.ignore_patterns("gradebook.db", "judged.sqlite", "release", "submitted", "submissions",
                                                  "autograded", "feedback", "*.sqlite", "grades", ".cache",
                                                  "__pycache__", "extensions.yaml"))
    (root / ".venv").symlink_to(Path(sys.executable).parent.parent)
    course = root / "assignments"
    written = files_of(text)
    assert set(written) == {"roster.csv", "lms-map.csv", "extensions.yaml"}, set(written)
    for name, body in written.items():
        (course / name).write_text(body)
    small = solution("delaunay", "accepted_walk.py") + (
        "\n_inner = delaunay\n\ndef delaunay(points):\n    return _inner(points) if len(points) <= 12 else []\n")
    for student, source in (("ada", solution("delaunay", "accepted_walk.py")),
                            ("bob", solution("delaunay", "wrong_tutorial.py")), ("cy", small)):
        (course / "submissions" / "delaunay" / student).mkdir(parents=True)
        (course / "submissions" / "delaunay" / student / "delaunay.py").write_text(source)
    (course / "submissions" / "exam" / "ada").mkdir(parents=True)
    (course / "submissions" / "exam" / "ada" / "bowyer-watson-timed.py").write_text(
        solution("bowyer-watson-timed", "accepted_scan.py"))

    def run(line: str) -> subprocess.CompletedProcess:
        r = subprocess.run(["bash", "-c", f"set -e\n{prelude}\n{line}\n"], cwd=root, capture_output=True, text=True,
                           timeout=1200)
        assert r.returncode == 0, f"{line!r} failed ({r.returncode}):\n{r.stdout[-2000:]}\n{r.stderr[-3000:]}"
        return r

    checked, scores = [], {}
    for line in steps:
        if "regrade" in line and "--diff" in line:  # the fix: a case added to the tiny group
            yaml = course / "delaunay" / "course.yaml"
            old = yaml.read_text()
            yaml.write_text(old.replace("      - {kind: uniform, n: 12}\n",
                                        "      - {kind: uniform, n: 12}\n      - {kind: uniform, n: 20}\n", 1))
            assert yaml.read_text() != old
        out = run(line)
        if " grade delaunay" in line:
            scores = {r["student"]: float(r["score"]) for r in csv.DictReader(open(course / "delaunay.csv"))}
            assert scores["ada"] == 100 and scores["bob"] < 100 and 0 < scores["cy"] < 100, scores
        elif "timed start" in line or "timed status" in line:
            assert "30 minutes + 15 extra (your extension)" in out.stdout, out.stdout
        elif "timed submit" in line:
            assert "final score 100/100" in out.stdout, out.stdout
        elif "regrade" in line and "--diff" in line:
            rows = {r["student"]: r for r in csv.DictReader(open(course / "delaunay-regrade.csv"))}
            assert set(rows) == {"ada", "bob", "cy"}
            assert all("tiny: tests changed" in r["changes"] for r in rows.values())
            assert float(rows["cy"]["new_score"]) == scores["cy"] - 15, rows["cy"]  # the new case fails cy
            assert float(rows["ada"]["delta"]) == 0 and "cy: " in out.stdout
            con = sqlite3.connect(course / "results.sqlite")  # the other groups were carried over, not judged
            new, old = [k for k, in con.execute("SELECT sha FROM submissions WHERE student='ada' ORDER BY rowid")]
            moved = con.execute("SELECT COUNT(*) FROM results a JOIN results b ON a.test=b.test AND a.student=b.student "
                                "WHERE a.sha=? AND b.sha=? AND a.grp!='tiny' AND a.judged_at!=b.judged_at",
                                (old, new)).fetchone()[0]
            assert moved == 0
        elif "--student bob" in line:
            assert "bob: " in out.stdout and "regraded on demand" in out.stdout and "1 regraded" in out.stdout
        elif "export-grades" in line:
            canvas = list(csv.reader(open(course / "grades" / "canvas.csv")))
            assert canvas[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "Delaunay (1201)",
                                 "Timed exam (1202)"]
            assert canvas[1][0] == "Points Possible" and canvas[1][5:] == ["10", "100"]
            assert {r[1]: r[5:] for r in canvas[2:]} == {"4001": ["10", "100"], "4002": [f"{scores['bob'] / 10:g}", "0"],
                                                         "4003": [f"{(scores['cy'] - 15) / 10:g}", "0"]}
            moodle = list(csv.reader(open(course / "grades" / "moodle.csv")))
            assert moodle[0] == ["Email address", "ID number", "Delaunay triangulation", "Timed exam"]
            missing = (course / "grades" / "missing.txt").read_text()
            assert "bob: no grade for bowyer-watson-timed" in missing and "cy: no grade for bowyer-watson-timed" in missing
            assert "missing.txt" in out.stdout
        else:
            pytest.fail(f"the README's step {line!r} has no check here: add one")
        checked.append(line)
    assert len(checked) == len(steps) == 7
