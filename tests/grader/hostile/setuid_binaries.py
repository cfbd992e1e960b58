# expect: WA
# Setuid-root binaries (su, mount, passwd, ...) were runnable with their privileges: NO_NEW_PRIVS
# was not set. A raw libc exec would run them as root-capable; with NO_NEW_PRIVS (asked here
# through prctl, past the audit hook) the kernel ignores the setuid bit, and in the bubblewrap
# jail every mount is nosuid too.
import ctypes

libc = ctypes.CDLL(None)
PR_GET_NO_NEW_PRIVS = 39


def delaunay(points):
    if libc.prctl(PR_GET_NO_NEW_PRIVS, 0, 0, 0, 0) != 1:
        raise RuntimeError("NO_NEW_PRIVS is not set: setuid binaries would gain root")
    return []
