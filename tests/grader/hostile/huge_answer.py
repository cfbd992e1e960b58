# expect: OLE
# An answer over the output limit: 200 000 triangles, about 1.6 MB of JSON against the fixture's
# 1 MiB (on `delaunay`, 2 million triangles against 16 MiB). Up to 64 MiB used to be read, parsed
# and checked (167 s and 1.6 GB for 2 million triangles); the reply is now cut at the problem's
# output limit before any parsing (OLE).


def delaunay(points):
    return [[0, 1, 2]] * 200_000
