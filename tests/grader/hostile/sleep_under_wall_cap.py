# expect: TLE
# A correct answer (brute force, fine for the fixture's few points) after sleeping 3.5 s per test:
# just under the old wall cap (3 x the 1 s limit + 1 s), so it was AC and held a judge for
# minutes on a real problem. A test is now stopped once it has been idle (neither computing nor
# waiting for a CPU) for 0.5 x the limit + 1 s.
import time
from itertools import combinations


def _orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _inside(a, b, c, d):
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    (ax, ay), (bx, by), (cx, cy) = rows
    return ((ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
            + (cx * cx + cy * cy) * (ax * by - bx * ay)) > 0


def delaunay(points):
    time.sleep(3.5)
    out = []
    for i, j, k in combinations(range(len(points)), 3):
        a, b, c = points[i], points[j], points[k]
        s = _orient(a, b, c)
        if s == 0:
            continue
        if s < 0:
            j, k, b, c = k, j, c, b
        if not any(_inside(a, b, c, p) for p in points):
            out.append([i, j, k])
    return out
