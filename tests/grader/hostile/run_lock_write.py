# expect: WA
# /run/lock is world-writable on the host; with raw libc open() it was writable from the jail.
import ctypes

libc = ctypes.CDLL(None)
O_WRONLY, O_CREAT = 0o1, 0o100


def delaunay(points):
    for path in (b"/run/lock/hostile-was-here", b"/var/tmp/hostile-was-here", b"/dev/shm/../hostile"):
        fd = libc.open(path, O_WRONLY | O_CREAT, 0o644)
        if fd >= 0 and not path.startswith(b"/dev/shm"):
            libc.unlink(path)
            raise RuntimeError("could write " + path.decode())
    return []
