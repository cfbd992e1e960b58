"""Wrong solution for `delaunay-3d` (expected WA): the textbook Bowyer-Watson taken to 3D the way
the original tutorial does it in 2D: a fixed super-tetrahedron at +-1e5, ``numpy.linalg.det``
with an epsilon for the in-sphere test, and every tetrahedron touching the super-tetrahedron
dropped at the end.

It is right on random points in the unit cube, but on cospherical points (the cube's eight
corners in `tiny`, the grids of `degenerate`) the epsilon turns ties into flat or overlapping
tetrahedra; at 1e-300 every test is "below epsilon", and points at 1e300 lie outside the
super-tetrahedron. Killed by `tiny` (test 3, the cube) first. Run: printf '4\\n0 0 0\\n1 0 0\\n0 1 0\\n0 0 1\\n' | python3 wrong_supertetra.py
"""
import sys

import numpy as np

EPS = 1e-12
BIG = 1e5


def _orient(P, a, b, c, d):
    return np.linalg.det(np.array([P[a] - P[d], P[b] - P[d], P[c] - P[d]]))


def _insphere(P, t, p):
    rows = [P[v] - P[p] for v in t]
    m = np.array([[r[0], r[1], r[2], r @ r] for r in rows])
    return np.linalg.det(m)


def delaunay_3d(points):
    n = len(points)
    if n < 4:
        return []
    P = np.vstack([np.asarray(points, dtype=float).reshape(-1, 3),
                   [[-BIG, -BIG, -BIG], [3 * BIG, -BIG, -BIG], [-BIG, 3 * BIG, -BIG], [-BIG, -BIG, 3 * BIG]]])
    s = [n, n + 1, n + 2, n + 3]
    if _orient(P, *s) < 0:
        s[0], s[1] = s[1], s[0]
    tets = [tuple(s)]
    for p in range(n):
        bad = [t for t in tets if _insphere(P, t, p) > EPS]
        faces = {}
        for t in bad:
            for f in ((t[1], t[3], t[2]), (t[0], t[2], t[3]), (t[0], t[3], t[1]), (t[0], t[1], t[2])):
                key = frozenset(f)
                faces[key] = None if key in faces else f
        tets = [t for t in tets if t not in bad]
        for f in faces.values():
            if f is not None:
                t = (f[0], f[1], f[2], p)
                if _orient(P, *t) < 0:
                    t = (f[1], f[0], f[2], p)
                tets.append(t)
    return [list(t) for t in tets if max(t) < n]


if __name__ == "__main__":
    tok = sys.stdin.read().split()
    k = int(tok[0])
    pts = [[float(tok[1 + 3 * i]), float(tok[2 + 3 * i]), float(tok[3 + 3 * i])] for i in range(k)]
    out = delaunay_3d(pts)
    sys.stdout.write(f"{len(out)}\n" + "".join(f"{a} {b} {c} {d}\n" for a, b, c, d in out))
