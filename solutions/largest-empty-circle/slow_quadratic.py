"""Correct but too slow for `largest-empty-circle`: the candidates of accepted_toussaint.py on a
Bowyer-Watson triangulation that scans every triangle at each insertion (quadratic; the same code
as solutions/delaunay/scan_quadratic.py). Expected verdict: TLE on the large group.

Function mode: largest_empty_circle(points). Stdio: python3 slow_quadratic.py < input
"""
import math
import sys


def exact(points):
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def orient(a, b, c):
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def in_circle(a, b, c, d):
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    (ax, ay), (bx, by), (cx, cy) = rows
    det = ((ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
           + (cx * cx + cy * cy) * (ax * by - bx * ay))
    return det > 0


def delaunay(points):
    P = exact(points)
    first = {}
    ids = [i for i, p in enumerate(P) if first.setdefault(p, i) == i]
    if len(ids) < 3:
        return []
    a, b = ids[0], ids[1]
    c = next((i for i in ids[2:] if orient(P[a], P[b], P[i]) != 0), None)
    if c is None:
        return []
    if orient(P[a], P[b], P[c]) < 0:
        b, c = c, b
    # None is the infinite vertex; ghost (u, v, None) lies across hull edge u->v (real side on the right)
    tris = [(a, b, c), (b, a, None), (c, b, None), (a, c, None)]

    def bad(t, p):
        u, v, w = t
        if w is None:
            s = orient(P[u], P[v], P[p])
            if s:
                return s > 0
            return min(P[u], P[v]) < P[p] < max(P[u], P[v])
        return in_circle(P[u], P[v], P[w], P[p])

    for p in ids:
        if p in (a, b, c):
            continue
        cavity = [t for t in tris if bad(t, p)]
        edges = {}
        for u, v, w in cavity:
            for e in ((u, v), (v, w), (w, u)):
                edges[e] = True
        boundary = [e for e in edges if (e[1], e[0]) not in edges]
        dead = set(cavity)
        tris = [t for t in tris if t not in dead]
        for u, v in boundary:
            if u is None:
                tris.append((v, p, None))
            elif v is None:
                tris.append((p, u, None))
            else:
                tris.append((u, v, p))
    return [list(t) for t in tris if t[2] is not None]



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
