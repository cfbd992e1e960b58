# expect: WA
# cffi (installed with the course through argon2-cffi) gives libc's open/read/write without any
# audit event. As an ordinary instructor with only rlimits, this read a file in the instructor's
# home (standing in for gradebook.db) and appended to it once per test. The kernel jail shows no
# home at all: open fails, nothing is read or written. (/home/instructor is replaced by the
# grading account's test directory, see tests/grader/test_hostile.py.)
import cffi

ffi = cffi.FFI()
ffi.cdef("int open(const char *path, int flags, ...); long read(int fd, void *buf, unsigned long n);"
         "long write(int fd, const void *buf, unsigned long n);")
libc = ffi.dlopen(None)


def delaunay(points):
    fd = libc.open(b"/home/instructor/gradebook.txt", 0o2002)  # O_RDWR | O_APPEND
    if fd >= 0:
        buf = ffi.new("char[100]")
        libc.read(fd, buf, 100)
        libc.write(fd, b"mallory 100\n", 12)
        raise RuntimeError("read and appended to the instructor's gradebook: " + ffi.string(buf).decode())
    return []
