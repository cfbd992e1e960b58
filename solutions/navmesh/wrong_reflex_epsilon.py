"""Wrong solution for `navmesh` (WA; killed by `degenerate`): a corner is reflex only when its turn
is below -1e-12.

The shortcut: "floating-point turns near 0 are noise, so only a clearly negative turn is a reflex
corner". The coordinates are exact (moved and scaled by a power of two), and a wall with a tiny
dip is a real reflex corner: in the room [[0, 0], [5, 2**-40], [10, 0], [10, 10], [0, 10]] a route
from (0, 0) to (10, 0) must bend at (5, 2**-40), whose turn is about -4e-14 after scaling; without
that corner there is no route at all.

Killed by: degenerate

It is `accepted_visibility.py` with one change, marked `SHORTCUT` below; `python -m grader stress navmesh wrong_reflex_epsilon.py`
finds an input that shows it. Function mode: the grader calls shortest_path(boundary, holes, start, goal). Stdio mode / Kattis:
python3 wrong_reflex_epsilon.py < input
"""
import heapq
import math
import sys

import numpy as np


class Room:
    def __init__(self, boundary, holes, start, goal):
        rings = [list(map(tuple, boundary))] + [list(map(tuple, h)) for h in holes]
        ox, oy = rings[0][0]
        big = max(abs(c - o) for r in rings for p in r + [tuple(start), tuple(goal)] for c, o in zip(p, (ox, oy)))
        scale = 2.0 ** -math.frexp(big)[1] if big > 0 else 1.0
        self.original, pts, ring_id, prv, nxt = [], [], [], [], []
        for r, ring in enumerate(rings):
            loc = [((x - ox) * scale, (y - oy) * scale) for x, y in ring]
            area = sum(a[0] * b[1] - a[1] * b[0] for a, b in zip(loc, loc[1:] + loc[:1]))
            if (area > 0) != (r == 0):        # free space on the left: boundary ccw, holes cw
                ring = ring[::-1]
            base, n = len(pts), len(ring)
            for i, p in enumerate(ring):
                self.original.append([float(p[0]), float(p[1])])
                pts.append(((p[0] - ox) * scale, (p[1] - oy) * scale))
                ring_id.append(r)
                prv.append(base + (i - 1) % n)
                nxt.append(base + (i + 1) % n)
        self.norm = lambda p: ((p[0] - ox) * scale, (p[1] - oy) * scale)
        P = np.array(pts, dtype=float)
        self.X, self.Y = P[:, 0], P[:, 1]
        self.nxt = np.array(nxt)
        self.AX, self.AY = self.X, self.Y                       # wall k: vertex k -> nxt[k]
        self.BX, self.BY = self.X[self.nxt], self.Y[self.nxt]
        self.ring = np.array(ring_id)
        self.first = np.flatnonzero(np.diff(self.ring, prepend=-1))    # each ring's first wall
        prv = np.array(prv)
        turn = (self.X - self.X[prv]) * (self.BY - self.Y) - (self.Y - self.Y[prv]) * (self.BX - self.X)
        self.reflex = np.flatnonzero(turn < -1e-12)    # SHORTCUT: an epsilon against rounding

    def free(self, mx, my):
        """Closed free space test for arrays of points (shape (k,))."""
        mx, my = mx[:, None], my[:, None]
        AX, AY, BX, BY = self.AX, self.AY, self.BX, self.BY
        o = (BX - AX) * (my - AY) - (BY - AY) * (mx - AX)
        on = (o == 0) & (np.minimum(AX, BX) <= mx) & (mx <= np.maximum(AX, BX)) \
            & (np.minimum(AY, BY) <= my) & (my <= np.maximum(AY, BY))
        up = (AY <= my) & (my < BY) & (o > 0)
        down = (BY <= my) & (my < AY) & (o < 0)
        wind = np.add.reduceat(up.astype(np.int64) - down, self.first, axis=1)   # per ring
        inside = (wind[:, 0] != 0) & ~(wind[:, 1:] != 0).any(axis=1)
        return on.any(axis=1) | inside

    def visible_from(self, px, py, qx, qy):
        """Which segments (px, py) -> (qx[j], qy[j]) lie in the closed free space."""
        AX, AY, BX, BY = self.AX, self.AY, self.BX, self.BY
        dx, dy = (qx - px)[:, None], (qy - py)[:, None]
        o1 = dx * (AY - py) - dy * (AX - px)
        o2 = dx * (BY - py) - dy * (BX - px)
        o3 = (BX - AX) * (py - AY) - (BY - AY) * (px - AX)
        o4 = (BX - AX) * (qy[:, None] - AY) - (BY - AY) * (qx[:, None] - AX)
        ok = ~(((o1 * o2) < 0) & ((o3 * o4) < 0)).any(axis=1)
        dd = dx * dx + dy * dy
        t = (dx * (AX - px) + dy * (AY - py)) / np.where(dd == 0, 1, dd)
        touch = (o1 == 0) & (t > 0) & (t < 1) & (dd > 0)        # polygon corners inside the segment
        ok &= self.free(px + (qx - px) / 2, py + (qy - py) / 2)
        for j in np.flatnonzero(ok & touch.any(axis=1)):
            ts = np.concatenate(([0.0], np.sort(t[j][touch[j]]), [1.0]))
            m = (ts[:-1] + ts[1:]) / 2
            ok[j] = self.free(px + m * (qx[j] - px), py + m * (qy[j] - py)).all()
        return ok


