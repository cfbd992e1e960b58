"""Wrong solution for `closest-pair` (WA on the tiny group): sorts by x and compares neighbours only.

The mistake: the closest pair need not be consecutive in x order; in the tiny test
(0,0) (3,0) (1,5) (3,6) (2,2.5) the closest points (1,5) and (3,6) have two points between them.

Function mode: the grader calls closest_pair(points). Stdio mode / Kattis: python3 wrong_x_neighbours.py < input

Example:
    >>> closest_pair([[0, 0], [5, 5], [1, 1], [5, 6]])
    [0, 2]
"""
import sys
from fractions import Fraction


def closest_pair(points):
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))

    def sq(i, j):
        return (Fraction(points[i][0]) - Fraction(points[j][0])) ** 2 + (Fraction(points[i][1]) - Fraction(points[j][1])) ** 2

    i, j = min(zip(order, order[1:]), key=lambda ij: sq(*ij))
    return sorted([i, j])


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    i, j = closest_pair(pts)
    sys.stdout.write(f"{i} {j}\n")


if __name__ == "__main__":
    main()
