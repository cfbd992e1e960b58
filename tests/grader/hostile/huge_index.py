# expect: WA
def delaunay(points):
    return [[10 ** 15, 1, 2]]
