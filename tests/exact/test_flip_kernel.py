"""The edge-flip checker's compiled topology replay (``reference_impl/exact/flip_kernel.py``) agrees
with the Python one (``flip_replay.topology``), and the checker gives the same verdict and message
with it and without it.

* Random walks of flips on generated triangulations (hypothesis): thousands of topologically valid
  flips, so the kernel's hash table deletes and re-inserts keys in long probe runs, with invalid
  flips (a hull edge, an edge not in the mesh, a flip repeated, a diagonal that is already an edge)
  put anywhere; both replays must refuse the same walks, and on the others give the same two
  opposite vertices at every flip and the same final triangles.
* The checker, with the kernel on every answer (``COMPILED_MIN_FLIPS = 0``) and with no kernel at
  all, on Lawson's flips and on corrupted ones (a hull edge, an edge not in the mesh, a repeated
  flip, a flip of a locally Delaunay edge whose quadrilateral is reflex, two flips swapped, an edge
  flipped there and back): the same ``(verdict, message)``; and a long answer (the strip, more than
  512 flips) takes the compiled path on its own.
* The exported Kattis validator never imports the kernel (``STANDALONE``), and a checker without
  numba or without the kernel module still accepts.

Run: .venv/bin/python -m pytest tests/exact/test_flip_kernel.py -q
"""
from __future__ import annotations

import random
import sys

import numpy as np
import pytest
import reference_impl.exact
from hypothesis import given, settings, strategies as st

from grader.judging import checker_runtime
from grader.problems import load_problem
from reference_impl import flip_to_delaunay
from reference_impl.exact import flip_kernel, flip_replay

PROBLEM = load_problem("edge-flip")
CHK = PROBLEM.checker
GEN = PROBLEM.generator


def _canon(tris) -> set:
    """Triangles as a set of rotations starting at their smallest vertex."""
    out = set()
    for t in tris:
        t = [int(v) for v in t]
        k = t.index(min(t))
        out.add(tuple(t[k:] + t[:k]))
    return out


def _both(n: int, triangles: list, flips: list):
    """Both replays' results, checked to agree; True when they accept."""
    py = flip_replay.topology(n, triangles, flips)
    ok, cs, ds, final = flip_kernel.replay(n, np.array(triangles, dtype=np.int64).reshape(-1, 3),
                                           np.array(flips, dtype=np.int64).reshape(-1, 2))
    assert ok == (py is not None), flips
    if ok:
        assert cs.tolist() == py[0] and ds.tolist() == py[1]
        python_final = [[key // n, key % n, w] for key, w in py[2].items()]
        assert _canon(final.tolist()) == _canon(python_final) and len(final) == len(_canon(python_final))
    return ok


def _walk(triangles: list, steps: int, rng: random.Random, bad_at: int | None, bad: str) -> list:
    """``steps`` flips chosen at random among the topologically valid ones (an interior edge whose
    new diagonal is not an edge yet), with one invalid flip of kind ``bad`` at step ``bad_at``."""
    opp = {}
    for a, b, c in triangles:
        opp[(a, b)], opp[(b, c)], opp[(c, a)] = c, a, b
    flips = []
    for s in range(steps):
        if s == bad_at:
            hull = sorted(e for e in opp if e[::-1] not in opp)
            if bad == "hull" and hull:
                flips.append(list(rng.choice(hull)))
            elif bad == "absent":
                verts = sorted({v for e in opp for v in e})
                pairs = [(u, v) for u in verts[:12] for v in verts[:12] if u != v and (u, v) not in opp]
                flips.append(list(rng.choice(pairs)) if pairs else [0, 0])
            elif bad == "repeat" and flips:
                flips.append(flips[-1])
            elif bad == "diagonal":
                stuck = [(a, b) for (a, b), c in opp.items() if (b, a) in opp and (opp[(b, a)], c) in opp]
                flips.append(list(rng.choice(stuck)) if stuck else [0, 0])
            return flips
        keys = list(opp)
        for _ in range(100):
            a, b = rng.choice(keys)
            c, d = opp[(a, b)], opp.get((b, a))
            if d is not None and c != d and (c, d) not in opp and (d, c) not in opp:
                break
        else:
            return flips
        c, d = opp.pop((a, b)), opp.pop((b, a))
        opp[(c, a)], opp[(a, d)], opp[(d, c)] = d, c, a
        opp[(d, b)], opp[(b, c)], opp[(c, d)] = c, d, b
        flips.append([a, b])
    return flips


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 10 ** 6), n=st.integers(4, 60), steps=st.integers(0, 3000),
       bad=st.sampled_from(["none", "hull", "absent", "repeat", "diagonal"]), where=st.floats(0, 1))
