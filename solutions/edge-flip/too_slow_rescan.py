"""Too-slow solution for `edge-flip` (expected TLE): correct flips (exact predicates), but after
every flip it rebuilds the edge list from the triangle list and scans it from the start for the
next illegal edge: O(n) per flip, O(n * flips) in all. Fine on small meshes, too slow on `large`.

Run: printf '4 2\\n0 0\\n4 0\\n4 1\\n0 3\\n0 1 3\\n1 2 3\\n' | python3 too_slow_rescan.py
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
    tris = [tuple(t) for t in triangles]
    flips = []
    while True:
        opp = {}
        for a, b, c in tris:                       # rebuilt from scratch after every flip
            opp[(a, b)], opp[(b, c)], opp[(c, a)] = c, a, b
        for (a, b), c in opp.items():
            d = opp.get((b, a))
            if a < b and d is not None and _inside(P[a], P[b], P[c], P[d]):
                tris = [t for t in tris if set(t) not in ({a, b, c}, {a, b, d})] + [(c, a, d), (d, b, c)]
                flips.append([a, b])
                break
        else:
            return flips


if __name__ == "__main__":
    tok = sys.stdin.read().split()
    n, m = int(tok[0]), int(tok[1])
    pts = [[float(tok[2 + 2 * i]), float(tok[3 + 2 * i])] for i in range(n)]
    s = 2 + 2 * n
    tris = [[int(tok[s + 3 * k]), int(tok[s + 3 * k + 1]), int(tok[s + 3 * k + 2])] for k in range(m)]
    out = flip_to_delaunay(pts, tris)
    sys.stdout.write(f"{len(out)}\n" + "".join(f"{a} {b}\n" for a, b in out))
