"""The hostile corpus: every file in tests/grader/hostile/ states its expected verdict on its
first line (``# expect: VERDICT``). Each must get exactly that verdict (never JE), leave no
process behind, and leave the checkout unchanged.  In the corpus, the path ``/work/main``
stands for "the checkout under test", ``/home/instructor`` for a directory in the grading
account's home (a gradebook, a class folder: :func:`instructor_home`) and ``/grader-cache`` for
the grader's test cache: they are replaced by the real paths before judging, so the attacks aim
at this checkout and this account wherever they are. tests/grader/test_jail_user.py runs this
file as an ordinary user too.

Run: .venv/bin/python -m pytest tests/grader/test_hostile.py -q
"""
from __future__ import annotations

import hashlib
import json
import os
import re
import resource
import shutil
import sqlite3
from pathlib import Path

import pytest

from grader.jail import refuses_processes
from grader.problems import cache_root
from grader.classroom.store import ResultStore
from grader.judging.verdicts import Verdict, format_table

from .conftest import HERE, sandbox_processes, tree_digest

CORPUS = sorted((HERE / "hostile").glob("*.py"))
WATCHED = ("grader", "assignments", "solutions", "tests/grader")


#: A header line giving the verdict where the jail refuses new processes (an ordinary user's jail).
NO_PROCESSES = "# expect when the jail refuses processes: "


def expected(path: Path) -> str:
    """The verdict the file's header promises for the jail this run judges in."""
    lines = path.read_text().splitlines()
    assert lines[0].startswith("# expect: "), f"{path.name} must start with '# expect: VERDICT'"
    other = [ln for ln in lines[1:6] if ln.startswith(NO_PROCESSES)]
    if other and refuses_processes():
        return other[0][len(NO_PROCESSES):].strip()
    return lines[0].split(":", 1)[1].strip()


@pytest.fixture(scope="module")
def instructor_home():
    """Files of the grading account that submissions attack (:func:`instructor_files`), in its
    home; removed afterwards."""
    top = instructor_files(Path.home() / f".grader-hostile-{os.getpid()}")
    yield top
    shutil.rmtree(top, ignore_errors=True)


def instructor_files(top: Path) -> Path:
    """A gradebook (text and nbgrader's sqlite) and a classmate's submission under ``top``."""
    (top / "submitted" / "bob").mkdir(parents=True)
    (top / "gradebook.txt").write_text("alice 10\nmallory 0\n")
    (top / "submitted" / "bob" / "delaunay.py").write_text("def delaunay(points):\n    return []\n")
    db = sqlite3.connect(top / "gradebook.db")
    db.execute("CREATE TABLE grade (student TEXT, score REAL)")
    db.execute("INSERT INTO grade VALUES ('mallory', 0)")
    db.commit()
    db.close()
    return top


def _files_digest(*tops: Path) -> str:
    h = hashlib.sha256()
    for top in tops:
        for p in sorted(top.rglob("*")) if top.is_dir() else []:
            h.update(str(p).encode() + (p.read_bytes() if p.is_file() else b""))
    return h.hexdigest()


@pytest.fixture(scope="module")
def checkout_guard(instructor_home):
    before = tree_digest(*WATCHED)
    theirs = _files_digest(instructor_home, cache_root())
    yield
    assert tree_digest(*WATCHED) == before, "a hostile submission changed the checkout"
    assert _files_digest(instructor_home, cache_root()) == theirs, "a hostile submission changed the account's files"
    assert not Path("/tmp/pwned-by-student").exists()
    assert not (HERE.parent.parent / "pwned.txt").exists()


def aimed_at_this_checkout(path: Path, tmp_path: Path, home: Path | None = None) -> Path:
    """``path`` with the corpus's stand-in paths replaced by the real ones (see the docstring)."""
    text = original = path.read_text()
    for stand_in, real in (("/work/main", HERE.parent.parent), ("/home/instructor", home), ("/grader-cache", cache_root())):
        if real is not None:
            text = text.replace(stand_in, str(real))
    if text == original:
        return path
    out = tmp_path / path.name
    out.write_text(text)
    return out


