# expect: MLE
# files_in_dev_shm.py as a program (stdio mode): 300 MB of files in /dev/shm through raw libc, then
# an answer and a normal exit. Its jail, and the files, end with it: the program waits until the
# judge has measured them (it then sees /dev/shm full: MLE); sampled only, it was judged WA.
import ctypes
import sys

libc = ctypes.CDLL(None, use_errno=True)
sys.stdin.read()
piece = b"\x01" * (512 << 10)
for i in range(600):
    fd = libc.open(f"/dev/shm/hog-{i}".encode(), 0o1101, 0o600)  # O_WRONLY | O_CREAT | O_TRUNC
    if fd >= 0:
        libc.write(fd, piece, len(piece))
        libc.close(fd)
print(0)
