# expect: SV
def delaunay(points):
    print(open("/etc/passwd").read())
    return []
