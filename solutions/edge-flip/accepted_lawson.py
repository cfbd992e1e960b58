"""Accepted solution for `edge-flip`: Lawson's algorithm with a stack of edges to re-check.

Each flip pushes the four outer edges of its quadrilateral, so the work is O(n + flips).
Predicates: a floating-point in-circle test with a conservative error bound, decided exactly with
Python integers (every coordinate times one common power of two) when the bound is not met.
Standard library only. Function mode: ``flip_to_delaunay(points, triangles)``; as a program it
reads the text format from stdin:

    printf '4 2\\n0 0\\n4 0\\n4 1\\n0 3\\n0 1 3\\n1 2 3\\n' | python3 solutions/edge-flip/accepted_lawson.py

Example:
    >>> flip_to_delaunay([[0, 0], [4, 0], [4, 1], [0, 3]], [[0, 1, 3], [1, 2, 3]])
    [[1, 3]]
"""
import sys


def _exact(points):
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([max(dx, dy) for (_, dx), (_, dy) in ratios], default=1)
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def _incircle_value(ax, ay, bx, by, cx, cy, dx, dy):
    adx, ady, bdx, bdy, cdx, cdy = ax - dx, ay - dy, bx - dx, by - dy, cx - dx, cy - dy
    alift, blift, clift = adx * adx + ady * ady, bdx * bdx + bdy * bdy, cdx * cdx + cdy * cdy
    det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady)
    return det, alift, blift, clift, adx, ady, bdx, bdy, cdx, cdy


def flip_to_delaunay(points, triangles):
    F = [(float(x), float(y)) for x, y in points]
    exact = []

    def inside(a, b, c, d):
        """d strictly inside the circumcircle of counter-clockwise a, b, c?"""
        det, al, bl, cl, adx, ady, bdx, bdy, cdx, cdy = _incircle_value(*F[a], *F[b], *F[c], *F[d])
        perm = (al * (abs(bdx * cdy) + abs(cdx * bdy)) + bl * (abs(cdx * ady) + abs(adx * cdy))
                + cl * (abs(adx * bdy) + abs(bdx * ady)))
        bound = 1e-14 * perm + 1e-290
        if bound < float("inf") and abs(det) > bound:
            return det > 0
        if not exact:
            exact.append(_exact(F))
        P = exact[0]
        return _incircle_value(*P[a], *P[b], *P[c], *P[d])[0] > 0

    opp = {}
    for a, b, c in triangles:
        opp[(a, b)], opp[(b, c)], opp[(c, a)] = c, a, b
    stack = [e for e in opp if e[0] < e[1]]
    flips = []
    while stack:
        a, b = stack.pop()
        c, d = opp.get((a, b)), opp.get((b, a))
        if c is None or d is None or not inside(a, b, c, d):
            continue               # no longer an edge, a hull edge, or locally Delaunay
        for e in ((a, b), (b, c), (c, a), (b, a), (a, d), (d, b)):
            del opp[e]
        opp[(c, a)], opp[(a, d)], opp[(d, c)] = d, c, a
        opp[(d, b)], opp[(b, c)], opp[(c, d)] = c, d, b
        flips.append([min(a, b), max(a, b)])
        stack += [(c, a), (a, d), (d, b), (b, c)]
    return flips


def main():
    tok = sys.stdin.read().split()
    n, m = int(tok[0]), int(tok[1])
    pts = [[float(tok[2 + 2 * i]), float(tok[3 + 2 * i])] for i in range(n)]
    b = 2 + 2 * n
    tris = [[int(tok[b + 3 * k]), int(tok[b + 3 * k + 1]), int(tok[b + 3 * k + 2])] for k in range(m)]
    flips = flip_to_delaunay(pts, tris)
    sys.stdout.write(f"{len(flips)}\n" + "".join(f"{a} {b}\n" for a, b in flips))


if __name__ == "__main__":
    main()
