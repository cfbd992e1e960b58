"""Wrong solution for `edge-flip` (expected WA): one pass over the starting edges, flipping each
one that is illegal at its turn, but never looking again at the edges a flip creates or changes.

This is the mistake of reading "flip every illegal edge" as one sweep: a flip makes the four outer
edges of its quadrilateral possibly illegal, and they must be re-checked (Lawson keeps a stack).
The final triangulation is then not Delaunay as soon as flips cascade: killed by `tiny` (random
points) and every larger group. Predicates are exact (Python integers), so only the bookkeeping
is wrong. Run: printf '4 2\\n0 0\\n4 0\\n4 1\\n0 3\\n0 1 3\\n1 2 3\\n' | python3 wrong_single_pass.py
"""
import sys


def _exact(points):
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([max(dx, dy) for (_, dx), (_, dy) in ratios], default=1)
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def _inside(a, b, c, d):
    adx, ady, bdx, bdy, cdx, cdy = a[0] - d[0], a[1] - d[1], b[0] - d[0], b[1] - d[1], c[0] - d[0], c[1] - d[1]
    return ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
            + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady)) > 0


def flip_to_delaunay(points, triangles):
    P = _exact(points)
    opp = {}
    for a, b, c in triangles:
        opp[(a, b)], opp[(b, c)], opp[(c, a)] = c, a, b
    flips = []
    for a, b in [e for e in opp if e[0] < e[1]]:      # the starting edges, once each
        c, d = opp.get((a, b)), opp.get((b, a))
        if c is None or d is None or not _inside(P[a], P[b], P[c], P[d]):
            continue
        for e in ((a, b), (b, c), (c, a), (b, a), (a, d), (d, b)):
            del opp[e]
        opp[(c, a)], opp[(a, d)], opp[(d, c)] = d, c, a
        opp[(d, b)], opp[(b, c)], opp[(c, d)] = c, d, b
        flips.append([a, b])
    return flips


if __name__ == "__main__":
    tok = sys.stdin.read().split()
    n, m = int(tok[0]), int(tok[1])
    pts = [[float(tok[2 + 2 * i]), float(tok[3 + 2 * i])] for i in range(n)]
    s = 2 + 2 * n
    tris = [[int(tok[s + 3 * k]), int(tok[s + 3 * k + 1]), int(tok[s + 3 * k + 2])] for k in range(m)]
    out = flip_to_delaunay(pts, tris)
    sys.stdout.write(f"{len(out)}\n" + "".join(f"{a} {b}\n" for a, b in out))
