"""Wrong answer: the original tutorial's cavity boundary (reference_impl/teaching/tutorial_bugs.py), which
keeps one copy of an edge shared by two bad triangles (it should drop both). Exact predicates
and a large super-triangle otherwise.

Why it is wrong: the kept inner edge makes new triangles that overlap.
Killed by: tiny (a square with its centre, or ten random points).

Function mode: delaunay(points) / bowyer_watson(points). Stdio: python3 wrong_shared_edges.py < input

Example:
    >>> len(delaunay([[7, 4], [8, 9], [2, 4]]))       # the same triangle twice
    2
"""
import sys


def exact(points):
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def in_circle(a, b, c, d):
    (ax, ay), (bx, by), (cx, cy) = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    return ((ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
            + (cx * cx + cy * cy) * (ax * by - bx * ay)) > 0


def delaunay(points):
    P = exact(points)
    first = {}
    ids = [i for i, p in enumerate(P) if first.setdefault(p, i) == i]
    if len(ids) < 3:
        return []
    x0, y0 = min(p[0] for p in P), min(p[1] for p in P)
    span = max(max(p[0] for p in P) - x0, max(p[1] for p in P) - y0) or 1
    n, M = len(P), 10 ** 6 * span
    P += [(x0 - 3 * M, y0 - 3 * M), (x0 + 3 * M, y0 - 3 * M), (x0, y0 + 3 * M)]
    tris = [(n, n + 1, n + 2)]
    for p in ids:
        bad = [t for t in tris if in_circle(P[t[0]], P[t[1]], P[t[2]], P[p])]
        boundary = []
        for t in bad:
            for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
                if e[::-1] not in boundary:
                    boundary.append(e)
        dead = set(bad)
        tris = [t for t in tris if t not in dead]
        tris += [(u, v, p) for u, v in boundary]
    return [list(t) for t in tris if max(t) < n]


bowyer_watson = delaunay


def main():
    data = sys.stdin.buffer.read().split()
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(int(data[0]))]
    tris = delaunay(pts)
    sys.stdout.write(f"{len(tris)}\n" + "".join(f"{a} {b} {c}\n" for a, b, c in tris))


if __name__ == "__main__":
    main()
