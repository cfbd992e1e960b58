# expect: PE
def delaunay(points):
    return [[10 ** 5000, 1, 2]]
