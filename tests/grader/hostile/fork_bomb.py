# expect: SV
import os


def delaunay(points):
    while True:
        os.fork()
