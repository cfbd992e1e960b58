"""The edge-flip checker's fast pass (``reference_impl/exact/flip_replay.py``) accepts only what the
integer-only replay accepts, and does accept valid answers (else it would save nothing).

Valid flip lists are Lawson's on generated starts (uniform, grid, cocircular, duplicated, far from
the origin, and coordinates too small for the float filters); corrupted ones drop, repeat, swap,
reverse or replace flips, or flip an edge of the
final triangulation there and back (the same final triangles through an illegal flip). On each, the checker's verdict and message must equal the integer-only
path's: its own replay (``replay``) followed by ``verify._check_delaunay_integers``.

Run: .venv/bin/python -m pytest tests/exact/test_flip_replay.py -q
"""
from __future__ import annotations

import random

import pytest

from grader.problems import load_problem
from reference_impl import flip_to_delaunay
from reference_impl.exact import bulk, flip_replay, verify

CHK = load_problem("edge-flip").checker
CASES = [({"kind": "uniform", "n": 60}, 1.0), ({"kind": "grid", "n": 49, "w": 7, "h": 7}, 1.0),
         ({"kind": "cocircular", "n": 40}, 1.0), ({"kind": "duplicates", "n": 50, "repeats": 10}, 1.0),
         ({"kind": "uniform", "n": 12}, 1.0), ({"kind": "clustered", "n": 60}, 1.0),
         ({"kind": "circle", "n": 30}, 1.0), ({"kind": "uniform", "n": 40, "offset": 2.0 ** 40}, 1.0),
         ({"kind": "uniform", "n": 40}, 2.0 ** -160)]


def _integer_verdict(points, triangles, flips) -> tuple[bool, str]:
    """The checker's answer without its fast pass: the exact replay, then the integer-only check."""
    final, message = CHK.replay(points, triangles, flips)
    if final is None:
        return False, message
    ok, why = verify._check_delaunay_integers(points, final)
    return ok, "ok" if ok else why


def _there_and_back(points, triangles, flips, rng: random.Random) -> list:
    """The flips, then an edge of the final triangulation flipped and its new edge flipped back:
    the same final triangles, through a flip that is illegal unless the four points are cocircular."""
    final, _ = CHK.replay(points, triangles, flips)
    opp = {}
    for u, v, w in final:
        opp[(u, v)], opp[(v, w)], opp[(w, u)] = w, u, v
    inner = sorted((u, v) for (u, v) in opp if (v, u) in opp)
    u, v = rng.choice(inner)
    return flips + [[u, v], [opp[(u, v)], opp[(v, u)]]]


def _corruptions(flips: list, edges: list, rng: random.Random) -> list:
    out = [flips[:-1], flips + flips[-1:], [list(reversed(f)) for f in flips]]
    for _ in range(6):
        k = rng.randrange(len(flips))
        out.append(flips[:k] + flips[k + 1:])                                   # one dropped
        j = rng.randrange(len(flips))
        swapped = flips[:]
        swapped[k], swapped[j] = swapped[j], swapped[k]
        out.append(swapped)                                                     # two swapped
        out.append(flips[:k] + [list(rng.choice(edges))] + flips[k + 1:])       # one replaced
        out.append(flips[:k + 1] + [flips[k][::-1]] + flips[k + 1:])            # flipped back at once
    return out


@pytest.mark.parametrize("case,scale", CASES)
def test_fast_pass_agrees_with_the_integer_replay(case, scale):
    gen = load_problem("edge-flip").generator
    rng = random.Random(7)
    for seed in range(2):
        points, triangles = gen.generate_args(case, seed)
        points = [[x * scale, y * scale] for x, y in points]
        if not triangles:
            continue
        flips = [list(f) for f in flip_to_delaunay(points, triangles)]
        assert flip_replay.accepts(points, triangles, flips, verify, bulk), case   # the fast pass is used
        assert flip_replay.accepts(points, triangles, flips, verify, None), case   # and without numpy
        edges = sorted({tuple(sorted((t[i], t[(i + 1) % 3]))) for t in triangles for i in range(3)})
        answers = [flips] + (_corruptions(flips, edges, rng) if flips else [[list(edges[0])]])
        answers += [_there_and_back(points, triangles, flips, rng) for _ in range(4)]
        for answer in answers:
            expected = _integer_verdict(points, triangles, answer)
            for b in (bulk, None):
                if flip_replay.accepts(points, triangles, answer, verify, b):
                    assert expected == (True, "ok"), (case, answer)
            ok, message = CHK.check([points, triangles], answer, None)
            assert ok == expected[0], (case, message, expected)
            if not ok:
                assert message.startswith(expected[1]) or expected[1] in message, (message, expected)


def test_malformed_answers_are_left_to_the_checker():
    points, triangles = [[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 3.0]], [[0, 1, 3], [1, 2, 3]]
    for flips in ([[1, 3, 0]], [[1, -1]], [[1, 4]], [(1, 3)], [[1.0, 3]], [[True, 3]], [[1, 1]], "13"):
        assert not flip_replay.accepts(points, triangles, flips, verify, bulk), flips
    assert not flip_replay.accepts(points, [[0, 1, 3], [0, 1, 3]], [[1, 3]], verify, bulk)  # an edge twice
