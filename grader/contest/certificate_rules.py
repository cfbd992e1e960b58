"""The certificate of each problem: which exact fact shows a wrong answer wrong (used by certificate.py).

Every builder takes the problem's parsed input (``args``), the submission's parsed answer, the
reference answer (or None) and the checker's message, and returns ``{"kind", "claim", ...}``. Every
predicate is decided with Python ``Fraction`` arithmetic on the input's doubles (each double is a
rational number exactly), and every computed value is written as a ``"p/q"`` string. When no
short exact witness exists the kind is ``differs``: the checker's message and the reference's
answer for the first item that differs.

Run: imported by :mod:`grader.contest.certificate` (``certify``); no command of its own.
Example:
    >>> closest_pair([[[0, 0], [5, 0], [0, 1]]], [0, 1], [0, 2], "")["closer"]
    [0, 2]
"""
from __future__ import annotations

import math
from collections import deque
from fractions import Fraction

from reference_impl.exact import verify

KINDS = {
    "delaunay": ["point-in-circumcircle", "not-counter-clockwise", "overlapping-triangles",
                 "hull-edge-uncovered", "one-sided-edge", "point-not-a-vertex", "differs"],
    "edge-flip": ["illegal-flip", "point-in-circumcircle", "not-counter-clockwise", "overlapping-triangles",
                  "hull-edge-uncovered", "one-sided-edge", "point-not-a-vertex", "differs"],
    "delaunay-3d": ["point-in-circumsphere", "flat-tetrahedron", "differs"],
    "emst": ["cheaper-edge", "cycle", "not-spanning", "differs"],
    "closest-pair": ["closer-pair", "differs"],
    "largest-empty-circle": ["point-in-circle", "centre-outside-hull", "larger-empty-circle", "differs"],
    "voronoi": ["vertex-nearer-other-site", "vertex-outside-box", "differs"],
    "proximity-network": ["not-gabriel-edge", "missing-gabriel-edge", "differs"],
    "navmesh": ["path-exists", "path-leaves-free-space", "outside-free-space", "shorter-path", "differs"],
    "obstacle-clearance": ["obstacle-too-close", "differs"],
    "dynamic-network": ["first-wrong-answer"],
}
KINDS["bowyer-watson-timed"] = KINDS["delaunay"]
BRUTE = 100_000  # triangle-point tests (or pairs) a brute-force witness search may look at
SMALL_N = 60     # all pairs are tried as witnesses (each with an O(n) scan) up to this many points


def q(v) -> str:
    """An exact value as text: ``q(Fraction(1, 2)) == '1/2'``, ``q(0.25) == '1/4'``."""
    return str(Fraction(v))


def frac(points) -> list[tuple]:
    return [tuple(Fraction(c) for c in p) for p in points]


def orient(a, b, c) -> Fraction:
    """Twice the signed area of (a, b, c): > 0 counter-clockwise."""
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def incircle(a, b, c, d) -> Fraction:
    """> 0 when d is strictly inside the circle through counter-clockwise a, b, c."""
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    (ax, ay), (bx, by), (cx, cy) = rows
    return ((ax * ax + ay * ay) * (bx * cy - cx * by) + (bx * bx + by * by) * (cx * ay - ax * cy)
            + (cx * cx + cy * cy) * (ax * by - bx * ay))


def sq(a, b) -> Fraction:
    return sum((x - y) ** 2 for x, y in zip(a, b))


def differs(reason: str, **extra) -> dict:
    return {"kind": "differs", "claim": reason, **extra}


