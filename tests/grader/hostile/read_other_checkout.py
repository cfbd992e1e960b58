# expect: WA
# Another copy of the course elsewhere on the machine (a second checkout, an instructor's
# folder): read past the audit hook with raw libc open(). Hiding was a deny-list (this checkout,
# /root, /home), so such a copy was readable; the jail is an allow-list now.
# tests/grader/test_sandbox.py creates /srv/hostile-course-copy/... before judging this.
import ctypes

libc = ctypes.CDLL(None)
PLACES = (b"/srv/hostile-course-copy/course/solutions/delaunay/accepted_walk.py",
          b"/srv/course/solutions/delaunay/accepted_walk.py", b"/opt/course/solutions/delaunay/accepted_walk.py")


def delaunay(points):
    for path in PLACES:
        if libc.open(path, 0) >= 0:
            raise RuntimeError("could read " + path.decode())
    return []
