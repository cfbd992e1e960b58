"""Input validator (Kattis convention: exit 42 = valid, 43 = invalid) for `navmesh`.

Format: n (3 <= n), then n lines "x y" (the boundary); h; then per hole m (3 <= m) and m lines
"x y"; then "sx sy" and "gx gy". Finite decimal numbers, one space, nothing after; at most 20000
polygon vertices in all. The polygons must be simple (no two edges meet except neighbours at their
shared corner, no zero-length or folded-back edge), the holes strictly inside the boundary and
pairwise disjoint, not nested (all exact: the doubles scaled to integers). Edges are compared by an
x-sweep, so the cost stays near-linear for the generated rooms.
Run: python3 validate_navmesh.py < case.in; echo $?

Example:
    >>> validate("4\\n0 0\\n4 0\\n4 4\\n0 4\\n1\\n3\\n1 1\\n2 1\\n1 2\\n0.5 0.5\\n3 3\\n")
    []
"""
import math
import re
import sys

NUMBER = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
COUNT = re.compile(r"0|[1-9]\d*")
MAX_VERTICES = 20000


def _parse(lines):
    pos = 0

    def count(what):
        nonlocal pos
        if pos >= len(lines) or not COUNT.fullmatch(lines[pos]):
            raise ValueError(f"line {pos + 1}: expected {what}, got {lines[pos][:40] if pos < len(lines) else 'end of input'!r}")
        pos += 1
        return int(lines[pos - 1])

    def point():
        nonlocal pos
        if pos >= len(lines):
            raise ValueError("input ends early: expected 'x y'")
        parts = lines[pos].split(" ")
        if len(parts) != 2 or not all(NUMBER.fullmatch(p) for p in parts):
            raise ValueError(f"line {pos + 1}: expected 'x y', got {lines[pos][:60]!r}")
        p = (float(parts[0]), float(parts[1]))
        if not all(math.isfinite(c) for c in p):
            raise ValueError(f"line {pos + 1}: coordinates must be finite")
        pos += 1
        return p

    total = 0

    def ring(what):
        nonlocal total
        m = count(f"the vertex count of the {what}")
        total += m
        if m < 3:
            raise ValueError(f"the {what} has {m} vertices; a polygon needs at least 3")
        if total > MAX_VERTICES:
            raise ValueError(f"more than {MAX_VERTICES} polygon vertices")
        return [point() for _ in range(m)]

    boundary = ring("boundary")
    holes = [ring(f"hole {k}") for k in range(count("the number of holes h"))]
    start, goal = point(), point()
    if pos != len(lines):
        raise ValueError(f"line {pos + 1}: unexpected text after the goal")
    return boundary, holes, start, goal


def _exact(points):
    ratios = [(x.as_integer_ratio(), y.as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def _orient(a, b, c):
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def _on(p, a, b):
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def _meet(a, b, c, d):
    """Do the closed segments ab and cd share a point?"""
    o1, o2, o3, o4 = _orient(a, b, c), _orient(a, b, d), _orient(c, d, a), _orient(c, d, b)
    if o1 != o2 and o3 != o4 and o1 * o2 <= 0 and o3 * o4 <= 0:
        return True
    return ((o1 == 0 and _on(c, a, b)) or (o2 == 0 and _on(d, a, b)) or (o3 == 0 and _on(a, c, d))
            or (o4 == 0 and _on(b, c, d)))


def _inside(p, ring):
    """Strictly inside (crossing number; p is known not to lie on the ring)."""
    inside = False
    n = len(ring)
    for i in range(n):
        a, b = ring[i], ring[(i + 1) % n]
        if (a[1] > p[1]) != (b[1] > p[1]) and (_orient(a, b, p) > 0) == (b[1] > a[1]):
            inside = not inside
    return inside


def _geometry(rings):
    edges = []  # (ring, index, a, b)
    for r, ring in enumerate(rings):
        n = len(ring)
        for i in range(n):
            a, b, c = ring[i], ring[(i + 1) % n], ring[(i + 2) % n]
            if a == b:
                return [f"ring {r}: vertices {i} and {(i + 1) % n} coincide"]
            if _orient(a, b, c) == 0 and ((c[0] - b[0]) * (a[0] - b[0]) + (c[1] - b[1]) * (a[1] - b[1])) > 0:
                return [f"ring {r}: the edges at vertex {(i + 1) % n} fold back on each other"]
            edges.append((r, i, a, b))
    edges.sort(key=lambda e: min(e[2][0], e[3][0]))
    active = []
    for e in edges:
        r, i, a, b = e
        x0 = min(a[0], b[0])
        active = [f for f in active if max(f[2][0], f[3][0]) >= x0]
        for f in active:
            s, j, c, d = f
            if min(c[1], d[1]) > max(a[1], b[1]) or min(a[1], b[1]) > max(c[1], d[1]):
                continue
            n = len(rings[r])
            if r == s and ((i + 1) % n == j or (j + 1) % n == i):
                continue  # neighbours: their shared corner (folds are rejected above)
            if _meet(a, b, c, d):
                what = f"edges {i} and {j} of ring {r}" if r == s else f"ring {r} (edge {i}) and ring {s} (edge {j})"
                return [f"{what} touch or cross: polygons must be simple, holes strictly inside and disjoint"]
        active.append(e)
    for k, hole in enumerate(rings[1:], start=1):
        if not _inside(hole[0], rings[0]):
            return [f"hole {k - 1} is not inside the boundary"]
        for j, other in enumerate(rings[1:], start=1):
            if j != k and _inside(hole[0], other):
                return [f"hole {k - 1} lies inside hole {j - 1}"]
    return []


def validate(text: str) -> list[str]:
    """Return a list of problems (empty when the input is valid)."""
    if not text.endswith("\n"):
        return ["the input must end with a newline"]
    try:
        boundary, holes, start, goal = _parse(text[:-1].split("\n"))
    except ValueError as e:
        return [str(e)]
    flat = _exact(boundary + [p for h in holes for p in h] + [start, goal])
    rings, pos = [], 0
    for ring in [boundary] + holes:
        rings.append(flat[pos:pos + len(ring)])
        pos += len(ring)
    return _geometry(rings)


if __name__ == "__main__":
    problems = validate(sys.stdin.read())
    for p in problems:
        print(p, file=sys.stderr)
    sys.exit(43 if problems else 42)
