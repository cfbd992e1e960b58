"""Accepted solution for `voronoi` (AC): `accepted_clip.py`, with an extra vertex in the middle of
every edge of every cell.

The statement allows extra vertices on an edge; this answer has twice the vertices a correct
answer needs, which the checker's stated size bounds ($2n + 16$ per cell, $20n + 32$ in all)
admit. Function mode: the grader calls voronoi_cells(points, bbox). Stdio mode / Kattis:
python3 accepted_midpoints.py < input
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



def clip(poly, nx, ny, c):
    """Sutherland-Hodgman: the part of the convex polygon where nx * x + ny * y <= c."""
    out = []
    m = len(poly)
    for k in range(m):
        px, py = poly[k - 1]
        qx, qy = poly[k]
        hp = nx * px + ny * py - c
        hq = nx * qx + ny * qy - c
        if (hp < 0 < hq) or (hq < 0 < hp):
            t = hp / (hp - hq)
            out.append((px + t * (qx - px), py + t * (qy - py)))
        if hq <= 0:
            out.append((qx, qy))
    return out


def voronoi_cells(points, bbox):
    pts = [(float(x), float(y)) for x, y in points]
    n = len(pts)
    big = max([abs(c) for p in pts for c in p] + [abs(float(v)) for v in bbox]) or 1.0
    e = math.frexp(big)[1]
    p = [(math.ldexp(x, -e), math.ldexp(y, -e)) for x, y in pts]          # unit scale: exact
    x0, y0, x1, y1 = (math.ldexp(float(v), -e) for v in bbox)
    first = {}
    rep = [first.setdefault(q, i) for i, q in enumerate(pts)]
    nbrs = {i: set() for i in first.values()}
    tris = delaunay(pts)
    if tris:
        for a, b, c in tris:
            for u, v in ((a, b), (b, c), (c, a)):
                nbrs[u].add(v)
                nbrs[v].add(u)
    else:                              # collinear (or < 3 distinct points): neighbours along the line
        chain = sorted(first.values(), key=lambda i: pts[i])
        for u, v in zip(chain, chain[1:]):
            nbrs[u].add(v)
            nbrs[v].add(u)
    cells = {}
    for i in nbrs:
        poly = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        px, py = p[i]
        for j in nbrs[i]:
            qx, qy = p[j]
            # closer to i than to j: (q - p) . x <= (|q|^2 - |p|^2) / 2, written around the midpoint
            nx, ny = qx - px, qy - py
            poly = clip(poly, nx, ny, nx * (0.5 * px + 0.5 * qx) + ny * (0.5 * py + 0.5 * qy))
            if not poly:
                break
        dedup = [q for k, q in enumerate(poly) if q != poly[k - 1]] if len(poly) > 1 else poly
        cells[i] = [[math.ldexp(x, e), math.ldexp(y, e)] for x, y in dedup] if len(dedup) >= 3 else []
    return [cells[rep[i]] for i in range(n)]


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    vals = [float(t) for t in data[1:2 * n + 5]]
    cells = voronoi_cells([(vals[2 * i], vals[2 * i + 1]) for i in range(n)], vals[2 * n:2 * n + 4])
    sys.stdout.write("".join(" ".join([str(len(c))] + [f"{x!r} {y!r}" for x, y in c]) + "\n" for c in cells))


_voronoi_cells = voronoi_cells


def voronoi_cells(points, bbox):  # every edge split at its midpoint
    cells = []
    for cell in _voronoi_cells(points, bbox):
        out = []
        for k, (x, y) in enumerate(cell):
            nx, ny = cell[(k + 1) % len(cell)]
            out += [[x, y], [0.5 * x + 0.5 * nx, 0.5 * y + 0.5 * ny]]
        cells.append(out)
    return cells


if __name__ == "__main__":
    main()
