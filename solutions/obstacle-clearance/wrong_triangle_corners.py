"""Wrong solution for `obstacle-clearance` (WA; killed by `degenerate`): the clearance at start and
goal measured only to the corners of the Delaunay triangle they lie in.

The shortcut: "the triangle that holds the start is empty, so its nearest obstacle is one of the
triangle's corners". The nearest obstacle of a point is the site of the Voronoi cell it lies in,
which need not be a corner of its Delaunay triangle: across the long edge of an obtuse triangle the
cell of its far corner reaches into the next triangle. With obstacles (0, 0), (10, 0), (5, 2) and
(5, -14) the start (5, -0.5) lies in the triangle (0, 0), (5, -14), (10, 0), 5.02 from its nearest
corner but only 2.5 from (5, 2). Outside the hull every obstacle is measured.

Killed by: degenerate

It is `accepted_delaunay.py` with one change, marked `SHORTCUT` below; `python -m grader stress obstacle-clearance wrong_triangle_corners.py`
finds an input that shows it. Function mode: the grader calls max_clearance(points, start, goal). Stdio mode / Kattis:
python3 wrong_triangle_corners.py < input
"""
import math
import sys

INF = -1  # the infinite vertex of ghost triangles


def exact(points):
    """Scale all coordinates by one power of two so that they become Python ints (exact)."""
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def orient(a, b, c):
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def incircle(a, b, c, d):
    adx, ady = a[0] - d[0], a[1] - d[1]
    bdx, bdy = b[0] - d[0], b[1] - d[1]
    cdx, cdy = c[0] - d[0], c[1] - d[1]
    det = ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) - (bdx * bdx + bdy * bdy) * (adx * cdy - cdx * ady)
           + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))
    return (det > 0) - (det < 0)


def hilbert_order(P, idx):
    if not idx:
        return []
    xs = [P[i][0] for i in idx]
    ys = [P[i][1] for i in idx]
    x0, y0 = min(xs), min(ys)
    span = max(max(xs) - x0, max(ys) - y0) or 1
    side = 1 << 16

    def key(i):
        x = (P[i][0] - x0) * (side - 1) // span
        y = (P[i][1] - y0) * (side - 1) // span
        d, s = 0, side >> 1
        while s:
            rx = 1 if x & s else 0
            ry = 1 if y & s else 0
            d += s * s * ((3 * rx) ^ ry)
            if ry == 0:
                if rx == 1:
                    x, y = side - 1 - x, side - 1 - y
                x, y = y, x
            s >>= 1
        return d

    return sorted(idx, key=key)


