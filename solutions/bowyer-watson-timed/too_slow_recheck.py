"""Too slow (expected TLE) for `bowyer-watson-timed`: a correct Bowyer-Watson that, after every
insertion, re-checks the empty-circle property of every triangle against every point inserted so
far "to be safe". That makes it O(n^3): fine for 10 points, far over the limit for 250.

Function mode: bowyer_watson(points). Stdio: python3 too_slow_recheck.py < input

Example:
    >>> sorted(map(sorted, bowyer_watson([[0, 0], [1, 0], [0, 1]])))
    [[0, 1, 2]]
"""
import sys


def exact(points):
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def orient(a, b, c):
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def in_circle(a, b, c, d):
    (ax, ay), (bx, by), (cx, cy) = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    return ((ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
            + (cx * cx + cy * cy) * (ax * by - bx * ay)) > 0


def bowyer_watson(points):
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
    tris = [(a, b, c), (b, a, None), (c, b, None), (a, c, None)]
    inserted = [a, b, c]

    def bad(t, p):
        u, v, w = t
        if w is None:
            s = orient(P[u], P[v], P[p])
            return s > 0 if s else min(P[u], P[v]) < P[p] < max(P[u], P[v])
        return in_circle(P[u], P[v], P[w], P[p])

    for p in ids:
        if p in (a, b, c):
            continue
        cavity = [t for t in tris if bad(t, p)]
        edges = {e: True for u, v, w in cavity for e in ((u, v), (v, w), (w, u))}
        dead = set(cavity)
        tris = [t for t in tris if t not in dead]
        for u, v in [e for e in edges if (e[1], e[0]) not in edges]:
            tris.append((v, p, None) if u is None else (p, u, None) if v is None else (u, v, p))
        inserted.append(p)
        for t in tris:  # the needless full re-check: O(n^2) per insertion
            if t[2] is not None:
                for q in inserted:
                    assert not in_circle(P[t[0]], P[t[1]], P[t[2]], P[q])
    return [list(t) for t in tris if t[2] is not None]


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    tris = bowyer_watson(pts)
    sys.stdout.write(f"{len(tris)}\n" + "".join(f"{a} {b} {c}\n" for a, b, c in tris))


if __name__ == "__main__":
    main()
