# expect: RE
import os


def delaunay(points):
    os._exit(0)