def shortest_path(boundary, holes, start, goal):
    room = Room(boundary, holes, start, goal)
    s, g = [float(start[0]), float(start[1])], [float(goal[0]), float(goal[1])]
    ends = np.array([room.norm(s), room.norm(g)])
    if not room.free(ends[:, 0], ends[:, 1]).all():
        return None
    if s == g:
        return [s]
    nodes = [s, g] + [room.original[k] for k in room.reflex]
    NX = np.concatenate((ends[:, 0], room.X[room.reflex]))
    NY = np.concatenate((ends[:, 1], room.Y[room.reflex]))
    n = len(nodes)
    adj = [[] for _ in range(n)]
    for i in range(n - 1):
        ok = room.visible_from(NX[i], NY[i], NX[i + 1:], NY[i + 1:])
        for j in np.flatnonzero(ok) + i + 1:
            w = math.dist(nodes[i], nodes[j])
            adj[i].append((j, w))
            adj[j].append((i, w))
    dist, back = [math.inf] * n, [-1] * n
    dist[0] = 0.0
    heap = [(0.0, 0)]
    while heap:
        d, u = heapq.heappop(heap)
        if d > dist[u]:
            continue
        if u == 1:
            break
        for v, w in adj[u]:
            if d + w < dist[v]:
                dist[v], back[v] = d + w, u
                heapq.heappush(heap, (d + w, v))
    if back[1] < 0:
        return None   # cannot happen in a connected free space
    path, v = [], 1
    while v != -1:
        path.append(nodes[v])
        v = back[v]
    return path[::-1]


def read_input(text):
    tok = text.split()
    pos = 0

    def ring():
        nonlocal pos
        n = int(tok[pos])
        pts = [[float(tok[pos + 1 + 2 * i]), float(tok[pos + 2 + 2 * i])] for i in range(n)]
        pos += 1 + 2 * n
        return pts

    boundary = ring()
    h = int(tok[pos])
    pos += 1
    holes = [ring() for _ in range(h)]
    rest = [float(v) for v in tok[pos:pos + 4]]
    return boundary, holes, rest[:2], rest[2:]


def main():
    path = shortest_path(*read_input(sys.stdin.read()))
    if path is None:
        sys.stdout.write("0\n")
    else:
        sys.stdout.write(f"{len(path)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in path))


if __name__ == "__main__":
    main()
