"""Submissions as .py or .ipynb, function and stdio mode, reports and the judge CLI.

Run: .venv/bin/python -m pytest tests/grader/test_submissions.py -q
"""
from __future__ import annotations

import json
import os
import subprocess
import sys

import nbformat
import pytest

from grader.contest.report import render
from grader.judging.submissions import Submission

from .conftest import REPO

ACCEPTED = (REPO / "solutions" / "delaunay" / "accepted_walk.py").read_text()


def test_notebook_code_cells_without_magics(tmp_path, tiny_judge):
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_markdown_cell("# my solution"),
                nbformat.v4.new_code_cell("%matplotlib inline\n!pip install nothing\nimport math"),
                nbformat.v4.new_code_cell("%%time\nthis is not python"),
                nbformat.v4.new_code_cell(ACCEPTED.replace('if __name__ == "__main__":\n    main()', ""))]
    path = tmp_path / "sol.ipynb"
    nbformat.write(nb, path)
    assert "%matplotlib" not in Submission.from_path(path).source
    result = tiny_judge.judge_path(path)
    assert result.verdict == "AC" and result.mode == "function"


def test_stdio_mode_program(tmp_path, tiny_judge):
    path = tmp_path / "prog.py"
    path.write_text(ACCEPTED.replace("def delaunay(", "def triangulate(").replace("delaunay(pts)", "triangulate(pts)"))
    result = tiny_judge.judge_path(path)
    assert result.mode == "stdio"
    assert result.verdict == "AC", [t.message for t in result.tests]


def test_numpy_results_are_converted(tmp_path, tiny_judge):
    path = tmp_path / "np.py"
    path.write_text(ACCEPTED + "\nimport numpy as np\n_inner = delaunay\n"
                    "def delaunay(points):\n    return np.array(_inner(np.asarray(points).tolist()), dtype=np.int64).reshape(-1, 3)\n")
    assert tiny_judge.judge_path(path).verdict == "AC"


def test_wrong_file_type_is_ce(tmp_path, tiny_judge):
    path = tmp_path / "sol.txt"
    path.write_text("def delaunay(p): return []")
    assert tiny_judge.judge_path(path).verdict == "CE"


def test_html_report_shows_failing_picture(tmp_path, tiny_judge):
    result = tiny_judge.judge_path(REPO / "solutions" / "delaunay" / "wrong_tutorial.py")
    assert result.verdict == "WA"
    html = render(result, tiny_judge.problem, student="ada")
    assert "data:image/png;base64" in html and "WA" in html and "ada" in html


def test_cli_judge_json_fields(tmp_path):
    out = subprocess.run([sys.executable, "-m", "grader", "judge", "bowyer-watson-timed",
                          str(REPO / "solutions" / "bowyer-watson-timed" / "accepted_scan.py"), "--json"],
                         capture_output=True, text=True, cwd=REPO, check=True)
    data = json.loads(out.stdout)
    assert {"problem", "verdict", "score", "max_score", "tests"} <= set(data)
    assert data["verdict"] == "AC" and data["score"] == data["max_score"] == 100
    assert {"name", "group", "verdict", "time_s"} <= set(data["tests"][0])


def test_cli_table_and_errors():
    out = subprocess.run([sys.executable, "-m", "grader", "list"], capture_output=True, text=True, cwd=REPO)
    assert "delaunay" in out.stdout and "bowyer-watson-timed" in out.stdout
    bad = subprocess.run([sys.executable, "-m", "grader", "judge", "nope", "x.py"], capture_output=True, text=True, cwd=REPO)
    assert bad.returncode == 2 and "error:" in bad.stderr


def test_reader_refuses_links_special_and_oversize_files(tmp_path):
    from grader.judging.submissions import SubmissionError, read_submission_bytes

    real = tmp_path / "real.py"
    real.write_text("x = 1\n")
    (tmp_path / "link.py").symlink_to(real)
    os.mkfifo(tmp_path / "fifo.py")  # opening it must not block
    with open(tmp_path / "sparse.py", "wb") as f:
        f.truncate(2 << 30)
    (tmp_path / "d").symlink_to(tmp_path)
    cases = {"link.py": "symbolic link", "fifo.py": "not a regular file", "sparse.py": "larger than",
             "d/real.py": "folder of real.py is a symbolic link", "missing.py": "cannot read"}
    for name, expected in cases.items():
        with pytest.raises(SubmissionError, match=expected):
            read_submission_bytes(tmp_path / name)
    assert read_submission_bytes(tmp_path / "link.py", follow_links=True) == b"x = 1\n"


@pytest.mark.parametrize("text,expected", [
    ("[" * 100_000 + "]" * 100_000, "nested too deeply"),
    ('{"cells": [{"cell_type": "code", "source": [1, 2]}]}', "source is not text"),
    ('{"cells": [{"cell_type": "code", "source": {"a": 1}}]}', "source is not text"),
    ('{"cells": 5}', "no list of cells"),
    ("not json at all", "not a valid notebook"),
    ('{"cells": [{"cell_type": "code", "source": "x = \\"\\ud800\\""}], "x": "\\u001b[2J"}', None),
])
def test_malformed_notebooks_are_ce_not_tracebacks(tmp_path, tiny_judge, text, expected):
    path = tmp_path / "nb.ipynb"
    path.write_text(text, errors="surrogatepass")
    result = tiny_judge.judge_path(path)
    assert result.verdict in ("CE", "WA", "RE", "PE"), result.verdict
    if expected:
        assert result.verdict == "CE" and expected in result.tests[0].message
