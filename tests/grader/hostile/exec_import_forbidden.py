# expect: SV
def delaunay(points):
    exec("import shapely")
    return []