# -- triangulations ---------------------------------------------------------------------------
def triangulation(points: list, triangles: list, reason: str) -> dict:
    """The witness that ``triangles`` is not the Delaunay triangulation of ``points``."""
    P = frac(points)
    n = len(P)
    first: dict = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    T = [list(t) for t in triangles]
    for t in T:
        o = orient(*(P[v] for v in t))
        if o <= 0:
            what = "has zero area" if o == 0 else "is clockwise"
            return {"kind": "not-counter-clockwise", "triangle": t, "orient2d": q(o),
                    "claim": f"triangle {t} {what} (twice its signed area is {q(o)}); triangles must be "
                             "counter-clockwise with positive area."}
    distinct = [i for i in range(n) if rep[i] == i]
    if len(T) * n <= BRUTE:
        for t in T:
            corners = {P[v] for v in t}
            for d in distinct:
                if P[d] not in corners:
                    value = incircle(*(P[v] for v in t), P[d])
                    if value > 0:
                        return _in_circle(t, d, value)
    count: dict = {}
    for t in T:
        a, b, c = (rep[v] for v in t)
        for e in ((a, b), (b, c), (c, a)):
            count.setdefault(e, []).append(t)
    for (u, v), ts in count.items():
        if len(ts) > 1:
            return {"kind": "overlapping-triangles", "edge": [u, v], "triangles": ts[:2],
                    "claim": f"triangles {ts[0]} and {ts[1]} both lie on the left of the edge {u}->{v} "
                             "(both counter-clockwise): they overlap."}
    I = verify.exact_coordinates(points)
    hull = [rep[i] for i in verify.convex_hull_exact(I, keep_collinear=True)]
    hull_edges = [(hull[i], hull[(i + 1) % len(hull)]) for i in range(len(hull))]
    flat = len(distinct) < 3 or all(orient(P[hull[0]], P[hull[-1]], P[i]) == 0 for i in distinct)
    if not flat:
        for u, v in hull_edges:
            if (u, v) not in count:
                return {"kind": "hull-edge-uncovered", "edge": [u, v],
                        "claim": f"no point lies strictly right of {u}->{v}, an edge of the convex hull, "
                                 "but no triangle has this edge: part of the hull is not covered."}
        hull_set = set(hull_edges)
        for (u, v), ts in count.items():
            if (v, u) not in count and (u, v) not in hull_set:
                w = next((i for i in distinct if orient(P[u], P[v], P[i]) < 0), None)
                if w is not None:
                    return {"kind": "one-sided-edge", "edge": [u, v], "triangle": ts[0], "point": w,
                            "orient2d": q(orient(P[u], P[v], P[w])),
                            "claim": f"only triangle {ts[0]} has the edge {u}-{v}, yet point {w} lies strictly "
                                     "on its other side: there is a gap or an overlap at this edge."}
        used = {rep[v] for t in T for v in t}
        missing = next((i for i in distinct if i not in used), None)
        if missing is not None:
            return {"kind": "point-not-a-vertex", "point": missing,
                    "claim": f"point {missing} is a vertex of no triangle; every input point must be one."}
    opposite = {}
    for t in T:
        a, b, c = t
        opposite[(rep[a], rep[b])], opposite[(rep[b], rep[c])], opposite[(rep[c], rep[a])] = t, t, t
    for (u, v), t in opposite.items():
        s = opposite.get((v, u))
        if s is not None:
            d = next(x for x in s if rep[x] not in (u, v))
            value = incircle(*(P[x] for x in t), P[d])
            if value > 0:
                return _in_circle(t, d, value)
    return differs(reason)


def _in_circle(t: list, d: int, value: Fraction) -> dict:
    return {"kind": "point-in-circumcircle", "triangle": t, "point": d, "incircle": q(value),
            "claim": f"point {d} lies strictly inside the circumcircle of your triangle {t} (exact in-circle "
                     f"determinant {q(value)} > 0), so the triangulation is not Delaunay."}


def delaunay(args, triangles, expected, reason) -> dict:
    return triangulation(args[0], triangles, reason)


def edge_flip(args, flips, expected, reason, replay=None) -> dict:
    points, start = args
    from ..problems import load_problem

    final, message = load_problem("edge-flip").checker.replay(points, start, flips)
    if final is None:
        return {"kind": "illegal-flip", "claim": message + "."}
    cert = triangulation(points, final, reason)
    cert["after_flips"] = len(flips)
    cert["claim"] = f"after your {len(flips)} flips: " + cert["claim"]
    return cert


def delaunay_3d(args, tets, expected, reason) -> dict:
    P = frac(args[0])
    first: dict = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    distinct = [i for i in range(len(P)) if rep[i] == i]
    for t in tets:
        o = _det3(*[tuple(P[v][k] - P[t[3]][k] for k in range(3)) for v in t[:3]])
        if o == 0:
            return {"kind": "flat-tetrahedron", "tetrahedron": list(t), "orient3d": "0",
                    "claim": f"tetrahedron {list(t)} has zero volume (its four points are coplanar)."}
    if len(tets) * len(P) <= BRUTE:
        for t in tets:
            a, b, c, d = (P[v] for v in t)
            sign = 1 if _det3(*[tuple(p[k] - d[k] for k in range(3)) for p in (a, b, c)]) > 0 else -1
            corners = {a, b, c, d}
            for e in distinct:
                if P[e] not in corners:
                    value = sign * _insphere(a, b, c, d, P[e])
                    if value > 0:
                        return {"kind": "point-in-circumsphere", "tetrahedron": list(t), "point": e,
                                "insphere": q(value),
                                "claim": f"point {e} lies strictly inside the circumsphere of your tetrahedron "
                                         f"{list(t)} (exact in-sphere determinant {q(value)} > 0, for the "
                                         "positively oriented tetrahedron)."}
    return differs(reason)