def test_random_walks_agree(seed, n, steps, bad, where):
    points, triangles = GEN.generate_args({"kind": "uniform", "n": n}, seed % 1000)
    rng = random.Random(seed)
    bad_at = None if bad == "none" else int(where * steps)
    flips = _walk(triangles, steps, rng, bad_at, bad)
    ok = _both(len(points), triangles, flips)
    if bad_at is None or len(flips) <= bad_at:
        assert ok                                   # a valid walk is accepted by both
    elif bad != "repeat" or bad_at > 0:
        assert not ok                               # and the invalid flip refused by both


def test_a_long_walk_agrees_flip_by_flip():
    """20 000 flips on 300 points: a table of 4096 slots, keys deleted and re-inserted all along."""
    points, triangles = GEN.generate_args({"kind": "uniform", "n": 300}, 1)
    flips = _walk(triangles, 20_000, random.Random(5), None, "none")
    assert len(flips) == 20_000 and _both(len(points), triangles, flips)
    assert not _both(len(points), triangles, flips + [flips[-1]])


def test_malformed_starts_and_indices_are_refused_alike():
    tris = [[0, 1, 3], [1, 2, 3]]
    for triangles, flips, ok in ((tris, [[1, 3]], True), (tris, [], True), ([], [], True),
                                 (tris, [[1, 3], [1, 3]], False), (tris, [[1, 3], [3, 1]], False),
                                 (tris, [[0, 1]], False), (tris, [[0, 2]], False), (tris, [[2, 2]], False),
                                 ([[0, 1, 3], [0, 1, 3]], [[1, 3]], False), ([[0, 1, 1], [1, 2, 3]], [], False)):
        assert _both(4, triangles, flips) == ok, (triangles, flips)
    for triangles, flips in ((tris, [[1, 4]]), (tris, [[-1, 3]]), ([[0, 1, 5]], []), ([[0, -1, 2]], [])):
        assert not flip_kernel.replay(4, np.array(triangles).reshape(-1, 3), np.array(flips).reshape(-1, 2))[0]


def test_bad_arrays_are_a_value_error():
    tri, fl = np.array([[0, 1, 3], [1, 2, 3]]), np.array([[1, 3]])
    for args, words in (((4, tri[:, :2], fl), "(m, 3)"), ((4, tri, fl.ravel()), "(f, 2)"),
                        ((0, tri, fl), "n must be"), ((1 << 31, tri, fl), "n must be")):
        with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)")):
            flip_kernel.replay(*args)


# -- the checker with and without the kernel ----------------------------------------------------------------
def _check(monkeypatch, args, flips, kernel: bool) -> tuple[bool, str]:
    """The checker's ``(verdict, message)``, the kernel used on every answer or never."""
    with monkeypatch.context() as m:
        lib = CHK.flip_replay
        m.setattr(lib, "COMPILED_MIN_FLIPS", 0)
        m.setattr(lib, "_KERNEL", [flip_kernel if kernel else None])
        return CHK.check(args, flips, None)


def _corruptions(points, triangles, flips, rng: random.Random) -> list:
    final, _ = CHK.replay(points, triangles, flips)
    opp = {}
    for u, v, w in final:
        opp[(u, v)], opp[(v, w)], opp[(w, u)] = w, u, v
    hull = sorted(e for e in opp if e[::-1] not in opp)
    inner = sorted(e for e in opp if e[::-1] in opp)
    absent = next([u, v] for u in range(len(points)) for v in range(len(points))
                  if u != v and (u, v) not in opp and (v, u) not in opp)
    k = rng.randrange(len(flips))
    out = [flips + [list(hull[0])], flips + [absent], flips[:k + 1] + [flips[k]] + flips[k + 1:],
           flips[:k] + flips[k + 1:], flips + [list(rng.choice(inner))]]      # the last: already locally Delaunay
    j = rng.randrange(len(flips))
    swapped = flips[:]
    swapped[k], swapped[j] = swapped[j], swapped[k]
    u, v = rng.choice(inner)
    out += [swapped, flips + [[u, v], [opp[(u, v)], opp[(v, u)]]]]              # there and back
    return out


# 0 is a reflex corner of the quadrilateral 2 0 3 1 around the edge 0 1 (its new diagonal 2 3 is no edge yet)
REFLEX = [[[0.0, 0.0], [4.0, 0.0], [-1.0, 1.0], [-1.0, -1.0], [-3.0, 0.0]],
          [[0, 1, 2], [1, 0, 3], [0, 2, 4], [0, 4, 3]]]


@pytest.mark.parametrize("case,scale", [({"kind": "uniform", "n": 120}, 1.0), ({"kind": "grid", "n": 64, "w": 8, "h": 8}, 1.0),
                                        ({"kind": "duplicates", "n": 60, "repeats": 12}, 1.0),
                                        ({"kind": "circle", "n": 50}, 1.0), ({"kind": "strip", "n": 40}, 1.0),
                                        ({"kind": "uniform", "n": 40}, 2.0 ** -160)])   # untame: integer predicates
