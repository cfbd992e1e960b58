# expect: WA
# Kernel attack surface reached with raw libc calls: a new user namespace (unshare) and ptrace.
# Both succeeded inside the jail before; the seccomp filter answers EPERM now.
import ctypes

libc = ctypes.CDLL(None, use_errno=True)
CLONE_NEWUSER, PTRACE_TRACEME = 0x10000000, 0


def delaunay(points):
    if libc.unshare(CLONE_NEWUSER) == 0:
        raise RuntimeError("unshare(CLONE_NEWUSER) succeeded")
    if libc.ptrace(PTRACE_TRACEME, 0, None, None) == 0:
        raise RuntimeError("ptrace(PTRACE_TRACEME) succeeded")
    return []