def _det3(a, b, c):
    return (a[2] * (b[0] * c[1] - c[0] * b[1]) + b[2] * (c[0] * a[1] - a[0] * c[1])
            + c[2] * (a[0] * b[1] - b[0] * a[1]))


def _insphere(a, b, c, d, e):
    r = [tuple(p[i] - e[i] for i in range(3)) for p in (a, b, c, d)]
    lift = [x * x + y * y + z * z for x, y, z in r]
    ra, rb, rc, rd = r
    return (lift[3] * _det3(ra, rb, rc) - lift[2] * _det3(rd, ra, rb)
            + lift[1] * _det3(rc, rd, ra) - lift[0] * _det3(rb, rc, rd))


# -- graphs and pairs --------------------------------------------------------------------------
def closest_pair(args, pair, expected, reason) -> dict:
    P = frac(args[0])
    n = len(P)
    i, j = pair
    if not (0 <= i < n and 0 <= j < n) or i == j:
        return differs(reason)
    mine = sq(P[i], P[j])
    candidates = [tuple(expected)] if expected else []
    if n * n <= 2 * BRUTE:
        candidates += [(a, b) for a in range(n) for b in range(a + 1, n)]
    for a, b in candidates:
        d = sq(P[a], P[b])
        if d < mine:
            return {"kind": "closer-pair", "pair": [i, j], "closer": [a, b],
                    "distance2": {"answer": q(mine), "closer": q(d)},
                    "claim": f"points {a} and {b} are closer (squared distance {q(d)}) than your points "
                             f"{i} and {j} (squared distance {q(mine)})."}
    return differs(reason)


def _tree_path(adj: dict, s: int, t: int) -> list[int] | None:
    back = {s: None}
    todo = deque([s])
    while todo:
        u = todo.popleft()
        for v in adj.get(u, ()):
            if v not in back:
                back[v] = u
                todo.append(v)
    if t not in back:
        return None
    path = [t]
    while path[-1] != s:
        path.append(back[path[-1]])
    return path[::-1]


def emst(args, edges, expected, reason) -> dict:
    P = frac(args[0])
    n = len(P)
    adj: dict = {}
    for k, (i, j) in enumerate(edges):
        if not (0 <= i < n and 0 <= j < n) or i == j:
            return differs(reason)
        path = _tree_path(adj, i, j)
        if path is not None:
            return {"kind": "cycle", "edge": [i, j], "path": path,
                    "claim": f"your edge {i}-{j} closes a cycle: {i} and {j} are already joined by "
                             f"{'-'.join(map(str, path))}; a tree has no cycle."}
        adj.setdefault(i, []).append(j)
        adj.setdefault(j, []).append(i)
    if n and len(edges) < n - 1:
        far = next(v for v in range(1, n) if _tree_path(adj, 0, v) is None)
        return {"kind": "not-spanning", "point": far,
                "claim": f"point {far} is not joined to point 0 by your edges: the tree does not span."}
    tree = {(min(i, j), max(i, j)) for i, j in edges}
    candidates = [tuple(e) for e in (expected or [])]
    if n <= SMALL_N:
        candidates += [(a, b) for a in range(n) for b in range(a + 1, n)]
    for a, b in candidates:
        if (min(a, b), max(a, b)) in tree:
            continue
        path = _tree_path(adj, a, b)
        if path is None:
            continue
        w = sq(P[a], P[b])
        u, v = max(zip(path, path[1:]), key=lambda e: sq(P[e[0]], P[e[1]]))
        heavy = sq(P[u], P[v])
        if w < heavy:
            return {"kind": "cheaper-edge", "edge": [a, b], "heaviest": [u, v], "path": path,
                    "length2": {"edge": q(w), "heaviest": q(heavy)},
                    "claim": f"the edge {a}-{b} (squared length {q(w)}) is shorter than your edge {u}-{v} "
                             f"(squared length {q(heavy)}) on the tree path between {a} and {b}: swapping "
                             "them gives a shorter spanning tree."}
    return differs(reason)


