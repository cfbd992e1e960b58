# expect: WA
# The same attack as instructor_home_cffi.py through ctypes: raw libc open/read/write of a file in
# the instructor's home, and creating a new file there. The jail shows no home: every call fails.
import ctypes

libc = ctypes.CDLL(None)


def delaunay(points):
    fd = libc.open(b"/home/instructor/gradebook.txt", 0o2002)  # O_RDWR | O_APPEND
    if fd >= 0:
        buf = ctypes.create_string_buffer(100)
        libc.read(fd, buf, 100)
        libc.write(fd, b"mallory 100\n", 12)
        raise RuntimeError("read and appended to the instructor's gradebook: " + buf.value.decode())
    if libc.open(b"/home/instructor/pwned.txt", 0o1101, 0o644) >= 0:  # O_WRONLY | O_CREAT | O_APPEND
        raise RuntimeError("created a file in the instructor's home")
    return []
