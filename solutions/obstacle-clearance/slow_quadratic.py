"""Correct but too slow for `obstacle-clearance`: the bottleneck search of accepted_delaunay.py on
a Bowyer-Watson triangulation that scans every triangle at each insertion (quadratic; the same
code as solutions/delaunay/scan_quadratic.py). Expected verdict: TLE on the large group.

Function mode: max_clearance(points, start, goal). Stdio: python3 slow_quadratic.py < input
"""
import math
import sys


def exact(points):
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def orient(a, b, c):
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def in_circle(a, b, c, d):
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    (ax, ay), (bx, by), (cx, cy) = rows
    det = ((ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
           + (cx * cx + cy * cy) * (ax * by - bx * ay))
    return det > 0


def delaunay(points):
    P = exact(points)
    first = {}
    ids = [i for i, p in enumerate(P) if first.setdefault(p, i) == i]
    if len(ids) < 3:
        return []
    a, b = ids[0], ids[1]
    c = next((i for i in ids[2:] if orient(P[a], P[b], P[i]) != 0), None)
    if c is None:
        return []
    if orient(P[a], P[b], P[c]) < 0:
        b, c = c, b
    # None is the infinite vertex; ghost (u, v, None) lies across hull edge u->v (real side on the right)
    tris = [(a, b, c), (b, a, None), (c, b, None), (a, c, None)]

    def bad(t, p):
        u, v, w = t
        if w is None:
            s = orient(P[u], P[v], P[p])
            if s:
                return s > 0
            return min(P[u], P[v]) < P[p] < max(P[u], P[v])
        return in_circle(P[u], P[v], P[w], P[p])

    for p in ids:
        if p in (a, b, c):
            continue
        cavity = [t for t in tris if bad(t, p)]
        edges = {}
        for u, v, w in cavity:
            for e in ((u, v), (v, w), (w, u)):
                edges[e] = True
        boundary = [e for e in edges if (e[1], e[0]) not in edges]
        dead = set(cavity)
        tris = [t for t in tris if t not in dead]
        for u, v in boundary:
            if u is None:
                tris.append((v, p, None))
            elif v is None:
                tris.append((p, u, None))
            else:
                tris.append((u, v, p))
    return [list(t) for t in tris if t[2] is not None]



def locate(P, tris, q):
    """Index of a triangle (closed) holding q, or -1 for the outer face."""
    for k, (a, b, c) in enumerate(tris):
        if orient(P[a], P[b], q) >= 0 and orient(P[b], P[c], q) >= 0 and orient(P[c], P[a], q) >= 0:
            return k
    return -1


def max_clearance(points, start, goal):
    if not points:
        return math.inf
    pts = [(float(x), float(y)) for x, y in points]
    s, g = (float(start[0]), float(start[1])), (float(goal[0]), float(goal[1]))
    ends = min(min(math.hypot(x - s[0], y - s[1]) for x, y in pts), min(math.hypot(x - g[0], y - g[1]) for x, y in pts))
    tris = delaunay(pts)
    if not tris or ends == 0.0:
        return ends
    E = exact(pts + [s, g])
    P, qs, qg = E[:-2], E[-2], E[-1]
    outer = len(tris)
    fs, fg = locate(P, tris, qs), locate(P, tris, qg)
    fs, fg = (outer if fs < 0 else fs), (outer if fg < 0 else fg)
    if fs == fg:
        return ends
    face = {}
    for k, (a, b, c) in enumerate(tris):
        for u, v in ((a, b), (b, c), (c, a)):
            face[(u, v)] = k
    edges = []
    for (u, v), k in face.items():
        other = face.get((v, u), outer)
        if other == outer or k < other:
            edges.append((0.5 * math.hypot(pts[u][0] - pts[v][0], pts[u][1] - pts[v][1]), k, other))
    edges.sort(reverse=True)
    parent = list(range(outer + 1))

    def root(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for w, a, b in edges:
        ra, rb = root(a), root(b)
        if ra != rb:
            parent[ra] = rb
            if root(fs) == root(fg):
                return min(ends, w)
    return ends


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    vals = [float(t) for t in data[1:2 * n + 5]]
    pts = [(vals[2 * i], vals[2 * i + 1]) for i in range(n)]
    print(repr(max_clearance(pts, vals[2 * n:2 * n + 2], vals[2 * n + 2:2 * n + 4])))


if __name__ == "__main__":
    main()
