# expect: WA
# expect when the jail refuses processes: SV
# A raw-libc forked helper that detaches (its own session) and sleeps, left behind after the
# answer: as root the judge kills every process of the sandbox uid, and the test suite checks
# that none survives; an ordinary user's jail refuses the fork (SV), and the whole pid namespace
# ends with the sandbox anyway.
import ctypes

libc = ctypes.CDLL(None)


def delaunay(points):
    if libc.fork() == 0:
        libc.setsid()
        if libc.fork() == 0:
            libc.sleep(1000)
        libc._exit(0)
    return []