def _gabriel_blocker(P, i, j):
    for r, p in enumerate(P):
        if p != P[i] and p != P[j]:
            dot = (p[0] - P[i][0]) * (p[0] - P[j][0]) + (p[1] - P[i][1]) * (p[1] - P[j][1])
            if dot <= 0:
                return r, dot
    return None, None


def proximity_network(args, edges, expected, reason) -> dict:
    P = frac(args[0])
    n = len(P)
    if any(not (0 <= v < n) for e in edges for v in e):
        return differs(reason)
    mine = {(min(e), max(e)) for e in edges}
    for i, j in sorted(mine):
        if P[i] == P[j]:
            continue
        r, dot = _gabriel_blocker(P, i, j)
        if r is not None:
            where = "on the boundary of" if dot == 0 else "inside"
            return {"kind": "not-gabriel-edge", "edge": [i, j], "point": r, "dot": q(dot),
                    "claim": f"point {r} lies {where} the closed disc with diameter {i}-{j} ((p{r} - p{i}) . "
                             f"(p{r} - p{j}) = {q(dot)} <= 0), so {i}-{j} is not a Gabriel edge."}
    first: dict = {}
    rep = [first.setdefault(p, k) for k, p in enumerate(P)]
    candidates = [tuple(sorted(e)) for e in (expected or [])]
    if n <= SMALL_N:
        candidates += [(a, b) for a in range(n) for b in range(a + 1, n)]
    for a, b in candidates:
        if rep[a] == a and rep[b] == b and P[a] != P[b] and (a, b) not in mine:
            if _gabriel_blocker(P, a, b)[0] is None:
                return {"kind": "missing-gabriel-edge", "edge": [a, b],
                        "claim": f"no other point lies in the closed disc with diameter {a}-{b} (every "
                                 f"(p - p{a}) . (p - p{b}) > 0), so {a}-{b} is a Gabriel edge your answer lacks."}
    return differs(reason)


# -- circles, cells, clearance, paths, operations ----------------------------------------------
def _tolerance(checker_module, r_opt: float, values) -> Fraction:
    big = max([abs(c) for c in values] or [0.0])
    return Fraction(checker_module.REL_TOL * r_opt + checker_module.ABS_TOL * big)


def largest_empty_circle(args, circle, expected, reason) -> dict:
    from ..problems import load_problem

    points = args[0]
    P = frac(points)
    x, y, r = (Fraction(v) for v in circle)
    if expected is None:
        return differs(reason)
    eps = _tolerance(load_problem("largest-empty-circle").checker, expected[2], [c for p in points for c in p])
    if r - eps > 0:
        for i, p in enumerate(P):
            d2 = sq(p, (x, y))
            if d2 < (r - eps) ** 2:
                return {"kind": "point-in-circle", "point": i, "distance2": q(d2), "radius2": q(r * r),
                        "tolerance": q(eps),
                        "claim": f"point {i} is strictly inside your circle, deeper than the tolerance {float(eps):.3g} "
                                 f"(squared distance to the centre {q(d2)} < (r - tolerance)^2)."}
    I = verify.exact_coordinates(points)
    hull = verify.convex_hull_exact(I, keep_collinear=False)
    for a, b in zip(hull, hull[1:] + hull[:1]):
        o = orient(P[a], P[b], (x, y))
        if o < 0 and o * o > eps * eps * sq(P[a], P[b]):
            return {"kind": "centre-outside-hull", "hull_edge": [a, b], "orient2d": q(o),
                    "claim": f"your centre lies strictly outside the convex hull, beyond its edge {a}->{b} "
                             f"(by more than the tolerance {float(eps):.3g})."}
    better = _larger_circle(P, hull, Fraction(expected[0]), Fraction(expected[1]))
    if better is not None and better[1] > (r + eps) ** 2:
        (cx, cy), r2, via = better
        return {"kind": "larger-empty-circle", "centre": [q(cx), q(cy)], "radius2": q(r2), "through": via,
                "claim": f"the circle through points {via} with centre ({q(cx)}, {q(cy)}) in the hull has no point "
                         f"strictly inside and squared radius {q(r2)} > your {q(r * r)} (plus tolerance)."}
    return differs(reason, expected=list(expected))


