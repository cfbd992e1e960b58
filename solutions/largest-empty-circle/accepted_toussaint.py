"""Accepted solution for `largest-empty-circle`: Delaunay triangulation (exact Bowyer-Watson with
a visibility walk, expected O(n log n)), then the candidates of Toussaint's method.

The distance to the nearest point is convex inside each Voronoi cell, so the best centre is a
vertex of some cell clipped to the hull: a circumcentre of a Delaunay triangle inside the hull,
or a point where a Voronoi edge crosses the hull boundary (found by walking each hull edge
through the cells it crosses, with exact integer comparisons). The triangulation code is the
same as in solutions/delaunay/accepted_walk.py (a Kattis submission is one file).

Function mode: largest_empty_circle(points). Stdio: python3 accepted_toussaint.py < input

Example:
    >>> largest_empty_circle([[0, 0], [4, 0], [2, 1]])
    [1.25, 0.0, 1.25]
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



def convex_hull(P):
    """Strict convex hull of exact points P (indices, counter-clockwise), monotone chain; a
    repeated point is represented by its first index."""
    first = {}
    order = sorted((i for i, q in enumerate(P) if first.setdefault(q, i) == i), key=lambda i: P[i])

    def chain(ids):
        out = []
        for i in ids:
            while len(out) >= 2 and orient(P[out[-2]], P[out[-1]], P[i]) <= 0:
                out.pop()
            if not out or P[out[-1]] != P[i]:
                out.append(i)
        return out

    lower, upper = chain(order), chain(order[::-1])
    return lower[:-1] + upper[:-1]


def circumcentre(p, a, b, c):
    """Circumcentre of the float points a, b, c (computed relative to a)."""
    bx, by = p[b][0] - p[a][0], p[b][1] - p[a][1]
    cx, cy = p[c][0] - p[a][0], p[c][1] - p[a][1]
    d = 2.0 * (bx * cy - by * cx)
    bb, cc = bx * bx + by * by, cx * cx + cy * cy
    return p[a][0] + (cy * bb - by * cc) / d, p[a][1] + (bx * cc - cx * bb) / d


def in_hull(H, q, tol):
    """Is q in the convex polygon H (float vertices, CCW), up to tol times an edge's length (q may
    stand outside an edge by that much)? Binary search over the fan. The tolerance is relative to
    the edge, not absolute: far from the origin a hull can be tiny next to its coordinates (three
    points near 2^30 one unit apart), and an absolute tolerance then let a circumcentre a whole
    unit outside the hull count as inside."""

    def side(a, b):
        return (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])

    def outside(a, b):  # beyond edge a -> b by more than tol * |ab|: side = |ab| * signed distance
        return side(a, b) < -tol * ((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2)

    if outside(H[0], H[1]) or outside(H[-1], H[0]):
        return False
    lo, hi = 1, len(H) - 2
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if side(H[0], H[mid]) >= 0:
            lo = mid
        else:
            hi = mid - 1
    return not outside(H[lo], H[lo + 1])


def largest_empty_circle(points):
    pts = [(float(x), float(y)) for x, y in points]
    big = max(abs(c) for p in pts for c in p) or 1.0
    k = math.frexp(big)[1]
    p = [(math.ldexp(x, -k), math.ldexp(y, -k)) for x, y in pts]   # unit scale: no overflow
    P = exact(pts)
    tris = delaunay(pts)
    nbrs = {}
    for a, b, c in tris:
        for u, v in ((a, b), (b, c), (c, a)):
            nbrs.setdefault(u, set()).add(v)
            nbrs.setdefault(v, set()).add(u)
    hull = convex_hull(P)
    H = [p[i] for i in hull]
    best = (-1.0, 0.0, 0.0)
    # 1. circumcentres inside the hull (Voronoi vertices)
    for a, b, c in tris:
        cx, cy = circumcentre(p, a, b, c)
        if in_hull(H, (cx, cy), 1e-12):
            r = min(math.hypot(cx - p[v][0], cy - p[v][1]) for v in (a, b, c))
            best = max(best, (r, -cx, -cy))
    # 2. where Voronoi edges cross the hull: walk each hull edge u -> v through the cells it meets
    for i, u in enumerate(hull):
        v = hull[(i + 1) % len(hull)]
        U, V = P[u], P[v]
        dx, dy = V[0] - U[0], V[1] - U[1]
        s = u
        while s != v:
            S = P[s]
            s2 = (S[0] - U[0]) ** 2 + (S[1] - U[1]) ** 2
            choice = None                 # (numerator, denominator, q): t = num / den along u -> v
            for q in nbrs[s]:
                Q = P[q]
                den = 2 * (dx * (Q[0] - S[0]) + dy * (Q[1] - S[1]))
                if den <= 0:
                    continue
                num = (Q[0] - U[0]) ** 2 + (Q[1] - U[1]) ** 2 - s2
                if choice is None or num * choice[1] < choice[0] * den:
                    choice = (num, den, q)
            num, den, q = choice
            t = min(max(num / den, 0.0), 1.0)
            x = p[u][0] + t * (p[v][0] - p[u][0])
            y = p[u][1] + t * (p[v][1] - p[u][1])
            r = min(math.hypot(x - p[s][0], y - p[s][1]), math.hypot(x - p[q][0], y - p[q][1]))
            best = max(best, (r, -x, -y))
            s = q
    r, x, y = best
    return [math.ldexp(-x, k), math.ldexp(-y, k), math.ldexp(r, k)]


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    print(" ".join(repr(v) for v in largest_empty_circle(pts)))


if __name__ == "__main__":
    main()
