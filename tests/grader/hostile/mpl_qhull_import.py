# expect: SV
# matplotlib bundles Qhull as matplotlib._qhull: forbidding scipy.spatial and matplotlib.tri by
# name let this through (AC 100); the engine is forbidden under every name.
from matplotlib import _qhull


def delaunay(points):
    x = [float(p[0]) for p in points]
    y = [float(p[1]) for p in points]
    triangles, _neighbors = _qhull.delaunay(x, y, 0)
    return [[int(i) for i in t] for t in triangles]
