# expect: RE
def delaunay(points):
    return delaunay(points)
