# expect: SV
import importlib


def delaunay(points):
    spatial = importlib.import_module("scipy.spatial")
    return spatial.Delaunay(points).simplices
