"""Wrong solution for `dynamic-network` (WA; killed by `exhaustive`): special-cases small networks.

The shortcut: "with at most three live nodes, everyone is everyone's neighbour". Three nodes on a
line are not: the middle one separates the ends.

Killed by: exhaustive

It is `accepted_local.py` with one change, marked `SHORTCUT` below; `python -m grader stress dynamic-network wrong_small_all_linked.py`
finds an input that shows it. Function mode: the grader calls process(operations). Stdio mode / Kattis:
python3 wrong_small_all_linked.py < input
"""
import sys

INF = -1  # the infinite vertex of ghost triangles


def orient(a, b, c):
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def incircle(a, b, c, d):
    adx, ady = a[0] - d[0], a[1] - d[1]
    bdx, bdy = b[0] - d[0], b[1] - d[1]
    cdx, cdy = c[0] - d[0], c[1] - d[1]
    det = ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) - (bdx * bdx + bdy * bdy) * (adx * cdy - cdx * ady)
           + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))
    return (det > 0) - (det < 0)


class Network:
    def __init__(self, den=1, box=(0.0, 0.0, 1.0, 1.0), levels=1):
        self.box, self.levels = box, levels
        self.cells = {}  # (level, i, j) -> the position joined last in that grid cell
        self.den = den  # common denominator (a power of two) of every coordinate: vertices are ints
        self.count = 0
        self.pos = []  # node id -> (int x, int y), scaled by den
        self.alive = []
        self.at = {}  # position -> live node ids there (the vertex is the position itself)
        self.tri = None  # directed edge (u, v) -> w of triangle (u, v, w), CCW; vertices are positions
        self.edge_of = {}  # position -> a neighbour v with (position, v) in tri
        self.real = 0  # number of real (finite) triangles
        self.last = None

    # -- predicates with the infinite vertex -----------------------------------------------
    def in_ghost(self, u, v, p):  # ghost (u, v, INF): the real triangle is on the right of u->v
        s = orient(u, v, p)
        if s != 0:
            return s > 0
        return min(u[0], v[0]) <= p[0] <= max(u[0], v[0]) and min(u[1], v[1]) <= p[1] <= max(u[1], v[1])

    def conflict(self, u, v, w, p):
        if w == INF:
            return self.in_ghost(u, v, p)
        if u == INF:
            return self.in_ghost(v, w, p)
        if v == INF:
            return self.in_ghost(w, u, p)
        return incircle(u, v, w, p) > 0

    def add(self, u, v, w):
        t, e = self.tri, self.edge_of
        t[(u, v)] = w
        t[(v, w)] = u
        t[(w, u)] = v
        e[u], e[v], e[w] = v, w, u
        self.real += INF not in (u, v, w)

    def remove(self, u, v, w):
        t = self.tri
        del t[(u, v)], t[(v, w)], t[(w, u)]
        self.real -= INF not in (u, v, w)

    # -- building --------------------------------------------------------------------------
    def rebuild(self):
        """Triangulate the live positions from scratch (None when they are collinear or < 3)."""
        pts = list(self.at)
        self.tri = None
        if len(pts) < 3:
            return
        a, b = pts[0], pts[1]
        c = next((p for p in pts[2:] if orient(a, b, p) != 0), None)
        if c is None:
            return
        if orient(a, b, c) < 0:
            b, c = c, b
        self.tri, self.edge_of, self.real = {}, {}, 0
        self.add(a, b, c)
        self.add(b, a, INF)
        self.add(c, b, INF)
        self.add(a, c, INF)
        self.last = (a, b)
        for p in pts:
            if p not in (a, b, c):
                self.insert(p)

    def cell_keys(self, x, y):
        x0, y0, w, h = self.box
        fx, fy = (x / 2 - x0 / 2) / w, (y / 2 - y0 / 2) / h  # in [0, 1] (halves: no overflow at 1e308)
        return [(k, int(fx * (1 << k)), int(fy * (1 << k))) for k in range(self.levels, 0, -1)]

    def locate_start(self, x, y):
        """Start the walk at a live position joined in the finest grid cell around (x, y)."""
        for key in self.cell_keys(x, y):
            q = self.cells.get(key)
            if q is not None and q in self.at and q in self.edge_of and (q, self.edge_of[q]) in self.tri:
                self.last = (q, self.edge_of[q])
                return

    def insert(self, p):
        t = self.tri
        u, v = self.last if self.last in t else next(iter(t))
        w = t[(u, v)]
        if INF in (u, v, w):  # start from the real triangle next to this ghost
            while w != INF:
                u, v, w = v, w, u
            u, v = v, u
            w = t[(u, v)]
        while True:
            if orient(u, v, p) < 0:
                u, v = v, u
            elif orient(v, w, p) < 0:
                u, v = w, v
            elif orient(w, u, p) < 0:
                u, v = u, w
            else:
                break
            w = t[(u, v)]
            if w == INF:
                break
        start = (u, v, w)
        bad = {start}
        stack = [start]
        boundary = []
        while stack:
            tr = stack.pop()
            for x, y in ((tr[0], tr[1]), (tr[1], tr[2]), (tr[2], tr[0])):
                z = t.get((y, x))
                nb = (y, x, z)
                if nb in bad or (x, z, y) in bad or (z, y, x) in bad:
                    continue
                if self.conflict(y, x, z, p):
                    bad.add(nb)
                    stack.append(nb)
                else:
                    boundary.append((x, y))
        for tr in bad:
            self.remove(*tr)
        for x, y in boundary:
            self.add(x, y, p)
        self.last = boundary[0]

    def delete(self, p):
        """Remove vertex p: take out its star, fill the hole with Delaunay ears of its ring."""
        t = self.tri
        if len(self.at) < 3:
            self.rebuild()
            return
        ring = self.ring(p)  # CCW around p, may hold INF once
        for a, b in zip(ring, ring[1:] + ring[:1]):
            self.remove(p, a, b)
        while len(ring) > 3:
            for i in range(len(ring)):
                a, b, c = ring[i - 1], ring[i], ring[(i + 1) % len(ring)]
                if self.ear_ok(a, b, c, ring):
                    self.add(a, b, c)
                    del ring[i]
                    break
            else:  # no ear: the remaining positions are degenerate (collinear); start again
                self.rebuild()
                return
        a, b, c = ring
        if INF not in ring and orient(a, b, c) <= 0:
            self.rebuild()
            return
        self.add(a, b, c)
        if self.real == 0:  # the remaining positions are collinear
            self.rebuild()
            return
        self.last = next(((u, v) for u, v in zip(ring, ring[1:]) if INF not in (u, v)), None)

    def ear_ok(self, a, b, c, ring):
        if INF not in (a, b, c):
            if orient(a, b, c) <= 0:
                return False
        others = [x for x in ring if x not in (a, b, c) and x != INF]
        return not any(self.conflict(a, b, c, x) for x in others)

    def ring(self, p):
        """The neighbours of vertex p in CCW order (INF among them when p is on the hull)."""
        t = self.tri
        first = self.edge_of[p]
        ring = [first]
        while True:
            nxt = t[(p, ring[-1])]
            if nxt == first:
                return ring
            ring.append(nxt)

    def scale(self, x, y):
        (nx, dx), (ny, dy) = float(x).as_integer_ratio(), float(y).as_integer_ratio()
        return nx * (self.den // dx), ny * (self.den // dy)

    # -- the network -----------------------------------------------------------------------
    def neighbour_positions(self, p):
        if self.tri is None:  # collinear (or fewer than 3 positions): the adjacent ones on the line
            line = sorted(self.at)
            k = line.index(p)
            return line[max(k - 1, 0):k] + line[k + 1:k + 2]
        t = self.tri
        out = []
        for u in self.ring(p):
            if u == INF:
                continue
            w, z = t[(p, u)], t[(u, p)]
            if w != INF and z != INF and incircle(p, u, w, z) == 0:
                continue  # a tie diagonal: not in the strict Delaunay graph
            out.append(u)
        return out

    def join(self, x, y):
        node = len(self.pos)
        p = self.scale(x, y)
        self.pos.append(p)
        self.alive.append(True)
        if p in self.at:
            self.at[p].append(node)
            return node
        self.at[p] = [node]
        if self.tri is None:
            self.rebuild()
        else:
            self.locate_start(float(x), float(y))
            self.insert(p)
        for key in self.cell_keys(float(x), float(y)):
            self.cells[key] = p
        return node

    def fail(self, node):
        if not (type(node) is int and 0 <= node < len(self.pos) and self.alive[node]):
            return "error"
        self.alive[node] = False
        p = self.pos[node]
        self.at[p].remove(node)
        if not self.at[p]:
            del self.at[p]
            if self.tri is None:
                pass
            else:
                self.delete(p)
        return "ok"

    def neighbors(self, node):
        if not (type(node) is int and 0 <= node < len(self.pos) and self.alive[node]):
            return "error"
        p = self.pos[node]
        out = [v for v in self.at[p] if v != node]
        for q in self.neighbour_positions(p):
            out += self.at[q]
        return sorted(out)


def process(operations):
    den = 1  # denominators of doubles are powers of two: their maximum is a common multiple
    for op in operations:
        if op[0] == "join":
            den = max(den, float(op[1]).as_integer_ratio()[1], float(op[2]).as_integer_ratio()[1])
    xs = [float(op[1]) for op in operations if op[0] == "join"] or [0.0]
    ys = [float(op[2]) for op in operations if op[0] == "join"] or [0.0]
    box = (min(xs), min(ys), (max(xs) / 2 - min(xs) / 2) * 1.000001 or 1.0, (max(ys) / 2 - min(ys) / 2) * 1.000001 or 1.0)
    net = Network(den, box, max(1, (len(xs).bit_length() + 1) // 2))  # about one join per finest cell
    answers = []
    for op in operations:
        if op[0] == "join":
            answers.append(net.join(op[1], op[2]))
            net.count += 1
        elif op[0] == "fail":
            answers.append(net.fail(op[1]))
            net.count -= answers[-1] == "ok"
        elif op[0] == "neighbors":
            answers.append(net.neighbors(op[1]))
        else:
            answers.append(net.count)
    return answers


def main():
    lines = sys.stdin.read().split("\n")
    ops = []
    for line in lines[1:int(lines[0]) + 1]:
        parts = line.split()
        ops.append([parts[0]] + ([float(parts[1]), float(parts[2])] if parts[0] == "join" else
                                 [int(parts[1])] if len(parts) > 1 else []))
    out = []
    for a in process(ops):
        out.append(" ".join(map(str, [len(a)] + a)) if isinstance(a, list) else str(a))
    sys.stdout.write("\n".join(out) + "\n")


_process = process


def process(operations):  # SHORTCUT: <= 3 live nodes are all linked
    answers = _process(operations)
    live, next_id = set(), 0
    for k, op in enumerate(operations):
        if op[0] == "join":
            live.add(next_id)
            next_id += 1
        elif op[0] == "fail" and answers[k] == "ok":
            live.discard(op[1])
        elif op[0] == "neighbors" and answers[k] != "error" and len(live) <= 3:
            answers[k] = sorted(live - {op[1]})
    return answers


if __name__ == "__main__":
    main()
