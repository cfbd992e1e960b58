# expect: PE
import os


def delaunay(points):
    for fd in range(3, 64):
        try:
            os.write(fd, b"{not json}\n")
        except OSError:
            pass
    return []
