# expect: TLE
def delaunay(points):
    while True:
        pass
