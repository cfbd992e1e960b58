"""Too-slow solution for `closest-pair` (TLE): compares every pair of points, O(n^2).

Correct (exact integer squared distances) but about 5e9 comparisons for 100000 points.

Function mode: the grader calls closest_pair(points). Stdio mode / Kattis: python3 slow_brute_force.py < input

Example:
    >>> closest_pair([[0, 0], [5, 5], [1, 1], [5, 6]])
    [1, 3]
"""
import sys


def exact(points):
    """Scale all coordinates by one power of two so that they become Python ints (exact)."""
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def closest_pair(points):
    P = exact(points)
    best, pair = None, None
    for i in range(len(P)):
        xi, yi = P[i]
        for j in range(i + 1, len(P)):
            d = (xi - P[j][0]) ** 2 + (yi - P[j][1]) ** 2
            if best is None or d < best:
                best, pair = d, [i, j]
    return pair


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    i, j = closest_pair(pts)
    sys.stdout.write(f"{i} {j}\n")


if __name__ == "__main__":
    main()
