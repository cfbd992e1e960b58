"""Statements state the limits and points generated from problem.yaml/course.yaml (so they cannot
drift), and the committed user-facing text uses words a reader of this repository has.

Every problem found under assignments/ is checked, including ones added later.

Run: .venv/bin/python -m pytest tests/grader/test_statements.py -q
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys

import pytest

from grader.judging.languages import CPP
from grader.problems import statements
from grader.problems import ALWAYS_FORBIDDEN, REPO, Problem, list_problems

PROBLEMS = list_problems(REPO / "assignments")


def test_every_statement_is_up_to_date():
    """`python -m grader statements --check` over every problem: markers present, block current."""
    r = subprocess.run([sys.executable, "-m", "grader", "statements", "--check"], cwd=REPO, capture_output=True,
                       text=True, env={**os.environ, "GRADER_PROBLEMS": str(REPO / "assignments")})
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.parametrize("problem", PROBLEMS, ids=[p.id for p in PROBLEMS])
def test_block_states_the_limits_and_every_group(problem: Problem):
    text = statements.statement_path(problem).read_text()
    block = text.split(statements.BEGIN)[1].split(statements.END)[0]
    assert f"{problem.time_limit:g} s of CPU time per test" in block
    assert f"{problem.memory_mb} MiB" in block and f"{problem.output_mb} MiB" in block
    for g in problem.groups:
        assert re.search(rf"^\| {re.escape(g.name)} \| {g.points} \| \d+ \|", block, re.M), (g.name, block)
    assert f"({sum(g.points for g in problem.groups)} points in all)" in block
    # the C++ reader's part: both limits (course.yaml time_limits), the judge's own compile command
    assert (f"{problem.time_limit_for('python'):g} s of CPU time per test for Python, "
            f"{problem.time_limit_for('cpp'):g} s for C++") in block
    assert "## Submitting in C++" in block and f"`{' '.join(CPP.compile_command('main.cpp', 'main'))}`" in block
    assert ("any algorithm" in block) == bool(set(problem.forbidden) - set(ALWAYS_FORBIDDEN)), problem.id


def test_cpp_section_is_shared_and_follows_the_language_entry(monkeypatch):
    """One text for every problem (apart from the paragraph on forbidden libraries), and the flags
    are read from ``languages.CPP``: a changed entry changes every statement's block."""
    import dataclasses

    from grader.judging import languages

    sections = {tuple(statements.cpp_section(p)) for p in PROBLEMS}
    assert len(sections) <= 2
    shortest = min(sections, key=len)
    assert all(s[:len(shortest)] == shortest for s in sections)
    other = dataclasses.replace(languages.CPP, compile=("clang++", "-O3", "-o", "{binary}", "{source}"))
    monkeypatch.setattr(statements, "CPP", other)
    assert "`clang++ -O3 -o main main.cpp`" in "\n".join(statements.cpp_section(PROBLEMS[0]))


def _copy(tmp_path, pid: str = "delaunay"):
    dest = tmp_path / pid
    shutil.copytree(REPO / "assignments" / pid, dest, symlinks=True)
    return Problem.load(dest)


def test_check_finds_stale_and_missing_markers_and_rewrite_fixes(tmp_path, monkeypatch):
    p = _copy(tmp_path)
    monkeypatch.setenv("GRADER_PROBLEMS", str(tmp_path))
    assert statements.update_statements(check=True) == []
    yaml_file = p.path / "problem.yaml"
    yaml_file.write_text(yaml_file.read_text().replace("time_limit: 6", "time_limit: 7"))
    stale = statements.update_statements(check=True)
    assert len(stale) == 1 and "stale" in stale[0][1]
    assert statements.update_statements() and statements.update_statements(check=True) == []
    assert "7 s of CPU time per test for Python, 7 s for C++" in statements.statement_path(p).read_text()
    course = p.path / "course.yaml"
    course.write_text(course.read_text() + "time_limits: {cpp: 1.5}\n")
    assert statements.update_statements(check=True) and statements.update_statements()
    assert "7 s of CPU time per test for Python, 1.5 s for C++" in statements.statement_path(p).read_text()
    path = statements.statement_path(p)
    path.write_text(path.read_text().replace(statements.END, ""))
    r = subprocess.run([sys.executable, "-m", "grader", "statements", "--check", "delaunay"], cwd=REPO,
                       capture_output=True, text=True, env={**os.environ, "GRADER_PROBLEMS": str(tmp_path)})
    assert r.returncode == 1 and "lacks the marker lines" in r.stderr


def test_case_sizes():
    assert statements.case_size({"kind": "grid", "w": 3, "h": 4}) == 12
    assert statements.case_size({"kind": "duplicates", "n": 40, "repeats": 30}) == 70
    assert statements.case_size({"kind": "points", "points": [[0, 0], [1, 1]]}) == 2
    assert statements.case_size({"kind": "cocircular", "r": 5}) is None


USER_FACING = ("grader", "reference_impl", "assignments", "solutions", "tests", "benchmarks", "notebooks")
CITATION = re.compile("SPEC" + r"\s*(§|section\b|:)")  # written so that this file does not match itself


def _committed_text_files() -> list:
    try:
        names = subprocess.run(["git", "ls-files", *USER_FACING, "README.md"], cwd=REPO, capture_output=True,
                               text=True, check=True).stdout.split()
        files = [REPO / n for n in names]
    except (OSError, subprocess.CalledProcessError):  # not a git checkout: every file on disk
        files = [REPO / "README.md", *(f for d in USER_FACING for f in (REPO / d).rglob("*"))]
    return [f for f in files if f.is_file() and f.suffix in (".py", ".md", ".yaml", ".yml", ".ipynb", ".txt")]


def test_no_citations_of_a_document_the_reader_does_not_have():
    """READMEs, statements, docstrings and notebooks say what they mean in this repository's own
    words instead of citing the course's internal specification by section."""
    hits = []
    for f in _committed_text_files():
        for k, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
            if CITATION.search(line):
                hits.append(f"{f.relative_to(REPO)}:{k}: {line.strip()[:100]}")
    assert not hits, "\n".join(hits)
