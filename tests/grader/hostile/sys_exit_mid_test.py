# expect: RE
import sys


def delaunay(points):
    sys.exit(0)
