"""Seeded test generator for `edge-flip`: a point set and a (usually bad) triangulation of it.

``generate_args(case, seed)`` returns ``[points, triangles]``; ``solve(points, triangles)`` the
reference flip sequence (``reference_impl.flip_to_delaunay``, Lawson's algorithm; grader only).
The starting triangulations are built here with exact integer orientation tests:

* ``sweep``: points sorted by x, each joined to the hull edges it sees (long thin triangles,
  many illegal edges);
* ``fan``: every triangle through the first hull vertex (points in convex position);
* ``strip``: two rows of points joined by an L-shaped path, the worst case for flipping
  (Lawson needs a quadratic number of flips);
* ``delaunay``: already Delaunay (the answer is no flip at all).

Print one case:  python assignments/edge-flip/generators/generator.py '{"kind": "grid", "w": 3, "h": 2}' 7

Example:
    >>> generate_args({"kind": "points", "points": [[0, 0], [4, 0], [4, 1], [0, 3]], "shuffle": False}, 0)
    [[[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 3.0]], [[3, 0, 1], [3, 1, 2]]]
"""

from __future__ import annotations

import json
import math
import random
import sys

KINDS = ("points", "tutorial", "uniform", "clustered", "grid", "circle", "cocircular", "collinear",
         "duplicates", "strip")
START = ("sweep", "fan", "delaunay")


