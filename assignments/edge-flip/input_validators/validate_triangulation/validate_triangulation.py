"""Input validator (Kattis convention: exit 42 = valid, 43 = invalid) for `edge-flip`.

Format: a line "n m" (0 <= n <= 20000, 0 <= m <= 2n), n lines "x y" of finite decimal floats,
m lines "i j k" of 0-based indices. The triangles must triangulate the points (exact integer
tests): each strictly counter-clockwise and made of first occurrences of the coordinates; no
directed edge twice; the edges with a triangle on one side only form one closed, convex,
counter-clockwise cycle; every distinct point is a vertex; no triangle when all points are
collinear (or fewer than 3 are distinct), else at least one.
Run: python3 validate_triangulation.py < case.in; echo $?

Example:
    >>> validate("4 2\\n0 0\\n4 0\\n4 1\\n0 3\\n0 1 3\\n1 2 3\\n")
    []
"""
import math
import re
import sys

NUMBER = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
INT = re.compile(r"0|[1-9]\d*")
MAX_N = 20000


def _orient(a, b, c) -> int:
    d = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])
    return (d > 0) - (d < 0)


def _triangulation_problems(pts, tris) -> list:
    ratios = [(x.as_integer_ratio(), y.as_integer_ratio()) for x, y in pts]
    den = max([max(dx, dy) for (_, dx), (_, dy) in ratios], default=1)
    P = [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]
    first = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    distinct = sorted(first.values())
    flat = len(distinct) < 3 or all(_orient(P[distinct[0]], P[distinct[1]], P[i]) == 0 for i in distinct)
    if flat:
        return ["the points are collinear: there must be no triangle"] if tris else []
    if not tris:
        return ["the points are not collinear but there is no triangle"]
    edges = {}
    for k, (a, b, c) in enumerate(tris):
        if rep[a] != a or rep[b] != b or rep[c] != c:
            return [f"triangle {k} uses a repeated point's later index"]
        if _orient(P[a], P[b], P[c]) <= 0:
            return [f"triangle {k} is not strictly counter-clockwise"]
        for e in ((a, b), (b, c), (c, a)):
            if e in edges:
                return [f"directed edge {e} is used twice"]
            edges[e] = k
    if {v for t in tris for v in t} != set(distinct):
        return ["not every distinct point is a vertex"]
    nxt = {}
    for (u, v) in edges:
        if (v, u) not in edges:
            if u in nxt:
                return [f"the boundary passes twice through point {u}"]
            nxt[u] = v
    start = next(iter(nxt))
    cycle, u = [start], nxt[start]
    while u != start:
        if u not in nxt or len(cycle) > len(nxt):
            return ["the boundary is not one closed cycle"]
        cycle.append(u)
        u = nxt[u]
    if len(cycle) != len(nxt):
        return ["the boundary is more than one cycle (a hole)"]
    h = len(cycle)
    key = [(P[v][1], P[v][0]) for v in cycle]
    minima = 0
    for i in range(h):
        if _orient(P[cycle[i - 1]], P[cycle[i]], P[cycle[(i + 1) % h]]) < 0:
            return [f"the boundary turns right at point {cycle[i]}: it is not the convex hull"]
        minima += key[i - 1] > key[i] < key[(i + 1) % h]
    if minima != 1:
        return ["the boundary winds around more than once"]
    return []


def validate(text: str) -> list:
    """Return a list of problems (empty when the input is valid)."""
    if not text.endswith("\n"):
        return ["the input must end with a newline"]
    lines = text[:-1].split("\n")
    head = lines[0].split(" ")
    if len(head) != 2 or not all(INT.fullmatch(h) for h in head):
        return [f"first line must be 'n m', got {lines[0][:40]!r}"]
    n, m = int(head[0]), int(head[1])
    if n > MAX_N or m > 2 * n:
        return [f"n = {n}, m = {m}: need n <= {MAX_N} and m <= 2n"]
    if len(lines) != 1 + n + m:
        return [f"expected {n} point lines and {m} triangle lines, got {len(lines) - 1} lines"]
    pts = []
    for k, line in enumerate(lines[1:n + 1], start=2):
        parts = line.split(" ")
        if len(parts) != 2 or not all(NUMBER.fullmatch(p) for p in parts):
            return [f"line {k}: expected 'x y', got {line[:60]!r}"]
        x, y = float(parts[0]), float(parts[1])
        if not (math.isfinite(x) and math.isfinite(y)):
            return [f"line {k}: coordinates must be finite"]
        pts.append((x, y))
    tris = []
    for k, line in enumerate(lines[n + 1:], start=n + 2):
        parts = line.split(" ")
        if len(parts) != 3 or not all(INT.fullmatch(p) for p in parts) or not all(int(p) < n for p in parts):
            return [f"line {k}: expected 'i j k' with indices below {n}, got {line[:60]!r}"]
        tris.append(tuple(int(p) for p in parts))
    return _triangulation_problems(pts, tris)


if __name__ == "__main__":
    problems = validate(sys.stdin.read())
    for p in problems:
        print(p, file=sys.stderr)
    sys.exit(43 if problems else 42)
