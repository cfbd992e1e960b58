"""``python -m grader similarity``: a test class with one copied pair (renamed variables, reordered
functions, changed comments; one as a .py file, the other as an nbgrader-collected notebook), a
student who adapted the tutorial's code, three independent accepted solutions from solutions/,
two students who handed in only the starter code; escaping of everything from a submission.

Run: .venv/bin/python -m pytest tests/grader/test_similarity.py -q -n 0
"""
from __future__ import annotations

import csv
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from grader.classroom import similarity as sim
from grader.contest.report import report_name
from grader.classroom.similarity_report import run, show_code

from .conftest import HERE, REPO

FIX = HERE / "fixtures" / "similarity"
INDEPENDENT = {"ada": "delaunay/accepted_walk.py", "bo": "delaunay-3d/accepted_bw3d.py", "cy": "edge-flip/accepted_lawson.py"}


def starter_notebook() -> str:
    """The delaunay notebook as nbgrader releases it (the solution replaced by the stub)."""
    nb = json.loads((REPO / "assignments" / "source" / "delaunay" / "delaunay.ipynb").read_text())
    for c in nb["cells"]:
        if c["metadata"].get("nbgrader", {}).get("solution"):
            c["source"] = "# Define delaunay(points) in this cell.\n# YOUR CODE HERE\nraise NotImplementedError()\n"
    return json.dumps(nb)


def make_class(root: Path) -> Path:
    for student, src in INDEPENDENT.items():
        (root / student).mkdir(parents=True)
        shutil.copy(REPO / "solutions" / src, root / student / "delaunay.py")
    (root / "cy" / "delaunay.py").unlink()  # cy hands in a plain notebook (no nbgrader metadata)
    code = (REPO / "solutions" / INDEPENDENT["cy"]).read_text()
    cells = [{"cell_type": "code", "metadata": {}, "outputs": [], "execution_count": None, "source": part}
             for part in ("%matplotlib inline\n", code)]
    (root / "cy" / "work.ipynb").write_text(json.dumps({"cells": cells, "metadata": {}, "nbformat": 4,
                                                        "nbformat_minor": 5}))
    (root / "dee").mkdir()
    shutil.copy(FIX / "copied_original.py", root / "dee" / "delaunay.py")
    (root / "eve" / "delaunay").mkdir(parents=True)  # nbgrader's collected layout
    shutil.copy(FIX / "copied_renamed.ipynb", root / "eve" / "delaunay" / "delaunay.ipynb")
    (root / "finn").mkdir()
    shutil.copy(FIX / "tutorial_adapted.py", root / "finn" / "delaunay.py")
    for student in ("gus", "hal"):  # handed in the starter notebook unchanged
        (root / student).mkdir()
        (root / student / "delaunay.ipynb").write_text(starter_notebook())
    (root / "ivy").mkdir()  # no submission at all
    return root


@pytest.fixture(scope="module")
def analysis(tmp_path_factory) -> sim.Analysis:
    return sim.analyse("delaunay", make_class(tmp_path_factory.mktemp("class")))


def pair(analysis: sim.Analysis, a: str, b: str) -> sim.Pair:
    return next(p for p in analysis.pairs if {p.a.name, p.b.name} == {a, b})


def test_the_copied_pair_is_flagged_despite_renames_reordering_and_comments(analysis):
    p = pair(analysis, "dee", "eve")
    assert p.flagged and p.score > 0.8
    assert analysis.flagged[0] is p  # the top of the ranking
    # the copy really is disguised: no function name and no comment line of the original survives
    original, copy = (FIX / "copied_original.py").read_text(), p.b.code if p.b.name == "eve" else p.a.code
    assert not {"det3", "ccw", "inside_circle", "super_triangle"} & set(copy.replace("(", " ").split())
    assert [ln for ln in original.splitlines() if ln.strip().startswith("#") and ln.strip() in copy] == []


def test_the_student_who_adapted_the_tutorial_is_flagged_against_it(analysis):
    p = pair(analysis, "finn", "reference: tutorial")
    assert p.flagged and p.b.kind == "reference" and p.score == p.share_a > 0.5
    assert [q for q in analysis.flagged if "finn" in (q.a.name, q.b.name)] == [p]


def test_three_independent_accepted_solutions_are_not_flagged(analysis):
    for a, b in [("ada", "bo"), ("ada", "cy"), ("bo", "cy")]:
        p = pair(analysis, a, b)
        assert not p.flagged and p.score < 0.3, (a, b, p.score)
    assert {n for p in analysis.flagged for n in (p.a.name, p.b.name)} == {"dee", "eve", "finn", "reference: tutorial"}


