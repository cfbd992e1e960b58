"""Wrong solution for `edge-flip` (expected WA): Lawson's algorithm done right, but the in-circle
test is ``numpy.linalg.det`` of the 3x3 lifted matrix with an epsilon, as in the original
tutorial's code: ``det > 1e-12`` means "inside".

At 1e-300 every determinant is below the epsilon, so nothing is flipped and the result is not
Delaunay; at 1e9 offsets the rounding error is far above the epsilon. Killed by `degenerate`.
Run: printf '4 2\\n0 0\\n4 0\\n4 1\\n0 3\\n0 1 3\\n1 2 3\\n' | python3 wrong_float_incircle.py
"""
import sys

import numpy as np

EPS = 1e-12


def _inside(a, b, c, d):
    m = np.array([[a[0] - d[0], a[1] - d[1], (a[0] - d[0]) ** 2 + (a[1] - d[1]) ** 2],
                  [b[0] - d[0], b[1] - d[1], (b[0] - d[0]) ** 2 + (b[1] - d[1]) ** 2],
                  [c[0] - d[0], c[1] - d[1], (c[0] - d[0]) ** 2 + (c[1] - d[1]) ** 2]])
    return np.linalg.det(m) > EPS


def flip_to_delaunay(points, triangles):
    P = [(float(x), float(y)) for x, y in points]
    opp = {}
    for a, b, c in triangles:
        opp[(a, b)], opp[(b, c)], opp[(c, a)] = c, a, b
    stack = [e for e in opp if e[0] < e[1]]
    flips = []
    while stack and len(flips) < 10 * len(P) * len(P):
        a, b = stack.pop()
        c, d = opp.get((a, b)), opp.get((b, a))
        if c is None or d is None or not _inside(P[a], P[b], P[c], P[d]):
            continue
        for e in ((a, b), (b, c), (c, a), (b, a), (a, d), (d, b)):
            del opp[e]
        opp[(c, a)], opp[(a, d)], opp[(d, c)] = d, c, a
        opp[(d, b)], opp[(b, c)], opp[(c, d)] = c, d, b
        flips.append([a, b])
        stack += [(c, a), (a, d), (d, b), (b, c)]
    return flips


if __name__ == "__main__":
    tok = sys.stdin.read().split()
    n, m = int(tok[0]), int(tok[1])
    pts = [[float(tok[2 + 2 * i]), float(tok[3 + 2 * i])] for i in range(n)]
    s = 2 + 2 * n
    tris = [[int(tok[s + 3 * k]), int(tok[s + 3 * k + 1]), int(tok[s + 3 * k + 2])] for k in range(m)]
    out = flip_to_delaunay(pts, tris)
    sys.stdout.write(f"{len(out)}\n" + "".join(f"{a} {b}\n" for a, b in out))
