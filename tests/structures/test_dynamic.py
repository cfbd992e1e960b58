"""``reference_impl.structures.dynamic``: the dynamic-network answer key against independent oracles.

* a brute-force oracle in exact integer arithmetic that shares no code with the library:
  nodes u and v are neighbours when their Voronoi cells share an edge of positive length,
  i.e. when some open interval of the bisector of u and v is strictly closer to u and v
  than to every other live position (a linear program in one variable, solved exactly);
* for larger runs in general position, ``scipy.spatial.Delaunay`` of the live nodes, and a
  fresh ``Delaunay`` rebuilt for every query (its strict neighbours do not depend on how
  cocircular ties were broken, so they must match the incrementally updated ones).

Run: python -m pytest tests/structures/test_dynamic.py -q
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial
from hypothesis import given, strategies as st

from reference_impl import Delaunay
from grader.problems import load_problem
from reference_impl.structures.dynamic import DynamicNetwork
from reference_impl.exact.verify import exact_coordinates

process = load_problem("dynamic-network").generator.process   # the problem's adapter (JSON in, out)


# ------------------------------------------------------------------ the brute-force oracle
def voronoi_neighbours(P: list[tuple[int, int]], v: int) -> list[int]:
    """Indices j of the distinct integer points P whose Voronoi cell shares an edge with v's."""
    out = []
    vx, vy = P[v]
    for u, (ux, uy) in enumerate(P):
        if u == v:
            continue
        # bisector: x(t) = (v + u) / 2 + t * d, d perpendicular to u - v; for each other w,
        # |x - v|^2 < |x - w|^2  <=>  a t < b  (integers, derived by expanding the squares)
        dx, dy = -(uy - vy), ux - vx
        sx, sy = vx + ux, vy + uy
        lo, hi = None, None
        empty = False
        for w, (wx, wy) in enumerate(P):
            if w in (u, v):
                continue
            ex, ey = wx - vx, wy - vy
            a = 2 * (dx * ex + dy * ey)
            b = (wx * wx + wy * wy) - (vx * vx + vy * vy) - (sx * ex + sy * ey)
            if a == 0:
                if b <= 0:
                    empty = True
                    break
            elif a > 0:
                hi = Fraction(b, a) if hi is None else min(hi, Fraction(b, a))
            else:
                lo = Fraction(b, a) if lo is None else max(lo, Fraction(b, a))
        if not empty and (lo is None or hi is None or lo < hi):
            out.append(u)
    return out


class Oracle:
    """The network rebuilt from scratch for every query (brute force, exact)."""

    def __init__(self) -> None:
        self.pos: list[tuple[float, float]] = []
        self.alive: list[bool] = []

    def run(self, ops) -> list:
        answers = []
        for op in ops:
            if op[0] == "join":
                self.pos.append((float(op[1]), float(op[2])))
                self.alive.append(True)
                answers.append(len(self.pos) - 1)
            elif op[0] == "count":
                answers.append(sum(self.alive))
            else:
                i = op[1]
                if not (0 <= i < len(self.pos) and self.alive[i]):
                    answers.append("error")
                elif op[0] == "fail":
                    self.alive[i] = False
                    answers.append("ok")
                else:
                    answers.append(self.neighbours(i))
        return answers

    def neighbours(self, i: int) -> list[int]:
        live = [j for j in range(len(self.pos)) if self.alive[j]]
        sites = sorted({self.pos[j] for j in live})
        P = exact_coordinates(sites)
        at = {s: k for k, s in enumerate(sites)}
        near = set(voronoi_neighbours(P, at[self.pos[i]]))
        return sorted(j for j in live if j != i and (at[self.pos[j]] in near or self.pos[j] == self.pos[i]))


