# expect: WA
# An answer under the output limit but with far more triangles than n points can have (at most
# 2n - 5): rejected by the checker before any triangle is looked at.


def delaunay(points):
    return [[0, 1, 2]] * 50_000
