# expect: TLE
# Sleeps 3.5 s per test: just under the old wall cap (3 x the 1 s limit + 1 s), so it was AC and
# held a judge for minutes on a real problem. The wall cap is now 1.5 x the limit + 1 s.
import time


def delaunay(points):
    time.sleep(3.5)
    return []
