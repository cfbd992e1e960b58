"""The docs test: the instructor's steps of ``assignments/README.md`` and the student edition's
README, followed as written, in copies of the course outside the checkout.

The instructor's part copies the course folder (``assignments/``, with a ``.venv`` beside it that is
this checkout's), sets the exchange in the instructor's own ``~/.jupyter/nbgrader_config.py`` as the
README says, and runs every line of the README's "Instructor workflow" block in order, each in a
bash that first runs the block's first line (``cd assignments && export PATH=...``). Between
release and collect two students, real accounts (nbgrader names a submission after the uid that
made it; ``tests/grader/ordinary_user.py`` creates them, so this part needs root, as in CI), run the
README's fetch and submit commands in their homes: one with a right solution, one with a solution
that is wrong on some degenerate input (collinear first points).
After each line the test checks what it should have made; every line of the block has a check, so a
README step without one fails here. The README's timed-exam ``deadline`` command is run in the copy
too, and the checkout's own gradebook must stay untouched.

The student's part writes the edition with ``python -m grader.student_edition`` and runs every
line of the ``sh`` blocks of its README in the edition, in a fresh venv, with nothing of this
checkout on ``PATH`` or ``PYTHONPATH``. The one line marked ``# interactive`` (JupyterLab) is
replaced by its headless equivalent: lessons 10 and 12 run top to bottom with the edition's
``jupyter nbconvert --execute`` (quick mode); a line marked ``# expect: V`` must print verdict V.

Run: .venv/bin/python -m pytest tests/nbgrader/test_docs.py -n 0 -q   (about 5 minutes; pip
needs the package registry for the edition's venv)
"""

from __future__ import annotations

import csv
import importlib.util
import json
import os
import re
import shutil
import sqlite3
import subprocess
import sys
import tempfile
from pathlib import Path

import nbformat
import pytest

from fake_class import Student, gradebook_scores, student_notebook
from grader.problems import REPO, list_problems

pytestmark = pytest.mark.slow
COURSE_ID = "delaunay-course"
LESSONS = ("10-contest-problems.ipynb", "12-timed-practice.ipynb")


def sh_blocks(markdown: str, after: str = "") -> list[list[str]]:
    """The lines of each fenced ``sh`` block of ``markdown`` that follows the text ``after``.

    >>> sh_blocks("x\\n```sh\\nls -l   # list\\n\\npwd\\n```\\n")
    [['ls -l   # list', 'pwd']]
    """
    text = markdown[markdown.index(after):] if after else markdown
    return [[ln.strip() for ln in b.splitlines() if ln.strip()] for b in re.findall(r"```sh\n(.*?)```", text, re.S)]


def backticked(markdown: str, prefix: str) -> str:
    """The first inline-code span of ``markdown`` that starts with ``prefix``, line breaks as spaces."""
    prose = re.sub(r"```.*?```", "", markdown, flags=re.S)  # fenced blocks would pair the backticks wrongly
    spans = [" ".join(s.split()) for s in re.findall(r"`([^`]+)`", prose)]
    return next(s for s in spans if s.startswith(prefix))


def bash(line: str, cwd: Path, env: dict, prelude: str = "", timeout: float = 1200) -> subprocess.CompletedProcess:
    script = f"set -e\n{prelude}\n{line}\n" if prelude else f"set -e\n{line}\n"
    return subprocess.run(["bash", "-c", script], cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)


def ok(r: subprocess.CompletedProcess, line: str) -> subprocess.CompletedProcess:
    assert r.returncode == 0, f"{line!r} failed ({r.returncode}):\n{r.stdout[-2000:]}\n{r.stderr[-3000:]}"
    return r


def account(tmp: Path, name: str, exchange: Path) -> dict:
    """The environment of ``name`` (the instructor, this process's own account): its own HOME, whose
    nbgrader config sets the exchange."""
    home = tmp / "home" / name
    (home / ".jupyter").mkdir(parents=True)
    (home / ".jupyter" / "nbgrader_config.py").write_text(f"c = get_config()\nc.Exchange.root = {str(exchange)!r}\n")
    env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHONPATH", "JUPYTER_CONFIG_DIR")}
    return {**env, "HOME": str(home), "USER": name, "LOGNAME": name}


