"""Wrong answer: the in-circle test is a float determinant compared with an epsilon (``det >
1e-9``), as the original tutorial suggests for "near-zero" cases
(reference_impl/teaching/tutorial_bugs.py); a large super-triangle, oriented triangles and a correct
cavity boundary otherwise.

Why it is wrong: a fixed threshold depends on the scale. At 1e-300 every determinant is below
it (no point is ever "inside"); near ties it decides the sign instead of the geometry.
Killed by: degenerate (nearly cocircular points, coordinates near 1e-300).

Function mode: delaunay(points) / bowyer_watson(points). Stdio: python3 wrong_epsilon.py < input

Example:
    >>> sorted(map(sorted, delaunay([[0, 0], [1, 0], [0, 1]])))
    [[0, 1, 2]]
"""
import sys


def in_circle(a, b, c, d):
    (ax, ay), (bx, by), (cx, cy) = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    return ((ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
            + (cx * cx + cy * cy) * (ax * by - bx * ay)) > 1e-9


def delaunay(points):
    P = [(float(x), float(y)) for x, y in points]
    first = {}
    ids = [i for i, p in enumerate(P) if first.setdefault(p, i) == i]
    if len(ids) < 3:
        return []
    x0, y0 = min(p[0] for p in P), min(p[1] for p in P)
    span = max(max(p[0] for p in P) - x0, max(p[1] for p in P) - y0) or 1.0
    n, M = len(P), 10 ** 6 * span
    P += [(x0 - 3 * M, y0 - 3 * M), (x0 + 3 * M, y0 - 3 * M), (x0, y0 + 3 * M)]
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
