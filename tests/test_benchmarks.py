"""The benchmark scripts stay runnable: every script under benchmarks/ compiles, the Delaunay
benchmark prints its table on small sizes, and the judge-overhead benchmark prints its tables for
two problems whose numbers add up, and the C++ solutions' benchmark proves their verdicts on one
problem (timings are printed, never asserted).

Run: .venv/bin/python -m pytest tests/test_benchmarks.py -q
"""
from __future__ import annotations

import json
import math
import py_compile
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
SCRIPTS = sorted((ROOT / "benchmarks").glob("*.py"))


@pytest.mark.parametrize("script", SCRIPTS, ids=[s.name for s in SCRIPTS])
def test_script_compiles(script, tmp_path):
    py_compile.compile(str(script), cfile=str(tmp_path / "out.pyc"), doraise=True)


def test_bench_delaunay_prints_its_table():
    run = subprocess.run([sys.executable, "benchmarks/bench_delaunay.py", "--quick", "--sizes", "100", "2000",
                          "--kinds", "uniform", "grid", "--repeat", "1"],
                         cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-3000:]
    rows = [line.split("|") for line in run.stdout.splitlines() if line.startswith(("uniform", "grid"))]
    assert [r[0].split()[0] for r in rows] == ["uniform", "uniform", "grid", "grid"], run.stdout
    for r in rows:
        ours, tri, ratio = float(r[1]), float(r[2]), float(r[4])
        assert ours > 0 and tri > 0, r
        # The times are printed rounded to 0.001 ms and the ratio (to 0.01) comes from the unrounded
        # times, so the ratio must lie in the interval the printed times allow, not at their quotient.
        low, high = max(ours - 5e-4, 0) / (tri + 5e-4), (ours + 5e-4) / max(tri - 5e-4, 1e-12)
        assert low - 0.005 <= ratio <= high + 0.005, (r, low, high)


@pytest.mark.slow
def test_bench_judge_overhead_quick(tmp_path):
    """Quick mode (two problems, 2 students): the output's shape and its sums, never its timings."""
    out = tmp_path / "overhead.json"
    run = subprocess.run([sys.executable, "benchmarks/bench_judge_overhead.py", "--quick", "--json", str(out)],
                         cwd=ROOT, capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stderr[-3000:]
    for heading in ("cpu method:", "== start-up of one judge command", "== empty-work classes", "== per student:",
                    "== per grade run", "== where a later student's overhead goes"):
        assert heading in run.stdout, (heading, run.stdout)
    data = json.loads(out.read_text())
    assert data["method"] in ("cgroup-v1", "cgroup-v2", "proc")
    assert data["method"] in run.stdout
    assert {"python -c pass", "python -m grader list"} <= set(data["startup"])
    assert all(v["cpu_median"] > 0 for v in data["startup"].values())
    runs = data["runs"]
    assert [(r["problem"], r["lang"]) for r in runs] == [("closest-pair", "python"), ("largest-empty-circle", "python")]
    for r in runs:
        students = r["students"]
        assert [s["student"] for s in students] == ["s1", "s2"]
        assert all(s["verdict"] == "AC" and s["tests"] > 0 for s in students), students
        for s in students:
            assert s["total"] > 0 and s["own"] > 0
            assert math.isclose(s["overhead"], s["total"] - s["own"], abs_tol=1e-9)
            assert math.isclose(s["ratio"], s["overhead"] / s["own"], rel_tol=1e-9)
            line = next(li.split() for li in run.stdout.splitlines() if li.startswith(f"{r['problem']} ")
                        and f" {s['student']} " in li)
            assert line[3] == str(s["tests"]) and float(line[4]) == round(s["total"], 3), line
        # the run's CPU is its start-up, its students and its tail (all read from one counter)
        parts = r["startup"] + sum(s["total"] for s in students) + r["tail"]
        assert math.isclose(parts, r["cpu"], abs_tol=1e-6), (parts, r["cpu"])
        b = r["extra"]["breakdown"]
        named = sum(b[k] for k in ("jail+child start", "imports", "per-test fixed", "transport", "checker"))
        assert math.isclose(named + b["rest"], b["overhead"], abs_tol=1e-9)
        assert math.isclose(b["overhead"], students[1]["overhead"], abs_tol=1e-9)  # students 2..n: here s2 alone
        assert r["extra"]["replay"]["tests"] == students[0]["tests"] and r["extra"]["replay"]["rejected"] == 0
    assert data["per_test_fixed"] * 29 + data["per_submission_fixed"] > 0


@pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++ (Debian's g++ 12)")
def test_bench_cpp_solutions_quick(tmp_path):
    """Quick mode on delaunay: every C++ solution compiled once and checked by the problem's checker
    under the problem's C++ limit; the table's shape and the expected verdicts (expected_cpp.yaml),
    never its timings."""
    out = tmp_path / "cpp.json"
    run = subprocess.run([sys.executable, "benchmarks/bench_cpp_solutions.py", "--problems", "delaunay", "--quick",
                          "--json", str(out)],
                         cwd=ROOT, capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    assert run.stdout.startswith("compiler: "), run.stdout
    assert "== delaunay:" in run.stdout
    expected = yaml.safe_load((ROOT / "solutions/delaunay/expected_cpp.yaml").read_text())
    sources = sorted(p.name for p in (ROOT / "solutions/delaunay").glob("*.cpp"))
    assert sorted(expected) == sources
    compiled = [line.split()[1] for line in run.stdout.splitlines() if line.startswith("compile ")]
    assert sorted(compiled) == sources  # each file compiled once
    rows = {line.split()[0]: line.split() for line in run.stdout.splitlines() if line.split()[:1] in ([s] for s in sources)}
    assert sorted(rows) == sources, run.stdout
    for name, want in expected.items():
        verdict, *groups = str(want).split()
        row = rows[name]
        assert row[1] == verdict and row[-1] == "yes", row
    report = json.loads(out.read_text())
    data = {r["file"]: r for r in report["results"]}
    (summary,) = report["problems"]
    # the cap is the problem's C++ limit from course.yaml, and the margins are printed
    assert summary["problem"] == "delaunay" and summary["limit_source"] == "course.yaml", summary
    assert f"C++ limit {summary['limit_s']:g} s per test (course.yaml)" in run.stdout
    assert "margins: limit " in run.stdout and "== summary:" in run.stdout
    assert summary["quadratic_verdict"] == "TLE"
    assert data["accepted.cpp"]["verdict"] == "AC" and data["accepted.cpp"]["groups_failed"] == []
    assert data["compile_error.cpp"]["verdict"] == "CE"
    assert "degenerate" in data["wrong_double.cpp"]["groups_failed"]
    assert "large" in data["quadratic.cpp"]["groups_failed"]
    assert run.stdout.rstrip().endswith("every verdict as expected")


def test_cpp_predicates_in_sync():
    """Every C++ solution's copy of the predicates is the master copy (solutions/cpp/predicates.hpp)."""
    run = subprocess.run([sys.executable, "solutions/cpp/sync_predicates.py", "--check"], cwd=ROOT,
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "all match" in run.stdout
