# expect: PE
def delaunay(points):
    return "0 1 2"
