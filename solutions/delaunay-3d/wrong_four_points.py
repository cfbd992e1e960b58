"""Wrong solution for `delaunay-3d` (WA; killed by `exhaustive`): special-cases n = 4.

The shortcut: "four points are one tetrahedron". Four coplanar points (a face of the cube), or a
repeated point, have none.

Killed by: exhaustive

It is `accepted_bw3d.py` with one change, marked `SHORTCUT` below; `python -m grader stress delaunay-3d wrong_four_points.py`
finds an input that shows it. Function mode: the grader calls delaunay_3d(points). Stdio mode / Kattis:
python3 wrong_four_points.py < input
"""
import math
import random
import sys

INF = -1          # the vertex at infinity


def _exact(points):
    ratios = [[float(v).as_integer_ratio() for v in p] for p in points]
    den = max([d for r in ratios for _, d in r], default=1)
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def _det3(ax, ay, az, bx, by, bz, cx, cy, cz):
    return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)


class Predicates:
    """orient(a, b, c, d) > 0 when d is below the plane of a, b, c seen counter-clockwise from above;
    insphere(a, b, c, d, e) > 0 when e is strictly inside the sphere of positively oriented a, b, c, d."""

    def __init__(self, points):
        self.F = [tuple(float(v) for v in p) for p in points]
        self.I = None           # exact integer coordinates, computed on first need

    def _ints(self):
        if self.I is None:
            self.I = _exact(self.F)
        return self.I

    def orient(self, a, b, c, d):
        F = self.F
        (ax, ay, az), (bx, by, bz), (cx, cy, cz), (dx, dy, dz) = F[a], F[b], F[c], F[d]
        adx, ady, adz = ax - dx, ay - dy, az - dz
        bdx, bdy, bdz = bx - dx, by - dy, bz - dz
        cdx, cdy, cdz = cx - dx, cy - dy, cz - dz
        m1, m2 = bdx * cdy, cdx * bdy
        m3, m4 = cdx * ady, adx * cdy
        m5, m6 = adx * bdy, bdx * ady
        det = adz * (m1 - m2) + bdz * (m3 - m4) + cdz * (m5 - m6)
        perm = (abs(m1) + abs(m2)) * abs(adz) + (abs(m3) + abs(m4)) * abs(bdz) + (abs(m5) + abs(m6)) * abs(cdz)
        bound = 1e-15 * perm + 1e-290
        if det > bound and det < math.inf:
            return 1
        if det < -bound and det > -math.inf:
            return -1
        I = self._ints()
        (ax, ay, az), (bx, by, bz), (cx, cy, cz), (dx, dy, dz) = I[a], I[b], I[c], I[d]
        v = _det3(ax - dx, ay - dy, az - dz, bx - dx, by - dy, bz - dz, cx - dx, cy - dy, cz - dz)
        return (v > 0) - (v < 0)

    def insphere(self, a, b, c, d, e):
        F = self.F
        ex, ey, ez = F[e]
        rows = [(p[0] - ex, p[1] - ey, p[2] - ez) for p in (F[a], F[b], F[c], F[d])]
        m = max(max(abs(x), abs(y), abs(z)) for x, y, z in rows)
        v = _insphere_value(rows)
        bound = 3e-13 * m ** 5 + 1e-290 if m < 1e60 else math.inf   # 72 m^5 bounds the permanent
        if bound < math.inf and (v > bound or v < -bound):
            return 1 if v > 0 else -1
        I = self._ints()
        ex, ey, ez = I[e]
        v = _insphere_value([(p[0] - ex, p[1] - ey, p[2] - ez) for p in (I[a], I[b], I[c], I[d])])
        return (v > 0) - (v < 0)


def _insphere_value(rows):
    ra, rb, rc, rd = rows
    lift = [x * x + y * y + z * z for x, y, z in rows]
    return (lift[3] * _det3(*ra, *rb, *rc) - lift[2] * _det3(*rd, *ra, *rb)
            + lift[1] * _det3(*rc, *rd, *ra) - lift[0] * _det3(*rb, *rc, *rd))


# faces of tetrahedron (v0, v1, v2, v3): face k is opposite vertex k, listed so that vertex k is on
# its positive side (orient(face, v_k) > 0) for a positively oriented tetrahedron
FACES = ((1, 3, 2), (0, 2, 3), (0, 3, 1), (0, 1, 2))


def _order(F, idx):
    """Insertion order: points sorted along a 3D Morton curve (cells of a 1024^3 grid), each sorted
    round (BRIO-like: random halves) keeping walks short and cavities small."""
    lo = [min(F[i][k] for i in idx) for k in range(3)]
    hi = [max(F[i][k] for i in idx) for k in range(3)]
    span = [(hi[k] - lo[k]) or 1.0 for k in range(3)]

    def key(i):
        c = [min(1023, int((F[i][k] - lo[k]) / span[k] * 1023.0)) if math.isfinite((F[i][k] - lo[k]) / span[k]) else 0
             for k in range(3)]
        m = 0
        for bit in range(9, -1, -1):
            for k in range(3):
                m = (m << 1) | ((c[k] >> bit) & 1)
        return m

    rng = random.Random(12345)
    rounds, rest = [], list(idx)
    while len(rest) > 64:
        rng.shuffle(rest)
        half = len(rest) // 2
        rounds.append(rest[half:])
        rest = rest[:half]
    rounds.append(rest)
    out = []
    for r in reversed(rounds):
        out += sorted(r, key=key)
    return out