def ordinary_user():
    """``tests/grader/ordinary_user.py`` (real accounts, run as them), loaded by its path."""
    spec = importlib.util.spec_from_file_location("ordinary_user", REPO / "tests" / "grader" / "ordinary_user.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def solution(problem: str, name: str) -> str:
    return (REPO / "solutions" / problem / name).read_text().split('\nif __name__ == "__main__":')[0] + "\n"


@pytest.fixture
def shared():
    """A folder outside tmp_path (which is 0700) that the students reach, removed even when the test fails."""
    path = Path(tempfile.mkdtemp(prefix="docs-exchange-"))
    path.chmod(0o755)
    yield path
    shutil.rmtree(path, ignore_errors=True)


@pytest.mark.xdist_group("docs-instructor")
def test_instructor_workflow_as_written(tmp_path, shared):
    users = ordinary_user()
    if why := users.can_run():
        pytest.skip(f"the students' fetch and submit need real accounts: {why}")
    readme = (REPO / "assignments" / "README.md").read_text()
    block = sh_blocks(readme, "**Instructor workflow**")[0]
    prelude, steps = block[0], block[1:]
    assert prelude.startswith("cd assignments &&"), prelude
    fetch = backticked(readme, "nbgrader fetch_assignment")
    submit = backticked(readme, "nbgrader submit")
    deadline = backticked(readme, "python -m grader.nbgrader_autograde deadline bowyer-watson-timed")

    root = tmp_path / "course"  # a copy of the course, as an instructor would take it
    shutil.copytree(REPO / "assignments", root / "assignments", symlinks=True,
                    ignore=shutil.ignore_patterns("gradebook.db", "judged.sqlite", "release", "submitted",
                                                  "autograded", "feedback", "grades.csv", ".cache", "__pycache__"))
    (root / ".venv").symlink_to(REPO / ".venv")
    course = root / "assignments"
    exchange = shared / "exchange"
    exchange.mkdir()
    exchange.chmod(0o777)  # the README: it must exist and be writable by everyone
    teacher = account(tmp_path, "teacher", exchange)
    checkout_db = REPO / "assignments" / "gradebook.db"
    before = checkout_db.stat().st_mtime_ns if checkout_db.exists() else None

    def run(line: str) -> subprocess.CompletedProcess:
        return ok(bash(line, root, teacher, prelude), line)

    klass = {"docs-bob": Student("docs-bob", solution("delaunay", "accepted_walk.py")),
             # wrong when its first points are collinear (85 of 100); CI time: judged in 3 CPU-s, where
             # wrong_epsilon.py, also partly right, takes 13 (autograde and the judge below each judge it)
             "docs-cy": Student("docs-cy", solution("delaunay", "wrong_prefix_collinear.py"))}
    right, wrong = klass
    checked = []
    for line in steps:
        out = run(line)
        if "db student add" in line:
            name = line.split("add")[1].split()[0]
            # the gradebook's roster (read directly: ``nbgrader db student list`` is 4 CPU-s of start-up)
            assert (name,) in sqlite3.connect(course / "gradebook.db").execute("SELECT id FROM student").fetchall()
        elif "generate_assignment" in line:
            released = nbformat.read(course / "release" / "delaunay" / "delaunay.ipynb", 4)
            assert "raise NotImplementedError()" in "".join(c.source for c in released.cells)
        elif "release_assignment" in line:
            assert (exchange / COURSE_ID / "outbound" / "delaunay" / "delaunay.ipynb").is_file()
            for s in klass.values():  # each student, in their own home, as the README tells them
                pw = users.ensure_user(s.name)
                home = Path(pw.pw_dir)
                shutil.rmtree(home / "delaunay", ignore_errors=True)  # an earlier run's fetch
                (home / ".jupyter").mkdir(exist_ok=True)
                (home / ".jupyter" / "nbgrader_config.py").write_text(
                    f"c = get_config()\nc.Exchange.root = {str(exchange)!r}\n")
                os.chown(home / ".jupyter", pw.pw_uid, pw.pw_gid)
                env = {"HOME": str(home), "PATH": f"{REPO / '.venv' / 'bin'}:/usr/local/bin:/usr/bin:/bin"}
                for cmd in (fetch, submit):
                    if cmd == submit:  # the student's code in the first solution cell
                        mine = home / "delaunay" / "delaunay.ipynb"
                        nbformat.write(student_notebook(nbformat.read(mine, 4), s), str(mine))
                    ok(users.run_as_user(["bash", "-c", f"set -e; cd {home}; {cmd}"], env=env, user=s.name,
                                         timeout=600), cmd)
            inbound = sorted(p.name.split("+")[0] for p in (exchange / COURSE_ID / "inbound").iterdir())
            assert inbound == sorted(klass)
        elif "nbgrader collect" in line:
            assert sorted(p.name for p in (course / "submitted").iterdir()) == sorted(klass)
        elif "nbgrader autograde" in line:
            scores = gradebook_scores(course, "delaunay")
            for name in klass:  # the gradebook says what the judge says, run from the copy as the README's CLI
                # no counterexample search (10 s for the wrong one): the score is what is compared
                judged = json.loads(bash(f"python -m grader judge delaunay submitted/{name}/delaunay/delaunay.ipynb "
                                         "--json --counterexample-seconds 0 || true", root, teacher, prelude).stdout)
                assert scores[name]["score"] == judged["score"], (name, scores[name], judged["verdict"], judged["tests"][0]["message"])
            assert scores[right]["score"] == 100 and 0 < scores[wrong]["score"] < 100, scores
            assert scores["ada"]["score"] == 0  # on the roster, submitted nothing
        elif "generate_feedback" in line:
            for name in klass:
                page = (course / "feedback" / name / "delaunay" / "delaunay.html").read_text(encoding="utf-8")
                assert f"{scores[name]['score']:g}" in page
                assert "≤" in page and "\\le" not in page  # the statement's maths as text: no MathJax offline
        elif "nbgrader export" in line:
            rows = {r["student_id"]: float(r["score"]) for r in csv.DictReader(open(course / "grades.csv"))
                    if r["assignment"] == "delaunay"}
            assert rows == {"ada": 0.0, right: 100.0, wrong: scores[wrong]["score"]}, rows
        elif "grade delaunay submitted --nbgrader" in line:
            assert (course / "judged.sqlite").is_file()
            for name in klass:
                assert re.search(rf"\b{name}\b", out.stdout), out.stdout[-2000:]
            assert gradebook_scores(course, "delaunay") == scores  # the parallel path writes the same grades
        else:
            pytest.fail(f"the README's step {line!r} has no check here: add one")
        checked.append(line)
    assert len(checked) == len(steps) >= 8

    # the timed exam's due date, set from the copy, lands in the copy's gradebook
    run(deadline)
    due = sqlite3.connect(course / "gradebook.db").execute(
        "SELECT duedate FROM assignment WHERE name = 'bowyer-watson-timed'").fetchone()
    assert due and due[0], "the copy's gradebook has no due date for the timed exam"
    after = checkout_db.stat().st_mtime_ns if checkout_db.exists() else None
    assert after == before, "a command run in the copy wrote the checkout's own gradebook"


def seed_numba_cache(edition: Path, checkout: Path = REPO) -> int:
    """Copy the checkout's compiled numba code (``__pycache__/*.nbi``, ``*.nbc`` and the
    ``*.deps.sha1`` stamps of ``reference_impl._jitcache``) beside the same sources in ``edition``;
    return the files copied.

    CI time: the edition's ``reference_impl warm`` then loads instead of compiling every kernel
    again (a minute of two CPUs). numba uses a cached function only when its source file's stamp
    (modification time and size: the edition is written with ``shutil.copytree``, which keeps
    them) and numba's version match, and compiles anything else, so a changed source in the
    edition is still compiled and run. Every kernel's cold compile stays in each CI run: ``make test``
    warms the fresh clone's empty cache first, and the hub's install compiles its venv's kernels.
    """
    copied = 0
    for f in sorted((checkout / "reference_impl").rglob("__pycache__/*")):
        if f.suffix in (".nbi", ".nbc") or f.name.endswith(".deps.sha1"):
            dest = edition / f.relative_to(checkout)
            if dest.parent.parent.is_dir():  # the edition has the sources' folder
                dest.parent.mkdir(exist_ok=True)
                shutil.copy2(f, dest)
                copied += 1
    return copied


@pytest.mark.xdist_group("docs-student")
def test_student_edition_readme_as_written(tmp_path):
    out = tmp_path / "student"
    r = subprocess.run([sys.executable, "-m", "grader.student_edition", str(out)], cwd=tmp_path,
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0 and r.stdout.strip() == str(out), r.stderr
    seed_numba_cache(out)
    steps = [ln for block in sh_blocks((out / "README.md").read_text()) for ln in block]
    env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHONPATH", "JUPYTER_CONFIG_DIR")}
    env["PATH"] = ":".join(p for p in env["PATH"].split(":") if not p.startswith(str(REPO)))
    env["HOME"] = str(tmp_path / "home")
    python = out / ".venv" / "bin" / "python"
    seen = set()
    for line in steps:
        if "# interactive" in line:  # JupyterLab: its headless equivalent, the lessons run top to bottom
            assert "jupyter lab notebooks" in line
            for lesson in LESSONS:
                run = ok(bash(f".venv/bin/jupyter nbconvert --to notebook --execute --output-dir {tmp_path} "
                              f"notebooks/{lesson}", out, {**env, "COURSE_QUICK": "1"}), lesson)
                nb = nbformat.read(tmp_path / lesson, 4)
                text = "".join(o.get("text", "") for c in nb.cells for o in c.get("outputs", []))
                assert not [o for c in nb.cells for o in c.get("outputs", []) if o.output_type == "error"]
                assert "withheld here" in text, lesson  # the hidden groups are not in the edition
                if lesson.startswith("10"):
                    assert "lesson/ring-12" in text and "verdict WA" in text
            seen.add("lessons")
            continue
        expect = re.search(r"# expect: (\w+)", line)
        run = bash(line, out, env)
        assert run.returncode == (1 if expect and expect.group(1) != "AC" else 0), (line, run.stdout[-2000:],
                                                                                     run.stderr[-3000:])
        if "pip install" in line:
            where = subprocess.run([str(python), "-c", "import grader; print(grader.__file__)"], cwd=tmp_path,
                                   capture_output=True, text=True, env=env).stdout
            assert where.strip() == str(out / "grader" / "__init__.py")
            seen.add("install")
        elif "reference_impl warm" in line:
            assert "done in" in run.stdout
            seen.add("warm")
        elif "grader list" in line:
            rows = {ln.split()[0]: ln.split()[4] for ln in run.stdout.splitlines()[1:]}
            assert rows == {p.id: "100" for p in list_problems()}, rows
            seen.add("list")
        elif "grader judge" in line:
            assert expect and f": {expect.group(1)} " in run.stdout, run.stdout[-1500:]
            seen.add("judge")
    assert seen == {"install", "warm", "list", "lessons", "judge"}, seen