def random_ops(rng, m: int, coords, p_join=0.45, p_fail=0.25, bad_ids=True) -> list:
    ops, live, joined = [], [], 0
    for _ in range(m):
        r = rng.random()
        if r < p_join or not live:
            x, y = coords(rng)
            ops.append(["join", x, y])
            live.append(joined)
            joined += 1
        elif r < p_join + p_fail:
            if bad_ids and rng.random() < 0.1:
                ops.append(["fail", int(rng.integers(-1, joined + 2))])      # maybe dead or unknown
                continue
            j = int(rng.integers(len(live)))
            ops.append(["fail", live[j]])
            live[j] = live[-1]
            live.pop()
        elif r < 0.97:
            if bad_ids and rng.random() < 0.05:
                ops.append(["neighbors", int(rng.integers(-1, joined + 2))])
            else:
                ops.append(["neighbors", live[int(rng.integers(len(live)))]])
        else:
            ops.append(["count"])
    return ops


COORDS = {
    "grid": lambda rng: (int(rng.integers(0, 4)), int(rng.integers(0, 4))),       # ties, duplicates
    "circle": lambda rng: [(0, 0), (5, 0), (-5, 0), (0, 5), (0, -5), (3, 4), (-3, 4), (3, -4),
                           (-3, -4), (4, 3), (-4, 3), (4, -3), (-4, -3)][int(rng.integers(13))],
    "line": lambda rng: (int(rng.integers(0, 8)), 2 * int(rng.integers(0, 2))),    # mostly collinear
    "float": lambda rng: (float(rng.random()), float(rng.random())),
    "tiny": lambda rng: (int(rng.integers(0, 5)) * 1e-300, int(rng.integers(0, 5)) * 1e-300),
}


@pytest.mark.parametrize("kind", sorted(COORDS))
def test_small_random_sequences_match_the_brute_force_oracle(kind):
    rng = np.random.default_rng(sorted(COORDS).index(kind))
    for _ in range(250):                       # 5 kinds x 250 = 1250 sequences
        ops = random_ops(rng, int(rng.integers(1, 30)), COORDS[kind])
        assert process(ops) == Oracle().run(ops), ops


ops_strategy = st.lists(
    st.one_of(st.tuples(st.just("join"), st.integers(-3, 3), st.integers(-3, 3)),
              st.tuples(st.just("fail"), st.integers(-1, 12)),
              st.tuples(st.just("neighbors"), st.integers(-1, 12)),
              st.tuples(st.just("count"))),
    max_size=40)


@given(ops=ops_strategy)
def test_hypothesis_sequences_match_the_oracle(ops):
    ops = [list(op) for op in ops]
    assert process(ops) == Oracle().run(ops)


def test_large_run_matches_scipy_and_a_fresh_rebuild():
    rng = np.random.default_rng(42)
    net = DynamicNetwork()
    ids = [net.join(x, y) for x, y in rng.random((1500, 2))]
    live = set(ids)
    for step in range(1500):
        r = rng.random()
        if r < 0.3:
            live.add(net.join(*rng.random(2)))
        elif r < 0.6:
            j = int(rng.choice(sorted(live)))
            net.fail(j)
            live.remove(j)
        if step % 100 == 0:                    # every node's neighbours against scipy
            L = np.array(sorted(live))
            tri = scipy.spatial.Delaunay(net.delaunay.points[L])
            ptr, nbr = tri.vertex_neighbor_vertices
            for k, i in enumerate(L.tolist()):
                assert net.neighbors(i) == sorted(L[nbr[ptr[k]:ptr[k + 1]]].tolist())
    assert len(net) == len(live) and net.nodes() == sorted(live)


