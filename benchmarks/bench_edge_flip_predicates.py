"""Benchmark: how fast the in-circle test must be for `edge-flip` (issue 43's speed hint).

    python benchmarks/bench_edge_flip_predicates.py            # the large group's tests
    python benchmarks/bench_edge_flip_predicates.py --quick    # the first large test only

Runs one Lawson algorithm (``solutions/edge-flip/accepted_lawson.py``'s stack of edges) on the
problem's own large tests with three in-circle predicates and prints the CPU time of each, with
the number of flips (the same for all three: every predicate is exact):

* ``fraction``: the determinant in ``fractions.Fraction`` on the input doubles;
* ``integers``: every coordinate scaled by one common power of two into a Python ``int``;
* ``filtered``: a float determinant with an error bound, the integers only when it is not met
  (what ``accepted_lawson.py`` does).

Example output line: ``large/01  n=10000  flips=...  fraction 40.1 s  integers 2.0 s  filtered 0.6 s``.
"""
from __future__ import annotations

import argparse
import importlib.util
import sys
import time
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

_spec = importlib.util.spec_from_file_location("_lawson", ROOT / "solutions/edge-flip/accepted_lawson.py")
lawson = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(lawson)


def _lawson(triangles, inside):
    """Lawson's flips with the predicate ``inside(a, b, c, d)``; the number of flips."""
    opp = {}
    for a, b, c in triangles:
        opp[(a, b)], opp[(b, c)], opp[(c, a)] = c, a, b
    stack = [e for e in opp if e[0] < e[1]]
    flips = 0
    while stack:
        a, b = stack.pop()
        c, d = opp.get((a, b)), opp.get((b, a))
        if c is None or d is None or not inside(a, b, c, d):
            continue
        for e in ((a, b), (b, c), (c, a), (b, a), (a, d), (d, b)):
            del opp[e]
        opp[(c, a)], opp[(a, d)], opp[(d, c)] = d, c, a
        opp[(d, b)], opp[(b, c)], opp[(c, d)] = c, d, b
        flips += 1
        stack += [(c, a), (a, d), (d, b), (b, c)]
    return flips


def predicates(points):
    """The three predicates (name -> inside(a, b, c, d)) on ``points``."""
    Q = [(Fraction(x), Fraction(y)) for x, y in points]
    P = lawson._exact(points)
    F = [(float(x), float(y)) for x, y in points]
    value = lawson._incircle_value

    def fraction(a, b, c, d):
        return value(*Q[a], *Q[b], *Q[c], *Q[d])[0] > 0

    def integers(a, b, c, d):
        return value(*P[a], *P[b], *P[c], *P[d])[0] > 0

    def filtered(a, b, c, d):
        det, al, bl, cl, adx, ady, bdx, bdy, cdx, cdy = value(*F[a], *F[b], *F[c], *F[d])
        perm = (al * (abs(bdx * cdy) + abs(cdx * bdy)) + bl * (abs(cdx * ady) + abs(adx * cdy))
                + cl * (abs(adx * bdy) + abs(bdx * ady)))
        bound = 1e-14 * perm + 1e-290
        if bound < float("inf") and abs(det) > bound:
            return det > 0
        return integers(a, b, c, d)

    return {"fraction": fraction, "integers": integers, "filtered": filtered}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="the first large test only")
    a = ap.parse_args(argv)
    from grader.problems import load_problem

    tests = [t for t in load_problem("edge-flip").tests() if t.group == "large"]
    for t in tests[:1] if a.quick else tests:
        tok = t.input_text.split()
        n, m = int(tok[0]), int(tok[1])
        pts = [(float(tok[2 + 2 * i]), float(tok[3 + 2 * i])) for i in range(n)]
        b = 2 + 2 * n
        tris = [tuple(int(v) for v in tok[b + 3 * k:b + 3 * k + 3]) for k in range(m)]
        line = [f"{t.name}  n={n}"]
        for name, inside in predicates(pts).items():
            t0 = time.process_time()
            flips = _lawson(tris, inside)
            line.append(f"{name} {time.process_time() - t0:.2f} s")
        line.insert(1, f"flips={flips}")
        print("  ".join(line), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
