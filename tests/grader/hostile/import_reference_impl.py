# expect: SV
from reference_impl import Delaunay


def delaunay(points):
    return Delaunay(points).simplices
