# expect: TLE
# expect when the jail refuses processes: SV
# The worker forks (raw libc, past the audit hook) two helpers that do about 1.5 CPU-seconds of
# work each, and waits for them on a pipe: its own CPU stays near zero. Charging only the
# worker's /proc entry, this was AC on a quiet machine (3 CPU-seconds reported as 0.001 s); the
# whole sandbox (its cgroup) is charged now: TLE, on a loaded machine too.
# It proves its helpers ran: a fork that fails for want of a process slot (EAGAIN: an earlier
# test's reaper not yet collected by the host's init, on a busy machine) is retried, and if
# fewer than two helpers report back the answer is an error (RE), never a quiet AC (seen once in
# 1993 runs). An ordinary user's jail refuses the fork itself: SV.
import ctypes
import os
import time
from fractions import Fraction
from itertools import combinations

libc = ctypes.CDLL(None)


def work():
    x = 0
    for i in range(30_000_000):
        x += i
    return x


def brute_force(points):
    P = [(Fraction(x), Fraction(y)) for x, y in points]

    def orient(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    def incircle(a, b, c, d):
        m = [[p[0] - d[0], p[1] - d[1], (p[0] - d[0]) ** 2 + (p[1] - d[1]) ** 2] for p in (a, b, c)]
        return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))

    out = []
    for i, j, k in combinations(range(len(P)), 3):
        o = orient(P[i], P[j], P[k])
        if o == 0:
            continue
        if o < 0:
            j, k = k, j
        if all(incircle(P[i], P[j], P[k], P[m]) <= 0 for m in range(len(P)) if m not in (i, j, k)):
            out.append([i, j, k])
    return out


def fork():
    for _ in range(100):
        pid = libc.fork()
        if pid >= 0:
            return pid
        time.sleep(0.02)
    return -1


def delaunay(points):
    r, w = os.pipe()
    for _ in range(2):
        if fork() == 0:
            work()
            os.write(w, b"x")
            os._exit(0)
    os.close(w)
    done = b""
    while chunk := os.read(r, 2):  # blocks without CPU until both helpers are done (end of file)
        done += chunk
    if done != b"xx":
        raise RuntimeError(f"only {len(done)} of 2 helpers ran")
    return brute_force(points)
