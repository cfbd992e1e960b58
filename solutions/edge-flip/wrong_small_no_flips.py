"""Wrong solution for `edge-flip` (WA; killed by `exhaustive`): special-cases small inputs.

The shortcut: "with four points or fewer there is nothing to flip". Two triangles of a convex
quadrilateral share a diagonal, and it is the wrong one when the fourth corner lies inside the
circle of the other three.

Killed by: exhaustive

It is `accepted_lawson.py` with one change, marked `SHORTCUT` below; `python -m grader stress edge-flip wrong_small_no_flips.py`
finds an input that shows it. Function mode: the grader calls flip_to_delaunay(points, triangles). Stdio mode / Kattis:
python3 wrong_small_no_flips.py < input
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


_flip_to_delaunay = flip_to_delaunay


def flip_to_delaunay(points, triangles):  # SHORTCUT: small inputs need no flip
    if len(points) <= 4:
        return []
    return _flip_to_delaunay(points, triangles)


if __name__ == "__main__":
    main()
