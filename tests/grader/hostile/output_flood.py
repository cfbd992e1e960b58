# expect: OLE
def delaunay(points):
    while True:
        print("x" * 100000)
