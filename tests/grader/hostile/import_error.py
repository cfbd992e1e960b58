# expect: CE
import numpyy


def delaunay(points):
    return []