def test_notebooks_and_py_files_mixed_only_solution_cells_count(analysis):
    docs = {d.name: d for d in analysis.students}
    assert set(docs) == {"ada", "bo", "cy", "dee", "eve", "finn", "gus", "hal"}  # ivy: nothing handed in
    assert docs["eve"].path == "eve/delaunay/delaunay.ipynb" and docs["dee"].path == "dee/delaunay.py"
    assert docs["cy"].path == "cy/work.ipynb" and "def flip_to_delaunay" in docs["cy"].code
    assert "def delaunay(points)" in docs["eve"].code and "check_samples" not in docs["eve"].code


def test_starter_code_is_boilerplate(analysis):
    p = pair(analysis, "gus", "hal")
    assert not p.flagged and p.tokens == 0
    # without the boilerplate the two identical starter notebooks would be one "copy"
    a, b = (sim.fingerprint(sim.Document(n, "student", n, p.a.code)) for n in ("gus", "hal"))
    assert sim.compare(a, b).score == 1.0 and sim.compare(a, b).flagged is False  # too small to flag anyway
    snippet = sim.statement_snippets((REPO / "assignments" / "delaunay" / "statement" / "problem.en.md").read_text())
    assert "1 1\n3 2\n5 1\n4 4" in snippet


def test_starter_notebook_counts_for_nobody_even_around_real_code(tmp_path):
    nb = json.loads((REPO / "assignments" / "source" / "delaunay" / "delaunay.ipynb").read_text())
    shared = "\n".join(f"def helper_{k}(pts):\n    return sorted((p[1], p[0] * {k}) for p in pts if p[0] > {k})\n"
                       for k in range(6))
    boiler = sim.boilerplate_hashes(sim.boilerplate("delaunay") + [shared])
    docs = [sim.fingerprint(sim.Document(n, "student", n, shared + own), boiler)
            for n, own in (("a", "x = 1\n"), ("b", "y = 2\n"))]
    assert sim.compare(*docs).tokens == 0
    assert nb["cells"]  # the source notebook was there to read


def test_report_and_csv(analysis, tmp_path):
    from grader.classroom.similarity_report import write_reports

    index = write_reports(analysis, tmp_path)
    page = index.read_text()
    ranking = page[page.index("highest similarity first"):]
    assert ranking.index(">dee<") < ranking.index(">finn<") < ranking.index(">ada<")
    assert 'href="similarity/pair-1.html"' in page and 'href="similarity/pair-2.html"' in page
    pair_pages = sorted((tmp_path / "similarity").glob("pair-*.html"))
    assert len(pair_pages) == 2
    first = pair_pages[0].read_text()
    assert "<mark>" in first and "dee" in first and "eve" in first and "0.9" in first
    rows = list(csv.DictReader(open(tmp_path / "similarity.csv")))
    assert rows[0]["flagged"] == "yes" and {rows[0]["a"], rows[0]["b"]} == {"dee", "eve"}
    assert len(rows) == 8 * 7 // 2 + 8  # every student pair, every student against the tutorial


def test_everything_from_submissions_is_escaped(tmp_path):
    evil = '<img src=x onerror=alert(1)>&"'
    code = "".join(f"def f{k}(a):\n    s = '</pre><script>alert({k})</script>'\n    return [a * i + {k} for i in range(a)]\n"
                   for k in range(8))
    for name in (evil, "=cmd|' -C calc'!A0"):
        (tmp_path / "class" / name).mkdir(parents=True)
        (tmp_path / "class" / name / "delaunay.py").write_text(code + "\x1b[2J\n")
    out = tmp_path / "out"
    out.mkdir()
    (out / "students").mkdir()
    (out / "students" / report_name(evil)).write_text("grading report")  # as `grade --reports` names it
    a = run("delaunay", tmp_path / "class", out)
    assert len(a.flagged) == 1
    text = (out / "similarity.html").read_text() + (out / "similarity" / "pair-1.html").read_text()
    assert "<script>" not in text and "<img" not in text and "\x1b" not in text
    assert "&lt;img src=x onerror=alert(1)&gt;&amp;&quot;" in text and "\\x1b" in text
    assert f'href="students/{report_name(evil)}"' in text and "%3C" not in report_name(evil)
    assert "'=cmd" in (out / "similarity.csv").read_text()
    assert show_code("a<b>", sim.np.zeros((2, 0), dtype=int)) == "a&lt;b&gt;"


