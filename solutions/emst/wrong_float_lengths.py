"""Wrong solution for `emst` (WA on the degenerate group): compares floating-point lengths.

The mistake: ``math.hypot`` rounds, so two edges whose lengths differ by less than an ulp look
equal and the tree may take the longer one (the near-tie triangles of the degenerate group).
Otherwise this is Prim's algorithm, as in slow_prim.py (too slow for the large group as well,
but the degenerate group fails first).

Function mode: the grader calls euclidean_mst(points). Stdio mode / Kattis: python3 wrong_float_lengths.py < input

Example:
    >>> euclidean_mst([[1, 1], [3, 2], [5, 1], [4, 4]])
    [[0, 1], [1, 2], [1, 3]]
"""
import math
import sys


def euclidean_mst(points):
    P = [(float(x), float(y)) for x, y in points]  # the mistake: float lengths
    n = len(P)
    if n < 2:
        return []
    best = [None] * n  # distance to the tree
    via = [0] * n
    done = [False] * n
    done[0] = True
    x0, y0 = P[0]
    for j in range(1, n):
        best[j] = math.hypot(P[j][0] - x0, P[j][1] - y0)
    edges = []
    for _ in range(n - 1):
        k = min((j for j in range(n) if not done[j]), key=lambda j: best[j])
        done[k] = True
        edges.append(sorted((via[k], k)))
        xk, yk = P[k]
        for j in range(n):
            if not done[j]:
                d = math.hypot(P[j][0] - xk, P[j][1] - yk)
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
