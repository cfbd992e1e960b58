# expect: MLE
# expect when the jail refuses processes: SV
# Three raw-libc forked helpers each fill 120 MB (360 MB for a 256 MB problem) while the worker
# itself stays small and answers. Measuring only the worker, it was judged on its answer (WA
# here) with 13 MB reported; the whole sandbox's memory (its cgroup) is limited and charged now.
import ctypes
import os
import select

libc = ctypes.CDLL(None)


def delaunay(points):
    r, w = os.pipe()
    for _ in range(3):
        if libc.fork() == 0:
            block = bytearray(b"\x01") * (120 << 20)  # written, so resident
            os.write(w, b"x")
            while True:
                libc.pause()
                block[0] += 1
    got = b""
    while len(got) < 3 and select.select([r], [], [], 3.0)[0]:
        got += os.read(r, 3)
    return []
