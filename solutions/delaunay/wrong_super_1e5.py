"""Wrong answer: the original tutorial's fixed super-triangle (reference_impl/teaching/tutorial_bugs.py) at
+-1e5 (exact predicates otherwise, and a correct cavity boundary).

Why it is wrong: a point outside the fixed super-triangle lies in no circumcircle, or in the
wrong ones, so points far from the origin are skipped or mis-connected.
Killed by: tiny, the tutorial's own test at 1e6: (1e6, 1e6), (2e6, 3e6), (4e6, 1e6).

Function mode: delaunay(points) / bowyer_watson(points). Stdio: python3 wrong_super_1e5.py < input

Example:
    >>> sorted(map(sorted, delaunay([[0, 0], [1, 0], [0, 1]])))
    [[0, 1, 2]]
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
    unit = exact([(1.0, 1.0)] + list(points))[0][0]  # 1.0 in the common integer scale
    n, M = len(P), 10 ** 5 * unit
    P += [(-M, -M), (M, -M), (0, M)]
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