def _larger_circle(P, hull, ex, ey):
    """The reference circle made exact: through the three points nearest its centre (or two, with
    the centre on a hull edge); None unless it is exactly empty with its centre in the hull."""
    near = sorted(range(len(P)), key=lambda i: sq(P[i], (ex, ey)))
    first: dict = {}
    near = [i for i in near if first.setdefault(P[i], i) == i][:3]
    H = [P[i] for i in hull]
    found = []
    if len(near) == 3:
        a, b, c = (P[i] for i in near)
        den = 2 * orient(a, b, c)
        if den:
            ax, ay = a
            bx, by, cx, cy = b[0] - ax, b[1] - ay, c[0] - ax, c[1] - ay
            b2, c2 = bx * bx + by * by, cx * cx + cy * cy
            found.append(((ax + (cy * b2 - by * c2) / den, ay + (bx * c2 - cx * b2) / den), near))
    if len(near) >= 2:
        a, b = P[near[0]], P[near[1]]
        for u, v in zip(H, H[1:] + H[:1]):        # the bisector of a, b crossing the hull edge u-v
            dx, dy = v[0] - u[0], v[1] - u[1]
            den = 2 * (dx * (b[0] - a[0]) + dy * (b[1] - a[1]))
            if den:
                t = (sq(b, u) - sq(a, u)) / den
                if 0 <= t <= 1:
                    found.append(((u[0] + t * dx, u[1] + t * dy), near[:2]))
    best = None
    for centre, via in found:
        r2 = sq(P[via[0]], centre)
        inside = all(orient(u, v, centre) >= 0 for u, v in zip(H, H[1:] + H[:1]))
        if inside and all(sq(p, centre) >= r2 for p in P) and (best is None or r2 > best[1]):
            best = (centre, r2, via)
    return best


def voronoi(args, cells, expected, reason) -> dict:
    from ..problems import load_problem

    points, box = args
    P = frac(points)
    ck = load_problem("voronoi").checker
    big = max([abs(c) for p in points for c in p] + [abs(v) for v in box])
    eps = ck.REL_TOL * max(box[2] - box[0], box[3] - box[1]) + ck.ABS_TOL * big
    for i, cell in enumerate(cells if len(points) * sum(map(len, cells)) <= BRUTE else []):
        for vx, vy in cell:
            v = (Fraction(vx), Fraction(vy))
            if not (box[0] - eps <= vx <= box[2] + eps and box[1] - eps <= vy <= box[3] + eps):
                return {"kind": "vertex-outside-box", "cell": i, "vertex": [vx, vy], "box": list(box),
                        "claim": f"the vertex ({vx!r}, {vy!r}) of cell {i} lies outside the box {list(box)}."}
            own = sq(v, P[i])
            for j, p in enumerate(P):
                d = sq(v, p)
                if d < own and math.sqrt(own) - math.sqrt(d) > 2 * eps:
                    return {"kind": "vertex-nearer-other-site", "cell": i, "vertex": [vx, vy], "point": j,
                            "distance2": {"own": q(own), "other": q(d)},
                            "claim": f"the vertex ({vx!r}, {vy!r}) of the cell of point {i} is nearer to point {j} "
                                     f"(squared distance {float(d):.6g}) than to point {i} ({float(own):.6g}): "
                                     "it is not in that cell."}
    k = next((i for i, (c, e) in enumerate(zip(cells, expected or [])) if c != e), None)
    return differs(reason, **({"cell": k, "expected": expected[k]} if k is not None else {}))


def obstacle_clearance(args, r, expected, reason) -> dict:
    points, start, goal = args
    if math.isfinite(r) and (expected is None or r > expected):
        P, R = frac(points), Fraction(r)
        for name, e in (("start", start), ("goal", goal)):
            E = tuple(Fraction(c) for c in e)
            k = min(range(len(P)), key=lambda i: sq(P[i], E), default=None)
            if k is not None and sq(P[k], E) < R * R:
                return {"kind": "obstacle-too-close", "endpoint": name, "point": k,
                        "distance2": q(sq(P[k], E)), "radius2": q(R * R),
                        "claim": f"obstacle {k} is closer to the {name} (squared distance {q(sq(P[k], E))}) than "
                                 f"your radius (squared {q(R * R)}): a disk that large cannot even stand there."}
    return differs(reason, expected=expected if expected is None or math.isfinite(expected) else "inf")


