"""Benchmark of ``python -m grader similarity`` on a class of 200 submissions.

The class is made from the course's own reference submissions (``solutions/*/*.py``, 50-odd
files): student k gets file k mod N with every local name renamed at random (so no two are
byte-identical), every third as a notebook whose solution cell holds the code. Timed: our whole
analysis (reading, boilerplate, fingerprints, 19,900 pairs + 200 against the tutorial) and the
report (HTML, pair pages, CSV); the anchor is copydetect's own ``CopyDetector`` (``run()``, no
report) on the same code as flat ``.py`` files, in the same run.

Run: .venv/bin/python benchmarks/bench_similarity.py [--students 200] [--repeat 3]
Prints numbers only; nothing is asserted (tests assert behaviour, not timings).
"""
from __future__ import annotations

import argparse
import io
import json
import keyword
import random
import sys
import tempfile
import time
import tokenize
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from grader.classroom import similarity as sim  # noqa: E402
from grader.classroom.similarity_report import write_reports  # noqa: E402

KEEP = set(keyword.kwlist) | set(dir(__builtins__ if isinstance(__builtins__, dict) else vars(__builtins__)))


def renamed(code: str, rng: random.Random) -> str:
    """``code`` with every name that is not a keyword, builtin or attribute renamed consistently."""
    names: dict[str, str] = {}
    out, prev = [], None
    for tok in tokenize.generate_tokens(io.StringIO(code).readline):
        if tok.type == tokenize.NAME and tok.string not in KEEP and not (prev and prev.string == "."):
            new = names.setdefault(tok.string, f"{tok.string[:2]}{rng.randrange(10**6)}")
            tok = tok._replace(string=new)
        out.append((tok.type, tok.string))
        prev = tok
    return tokenize.untokenize(out)


def make_class(root: Path, flat: Path, students: int, seed: int = 1) -> None:
    files = sorted(p for p in (REPO / "solutions").glob("*/*.py") if not p.is_symlink())
    rng = random.Random(seed)
    for k in range(students):
        code = renamed(files[k % len(files)].read_text(), rng)
        d = root / f"student{k:03d}"
        d.mkdir(parents=True)
        if k % 3 == 2:
            cell = {"cell_type": "code", "metadata": {"nbgrader": {"solution": True, "grade_id": "solution"}},
                    "source": code, "outputs": [], "execution_count": None}
            (d / "delaunay.ipynb").write_text(json.dumps({"cells": [cell], "metadata": {}, "nbformat": 4,
                                                          "nbformat_minor": 5}))
        else:
            (d / "delaunay.py").write_text(code)
        (flat / f"student{k:03d}.py").write_text(code)


def best_of(repeat: int, fn) -> tuple[tuple[float, float], object]:
    """(best wall time, its CPU time) of ``repeat`` calls, and the last result."""
    best, out = (float("inf"), 0.0), None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        best = min(best, (time.perf_counter() - t0, time.process_time() - c0))
    return best, out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--students", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    from copydetect import CopyDetector

    with tempfile.TemporaryDirectory() as tmp:
        root, flat = Path(tmp) / "class", Path(tmp) / "flat"
        flat.mkdir()
        make_class(root, flat, a.students)
        t_ours, analysis = best_of(a.repeat, lambda: sim.analyse("delaunay", root))
        t_report, _ = best_of(a.repeat, lambda: write_reports(analysis, Path(tmp) / "report"))

        def anchor():
            det = CopyDetector(test_dirs=[str(flat)], extensions=["py"], silent=True, autoopen=False)
            det.run()
            return det

        t_anchor, _ = best_of(a.repeat, anchor)
    print(f"class of {a.students} submissions ({a.students // 3} notebooks), {len(analysis.pairs)} pairs compared, "
          f"{len(analysis.flagged)} flagged (the solutions share code, and the renamed copies of one file are copies)")
    print(f"grader similarity: analysis {t_ours[0]:.2f} s ({t_ours[1]:.2f} s CPU), report {t_report[0]:.2f} s "
          f"({t_report[1]:.2f} s CPU), best of {a.repeat}")
    print(f"copydetect CopyDetector.run() on the same code: {t_anchor[0]:.2f} s ({t_anchor[1]:.2f} s CPU); "
          f"ratio ours/anchor {t_ours[0] / t_anchor[0]:.2f} (CPU {t_ours[1] / t_anchor[1]:.2f})")


if __name__ == "__main__":
    main()
