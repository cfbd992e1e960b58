"""Wrong solution for `closest-pair` (WA on the degenerate group): the same sweep in floating point.

The mistake: squared distances as floats. Near 1e300 they overflow to inf (every pair looks
equally far), near 1e-300 they underflow to 0, and two distances closer than an ulp look equal.
Otherwise this is the accepted solution, a plane sweep in O(n log n).

Points are visited by increasing x. The points less than sqrt(best) to the left of the sweep line
are kept sorted by y; a new point is compared only with those whose y is within sqrt(best) of its
own (a constant number, by a packing argument). All coordinates are scaled by one power of two
into Python integers, so every comparison is exact (no overflow at 1e300, no rounding to 0 at
1e-300, near-ties decided right); the window bounds use ``math.isqrt``, rounded outwards.

Function mode: the grader calls closest_pair(points). Stdio mode / Kattis: python3 wrong_float_distance.py < input

Example:
    >>> closest_pair([[0, 0], [3, 0], [1, 5], [3, 6], [2, 2.5]])
    [2, 3]
"""
import math
import sys
from bisect import bisect_left, insort
from collections import deque


def exact(points):
    """Scale all coordinates by one power of two so that they become Python ints (exact)."""
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def closest_pair(points):
    P = [(float(x), float(y)) for x, y in points]  # the mistake: no exact arithmetic
    order = sorted(range(len(P)), key=lambda i: P[i])
    best, pair = None, None
    active = []  # (y, x, index) of the points in the strip, sorted by y
    strip = deque()  # the same points in x order, to drop them when the strip narrows
    for i in order:
        x, y = P[i]
        if best is not None:
            r = math.sqrt(best)
            while strip and (x - P[strip[0]][0]) > r:
                j = strip.popleft()
                del active[bisect_left(active, (P[j][1], P[j][0], j))]
            k = bisect_left(active, (y - r,))
            while k < len(active) and active[k][0] <= y + r:
                yj, xj, j = active[k]
                d = (x - xj) ** 2 + (y - yj) ** 2
                if d < best:
                    best, pair = d, [j, i]
                    if d == 0:
                        return sorted(pair)
                k += 1
        else:
            j = strip[0] if strip else None
            if j is not None:
                best = (x - P[j][0]) ** 2 + (y - P[j][1]) ** 2
                pair = [j, i]
                if best == 0:
                    return sorted(pair)
        insort(active, (y, x, i))
        strip.append(i)
    return sorted(pair)


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    i, j = closest_pair(pts)
    sys.stdout.write(f"{i} {j}\n")


if __name__ == "__main__":
    main()