def test_large_run_on_a_grid_matches_a_fresh_rebuild():
    # a grid is all ties: the incremental triangulation may differ from a rebuild, the
    # Delaunay graph (strict neighbours) may not
    rng = np.random.default_rng(43)
    net = DynamicNetwork()
    for x, y in rng.integers(0, 30, (600, 2)):
        net.join(int(x), int(y))
    live = set(range(600))
    for step in range(600):
        if rng.random() < 0.5:
            j = int(rng.choice(sorted(live)))
            net.fail(j)
            live.remove(j)
        else:
            x, y = rng.integers(0, 30, 2)
            live.add(net.join(int(x), int(y)))
        if step % 60 == 0:
            L = np.array(sorted(live))
            pts = net.delaunay.points[L]
            fresh = Delaunay(pts)
            im = fresh.index_map
            for k in rng.choice(len(L), 40, replace=False).tolist():
                want = set(L[fresh.vertex_neighbors(k, strict=True)].tolist())
                # every node at a neighbouring position, and the other nodes at the same one
                want = {int(L[j]) for j in range(len(L)) if int(L[im[j]]) in want or
                        (im[j] == im[k] and j != k)}
                assert net.neighbors(int(L[k])) == sorted(want)


def test_nearest_nodes_are_not_the_delaunay_neighbours():
    # Delaunay neighbours are not "the nearest three nodes", and not a minimal network
    net = DynamicNetwork()
    for p in [(0, 0), (1, 0), (2, 0), (0, 5)]:
        net.join(*p)
    assert net.neighbors(0) == [1, 3]          # 2 is nearer than 3 but not a neighbour
    assert len(net.links()) == 5 > len(net) - 1
    ring = DynamicNetwork()
    centre = ring.join(0, 0)
    for k in range(12):
        ring.join(np.cos(k * np.pi / 6) * 10, np.sin(k * np.pi / 6) * 10)
    assert len(ring.neighbors(centre)) == 12   # far more than three


def test_square_ties_give_four_links_not_five():
    net = DynamicNetwork()
    for p in [(0, 0), (1, 0), (1, 1), (0, 1)]:
        net.join(*p)
    assert net.links() == [(0, 1), (0, 3), (1, 2), (2, 3)]
    assert len(net.delaunay.edges()) == 5      # the triangulation needs one diagonal


def test_flat_and_tiny_networks():
    net = DynamicNetwork()
    a = net.join(0, 0)
    assert net.neighbors(a) == []
    b = net.join(3, 3)
    assert net.neighbors(a) == [b] and net.neighbors(b) == [a]
    c = net.join(1, 1)
    assert net.neighbors(a) == [c] and net.neighbors(c) == [a, b]
    d = net.join(1, 0)
    assert net.neighbors(a) == [c, d]
    net.fail(d)
    assert net.neighbors(a) == [c] and net.neighbors(c) == [a, b]
    net.fail(c)
    assert net.neighbors(a) == [b]


def test_co_located_nodes():
    net = DynamicNetwork()
    a, b, c = net.join(0, 0), net.join(2, 0), net.join(0, 2)
    a2 = net.join(0.0, -0.0)                   # the same position as a (-0.0 == 0.0)
    assert net.neighbors(a) == [b, c, a2] and net.neighbors(a2) == [a, b, c]
    assert net.neighbors(b) == [a, c, a2]
    net.fail(a)
    assert net.neighbors(b) == [c, a2] and net.neighbors(a2) == [b, c]
    net.fail(a2)
    assert net.neighbors(b) == [c]


def test_errors():
    net = DynamicNetwork()
    net.join(0, 0)
    with pytest.raises(ValueError, match="never joined"):
        net.fail(1)
    with pytest.raises(ValueError, match="integer"):
        net.neighbors(0.0)
    net.fail(0)
    with pytest.raises(ValueError, match="has failed"):
        net.fail(0)
    with pytest.raises(ValueError, match="finite"):
        net.join(float("nan"), 0)
    assert process([["fail", 0], ["neighbors", 3], ["join", 1, 1], ["fail", 0], ["count"]]) == \
        ["error", "error", 0, "ok", 0]
    for bad, word in [([["jump", 1]], "unknown operation"), ([["join", 1]], "takes 2"),
                      ([["join", "a", 1]], "number"), ([["join", float("inf"), 1]], "finite"),
                      ([["join", 10 ** 400, 1]], "finite"),
                      ([["fail", 1.5]], "integer"), ([["fail", True]], "integer"),
                      (["count"], "list"), ([[]], "list")]:
        with pytest.raises(ValueError, match=word):
            process(bad)
