# expect: SV
from scipy.spatial import Delaunay


def delaunay(points):
    return Delaunay(points).simplices