def delaunay(points):
    P = exact(points)
    first = {}
    distinct = [i for i, p in enumerate(P) if first.setdefault(p, i) == i]
    if len(distinct) < 3:
        return []
    a = distinct[0]
    b = distinct[1]
    c = next((i for i in distinct[2:] if orient(P[a], P[b], P[i]) != 0), None)
    if c is None:
        return []  # all collinear
    if orient(P[a], P[b], P[c]) < 0:
        b, c = c, b
    tri_of = {}  # directed edge (u, v) -> third vertex w of the triangle (u, v, w), CCW

    def add(u, v, w):
        tri_of[(u, v)] = w
        tri_of[(v, w)] = u
        tri_of[(w, u)] = v

    def remove(u, v, w):
        del tri_of[(u, v)], tri_of[(v, w)], tri_of[(w, u)]

    add(a, b, c)
    add(b, a, INF)
    add(c, b, INF)
    add(a, c, INF)

    def conflict(u, v, w, p):
        if w == INF:
            return in_ghost(u, v, p)
        if u == INF:
            return in_ghost(v, w, p)
        if v == INF:
            return in_ghost(w, u, p)
        return incircle(P[u], P[v], P[w], P[p]) > 0

    def in_ghost(u, v, p):  # ghost (u, v, INF): the real triangle is on the right of u->v
        s = orient(P[u], P[v], P[p])
        if s != 0:
            return s > 0
        pu, pv, pp = P[u], P[v], P[p]
        return min(pu[0], pv[0]) <= pp[0] <= max(pu[0], pv[0]) and min(pu[1], pv[1]) <= pp[1] <= max(pu[1], pv[1])

    last = (a, b)
    for p in hilbert_order(P, [i for i in distinct if i not in (a, b, c)]):
        # visibility walk to a triangle in conflict with p
        u, v = last if last in tri_of else next(iter(tri_of))
        w = tri_of[(u, v)]
        if INF in (u, v, w):  # start from the real triangle next to this ghost
            while w != INF:
                u, v, w = v, w, u
            u, v = v, u
            w = tri_of[(u, v)]
        pp = P[p]
        while True:
            if orient(P[u], P[v], pp) < 0:
                u, v = v, u
            elif orient(P[v], P[w], pp) < 0:
                u, v = w, v
            elif orient(P[w], P[u], pp) < 0:
                u, v = u, w
            else:
                break
            w = tri_of[(u, v)]
            if w == INF:
                break  # crossed the hull: p is outside, and this ghost conflicts with it
        # grow the cavity from (u, v, w)
        start = (u, v, w)
        bad = {start}
        stack = [start]
        boundary = []
        while stack:
            t = stack.pop()
            for x, y in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
                z = tri_of.get((y, x))
                nb = (y, x, z)
                key = None
                for rot in (nb, (x, z, y), (z, y, x)):
                    if rot in bad:
                        key = rot
                        break
                if key is not None:
                    continue
                if conflict(y, x, z, p):
                    bad.add(nb)
                    stack.append(nb)
                else:
                    boundary.append((x, y))
        for t in bad:
            remove(*t)
        for x, y in boundary:
            add(x, y, p)
        last = boundary[0]
    out = []
    seen = set()
    for (u, v), w in tri_of.items():
        if INF in (u, v, w):
            continue
        key = min((u, v, w), (v, w, u), (w, u, v))
        if key not in seen:
            seen.add(key)
            out.append(list(key))
    return out



def locate(P, tris, q):
    """Index of a triangle (closed) holding q, or -1 for the outer face."""
    for k, (a, b, c) in enumerate(tris):
        if orient(P[a], P[b], q) >= 0 and orient(P[b], P[c], q) >= 0 and orient(P[c], P[a], q) >= 0:
            return k
    return -1


def max_clearance(points, start, goal):
    if not points:
        return math.inf
    pts = [(float(x), float(y)) for x, y in points]
    s, g = (float(start[0]), float(start[1])), (float(goal[0]), float(goal[1]))
    tris = delaunay(pts)
    if not tris:
        return min(min(math.hypot(x - s[0], y - s[1]) for x, y in pts), min(math.hypot(x - g[0], y - g[1]) for x, y in pts))
    E = exact(pts + [s, g])
    P, qs, qg = E[:-2], E[-2], E[-1]
    outer = len(tris)
    fs, fg = locate(P, tris, qs), locate(P, tris, qg)

    def clearance(q, f):
        # SHORTCUT: inside the hull, only the corners of q's own triangle are measured
        near = tris[f] if f >= 0 else range(len(pts))
        return min(math.hypot(pts[i][0] - q[0], pts[i][1] - q[1]) for i in near)

    ends = min(clearance(s, fs), clearance(g, fg))
    if ends == 0.0:
        return ends
    fs, fg = (outer if fs < 0 else fs), (outer if fg < 0 else fg)
    if fs == fg:
        return ends
    face = {}
    for k, (a, b, c) in enumerate(tris):
        for u, v in ((a, b), (b, c), (c, a)):
            face[(u, v)] = k
    edges = []
    for (u, v), k in face.items():
        other = face.get((v, u), outer)
        if other == outer or k < other:
            edges.append((0.5 * math.hypot(pts[u][0] - pts[v][0], pts[u][1] - pts[v][1]), k, other))
    edges.sort(reverse=True)
    parent = list(range(outer + 1))

    def root(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for w, a, b in edges:
        ra, rb = root(a), root(b)
        if ra != rb:
            parent[ra] = rb
            if root(fs) == root(fg):
                return min(ends, w)
    return ends


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    vals = [float(t) for t in data[1:2 * n + 5]]
    pts = [(vals[2 * i], vals[2 * i + 1]) for i in range(n)]
    print(repr(max_clearance(pts, vals[2 * n:2 * n + 2], vals[2 * n + 2:2 * n + 4])))


if __name__ == "__main__":
    main()
