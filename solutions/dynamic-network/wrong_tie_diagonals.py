"""Wrong solution for `dynamic-network` (WA): keeps the tie diagonals, e.g. both diagonals of a square.

The one mistake: a bisector piece of length zero (a single Voronoi vertex shared by four or more
cocircular nodes) is counted as a link (`lo > hi` instead of `lo >= hi`), so the corners of a square
get 5 links. Otherwise the slow solution below (too slow for the large group as well).

From here on: the slow solution, each neighbour query answered from scratch.

Correct, with exact integers: u and v are neighbours when their Voronoi cells share an edge of
positive length, i.e. the part of the perpendicular bisector of u and v that is strictly closer to
them than to every other live position is an open interval that is not empty. Each query clips
the bisector by every other position (O(n)) for every candidate (O(n)): O(n^2) per query, hours
for 10000 nodes. Coincident nodes are one position; they are neighbours of each other.

Function mode: the grader calls process(operations). Stdio mode / Kattis: python3 wrong_tie_diagonals.py < input

Example:
    >>> process([["join", 0, 0], ["join", 1, 0], ["join", 1, 1], ["join", 0, 1], ["neighbors", 0],
    ...          ["fail", 3], ["neighbors", 0], ["count"]])
    [0, 1, 2, 3, [1, 2, 3], 'ok', [1, 2], 3]
"""
import sys
from fractions import Fraction


def linked(p, q, others):
    """Does an open piece of the bisector of p and q lie strictly closer to p than to every r?"""
    mx, my = p[0] + q[0], p[1] + q[1]  # twice the midpoint
    dx, dy = p[1] - q[1], q[0] - p[0]  # direction of the bisector: L(t) = (m + t d) / 2
    lo, hi = None, None
    for r in others:
        # |L - p|^2 < |L - r|^2  <=>  2 L.(r - p) < |r|^2 - |p|^2  <=>  a t < b
        ex, ey = r[0] - p[0], r[1] - p[1]
        a = dx * ex + dy * ey
        b = (r[0] ** 2 + r[1] ** 2 - p[0] ** 2 - p[1] ** 2) - (mx * ex + my * ey)
        if a == 0:
            if b <= 0:
                return False
        elif a > 0:
            hi = Fraction(b, a) if hi is None else min(hi, Fraction(b, a))
        else:
            lo = Fraction(b, a) if lo is None else max(lo, Fraction(b, a))
        if lo is not None and hi is not None and lo > hi:
            return False
    return True


def process(operations):
    joins = [op for op in operations if op[0] == "join"]
    den = max([1] + [max(float(op[1]).as_integer_ratio()[1], float(op[2]).as_integer_ratio()[1]) for op in joins])
    pos, alive, answers = [], [], []
    for op in operations:
        if op[0] == "join":
            (nx, dx), (ny, dy) = float(op[1]).as_integer_ratio(), float(op[2]).as_integer_ratio()
            pos.append((nx * (den // dx), ny * (den // dy)))
            alive.append(True)
            answers.append(len(pos) - 1)
        elif op[0] == "count":
            answers.append(sum(alive))
        elif not (0 <= op[1] < len(pos) and alive[op[1]]):
            answers.append("error")
        elif op[0] == "fail":
            alive[op[1]] = False
            answers.append("ok")
        else:
            p = pos[op[1]]
            live = {pos[i] for i in range(len(pos)) if alive[i]}
            near = {q for q in live if q != p and linked(p, q, [r for r in live if r not in (p, q)])}
            answers.append([i for i in range(len(pos)) if alive[i] and i != op[1] and (pos[i] in near or pos[i] == p)])
    return answers


def main():
    lines = sys.stdin.read().split("\n")
    ops = []
    for line in lines[1:int(lines[0]) + 1]:
        parts = line.split()
        ops.append([parts[0]] + ([float(parts[1]), float(parts[2])] if parts[0] == "join" else
                                 [int(parts[1])] if len(parts) > 1 else []))
    out = []
    for a in process(ops):
        out.append(" ".join(map(str, [len(a)] + a)) if isinstance(a, list) else str(a))
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
