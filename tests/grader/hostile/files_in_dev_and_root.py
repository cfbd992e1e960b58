# expect: RE
# Files written straight into /dev and into / of the jail through raw libc: bubblewrap's --dev
# and its new root are tmpfs owned by the sandbox's uid, writable and without a size (root: the
# cgroup's MLE; an ordinary account: 300 MB kept on the host, WA). Both are read-only now: the
# writes fail, and the submission says so (its own RuntimeError: RE).
import ctypes

libc = ctypes.CDLL(None, use_errno=True)
PIECE = b"\x01" * (512 << 10)


def delaunay(points):
    refused = []
    for prefix in ("/dev/hog-", "/hog-"):
        for i in range(300):
            fd = libc.open(f"{prefix}{i}".encode(), 0o1101, 0o600)  # O_WRONLY | O_CREAT | O_TRUNC
            if fd < 0:
                refused.append(f"{prefix}: errno {ctypes.get_errno()}")
                break
            libc.write(fd, PIECE, len(PIECE))
            libc.close(fd)
    if len(refused) == 2:
        raise RuntimeError("not writable: " + ", ".join(refused))
    return []
