# expect: PE
def delaunay(points):
    return [[float("nan"), 1, 2]]
