"""Wrong answer: the original tutorial's Bowyer-Watson transcribed faithfully
(the same code, with the inputs on which each bug shows: reference_impl/teaching/tutorial_bugs.py).

Its bugs: the in-circle determinant is only right for counter-clockwise triangles but triangles
are never oriented; the cavity boundary keeps an edge shared by two bad triangles (it skips the
second copy instead of dropping both); a fixed super-triangle at +-1e5; np.linalg.det in floats.
Expected verdict: WA (it happens to get the tutorial's own 4-point example right).
Killed by: tiny (a square with its centre, or ten random points: the kept edge makes triangles overlap).

Function mode: delaunay(points) / bowyer_watson(points). Stdio: python3 wrong_tutorial.py < input

Example:
    >>> len(delaunay([[1, 1], [3, 2], [5, 1], [4, 4]])) > 0
    True
"""
import sys

import numpy as np


class Triangle:
    def __init__(self, a, b, c):
        self.vertices = [a, b, c]

    def circumcircle_contains(self, point):
        (ax, ay), (bx, by), (cx, cy) = self.vertices
        dx, dy = point
        mat = np.array([
            [ax - dx, ay - dy, (ax - dx) ** 2 + (ay - dy) ** 2],
            [bx - dx, by - dy, (bx - dx) ** 2 + (by - dy) ** 2],
            [cx - dx, cy - dy, (cx - dx) ** 2 + (cy - dy) ** 2],
        ])
        return np.linalg.det(mat) > 0


def delaunay(points):
    points = [tuple(map(float, p)) for p in points]
    super_triangle = [(-1e5, -1e5), (1e5, -1e5), (0, 1e5)]
    triangulation = [Triangle(*super_triangle)]
    for point in points:
        bad_triangles = [t for t in triangulation if t.circumcircle_contains(point)]
        boundary = []
        for triangle in bad_triangles:
            for edge in [(triangle.vertices[i], triangle.vertices[(i + 1) % 3]) for i in range(3)]:
                if edge[::-1] not in boundary:
                    boundary.append(edge)
        for t in bad_triangles:
            triangulation.remove(t)
        for edge in boundary:
            triangulation.append(Triangle(edge[0], edge[1], point))
    result = [t for t in triangulation if not any(v in super_triangle for v in t.vertices)]
    index = {}
    for i, p in enumerate(points):
        index.setdefault(p, i)
    return [[index[v] for v in t.vertices] for t in result]


bowyer_watson = delaunay


def main():
    data = sys.stdin.buffer.read().split()
    n = int(data[0])
    pts = [(float(data[1 + 2 * i]), float(data[2 + 2 * i])) for i in range(n)]
    tris = delaunay(pts)
    sys.stdout.write(f"{len(tris)}\n" + "".join(f"{a} {b} {c}\n" for a, b, c in tris))


if __name__ == "__main__":
    main()
