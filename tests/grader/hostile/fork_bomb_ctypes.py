# expect: TLE
# expect when the jail refuses processes: SV
# Bypasses the audit hook with a raw libc fork: RLIMIT_NPROC (binding: the child has its own uid)
# caps the process count, and the judge kills every process of the sandbox uid afterwards.
import ctypes

libc = ctypes.CDLL(None)


def delaunay(points):
    while True:
        libc.fork()
