# expect: WA
# Raw libc open() bypasses the audit hook; the checkout is not even visible in the jail.
import ctypes

libc = ctypes.CDLL(None)


def delaunay(points):
    for path in (b"/work/main/assignments/delaunay/problem.yaml", b"/work/main/grader/contest/judge.py",
                 b"/root/.bashrc"):
        if libc.open(path, 0) >= 0:
            raise RuntimeError("could open " + path.decode())
    return []