def _points(case: dict, rng: random.Random) -> list[tuple[float, float]]:
    kind = case.get("kind")
    n = int(case.get("n", 10))
    if kind == "points":
        return [tuple(p) for p in case["points"]]
    if kind == "tutorial":
        return [(1, 1), (3, 2), (5, 1), (4, 4)]
    if kind == "uniform":
        return [(rng.random(), rng.random()) for _ in range(n)]
    if kind == "clustered":  # a few clusters of very different sizes in a sparse cloud
        pts = [(rng.random(), rng.random()) for _ in range(n // 4)]
        for size, spread in ((n // 2, 1e-4), (n - n // 4 - n // 2, 1e-8)):
            cx, cy = rng.random(), rng.random()
            pts += [(cx + rng.gauss(0, spread), cy + rng.gauss(0, spread)) for _ in range(size)]
        return pts
    if kind == "grid":  # every square is cocircular: ties everywhere
        w, h = int(case.get("w", 6)), int(case.get("h", case.get("w", 6)))
        return [(i, j) for i in range(w) for j in range(h)]
    if kind == "circle":  # nearly cocircular floats
        return [(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)) for k in range(n)]
    if kind == "cocircular":  # integer points exactly on x^2 + y^2 = r^2
        r = int(case.get("r", 25))
        return [(x, y) for x in range(-r, r + 1) for y in range(-r, r + 1) if x * x + y * y == r * r]
    if kind == "collinear":
        return [(k, 2 * k + 1) for k in range(n)]
    if kind == "duplicates":
        base = [(rng.randint(0, 5), rng.randint(0, 5)) for _ in range(n)]
        return base + [rng.choice(base) for _ in range(int(case.get("repeats", n)))]
    # strip: k points on each of two slightly bent rows; see _strip_triangles
    k = n // 2
    return [(float(i), 0.0) for i in range(k)] + [(i + 0.5, 1.0) for i in range(k)]


def _exact(points) -> list[tuple[int, int]]:
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([max(dx, dy) for (_, dx), (_, dy) in ratios], default=1)
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def _orient(a, b, c) -> int:
    d = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])
    return (d > 0) - (d < 0)


def sweep_triangulation(points) -> list[list[int]]:
    """A triangulation of the points (duplicates: first index) by an x-sorted sweep, exact.

    >>> sweep_triangulation([(0, 0), (1, 0), (0, 1), (1, 1)])
    [[2, 0, 1], [2, 1, 3]]
    """
    P = _exact(points)
    first: dict = {}
    for i, p in enumerate(P):
        first.setdefault(p, i)
    order = sorted(first.values(), key=lambda i: P[i])
    if len(order) < 3:
        return []
    k = 2
    while k < len(order) and _orient(P[order[0]], P[order[1]], P[order[k]]) == 0:
        k += 1
    if k == len(order):
        return []                                        # all collinear
    chain, p = order[:k], order[k]
    tris = []
    s = _orient(P[chain[0]], P[chain[-1]], P[p])
    for a, b in zip(chain, chain[1:]):
        tris.append([a, b, p] if s > 0 else [b, a, p])
    # the hull as a counter-clockwise cycle (next / previous maps)
    cyc = chain + [p] if s > 0 else [chain[0], p] + chain[:0:-1]
    nxt = {cyc[i]: cyc[(i + 1) % len(cyc)] for i in range(len(cyc))}
    prv = {v: u for u, v in nxt.items()}
    last = p
    for q in order[k + 1:]:
        # q is right of (or above) every inserted point; walk the visible edges around `last`
        u = last
        while _orient(P[u], P[nxt[u]], P[q]) < 0:        # edge u -> nxt[u] sees q
            tris.append([nxt[u], u, q])
            u = nxt[u]
        right = u
        u = last
        while _orient(P[prv[u]], P[u], P[q]) < 0:
            tris.append([u, prv[u], q])
            u = prv[u]
        left = u
        # the visible chain left .. right is replaced by left -> q -> right
        v = left
        while v != right:
            w = nxt[v]
            if v != left:
                del nxt[v], prv[v]
            v = w
        nxt[left], prv[q], nxt[q], prv[right] = q, left, right, q
        last = q
    return tris


def _strip_triangles(k: int) -> list[list[int]]:
    """Bottom row 0..k-1, top row k..2k-1: fan from bottom point 0 to the whole top row, then from
    top point 2k-1 to the whole bottom row (the far corner of the flip lattice from Delaunay)."""
    tris = [[0, k + j + 1, k + j] for j in range(k - 1)]
    tris += [[i, i + 1, 2 * k - 1] for i in range(k - 1)]
    return tris


def generate_args(case: dict, seed: int) -> list:
    """``[points, triangles]`` for one case; the same ``(case, seed)`` gives the same test."""
    rng = random.Random(seed)
    kind = case.get("kind")
    if kind not in KINDS:
        raise ValueError(f"edge-flip generator: unknown case kind {kind!r}; expected one of {', '.join(KINDS)}")
    start = case.get("start", "strip" if kind == "strip" else "sweep")
    if kind != "strip" and start not in START:
        raise ValueError(f"edge-flip generator: unknown start {start!r}; expected one of {', '.join(START)}")
    pts = _points(case, rng)
    scale, offset = float(case.get("scale", 1.0)), float(case.get("offset", 0.0))
    pts = [(float(x) * scale + offset, float(y) * scale + offset) for x, y in pts]
    if kind == "strip":
        tris = _strip_triangles(len(pts) // 2)
    elif start == "delaunay":
        from reference_impl import Delaunay
        tris = Delaunay(pts).simplices.tolist() if len(pts) >= 3 else []
    elif start == "fan":
        from reference_impl.exact.verify import convex_hull_exact
        hull = convex_hull_exact(_exact(pts), keep_collinear=True)
        tris = [[hull[0], hull[i], hull[i + 1]] for i in range(1, len(hull) - 1)] if len(hull) >= 3 else []
    else:
        tris = sweep_triangulation(pts)
    points = [[x, y] for x, y in pts]
    if case.get("shuffle", True):           # relabel the points (and the triangles with them)
        perm = list(range(len(points)))
        rng.shuffle(perm)                   # new index of old point i is perm[i]
        inv = [0] * len(perm)
        for old, new in enumerate(perm):
            inv[new] = old
        points = [points[inv[j]] for j in range(len(points))]
        tris = [[perm[v] for v in t] for t in tris]
        rng.shuffle(tris)
        tris = [t[r:] + t[:r] for t, r in ((t, rng.randrange(3)) for t in tris)]
        first: dict = {}
        rep = [first.setdefault(tuple(p), i) for i, p in enumerate(points)]
        tris = [[rep[v] for v in t] for t in tris]    # a repeated point is named by its first index
    return [points, tris]


def solve(points: list, triangles: list) -> list[list[int]]:
    """The reference answer: Lawson's flips, in order (each as [i, j], i < j)."""
    from reference_impl import flip_to_delaunay

    return [list(e) for e in flip_to_delaunay(points, triangles)] if triangles else []


if __name__ == "__main__":
    pts, tris = generate_args(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(pts)} {len(tris)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in pts)
                     + "".join(f"{a} {b} {c}\n" for a, b, c in tris))
