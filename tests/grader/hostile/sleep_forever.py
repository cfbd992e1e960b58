# expect: TLE
import time


def delaunay(points):
    time.sleep(1000)
