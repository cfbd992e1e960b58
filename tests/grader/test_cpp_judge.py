"""C++ submissions through every judge command: ``judge`` (table, ``--json``, ``--report``),
``grade`` on a class mixing Python and C++, ``stress`` on a ``.cpp``, ``timed submit`` with a
``.cpp``, ``similarity`` (C++ compared with C++ only), and the language rules underneath.

Cheap on purpose: the tiny closest-pair fixture (tests/grader/fixtures/tiny-closest-pair, five
tests) and small sources that include only ``<cstdio>``; the real problems only where a command
needs them (``timed``: bowyer-watson-timed with a program failing at once; ``stress``: closest-pair).

Run: .venv/bin/python -m pytest tests/grader/test_cpp_judge.py -q -p no:cacheprovider
"""
from __future__ import annotations

import csv
import json
import os
import subprocess
import sys


import grader.contest.judge as judge_module
from grader.classroom.similarity import analyse
from grader.contest.stress import stress
from grader.judging.languages import CPP, PYTHON, SUFFIXES, accepted_files, language_of
from grader.judging.submissions import Submission

from .conftest import HERE, REPO

FIXTURES = str(HERE / "fixtures")
#: A correct closest pair for small inputs (brute force on exact long doubles of small integers).
BRUTE_CPP = r"""#include <cstdio>
int main() {
    int n; if (std::scanf("%d", &n) != 1) return 1;
    static double x[5000], y[5000];
    for (int i = 0; i < n; ++i) std::scanf("%lf %lf", &x[i], &y[i]);
    int bi = 0, bj = 1; long double best = -1;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            long double dx = (long double)x[i] - x[j], dy = (long double)y[i] - y[j], d = dx * dx + dy * dy;
            if (best < 0 || d < best) { best = d; bi = i; bj = j; }
        }
    std::printf("%d %d\n", bi, bj);
    return 0;
}
"""
#: Always the first two points: wrong as soon as they are not a closest pair.
FIRST_TWO_CPP = "#include <cstdio>\nint main() { std::printf(\"0 1\\n\"); return 0; }\n"
BRUTE_PY = """def closest_pair(points):
    best = None
    for i in range(len(points)):
        for j in range(i + 1, len(points)):
            d = (points[i][0] - points[j][0]) ** 2 + (points[i][1] - points[j][1]) ** 2
            if best is None or d < best[0]:
                best = (d, i, j)
    return [best[1], best[2]]
"""


def grader(*args: str, problems: str | None = FIXTURES, cwd=REPO) -> subprocess.CompletedProcess:
    env = {**os.environ, **({"GRADER_PROBLEMS": problems} if problems else {})}
    return subprocess.run([sys.executable, "-m", "grader", *args], capture_output=True, text=True, cwd=cwd, env=env,
                          timeout=600)


def test_cpp_is_a_judged_language_with_one_suffix_rule():
    assert language_of("a/main.cpp") is CPP and language_of("x.cc") is CPP and language_of("x.cxx") is CPP
    assert language_of("main.CPP") is None and language_of("x.PY") is None  # suffixes as written
    assert PYTHON.extraction("x.IPYNB") == "source"  # the same rule: case as written
    assert {".cpp", ".cc", ".cxx", ".py", ".ipynb"} == set(SUFFIXES)
    assert "C++" in accepted_files()
    sub = Submission.from_source("int main() { syntax error", "main.cpp")
    assert sub.language is CPP and sub.syntax_error() is None and sub.mode("closest_pair") == "stdio"
    assert Submission.from_source("def closest_pair(p): return [0, 1]\n").mode("closest_pair") == "function"


def test_judge_command_table_json_and_report(tmp_path):
    good = tmp_path / "mine.cpp"
    good.write_text(BRUTE_CPP)
    r = grader("judge", "tiny-closest-pair", str(good))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "AC" in r.stdout and "score 100/100" in r.stdout
    report = tmp_path / "r.html"
    js = json.loads(grader("judge", "tiny-closest-pair", str(good), "--json", "--report", str(report)).stdout)
    assert js["verdict"] == "AC" and js["score"] == 100 and js["mode"] == "stdio"
    assert report.is_file() and "AC" in report.read_text()
    bad = tmp_path / "broken.cc"
    bad.write_text("int main() { return undefined_thing; }\n")
    r = grader("judge", "tiny-closest-pair", str(bad), "--json")
    assert r.returncode == 1
    js = json.loads(r.stdout)
    assert js["verdict"] == "CE" and "undefined_thing" in js["tests"][0]["message"]
    assert "C++" in grader("judge", "--help").stdout


