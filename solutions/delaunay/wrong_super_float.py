"""Wrong answer: Bowyer-Watson with a finite super-triangle (10^6 x the bounding box) and float
predicates. Everything else is right (points normalised to the unit box, triangles kept
counter-clockwise, the cavity boundary drops edges shared by two bad triangles). It passes every
test of the course except the nearly flat hull triangles.

Why it is wrong: a nearly flat hull triangle has a huge circumcircle that contains a super
vertex, so it is never created, and float incircle signs near ties come from rounding.
Killed by: degenerate. On `bowyer-watson-timed` only the input (0, 0), (1, 1e-12), (2, 0), (1, 1)
kills it; on `delaunay` 64 nearly cocircular points already do (overlapping triangles).

Function mode: delaunay(points) / bowyer_watson(points). Stdio: python3 wrong_super_float.py < input

Example:
    >>> sorted(map(sorted, delaunay([[0, 0], [1, 0], [0, 1]])))
    [[0, 1, 2]]
"""
import math
import sys


def in_circle(a, b, c, d):
    (ax, ay), (bx, by), (cx, cy) = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    return ((ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
            + (cx * cx + cy * cy) * (ax * by - bx * ay)) > 0


def delaunay(points):
    first = {}
    ids = [i for i, p in enumerate(points) if first.setdefault(tuple(p), i) == i]
    if len(ids) < 3:
        return []
    x0, y0 = min(p[0] for p in points), min(p[1] for p in points)
    span = max(max(p[0] for p in points) - x0, max(p[1] for p in points) - y0) or 1.0
    s = 2.0 ** -math.frexp(span)[1]  # a power of two: scaling adds no rounding
    P = [((p[0] - x0) * s, (p[1] - y0) * s) for p in points]
    n, M = len(P), 1e6
    P += [(-3 * M, -3 * M), (3 * M, -3 * M), (0.5, 3 * M)]
    tris = [(n, n + 1, n + 2)]
    for p in ids:
        bad = [t for t in tris if in_circle(P[t[0]], P[t[1]], P[t[2]], P[p])]
        edges = {(t[k], t[(k + 1) % 3]) for t in bad for k in range(3)}
        dead = set(bad)
        tris = [t for t in tris if t not in dead]
        tris += [(u, v, p) for u, v in edges if (v, u) not in edges]
    return [list(t) for t in tris if max(t) < n]


bowyer_watson = delaunay


def main():
    data = sys.stdin.buffer.read().split()
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(int(data[0]))]
    tris = delaunay(pts)
    sys.stdout.write(f"{len(tris)}\n" + "".join(f"{a} {b} {c}\n" for a, b, c in tris))


if __name__ == "__main__":
    main()
