"""Wrong answer: the cavity boundary is kept as undirected edges (sorted pairs), so new triangles
come out in either orientation, and the in-circle determinant is read as "inside" when positive,
which is only true for counter-clockwise triangles. Exact predicates, a large super-triangle,
and the output is oriented counter-clockwise at the end (so only the triangulation is wrong).

Killed by: sample.

Function mode: delaunay(points) / bowyer_watson(points). Stdio: python3 wrong_unoriented.py < input

Example:
    >>> delaunay([[0, 0], [1, 0], [0, 1]])     # already wrong: the one triangle is lost
    []
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
        count = {}
        for t in bad:
            for k in range(3):
                e = tuple(sorted((t[k], t[(k + 1) % 3])))
                count[e] = count.get(e, 0) + 1
        dead = set(bad)
        tris = [t for t in tris if t not in dead]
        tris += [(u, v, p) for (u, v), c in count.items() if c == 1]
    return [list(t) if orient(P[t[0]], P[t[1]], P[t[2]]) > 0 else [t[1], t[0], t[2]]
            for t in tris if max(t) < n]


def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


bowyer_watson = delaunay


def main():
    data = sys.stdin.buffer.read().split()
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(int(data[0]))]
    tris = delaunay(pts)
    sys.stdout.write(f"{len(tris)}\n" + "".join(f"{a} {b} {c}\n" for a, b, c in tris))


if __name__ == "__main__":
    main()
