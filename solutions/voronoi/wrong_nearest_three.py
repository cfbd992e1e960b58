"""Wrong answer: each cell clipped by the bisectors of the site's three nearest neighbours only.

The mistake: believing that a point's Delaunay (Voronoi) neighbours are its nearest three points.
A site usually has about six Voronoi neighbours, and some of them are far away (on the hull, or
next to a small cluster), so cells come out too large. Killed by the tiny group (the corners and
centre of a square: the centre has four neighbours at the same distance).

Function mode: voronoi_cells(points, bbox). Stdio: python3 wrong_nearest_three.py < input
"""
import math
import sys


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
    big = max([abs(c) for q in pts for c in q] + [abs(float(v)) for v in bbox]) or 1.0
    e = math.frexp(big)[1]
    p = [(math.ldexp(x, -e), math.ldexp(y, -e)) for x, y in pts]
    x0, y0, x1, y1 = (math.ldexp(float(v), -e) for v in bbox)
    cells = []
    for i, (px, py) in enumerate(p):
        others = [j for j in range(len(p)) if p[j] != p[i]]
        others = sorted(others, key=lambda j: (p[j][0] - px) ** 2 + (p[j][1] - py) ** 2)[:3]
        poly = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        for j in others:
            qx, qy = p[j]
            nx, ny = qx - px, qy - py
            poly = clip(poly, nx, ny, nx * (0.5 * px + 0.5 * qx) + ny * (0.5 * py + 0.5 * qy))
            if not poly:
                break
        dedup = [q for k, q in enumerate(poly) if q != poly[k - 1]] if len(poly) > 1 else poly
        cells.append([[math.ldexp(x, e), math.ldexp(y, e)] for x, y in dedup] if len(dedup) >= 3 else [])
    return cells


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    vals = [float(t) for t in data[1:2 * n + 5]]
    cells = voronoi_cells([(vals[2 * i], vals[2 * i + 1]) for i in range(n)], vals[2 * n:2 * n + 4])
    sys.stdout.write("".join(" ".join([str(len(c))] + [f"{x!r} {y!r}" for x, y in c]) + "\n" for c in cells))


if __name__ == "__main__":
    main()
