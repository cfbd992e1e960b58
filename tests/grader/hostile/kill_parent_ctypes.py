# expect: WA
# libc kill() bypasses the audit hook, but the child runs as another uid: EPERM, nothing happens.
import ctypes
import os

libc = ctypes.CDLL(None)


def delaunay(points):
    libc.kill(os.getppid(), 9)
    libc.kill(-1, 9)
    return []
