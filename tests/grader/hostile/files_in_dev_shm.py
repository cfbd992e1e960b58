# expect: MLE
# 300 MB of files in /dev/shm (the problem's memory limit: 256 MB), written through raw libc (the
# audit hook refuses the path in Python) in pieces under the output limit (RLIMIT_FSIZE), errors
# ignored. bubblewrap's /dev/shm had no size: as an ordinary account 3 GiB stayed on the host per
# test, judged WA with 17 MB reported. Now /dev/shm is a sized tmpfs within the memory limit, and
# filling it is MLE ("kept N MB in /dev/shm").
import ctypes

libc = ctypes.CDLL(None, use_errno=True)
PIECE = b"\x01" * (512 << 10)


def fill(prefix: str, pieces: int) -> int:
    written = 0
    for i in range(pieces):
        fd = libc.open(f"{prefix}{i}".encode(), 0o1101, 0o600)  # O_WRONLY | O_CREAT | O_TRUNC
        if fd < 0:
            continue
        written += max(0, libc.write(fd, PIECE, len(PIECE)))
        libc.close(fd)
    return written


def delaunay(points):
    fill("/dev/shm/hog-", 600)
    return []