@pytest.mark.parametrize("path", CORPUS, ids=[p.stem for p in CORPUS])
def test_hostile_submission_gets_its_verdict(path: Path, tiny_judge, checkout_guard, instructor_home, tmp_path):
    result = tiny_judge.judge_path(aimed_at_this_checkout(path, tmp_path, instructor_home))
    verdicts = [t.verdict for t in result.tests]
    assert Verdict.JE not in verdicts, [t.message for t in result.tests if t.verdict == Verdict.JE]
    assert result.verdict == expected(path), [(t.name, str(t.verdict), t.message[:200]) for t in result.tests]
    assert sandbox_processes() == [], "processes of the sandbox uid survived the judging"
    assert os.getpid() > 0  # the grader is alive
    assert result.judge_time_s < 180, "one hostile submission held the judge for minutes"
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss < 3 << 20, "the grader grew over 3 GB"
    shows_safely(result)


CONTROL = re.compile(r"[\x00-\x09\x0b-\x1f\x7f-\x9f\ud800-\udfff]")


def shows_safely(result) -> None:
    """Whatever the submission said, the judge's outputs are valid UTF-8 without control characters
    (no ANSI escapes; newlines only where the judge put them) and the store accepts them."""
    table = format_table(result)
    table.encode("utf-8")
    assert not CONTROL.search(table), repr(CONTROL.search(table))
    json.dumps(result.to_json(), ensure_ascii=False).encode("utf-8")
    store = ResultStore(":memory:")
    store.begin("student", result.problem, result.submission, "sha", 0.0)
    for t in result.tests:
        assert not CONTROL.search(t.message), repr(t.message[:200])
        store.add_test("student", result.problem, "sha", t)
    store.finish("student", result.problem, "sha", result)
    assert store.is_done("student", result.problem, "sha")
    store.close()


def test_student_text_is_shown_escaped(tiny_judge):
    r = tiny_judge.judge_path(HERE / "hostile" / "ansi_message.py")
    assert "\\x1b[2J" in r.tests[0].message and "\\nsample/1  AC" in r.tests[0].message
    r = tiny_judge.judge_path(HERE / "hostile" / "surrogate_message.py")
    assert "\\ud800 broken \\udfff" in r.tests[0].message


def test_messages_help_the_student(tiny_judge):
    r = tiny_judge.judge_path(HERE / "hostile" / "missing_entry.py")
    assert "delaunay_triangulation" in r.tests[0].message
    r = tiny_judge.judge_path(HERE / "hostile" / "import_scipy_spatial.py")
    assert "scipy.spatial" in r.tests[0].message
    r = tiny_judge.judge_path(HERE / "hostile" / "huge_index.py")
    assert "outside" in r.tests[0].message and r.tests[0].input_preview.startswith("4\n")


def test_files_in_the_jail_count_as_memory(tiny_judge):
    """Issue "Hardening round 4", item 2: 300 MB of files (256 MB allowed) kept in /dev/shm or
    /tmp is MLE saying where (a program too: it waits until they are measured), with the files
    counted in the memory reported (as an ordinary account bubblewrap's unsized /dev/shm held
    3 GiB per test: WA, 17 MB reported); /dev and the jail's root are read-only. Nothing is left
    on the host."""
    limit = tiny_judge.problem.memory_mb
    for name, where, size in (("files_in_dev_shm", "/dev/shm", 8), ("files_in_tmp", "/tmp", 32),
                              ("files_in_dev_shm_stdio", "/dev/shm", 8)):
        t = tiny_judge.judge_path(HERE / "hostile" / f"{name}.py").tests[0]
        assert t.verdict == "MLE" and f"kept {size} MB in {where}," in t.message, (t.verdict, t.message)
        assert size <= t.memory_mb <= limit, t.memory_mb
    t = tiny_judge.judge_path(HERE / "hostile" / "files_in_dev_and_root.py").tests[0]
    assert t.verdict == "RE" and "not writable: /dev/hog-: errno" in t.message, (t.verdict, t.message)
    assert t.memory_mb < limit
    assert not [p for d in ("/dev/shm", "/tmp", "/") for p in Path(d).glob("hog-*")]


def test_a_program_is_not_charged_the_graders_memory(tiny_judge, tmp_path):
    """A program's (stdio) memory is its sandbox's: ``ru_maxrss`` of the process the grader starts
    keeps the grader's own RSS from before ``exec`` (after compiling numba, 249 MB was reported for
    files_in_dev_shm_stdio, a program of 17 MB)."""
    ballast = b"\x01" * (200 << 20)  # the grader holds 200 MB when it forks
    sub = tmp_path / "echo.py"
    sub.write_text("import sys\nsys.stdin.read()\nprint(0)\n")
    t = tiny_judge.judge_path(sub).tests[0]
    assert len(ballast) and 0 < t.memory_mb < 100, t.memory_mb