def test_checker_verdicts_and_messages_are_the_same(case, scale, monkeypatch):
    rng = random.Random(3)
    points, triangles = GEN.generate_args(case, 2)
    points = [[x * scale, y * scale] for x, y in points]
    flips = [list(f) for f in flip_to_delaunay(points, triangles)]
    assert flips
    calls = []
    real = flip_kernel.replay
    monkeypatch.setattr(flip_kernel, "replay", lambda *a: calls.append(1) or real(*a))
    for answer in [flips] + _corruptions(points, triangles, flips, rng):
        with_kernel = _check(monkeypatch, [points, triangles], answer, True)
        assert with_kernel == _check(monkeypatch, [points, triangles], answer, False), (case, answer[-3:])
        if answer is flips:
            assert with_kernel == (True, "ok")
            with monkeypatch.context() as m:          # and the fast pass itself accepts (else it saves nothing)
                m.setattr(CHK.flip_replay, "COMPILED_MIN_FLIPS", 0)
                m.setattr(CHK.flip_replay, "_KERNEL", [flip_kernel])
                assert CHK.flip_replay.accepts(points, triangles, flips, CHK.verify, CHK.bulk)
    assert calls                                       # the compiled path was taken


def test_reflex_quad_and_hand_made_cases(monkeypatch):
    assert _both(5, REFLEX[1], [[0, 1]])              # topologically a flip: the predicates refuse it
    for args, flips, words in ((REFLEX, [[0, 1]], "already locally Delaunay"),
                               (REFLEX, [[1, 0]], "already locally Delaunay"),
                               (REFLEX, [[2, 1]], "convex hull edge"), (REFLEX, [[1, 3]], "convex hull edge"),
                               (REFLEX, [[2, 3]], "not an edge"), (REFLEX, [[4, 1]], "not an edge"),
                               (REFLEX, [[1, 5]], "index outside"), (REFLEX, [[0, 2], [0, 1]], "already locally")):
        got = _check(monkeypatch, args, flips, True)
        assert got == _check(monkeypatch, args, flips, False)
        assert not got[0] and words in got[1], got


def test_a_long_answer_takes_the_compiled_path(monkeypatch):
    points, triangles = GEN.generate_args({"kind": "strip", "n": 80}, 1)
    flips = [list(f) for f in flip_to_delaunay(points, triangles)]
    assert len(flips) >= CHK.flip_replay.COMPILED_MIN_FLIPS
    calls = []
    real = flip_kernel.replay
    monkeypatch.setattr(flip_kernel, "replay", lambda *a: calls.append(1) or real(*a))
    monkeypatch.setattr(CHK.flip_replay, "_KERNEL", [flip_kernel])
    assert CHK.check([points, triangles], flips, None) == (True, "ok") and calls
    assert CHK.flip_replay.accepts(points, triangles, flips, CHK.verify, CHK.bulk)
    bad = flips[:100] + [flips[99]] + flips[100:]
    assert CHK.check([points, triangles], bad, None) == _check(monkeypatch, [points, triangles], bad, False)
    assert "flip 100 = " in CHK.check([points, triangles], bad, None)[1]


def test_without_the_kernel_module_the_python_replay_accepts(monkeypatch):
    monkeypatch.setitem(sys.modules, "reference_impl.exact.flip_kernel", None)   # import fails
    monkeypatch.delattr(reference_impl.exact, "flip_kernel")
    monkeypatch.setattr(CHK.flip_replay, "_KERNEL", [])
    monkeypatch.setattr(CHK.flip_replay, "COMPILED_MIN_FLIPS", 0)
    assert CHK.flip_replay.compiled_kernel() is None
    points, triangles = GEN.generate_args({"kind": "uniform", "n": 60}, 4)
    flips = [list(f) for f in flip_to_delaunay(points, triangles)]
    assert CHK.flip_replay.accepts(points, triangles, flips, CHK.verify, CHK.bulk)


def test_the_exported_validator_never_imports_the_kernel():
    ns = {"__name__": "exported_checker"}
    exec(compile(checker_runtime.embed(PROBLEM.checker_path.read_text()), "checker.py", "exec"), ns)
    lib = ns["flip_replay"]
    assert lib.STANDALONE and lib.compiled_kernel() is None
    assert not CHK.flip_replay.STANDALONE and CHK.flip_replay.compiled_kernel() is flip_kernel
    points, triangles = GEN.generate_args({"kind": "strip", "n": 80}, 1)
    flips = [list(f) for f in flip_to_delaunay(points, triangles)]
    assert ns["check"]([points, triangles], flips, None) == (True, "ok")
