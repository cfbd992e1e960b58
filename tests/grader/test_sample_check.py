"""``%check_samples PROBLEM [FILE]``: the notebooks' sample check on the notebook itself or on another
file the student names (a ``.py`` program, a ``.cpp`` file once the judge takes C++). The path
through the magic is the same for every language: the file goes to the judge, which decides.

Run: .venv/bin/python -m pytest tests/grader/test_sample_check.py -q
"""
from __future__ import annotations

import shutil

import pytest

from grader.contest import sample_check
from grader.judging.languages import accepted_files
from grader.problems import REPO

SOLUTIONS = REPO / "solutions" / "delaunay"


def test_parse_line(tmp_path):
    (tmp_path / "mine.cpp").write_text("int main() {}\n")
    assert sample_check.parse_line("delaunay", tmp_path) == ("delaunay", None)
    assert sample_check.parse_line("delaunay mine.cpp", tmp_path) == ("delaunay", tmp_path / "mine.cpp")
    with pytest.raises(ValueError, match="usage: %check_samples PROBLEM_ID"):
        sample_check.parse_line("", tmp_path)
    with pytest.raises(ValueError, match="usage"):
        sample_check.parse_line("delaunay a.cpp b.cpp", tmp_path)
    with pytest.raises(ValueError, match="problem 'delaunay': no file other.cpp"):
        sample_check.parse_line("delaunay other.cpp", tmp_path)


def _magic(monkeypatch, tmp_path, line: str) -> str:
    """Run the magic's function outside IPython (no kernel: no function to draw) and return its HTML."""
    shown = []
    import IPython.display

    # display(obj, display_id=True) shows the verdicts first; without a kernel it returns None, so
    # a picture, if any, comes as a second display holding the verdicts too
    monkeypatch.setattr(IPython.display, "display", lambda obj, **kw: shown.append(obj.data))
    monkeypatch.chdir(tmp_path)
    sample_check.check_samples(line)
    assert 1 <= len(shown) <= 2 and all(shown[0] in later for later in shown[1:])
    return shown[0]


def test_a_named_program_is_checked_on_the_samples(monkeypatch, tmp_path):
    shutil.copy(SOLUTIONS / "accepted_walk.py", tmp_path / "mine.py")
    html = _magic(monkeypatch, tmp_path, "delaunay mine.py")
    assert "judged mine.py" in html and "samples: <b>AC</b>" in html and "sample/1-tutorial" in html


def test_a_file_the_judge_does_not_take_gets_a_verdict(tmp_path):
    """A kind of file outside the judge's languages is CE naming what it takes, never a crash."""
    (tmp_path / "mine.rs").write_text("fn main() {}\n")
    result, _problem = sample_check.judge_samples("delaunay", tmp_path / "mine.rs")
    assert result.verdict == "CE" and accepted_files() in result.tests[0].message


def test_cpp_on_the_samples(monkeypatch, tmp_path):
    shutil.copy(SOLUTIONS / "accepted.cpp", tmp_path / "mine.cpp")
    html = _magic(monkeypatch, tmp_path, "delaunay mine.cpp")
    assert "judged mine.cpp" in html and "samples: <b>AC</b>" in html
    shutil.copy(SOLUTIONS / "compile_error.cpp", tmp_path / "broken.cpp")
    result, _problem = sample_check.judge_samples("delaunay", tmp_path / "broken.cpp")
    assert result.verdict == "CE"
