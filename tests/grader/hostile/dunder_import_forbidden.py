# expect: SV
def delaunay(points):
    try:
        tri = __import__("triangle")
    except BaseException:
        return []  # catching the refusal does not hide it
    return tri.triangulate({"vertices": points})["triangles"]
