"""``judge_file`` called from a Jupyter kernel (nbclient) judges in the jail and gives the right
verdicts: what lesson 00's in-kernel judge and ``%check_samples`` do.

The kernel is a child of this test with the fixture problems on ``GRADER_PROBLEMS``; it judges an
accepted, a wrong and a crashing submission, and prints the verdicts and the jail as JSON.
"""
from __future__ import annotations

import json

import nbformat
import pytest

from grader.jail.sandbox import jail_kind

from .conftest import HERE, REPO

CELL = """
import json
from grader import judge_file
from grader.jail.sandbox import mechanism
out = {{name: judge_file("tiny-delaunay", path).verdict for name, path in {files!r}.items()}}
print(json.dumps({{"verdicts": out, "jail": mechanism()}}))
"""


@pytest.mark.skipif(jail_kind() == "none", reason="no kernel jail for this account (bubblewrap or user namespaces"
                    " missing; python -m grader.sandbox says which): judge_file would refuse")
def test_judge_file_from_a_kernel_gives_the_right_verdicts(tmp_path, monkeypatch):
    from nbclient import NotebookClient

    wrong = tmp_path / "wrong.py"
    wrong.write_text("def delaunay(points):\n    return [[0, 1, 2]] * 3\n")
    crash = tmp_path / "crash.py"
    crash.write_text("def delaunay(points):\n    raise ValueError('no')\n")
    files = {"accepted": str(REPO / "solutions/delaunay/accepted_walk.py"), "wrong": str(wrong), "crash": str(crash)}
    monkeypatch.setenv("GRADER_PROBLEMS", str(HERE / "fixtures"))
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(CELL.format(files=files))])
    NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}).execute()
    text = "".join(o.get("text", "") for o in nb.cells[0].outputs if o.get("output_type") == "stream")
    got = json.loads(text.strip().splitlines()[-1])
    assert got["verdicts"] == {"accepted": "AC", "wrong": "WA", "crash": "RE"}, got
    assert got["jail"].startswith(("bwrap", "namespaces")), got