def test_links_are_never_followed_and_references_are_read(tmp_path):
    cls = make_class(tmp_path / "class")
    (cls / "joe").mkdir()
    (cls / "joe" / "delaunay.py").symlink_to(cls / "dee" / "delaunay.py")
    ref = tmp_path / "public-repos" / "someone"
    ref.mkdir(parents=True)
    shutil.copy(REPO / "solutions" / "delaunay-3d" / "accepted_bw3d.py", ref / "bw3d.py")
    a = sim.analyse("delaunay", cls, references=[tmp_path / "public-repos", REPO / "assignments"])
    joe = next(d for d in a.students if d.name == "joe")
    assert joe.code == "" and "symbolic link" in joe.note
    assert not any("joe" in (p.a.name, p.b.name) for p in a.pairs)
    assert pair(a, "bo", "reference: public-repos/someone/bw3d.py").flagged
    assert not any("generators" in r.path or "output_validator" in r.path for r in a.references)  # hidden tests' side


def grader(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "grader", *args], capture_output=True, text=True, cwd=REPO)


def test_cli_similarity_and_exit_codes(tmp_path):
    cls = make_class(tmp_path / "class")
    r = grader("similarity", "delaunay", str(cls), "--reports", str(tmp_path / "r"))
    assert r.returncode == 0, r.stderr
    assert "dee  ~  eve" in r.stdout and "finn  ~  reference: tutorial" in r.stdout and "2 flagged pairs" in r.stdout
    assert (tmp_path / "r" / "similarity.html").is_file()
    for args, words in [(["nope", str(cls)], "unknown problem"), (["delaunay", str(tmp_path / "none")], "does not exist"),
                        (["delaunay", str(cls), "--threshold", "2"], "threshold"),
                        (["delaunay", str(cls), "--reference", str(tmp_path / "none")], "reference folder")]:
        r = grader("similarity", *args, "--reports", str(tmp_path / "r2"))
        assert r.returncode == 2 and words in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr


def test_grade_similarity_writes_the_report_next_to_the_grades(tmp_path):
    """Two students hand in the same code: ``grade --similarity`` judges them, then flags the pair in
    a report linked to their grading reports. CI time: their copy answers at once (an empty list, WA
    on every test), so the judging takes seconds, not the half minute of the exact Fraction
    arithmetic running into the time limit; the similarity of the copied code is the point here,
    and ``grade``'s scores of real solutions are tested in test_grade.py."""
    source = (FIX / "copied_original.py").read_text()
    assert source.count("def delaunay(points):\n") == 1
    source = source.replace("def delaunay(points):\n", "def delaunay(points):\n    return []\n")
    for student in ("kim", "lou"):
        (tmp_path / "class" / student).mkdir(parents=True)
        (tmp_path / "class" / student / "delaunay.py").write_text(source)
    r = grader("grade", "delaunay", str(tmp_path / "class"), "--db", str(tmp_path / "db.sqlite"), "--quiet",
               "--reports", str(tmp_path / "reports"), "--similarity")
    assert r.returncode == 0, r.stderr
    assert "kim  ~  lou" in r.stderr and "kim" in r.stdout
    assert re.search(r"^kim +WA +0/100", r.stdout, re.M) and re.search(r"^lou +WA +0/100", r.stdout, re.M), r.stdout
    page = (tmp_path / "reports" / "similarity.html").read_text()
    assert f'href="students/{report_name("kim")}"' in page  # linked to the grading report


def test_scores_are_the_same_in_every_run(tmp_path):
    """copydetect's own k-gram hash is Python's hash() (salted per process); ours is not."""
    cls = make_class(tmp_path / "class")
    for out in ("r1", "r2"):
        assert grader("similarity", "delaunay", str(cls), "--reports", str(tmp_path / out)).returncode == 0
    assert (tmp_path / "r1" / "similarity.csv").read_text() == (tmp_path / "r2" / "similarity.csv").read_text()


def test_short_empty_and_odd_code_compares(tmp_path):
    for code in ("", "x = 1", "é" * 40 + "\n", 'def f():\n    return "\\ud800"\n' * 5):
        d = sim.fingerprint(sim.Document("a", "student", "a.py", code))
        p = sim.compare(d, d)
        assert 0 <= p.score <= 1 and not (p.flagged and p.tokens < sim.MIN_TOKENS)


def test_nothing_from_the_hidden_tests_is_read(tmp_path, monkeypatch):
    from grader.problems import Problem
    from grader.classroom.similarity_report import write_reports

    def refuse(*args, **kwargs):
        raise AssertionError("the similarity report read the problem's tests")

    for name in ("tests", "read_answer", "digest"):
        monkeypatch.setattr(Problem, name, refuse)
    a = sim.analyse("delaunay", make_class(tmp_path / "class"))
    write_reports(a, tmp_path / "out")
    assert len(a.flagged) == 2
