# expect: WA
# A classmate's submission in the class folder (/home/instructor/submitted/bob/... is replaced by
# a real file of the grading account, see tests/grader/test_hostile.py): reading it through libc
# would let a student copy it; the jail shows no class folder.
import ctypes

libc = ctypes.CDLL(None)
libc.opendir.restype = ctypes.c_void_p


def delaunay(points):
    if libc.open(b"/home/instructor/submitted/bob/delaunay.py", 0) >= 0:
        raise RuntimeError("read a classmate's submission")
    if libc.opendir(b"/home/instructor/submitted"):
        raise RuntimeError("listed the class folder")
    return []
