"""Wrong solution for `closest-pair` (WA; killed by `exhaustive`): a heuristic sweep.

The shortcut: compare each point only with its neighbours in x order and in y order. The closest
pair can be separated in both orders: A = (0, 0) and B = (3, 3) with (1, 10) and (2, -10) between
them in x and (100, 1) between them in y. Exact integer arithmetic, so only the heuristic is wrong;
`python -m grader stress closest-pair wrong_xy_neighbours.py` finds an input that shows it.

Function mode: the grader calls closest_pair(points). Stdio mode / Kattis: python3 wrong_xy_neighbours.py < input

Example:
    >>> closest_pair([[0, 0], [5, 5], [1, 1], [5, 6]])
    [0, 2]
"""
import sys
from fractions import Fraction


def closest_pair(points):
    P = [(Fraction(x), Fraction(y)) for x, y in points]

    def sq(ij):
        (ax, ay), (bx, by) = P[ij[0]], P[ij[1]]
        return (ax - bx) ** 2 + (ay - by) ** 2

    pairs = []
    for key in (lambda i: P[i], lambda i: (P[i][1], P[i][0])):   # x order, then y order
        order = sorted(range(len(P)), key=key)
        pairs += list(zip(order, order[1:]))
    return sorted(min(pairs, key=sq))


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    i, j = closest_pair(pts)
    sys.stdout.write(f"{i} {j}\n")


if __name__ == "__main__":
    main()
