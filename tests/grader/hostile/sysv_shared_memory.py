# expect: MLE
# expect when the jail refuses processes: RE
# 40 SysV shared memory segments of 8 MB (320 MB for a 256 MB problem), each attached, filled and
# detached: a segment outlives shmdt, outside the address space. As root the cgroup charges it
# (MLE); an ordinary account has no cgroup: 320 MB stayed on the host, judged WA. Its jail now
# refuses shmget (EPERM), which the submission reports (its own RuntimeError: RE).
import ctypes

libc = ctypes.CDLL(None, use_errno=True)
libc.shmat.restype = ctypes.c_void_p
libc.shmat.argtypes = [ctypes.c_int, ctypes.c_void_p, ctypes.c_int]
libc.shmdt.argtypes = [ctypes.c_void_p]


def delaunay(points):
    for made in range(40):
        sid = libc.shmget(0, 8 << 20, 0o1600)  # IPC_PRIVATE, IPC_CREAT | 0600
        if sid < 0:
            raise RuntimeError(f"shmget refused (errno {ctypes.get_errno()}) after {made} segments")
        addr = libc.shmat(sid, None, 0)
        ctypes.memset(addr, 1, 8 << 20)
        libc.shmdt(addr)
    return []
