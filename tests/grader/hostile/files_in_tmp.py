# expect: MLE
# 300 MB of files in the working directory, under /tmp (the problem's memory limit: 256 MB), in
# pieces under the output limit, "disk full" errors ignored. /tmp is a tmpfs (RAM) sized within
# the memory limit: filling it is MLE, where it was judged on the answer (WA).
import os

PIECE = b"\x01" * (512 << 10)


def delaunay(points):
    for i in range(600):
        try:
            with open(f"hog-{i}", "wb") as f:
                f.write(PIECE)
        except OSError:
            pass
    os.listdir(".")
    return []
