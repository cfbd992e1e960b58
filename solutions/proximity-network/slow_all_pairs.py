"""Too-slow solution for `proximity-network` (TLE): tests every pair against every point, O(n^3).

Correct (the closed-disc test with exact integers, repeated points merged into their smallest
index) but about 1e12 operations for 10000 points.

Function mode: the grader calls gabriel_graph(points). Stdio mode / Kattis: python3 slow_all_pairs.py < input

Example:
    >>> gabriel_graph([[0, 0], [1, 0], [1, 1], [0, 1]])
    [[0, 1], [0, 3], [1, 2], [2, 3]]
"""
import sys


def exact(points):
    """Scale all coordinates by one power of two so that they become Python ints (exact)."""
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def gabriel_graph(points):
    P = exact(points)
    first = {}
    distinct = [i for i, p in enumerate(P) if first.setdefault(p, i) == i]
    edges = []
    for a, i in enumerate(distinct):
        xi, yi = P[i]
        for j in distinct[a + 1:]:
            xj, yj = P[j]
            if all((P[r][0] - xi) * (P[r][0] - xj) + (P[r][1] - yi) * (P[r][1] - yj) > 0
                   for r in distinct if r != i and r != j):
                edges.append([i, j])
    return edges


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    edges = gabriel_graph(pts)
    sys.stdout.write(f"{len(edges)}\n" + "".join(f"{u} {v}\n" for u, v in edges))


if __name__ == "__main__":
    main()
