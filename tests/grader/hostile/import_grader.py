# expect: SV
import grader


def delaunay(points):
    return []
