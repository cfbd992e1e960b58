# expect: WA
# The grader caches every problem's generated tests, hidden answers included, in the instructor's
# .cache/grader/ (GRADER_CACHE; /grader-cache here is replaced by that path). Listing it with
# libc opendir and reading its files with libc open bypasses the audit hook; the jail does not
# contain it.
import ctypes

libc = ctypes.CDLL(None)
libc.opendir.restype = ctypes.c_void_p


def delaunay(points):
    if libc.opendir(b"/grader-cache/tiny-delaunay"):
        raise RuntimeError("listed the grader's test cache")
    if libc.opendir(b"/grader-cache"):
        raise RuntimeError("listed the grader's cache")
    return []