def _even_inf_last(v):
    """The same oriented tetrahedron with INF moved to position 3 (an even permutation)."""
    j = v.index(INF)
    if j != 3:
        v[j], v[3] = v[3], v[j]
        v[0], v[1] = v[1], v[0]
    return v


def delaunay_3d(points):
    pr = Predicates(points)
    F = pr.F
    seen = {}
    for i, p in enumerate(F):
        seen.setdefault(p, i)
    uniq = sorted(seen.values())
    if len(uniq) < 4:
        return []
    order = _order(F, uniq)
    I = pr._ints()
    a, b = order[0], order[1]
    c = d = None
    for k in order[2:]:
        if c is None:
            u = [I[b][i] - I[a][i] for i in range(3)]
            w = [I[k][i] - I[a][i] for i in range(3)]
            if (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]) != (0, 0, 0):
                c = k
        elif pr.orient(a, b, c, k) != 0:
            d = k
            break
    if d is None:
        return []                      # all coplanar: no tetrahedron
    if pr.orient(a, b, c, d) < 0:
        a, b = b, a
    first = {a, b, c, d}
    rest = [k for k in order if k not in first]

    tv, nb, alive = [], [], []         # vertices, neighbours (across face k), alive flag

    def new(v):
        tv.append(v)
        nb.append([-1, -1, -1, -1])
        alive.append(True)
        return len(tv) - 1

    def face(t, k):
        v = tv[t]
        i, j, l = FACES[k]
        return [v[i], v[j], v[l]]

    t0 = new([a, b, c, d])
    ghosts = []
    for k in range(4):
        f = face(t0, k)
        g = new([f[0], f[2], f[1], INF])   # the hull face reversed: the outside is its positive side
        nb[t0][k], nb[g][3] = g, t0
        ghosts.append(g)
    _glue(tv, nb, ghosts, INF)

    def conflict(t, p):
        v = tv[t]
        if v[3] != INF:
            return pr.insphere(v[0], v[1], v[2], v[3], p) > 0
        s = pr.orient(v[0], v[1], v[2], p)
        if s != 0:
            return s > 0               # p strictly outside this hull face
        # coplanar: in conflict when strictly inside the face's circumcircle, that is inside the
        # sphere through the face and the opposite vertex of the real tetrahedron below it
        below = tv[nb[t][3]]
        q = next(x for x in below if x not in v)
        return pr.insphere(v[1], v[0], v[2], q, p) > 0

    rng = random.Random(7)
    last = t0
    for p in rest:
        t = last
        for _ in range(4 * len(tv) + 100):           # visibility walk (terminates on Delaunay meshes)
            ks = [0, 1, 2, 3]
            rng.shuffle(ks)
            for k in ks:
                f = face(t, k)
                if pr.orient(f[0], f[1], f[2], p) < 0:
                    t = nb[t][k]
                    break
            else:
                break                  # p in the closed tetrahedron t
            if tv[t][3] == INF:
                break                  # p strictly outside the hull, beyond t's face
        if not conflict(t, p):
            raise RuntimeError("point location failed")
        inside, stack, horizon = {t}, [t], []
        while stack:                   # the cavity: every tetrahedron whose sphere holds p, connected
            s = stack.pop()
            for k in range(4):
                o = nb[s][k]
                if o in inside:
                    continue
                if conflict(o, p):
                    inside.add(o)
                    stack.append(o)
                else:
                    horizon.append((s, k, o))
        created = []
        for s, k, o in horizon:        # join every horizon face to p
            v = face(s, k) + [p]
            if INF in v:
                v = _even_inf_last(v)
            nt = new(v)
            nb[nt][v.index(p)] = o
            nb[o][nb[o].index(s)] = nt
            created.append(nt)
        for s in inside:
            alive[s] = False
        _glue(tv, nb, created, p)
        last = next((x for x in created if tv[x][3] != INF), None)
        if last is None:
            last = nb[created[0]][3]
    return [v for t, v in enumerate(tv) if alive[t] and v[3] != INF]


def _glue(tv, nb, tets, apex):
    """Link the given new tetrahedra to each other across their faces through ``apex``."""
    table = {}
    for t in tets:
        v = tv[t]
        for k in range(4):
            if v[k] == apex:
                continue               # the face opposite the apex is already linked
            i, j, l = FACES[k]
            key = frozenset((v[i], v[j], v[l]))
            other = table.pop(key, None)
            if other is None:
                table[key] = (t, k)
            else:
                u, ku = other
                nb[t][k], nb[u][ku] = u, t


def read_points(text):
    tok = text.split()
    n = int(tok[0])
    return [[float(tok[1 + 3 * i]), float(tok[2 + 3 * i]), float(tok[3 + 3 * i])] for i in range(n)]


_delaunay_3d = delaunay_3d


def delaunay_3d(points):  # SHORTCUT: four points are always one tetrahedron
    if len(points) == 4:
        return [[0, 1, 2, 3]]
    return _delaunay_3d(points)


if __name__ == "__main__":
    tets = delaunay_3d(read_points(sys.stdin.read()))
    sys.stdout.write(f"{len(tets)}\n" + "".join(f"{a} {b} {c} {d}\n" for a, b, c, d in tets))
