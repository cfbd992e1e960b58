"""Wrong answer: moves the disk along the straight segment from start to goal.

The mistake: the answer is taken as the distance from the segment start-goal to its nearest
obstacle, as if the disk could not go around; a detour often keeps a wider clearance.
Killed by sample 1 and tiny 01 (the straight way up passes through the obstacle (4,4)).

Function mode: max_clearance(points, start, goal). Stdio: python3 wrong_straight_line.py < input
"""
import math
import sys


def segment_distance(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    t = 0.0 if L == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def max_clearance(points, start, goal):
    if not points:
        return math.inf
    return min(segment_distance(p, start, goal) for p in points)


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    vals = [float(t) for t in data[1:2 * n + 5]]
    pts = [(vals[2 * i], vals[2 * i + 1]) for i in range(n)]
    print(repr(max_clearance(pts, vals[2 * n:2 * n + 2], vals[2 * n + 2:2 * n + 4])))


if __name__ == "__main__":
    main()
