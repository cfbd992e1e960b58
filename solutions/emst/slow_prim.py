"""Too-slow solution for `emst` (TLE on the large group): Prim's algorithm on the complete graph.

Correct (exact integer squared lengths, repeated points joined by zero-length edges), but every
step scans all points: O(n^2), about 4e8 length computations for 20000 points.

Function mode: the grader calls euclidean_mst(points). Stdio mode / Kattis: python3 slow_prim.py < input

Example:
    >>> euclidean_mst([[1, 1], [3, 2], [5, 1], [4, 4]])
    [[0, 1], [1, 2], [1, 3]]
"""
import sys


def exact(points):
    """Scale all coordinates by one power of two so that they become Python ints (exact)."""
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def euclidean_mst(points):
    P = exact(points)
    n = len(P)
    if n < 2:
        return []
    best = [None] * n  # squared distance to the tree
    via = [0] * n
    done = [False] * n
    done[0] = True
    x0, y0 = P[0]
    for j in range(1, n):
        best[j] = (P[j][0] - x0) ** 2 + (P[j][1] - y0) ** 2
    edges = []
    for _ in range(n - 1):
        k = min((j for j in range(n) if not done[j]), key=lambda j: best[j])
        done[k] = True
        edges.append(sorted((via[k], k)))
        xk, yk = P[k]
        for j in range(n):
            if not done[j]:
                d = (P[j][0] - xk) ** 2 + (P[j][1] - yk) ** 2
                if d < best[j]:
                    best[j], via[j] = d, k
    return edges


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    edges = euclidean_mst(pts)
    sys.stdout.write(f"{len(edges)}\n" + "".join(f"{u} {v}\n" for u, v in edges))


if __name__ == "__main__":
    main()
