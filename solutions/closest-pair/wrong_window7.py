"""Wrong solution for `closest-pair` (WA; killed by `degenerate`): a fixed window of 7.

The shortcut: the strip argument of the divide-and-conquer proof says "at most 7 points of the
strip need to be checked", so each point is compared only with the next 7 points in (x, y) sorted
order. That bound holds inside the y-sorted strip of width 2d, not in x order: ten points
A = (0, 0), (0, 10), (0, 20), ..., (0, 80), B = (1, 0) put eight points between A and B in (x, y)
order, and the closest pair A, B is never compared. Exact integer arithmetic, so only the window
is wrong.

Killed by: degenerate

`python -m grader stress closest-pair wrong_window7.py` finds an input that shows it.
Function mode: the grader calls closest_pair(points). Stdio mode / Kattis: python3 wrong_window7.py < input

Example:
    >>> closest_pair([[0, 0], [5, 5], [1, 1], [5, 6]])
    [0, 2]
"""
import sys

WINDOW = 7


def exact(points):
    """Scale all coordinates by one power of two so that they become Python ints (exact)."""
    ratios = [(float(x).as_integer_ratio(), float(y).as_integer_ratio()) for x, y in points]
    den = max([1] + [max(dx, dy) for (_, dx), (_, dy) in ratios])
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def closest_pair(points):
    P = exact(points)
    order = sorted(range(len(P)), key=lambda i: P[i])
    best, pair = None, None
    for k, i in enumerate(order):
        for j in order[k + 1:k + 1 + WINDOW]:         # SHORTCUT: the next 7 in (x, y) order only
            d = (P[i][0] - P[j][0]) ** 2 + (P[i][1] - P[j][1]) ** 2
            if best is None or d < best:
                best, pair = d, (i, j)
    return sorted(pair)


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    i, j = closest_pair(pts)
    sys.stdout.write(f"{i} {j}\n")


if __name__ == "__main__":
    main()
