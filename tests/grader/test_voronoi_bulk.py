"""The voronoi checker's bulk pass (``_settled``: cells that pass every test with a margin, decided
at once with numpy) never changes a verdict or a message: on the reference answers and on answers
corrupted near the tolerance (vertices moved by 0.2 to 100 eps, dropped, repeated, split edges,
reversed or swapped cells, cells shrunk or pushed out of the box, one vertex pushed out of an
edge's middle in the answer or in the true cell), ``check`` gives exactly what it gives with the
bulk pass switched off.

Run: .venv/bin/python -m pytest tests/grader/test_voronoi_bulk.py -q
"""
from __future__ import annotations

import math
import random

import pytest

from grader.problems import load_problem

PROBLEM = load_problem("voronoi")
CHK = PROBLEM.checker


def _tests(count: int) -> list:
    """A few tests big enough for the bulk pass (at least BULK_MIN vertices), smallest first."""
    out = []
    for t in PROBLEM.tests():
        args = CHK.read_input(t.input_text)
        expected = PROBLEM.read_answer(t, args)
        size = sum(map(len, expected))
        if CHK.BULK_MIN <= size <= 3000:
            out.append((size, t.name, args, expected))
    out.sort(key=lambda s: s[:2])
    step = max(1, len(out) // count)
    return [(name, args, expected) for _, name, args, expected in out[::step][:count]]


def _eps(args) -> float:
    """The checker's tolerance in the input's units."""
    points, (x0, y0, x1, y1) = args
    big = max([abs(c) for p in points for c in p] + [abs(x0), abs(y0), abs(x1), abs(y1)])
    return CHK.REL_TOL * max(x1 - x0, y1 - y0) + CHK.ABS_TOL * big


def _corruptions(args, ref: list, rng: random.Random) -> list:
    eps = _eps(args)
    (x0, y0, x1, y1) = args[1]
    out = []
    for f in (0.2, 0.5, 0.69, 0.71, 0.99, 1.01, 1.5, 3.0, 100.0):
        i = rng.randrange(len(ref))
        if not ref[i]:
            continue
        j = rng.randrange(len(ref[i]))
        a = rng.uniform(0, 2 * math.pi)
        cell = [v[:] for v in ref[i]]
        cell[j] = [cell[j][0] + f * eps * math.cos(a), cell[j][1] + f * eps * math.sin(a)]
        out.append(ref[:i] + [cell] + ref[i + 1:])                                  # a vertex moved
        out.append([[[x + f * eps, y] for x, y in c] for c in ref])                 # every vertex moved
    for i in rng.sample(range(len(ref)), min(4, len(ref))):
        c = ref[i]
        if len(c) < 3:
            continue
        j = rng.randrange(len(c))
        mid = [(c[j][0] + c[j - 1][0]) / 2, (c[j][1] + c[j - 1][1]) / 2]
        cx, cy = sum(x for x, _ in c) / len(c), sum(y for _, y in c) / len(c)
        for cell in (c[:j] + c[j + 1:], c[:j] + [c[j]] + c[j:], c[:j] + [mid] + c[j:], c[::-1], c[j:] + c[:j],
                     [[cx + (x - cx) * (1 - 1e-7), cy + (y - cy) * (1 - 1e-7)] for x, y in c],
                     [[min(max(x, x0), x1) - 0.6 * eps if x == x0 else x, y] for x, y in c], []):
            out.append(ref[:i] + [cell] + ref[i + 1:])
        k = (i + 1) % len(ref)
        swapped = ref[:]
        swapped[i], swapped[k] = swapped[k], swapped[i]
        out.append(swapped)
    return [(answer, ref) for answer in out] + _bumps(ref, eps, rng)


def _bumps(ref: list, eps: float, rng: random.Random) -> list:
    """(answer, true cells) pairs where the two differ by one vertex pushed f eps out of an edge's
    middle, in the answer (a vertex outside the true cell) or in the true cells (a corner the answer
    misses): every other vertex matches, so only the closeness tests can tell."""
    out = []
    for f in (0.5, 0.9, 1.1, 2.0, 5.0):
        i = rng.randrange(len(ref))
        c = ref[i]
        if len(c) < 3:
            continue
        j = max(range(len(c)), key=lambda m: math.dist(c[m], c[m - 1]))       # the longest edge
        (ax, ay), (bx, by) = c[j - 1], c[j]
        length = math.dist(c[j - 1], c[j])
        bump = [(ax + bx) / 2 + f * eps * (by - ay) / length, (ay + by) / 2 - f * eps * (bx - ax) / length]  # outward
        bumped = ref[:i] + [c[:j] + [bump] + c[j:]] + ref[i + 1:]
        out += [(bumped, ref), (ref, bumped)]
    return out


@pytest.mark.parametrize("name,args,expected", _tests(6))
def test_bulk_pass_changes_no_verdict(name, args, expected, monkeypatch):
    rng = random.Random(name)
    answers = [(expected, expected)] + _corruptions(args, expected, rng)
    bulk_pass, seen = CHK._settled, []
    monkeypatch.setattr(CHK, "_settled", lambda *a: seen.append(bulk_pass(*a)) or seen[-1])
    with_bulk = [CHK.check(args, a, e) for a, e in answers]
    assert seen[0] is not None and sum(seen[0]) > len(seen[0]) // 2, name  # the bulk pass settles most valid cells
    monkeypatch.setattr(CHK, "_settled", lambda *a: None)
    without = [CHK.check(args, a, e) for a, e in answers]
    assert with_bulk[0] == (True, "ok")
    assert with_bulk == without
    assert sum(not ok for ok, _ in without) >= 5, name        # the corruptions do reach the rejections
