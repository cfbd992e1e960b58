# expect: MLE
def delaunay(points):
    return bytearray(10 ** 11)
