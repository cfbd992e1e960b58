# expect: WA
import ctypes

libc = ctypes.CDLL(None)


def delaunay(points):
    for path in (b"/work/main/grader/__init__.py", b"/work/main/pwned.txt", b"/tmp/pwned-by-student"):
        fd = libc.open(path, 0o1101, 0o644)  # O_WRONLY | O_CREAT | O_APPEND
        if fd >= 0:
            libc.write(fd, b"pwned\n", 6)
    return []
