"""Accepted solution for `bowyer-watson-timed` (AC): the quadratic scan of `scan_quadratic.py` with
every coordinate a `fractions.Fraction`, the exact arithmetic a student reaches for first.

Exact, but each Fraction operation normalises by a gcd: at n = 250 this takes about 2.6 s of CPU,
where the same scan on Python integers (every double is an integer times a power of two: scale
all coordinates by one power of two) takes 0.07 s; the 6 s limit admits both, and not the cubic
`too_slow_recheck.py` (about 12 s). Function mode: the grader calls bowyer_watson(points). Stdio
mode / Kattis: python3 accepted_fraction.py < input
"""
import sys
from fractions import Fraction


def exact(points):
    return [(Fraction(float(x)), Fraction(float(y))) for x, y in points]


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


bowyer_watson = delaunay


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    tris = delaunay(pts)
    sys.stdout.write(f"{len(tris)}\n" + "".join(f"{a} {b} {c}\n" for a, b, c in tris))


if __name__ == "__main__":
    main()
