"""Wrong for `navmesh`: the straight segment from start to goal, never checked against the holes.

The student's shortcut: "if both ends are in the room, walk straight there". Right when nothing is
in the way (and for start == goal, or an end outside the room), wrong as soon as a hole or a notch
of the wall blocks the line. Killed by the tiny group (a square pillar between start and goal).

Function mode: shortest_path(boundary, holes, start, goal). Stdio: python3 wrong_straight_line.py < input

Example:
    >>> shortest_path([[0, 0], [4, 0], [4, 4], [0, 4]], [], [1, 1], [3, 2])
    [[1.0, 1.0], [3.0, 2.0]]
"""
import sys


def inside(p, ring):
    """Even-odd rule (points on the wall may go either way)."""
    x, y = p
    res = False
    for (ax, ay), (bx, by) in zip(ring, ring[1:] + ring[:1]):
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            res = not res
    return res


def shortest_path(boundary, holes, start, goal):
    s, g = [float(start[0]), float(start[1])], [float(goal[0]), float(goal[1])]
    for p in (s, g):
        if not inside(p, [list(q) for q in boundary]) or any(inside(p, [list(q) for q in h]) for h in holes):
            return None
    return [s] if s == g else [s, g]


def main():
    tok = sys.stdin.read().split()
    pos = 0

    def ring():
        nonlocal pos
        n = int(tok[pos])
        pos += 1 + 2 * n
        return [[float(tok[pos - 2 * n + 2 * i]), float(tok[pos - 2 * n + 2 * i + 1])] for i in range(n)]

    boundary = ring()
    pos += 1
    holes = [ring() for _ in range(int(tok[pos - 1]))]
    start, goal = [float(v) for v in tok[pos:pos + 2]], [float(v) for v in tok[pos + 2:pos + 4]]
    path = shortest_path(boundary, holes, start, goal)
    sys.stdout.write("0\n" if path is None else f"{len(path)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in path))


if __name__ == "__main__":
    main()
