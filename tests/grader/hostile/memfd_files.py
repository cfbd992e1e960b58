# expect: RE
# expect when the jail refuses processes: WA
# Anonymous in-memory files (memfd_create), each written up to the output limit (RLIMIT_FSIZE) and
# kept open: RAM outside the address space, as many as the open-files limit allows (64 x 16 MB for
# a problem with the default output limit; measured here: 49 MB for this 1 MB one). As root the
# cgroup charges them (60 MB is within 256 MB: it says so, RE); an ordinary account has no cgroup,
# and its jail now refuses memfd_create (EPERM): nothing kept, judged on the answer (WA).
import ctypes

libc = ctypes.CDLL(None, use_errno=True)


def delaunay(points):
    callback = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p)(lambda a, b: 0)
    libc.qsort((ctypes.c_int * 3)(3, 1, 2), 3, 4, callback)  # libffi closures work without memfd
    piece = b"\x01" * ((1 << 20) - 4096)
    held = []
    for _ in range(60):
        fd = libc.memfd_create(b"hog", 0)
        if fd < 0:
            break
        libc.write(fd, piece, len(piece))
        held.append(fd)
    if held:
        raise RuntimeError(f"kept {len(held)} MB in memfd files")
    return []