def test_grade_a_class_mixing_python_and_cpp(tmp_path):
    subs = tmp_path / "submissions"
    for student, name, code in (("ada", "closest-pair.py", BRUTE_PY), ("bo", "main.cpp", BRUTE_CPP),
                                ("cy", "first_two.cpp", FIRST_TWO_CPP), ("di", "oops.cxx", "int main( {}\n")):
        (subs / student).mkdir(parents=True)
        (subs / student / name).write_text(code)
    grades = tmp_path / "grades.csv"
    r = grader("grade", "tiny-closest-pair", str(subs), "--db", str(tmp_path / "r.sqlite"), "--csv", str(grades),
               "--quiet")
    assert r.returncode == 0, r.stdout + r.stderr
    rows = {row["student"]: row for row in csv.DictReader(grades.open())}
    assert rows["ada"]["verdict"] == "AC" and rows["bo"]["verdict"] == "AC", rows
    assert rows["cy"]["verdict"] == "WA" and rows["di"]["verdict"] == "CE", rows
    assert float(rows["bo"]["score"]) == 100 and float(rows["cy"]["score"]) == 0


def test_stress_finds_a_small_failing_input_and_compiles_once(tmp_path, monkeypatch):
    compiles = []
    real = judge_module.compile_source
    monkeypatch.setattr(judge_module, "compile_source", lambda *a, **k: compiles.append(1) or real(*a, **k))
    wrong = tmp_path / "first_two.cpp"
    wrong.write_text(FIRST_TWO_CPP)
    failure = stress("closest-pair", wrong, seconds=60)
    assert failure is not None and failure.verdict == "WA", failure
    assert int(failure.input_text.split()[0]) <= 4, failure.input_text  # three points suffice
    assert len(compiles) == 1, "stress compiled the submission more than once"


def test_timed_submit_with_a_cpp_file(tmp_path):
    db = str(tmp_path / "exam.sqlite")
    assert grader("timed", "start", "bowyer-watson-timed", "ada", "--db", db, problems=None).returncode == 0
    mine = tmp_path / "ada.cpp"
    mine.write_text("#include <cstdio>\nint main() { std::puts(\"no triangles here\"); }\n")
    r = grader("timed", "submit", "bowyer-watson-timed", "ada", str(mine), "--db", db, "--json", problems=None)
    assert r.returncode == 1, r.stdout + r.stderr
    out = json.loads(r.stdout)
    verdict = out.get("verdict") or out.get("result", {}).get("verdict")
    assert verdict in ("PE", "WA"), out


def test_similarity_compares_cpp_with_cpp_only(tmp_path):
    subs = tmp_path / "submissions"
    renamed = BRUTE_CPP.replace("best", "smallest").replace("bi", "first").replace("bj", "second")
    for student, name, code in (("ada", "closest-pair.py", BRUTE_PY), ("bo", "main.cpp", BRUTE_CPP),
                                ("cy", "copy.cpp", "// my own work\n" + renamed)):
        (subs / student).mkdir(parents=True)
        (subs / student / name).write_text(code)
    analysis = analyse("closest-pair", subs, threshold=0.5)
    pairs = {frozenset((p.a.name, p.b.name)) for p in analysis.pairs if p.b.kind == "student"}
    assert pairs == {frozenset(("bo", "cy"))}, pairs  # Python is never compared with C++
    assert [(p.a.name, p.b.name) for p in analysis.flagged] in ([("bo", "cy")], [("cy", "bo")]), analysis.flagged
    r = grader("similarity", "closest-pair", str(subs), "--reports", str(tmp_path / "sim"), problems=None)
    assert r.returncode in (0, 1), r.stdout + r.stderr
    assert "bo" in r.stdout and "cy" in r.stdout and (tmp_path / "sim" / "similarity.html").is_file()