def navmesh(args, path, expected, reason) -> dict:
    """Decided exactly by :mod:`reference_impl.exact.free_space` (Fractions of the input doubles)."""
    from reference_impl.exact import free_space

    boundary, holes, start, goal = args
    sound = expected is not None and free_space.path_problem(expected, boundary, holes) is None
    if path is None and sound:
        return {"kind": "path-exists", "path": expected,
                "claim": f"the path {expected} goes from start to goal inside the closed free space (checked "
                         "exactly), so the answer cannot be None."}
    if path:
        problem = free_space.path_problem(path, boundary, holes)
        if problem:
            return {"kind": "path-leaves-free-space", "claim": problem + " (checked exactly)."}
    if path is not None and expected is None:
        for name, p in (("start", start), ("goal", goal)):
            if not free_space.point_in_free_space(p, boundary, holes):
                return {"kind": "outside-free-space", "endpoint": name,
                        "claim": f"the {name} {p} lies outside the closed free space (checked exactly): "
                                 "the answer must be None."}
    if path and sound and free_space.path_length(expected) < free_space.path_length(path):
        return {"kind": "shorter-path", "path": expected,
                "claim": f"the path {expected} stays in the free space (checked exactly) and has length "
                         f"{free_space.path_length(expected):.9g} < your {free_space.path_length(path):.9g}."}
    return differs(reason, expected=expected)


def dynamic_network(args, answers, expected, reason) -> dict:
    (ops,) = args
    for k, (got, want) in enumerate(zip(answers, expected or [])):
        if got != want:
            return {"kind": "first-wrong-answer", "operation": k, "op": ops[k], "answer": got, "expected": want,
                    "claim": f"operation {k} ({' '.join(map(str, ops[k]))}) after the {k} before it: your answer "
                             f"{got!r}, the right answer {want!r}."}
    return differs(reason)


BUILDERS = {"delaunay": delaunay, "bowyer-watson-timed": delaunay, "edge-flip": edge_flip,
            "delaunay-3d": delaunay_3d, "emst": emst, "closest-pair": closest_pair,
            "largest-empty-circle": largest_empty_circle, "voronoi": voronoi,
            "proximity-network": proximity_network, "navmesh": navmesh,
            "obstacle-clearance": obstacle_clearance, "dynamic-network": dynamic_network}


def overlay(axes, problem_id: str, args: list, cert: dict) -> None:
    """Draw a certificate's witness on ``axes`` (red): circles, edges, points."""
    from matplotlib.patches import Circle

    pts = args[0] if problem_id not in ("navmesh", "dynamic-network") else []
    xy = [(float(p[0]), float(p[1])) for p in pts]

    def seg(e, style="r-"):
        axes.plot([xy[e[0]][0], xy[e[1]][0]], [xy[e[0]][1], xy[e[1]][1]], style, lw=2.5)

    if "triangle" in cert and "point" in cert and cert["kind"] == "point-in-circumcircle":
        a, b, c = (xy[v] for v in cert["triangle"])
        d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
        ux = sum((p[0] ** 2 + p[1] ** 2) * (s[1] - t[1]) for p, s, t in ((a, b, c), (b, c, a), (c, a, b))) / d
        uy = sum((p[0] ** 2 + p[1] ** 2) * (t[0] - s[0]) for p, s, t in ((a, b, c), (b, c, a), (c, a, b))) / d
        axes.add_patch(Circle((ux, uy), math.dist((ux, uy), a), fill=False, color="red", lw=1.5))
        axes.fill(*zip(*(a, b, c)), color="red", alpha=0.2)
    if cert.get("kind") == "larger-empty-circle":
        cx, cy = (float(Fraction(v)) for v in cert["centre"])
        axes.add_patch(Circle((cx, cy), math.sqrt(float(Fraction(cert["radius2"]))), fill=False, color="green"))
    for key in ("edge", "closer", "heaviest", "hull_edge"):
        if key in cert and xy:
            seg(cert[key], "g-" if key in ("closer", "edge") and cert["kind"] != "not-gabriel-edge" else "r-")
    if "point" in cert and xy and isinstance(cert["point"], int):
        axes.plot(*xy[cert["point"]][:2], "r*", ms=16)
    if "vertex" in cert:
        axes.plot(*cert["vertex"], "rx", ms=14)
    axes.set_aspect("equal", adjustable="datalim")
