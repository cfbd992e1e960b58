"""Exact checkers: is this a valid Delaunay triangulation (2D) or tetrahedralisation (3D)?

The judge uses these to accept *any* valid answer (cocircular ties make the
Delaunay triangulation non-unique), and the tests use them as an oracle that
shares no code with the predicates it checks: every decision here is made with
Python integers, after scaling all coordinates by one common power of two.

Run the doctest:  python -m pytest reference_impl/exact/verify.py

>>> pts = [(0, 0), (1, 0), (0, 1), (1, 1)]
>>> check_delaunay(pts, [(0, 1, 3), (0, 3, 2)])
(True, 'ok')
>>> check_delaunay(pts, [(0, 3, 1), (0, 3, 2)])[0]   # clockwise triangle
False

Why the checks below are enough (a short proof, so that nobody has to trust
a long list of ad-hoc tests):

1. every triangle is strictly counter-clockwise (positive area), and
2. the triangles' boundaries add up, as a chain of directed edges, to exactly
   the convex-hull cycle (collinear hull points included).

Then for every point y not on an edge, the number of triangles covering y equals
the winding number of the hull cycle around y (1 inside, 0 outside), because
each triangle covers y with sign +1.  So the triangles tile the hull with no
overlap; and a point of the set lying inside a triangle or an edge would force
an overlap.  With 3. every distinct point used as a vertex, the triangles form a
triangulation of the points; and 4. every interior edge locally Delaunay makes
it (globally) Delaunay (Delaunay's lemma).
"""
from __future__ import annotations

from typing import Iterable, Sequence

import itertools
import math
import operator

__all__ = ["exact_coordinates", "orient_exact", "incircle_exact", "convex_hull_exact",
           "check_delaunay", "check_triangulation_size", "brute_force_empty_circles",
           "exact_coordinates_3d", "orient3d_exact", "insphere_exact", "check_delaunay_3d",
           "brute_force_empty_spheres", "exact_sign"]


def exact_coordinates(points: Iterable[Sequence[float]]) -> list[tuple[int, int]]:
    """Return the points as integer pairs, all scaled by one common power of two.

    Signs of orientation and in-circle determinants are invariant under a common
    positive scaling, so the integer versions give the exact answers.

    >>> exact_coordinates([(0.5, 1.0), (0.25, -2.0)])
    [(2, 4), (1, -8)]
    """
    ratios = []
    for p in points:
        x, y = float(p[0]), float(p[1])
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"point {tuple(p)!r} is not finite")
        ratios.append((x.as_integer_ratio(), y.as_integer_ratio()))
    den = 1
    for (_, dx), (_, dy) in ratios:
        den = max(den, dx, dy)  # denominators are powers of two: the max is a common multiple
    return [(nx * (den // dx), ny * (den // dy)) for (nx, dx), (ny, dy) in ratios]


def orient_exact(a: tuple[int, int], b: tuple[int, int], c: tuple[int, int]) -> int:
    """Sign of twice the signed area of (a, b, c): +1 counter-clockwise, 0 collinear.

    >>> orient_exact((0, 0), (1, 0), (0, 1))
    1
    """
    d = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])
    return (d > 0) - (d < 0)


def incircle_exact(a, b, c, d) -> int:
    """+1 if d is strictly inside the circle through CCW a, b, c; 0 on it; -1 outside.

    >>> incircle_exact((0, 0), (2, 0), (0, 2), (1, 1))
    1
    """
    adx, ady = a[0] - d[0], a[1] - d[1]
    bdx, bdy = b[0] - d[0], b[1] - d[1]
    cdx, cdy = c[0] - d[0], c[1] - d[1]
    det = ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
           + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
           + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))
    return (det > 0) - (det < 0)


def convex_hull_exact(P: list[tuple[int, int]], keep_collinear: bool = True) -> list[int]:
    """Indices of the convex hull of integer points, counter-clockwise (Andrew's chain).

    Duplicated coordinates appear once (the smallest index).  With
    ``keep_collinear`` the points lying on hull edges are included.

    >>> convex_hull_exact([(0, 0), (2, 0), (1, 0), (0, 2), (1, 1)])
    [0, 2, 1, 4, 3]
    """
    first: dict[tuple[int, int], int] = {}
    for i, p in enumerate(P):
        first.setdefault(p, i)
    order = sorted(first.values(), key=lambda i: P[i])
    if len(order) <= 2:
        return order

    def chain(seq):
        out: list[int] = []
        for i in seq:
            while len(out) >= 2:
                s = orient_exact(P[out[-2]], P[out[-1]], P[i])
                if s < 0 or (s == 0 and not keep_collinear):
                    out.pop()
                else:
                    break
            out.append(i)
        return out

    lower, upper = chain(order), chain(order[::-1])
    if all(orient_exact(P[order[0]], P[order[-1]], P[i]) == 0 for i in order):
        return order  # all collinear: the "hull" is the sorted chain
    return lower[:-1] + upper[:-1]


def _rows(triangles) -> list[list]:
    """Triangles as a list of rows (numpy arrays, lists or tuples), without importing numpy."""
    rows = triangles.tolist() if hasattr(triangles, "tolist") else list(triangles)
    return [list(t) for t in rows]


def _index_rows(rows: list, n: int, width: int, what: str) -> tuple[list | None, str]:
    """The rows as lists of ``width`` integer indices in 0..n-1, or ``(None, what is wrong)``.

    >>> _index_rows([[0, 1, 2]], 3, 3, "triangle")
    ([[0, 1, 2]], 'ok')
    """
    out = []
    for k, t in enumerate(rows):
        try:
            ids = [operator.index(v) for v in t]
        except TypeError:
            return None, f"{what} {k} has non-integer vertex indices {list(t)!r}"
        if len(ids) != width:
            return None, f"{what} {k} = {ids} does not have exactly {width} vertices"
        if any(v < 0 or v >= n for v in ids):
            return None, f"{what} {k} = {ids} has an index outside 0..{n - 1}"
        out.append(ids)
    return out, "ok"


def check_delaunay(points, triangles, bulk=None) -> tuple[bool, str]:
    """Check exactly that ``triangles`` is a Delaunay triangulation of ``points``.

    ``points`` is (n, 2) finite floats; ``triangles`` is (m, 3) point indices in
    counter-clockwise order.  Any index of a duplicated point may be used.
    All-collinear input (or fewer than 3 distinct points) has exactly one valid
    answer: no triangles.  Returns ``(ok, message)``; the message names the
    first problem found.

    Two passes, one verdict: :func:`_delaunay_accepts` (float filters with a proven
    error bound, integers where they cannot decide; the points' preparation cached
    per list) accepts a valid answer fast, and anything it does not accept is
    decided again, with the message, by the integer-only :func:`_check_delaunay_integers`.
    ``bulk``: the module ``reference_impl/exact/bulk.py`` (numpy), to filter all triangles at once.
    """
    if _delaunay_accepts(points, triangles, bulk):
        return True, "ok"
    return _check_delaunay_integers(points, triangles)


def _check_delaunay_integers(points, triangles) -> tuple[bool, str]:
    """:func:`check_delaunay` in Python integers only, naming the first problem found."""
    P = exact_coordinates(points)
    n = len(P)
    tris = _rows(triangles)
    canon: dict[tuple[int, int], int] = {}
    for i, p in enumerate(P):
        canon.setdefault(p, i)
    rep = [canon[p] for p in P]
    rows, message = _index_rows(tris, n, 3, "triangle")
    if rows is None:
        return False, message
    T = [(rep[a], rep[b], rep[c]) for a, b, c in rows]

    hull = convex_hull_exact(P, keep_collinear=True)
    distinct = sorted(set(rep))
    flat = len(distinct) < 3 or all(orient_exact(P[hull[0]], P[hull[-1]], P[i]) == 0 for i in distinct)
    if flat:
        if T:
            return False, "the points are all collinear (or fewer than 3 distinct): no triangle is possible"
        return True, "ok"

    # 1. positive orientation
    for k, (a, b, c) in enumerate(T):
        s = orient_exact(P[a], P[b], P[c])
        if s <= 0:
            what = "degenerate (zero area)" if s == 0 else "clockwise"
            return False, f"triangle {k} = {tuple(tris[k])} is {what}; triangles must be counter-clockwise"
    # 2. boundary chain equals the hull cycle
    count: dict[tuple[int, int], int] = {}
    for a, b, c in T:
        for u, v in ((a, b), (b, c), (c, a)):
            count[(u, v)] = count.get((u, v), 0) + 1
    for (u, v), m in count.items():
        if m > 1:
            return False, f"the directed edge {u}->{v} is used by {m} triangles: triangles overlap"
    hull_edges = {(hull[i], hull[(i + 1) % len(hull)]) for i in range(len(hull))}
    for (u, v) in count:
        if (v, u) not in count and (u, v) not in hull_edges:
            return False, (f"edge {u}-{v} has a triangle on one side only but is not a convex hull edge "
                           "(a hole, a gap or an overlap)")
    for e in hull_edges:
        if e not in count:
            return False, f"convex hull edge {e[0]}-{e[1]} is not covered by any triangle"
        if (e[1], e[0]) in count:
            return False, f"a triangle lies outside the convex hull across edge {e[0]}-{e[1]}"
    # 3. every distinct point is a vertex
    used = {v for t in T for v in t}
    missing = [i for i in distinct if i not in used]
    if missing:
        return False, f"point {missing[0]} {tuple(points[missing[0]])} is not a vertex of any triangle"
    # 4. local Delaunay on every interior edge
    opposite = {}
    for a, b, c in T:
        opposite[(a, b)] = c
        opposite[(b, c)] = a
        opposite[(c, a)] = b
    for (u, v), w in opposite.items():
        x = opposite.get((v, u))
        if x is not None and u < v and incircle_exact(P[u], P[v], P[w], P[x]) > 0:
            return False, (f"edge {u}-{v} is not Delaunay: point {x} is strictly inside the "
                           f"circumcircle of triangle ({u}, {v}, {w})")
    return True, "ok"


# ----------------------------------------------------------------------------- the fast pass
# Shewchuk's float filters ("Adaptive precision floating-point arithmetic and fast robust geometric
# predicates", 1997): evaluated in doubles in his order, a determinant whose magnitude exceeds
# ERRBOUND x its permanent has the exact determinant's sign, provided no operation underflows or
# overflows.  The bounds below are twice his (a margin), and the filters are used only on "tame"
# point sets, whose every coordinate is 0 or of magnitude in [2^-150, 2^150]: then a nonzero
# difference of two coordinates lies in [2^-202, 2^151] and a product of up to five of them (the
# in-sphere's) in [2^-1010, 2^755], normal doubles.  Where a filter cannot decide, the integers do.
_EPS = 2.0 ** -53
_CCW_BOUND = 2 * (3.0 + 16.0 * _EPS) * _EPS
_ICC_BOUND = 2 * (10.0 + 96.0 * _EPS) * _EPS
_O3D_BOUND = 2 * (7.0 + 56.0 * _EPS) * _EPS
_ISP_BOUND = 2 * (16.0 + 224.0 * _EPS) * _EPS
_TAME_LO, _TAME_HI = 2.0 ** -150, 2.0 ** 150


def _tame(coords) -> bool:
    """Is every coordinate 0 or of magnitude in [2^-150, 2^150] (the filters' range)?

    >>> _tame([(0.0, 1e-3), (2.0, -5.0)]), _tame([(1e-300, 1.0)])
    (True, False)
    """
    return all(v == 0.0 or _TAME_LO <= abs(v) <= _TAME_HI for p in coords for v in p)


def orient_filtered(F, P, a: int, b: int, c: int) -> int:
    """orient2d of points a, b, c: doubles ``F`` when the filter decides, else integers ``P``
    (``F`` from a tame set; ``P`` its :func:`exact_coordinates`).

    >>> orient_filtered([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], [(0, 0), (1, 0), (0, 1)], 0, 1, 2)
    1
    """
    (ax, ay), (bx, by), (cx, cy) = F[a], F[b], F[c]
    left = (ax - cx) * (by - cy)
    right = (ay - cy) * (bx - cx)
    det = left - right
    bound = _CCW_BOUND * (abs(left) + abs(right))
    if det > bound:
        return 1
    if -det > bound:
        return -1
    return orient_exact(P[a], P[b], P[c])


def incircle_filtered(F, P, a: int, b: int, c: int, d: int) -> int:
    """:func:`incircle_exact` of points a, b, c, d: doubles when the filter decides, else integers.

    >>> incircle_filtered([(0.0, 0.0), (2.0, 0.0), (0.0, 2.0), (1.0, 1.0)], [(0, 0), (2, 0), (0, 2), (1, 1)], 0, 1, 2, 3)
    1
    """
    (ax, ay), (bx, by), (cx, cy), (dx, dy) = F[a], F[b], F[c], F[d]
    adx, ady, bdx, bdy, cdx, cdy = ax - dx, ay - dy, bx - dx, by - dy, cx - dx, cy - dy
    bdxcdy, cdxbdy = bdx * cdy, cdx * bdy
    cdxady, adxcdy = cdx * ady, adx * cdy
    adxbdy, bdxady = adx * bdy, bdx * ady
    alift, blift, clift = adx * adx + ady * ady, bdx * bdx + bdy * bdy, cdx * cdx + cdy * cdy
    det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady)
    bound = _ICC_BOUND * ((abs(bdxcdy) + abs(cdxbdy)) * alift + (abs(cdxady) + abs(adxcdy)) * blift
                          + (abs(adxbdy) + abs(bdxady)) * clift)
    if det > bound:
        return 1
    if -det > bound:
        return -1
    return incircle_exact(P[a], P[b], P[c], P[d])


#: per point list, what every check of it needs (see :func:`_prepared`); bounded by _PREPARED_MAX points
_PREPARED: dict = {}
_PREPARED_MAX = 4_000_000


def _prepared(points, kind: str, build):
    """``build(points)``, cached for a point *list* checked again (a judge checks every student's
    answer to one test against the same list): the entry holds the list and a copy of its rows,
    and is used only while the list is that object and still equal to the copy."""
    if type(points) is not list:
        return build(points)
    key = (id(points), kind)
    hit = _PREPARED.get(key)
    if hit is not None and hit[0] is points and hit[1] == points:
        return hit[2]
    data = build(points)
    if sum(len(h[1]) for h in _PREPARED.values()) + len(points) > _PREPARED_MAX:
        _PREPARED.clear()
    _PREPARED[key] = (points, [p[:] for p in points], data)
    return data


def _prepare_2d(points) -> tuple:
    """(P, F, rep, number of distinct points, directed hull edges, all collinear?, tame?)."""
    P = exact_coordinates(points)
    F = [(float(p[0]), float(p[1])) for p in points]
    canon: dict = {}
    rep = [canon.setdefault(p, i) for i, p in enumerate(P)]
    distinct = sorted(canon.values())
    hull = convex_hull_exact(P, keep_collinear=True)
    flat = len(distinct) < 3 or all(orient_exact(P[hull[0]], P[hull[-1]], P[i]) == 0 for i in distinct)
    hull_edges = {(hull[i], hull[(i + 1) % len(hull)]) for i in range(len(hull))}
    return P, F, rep, len(distinct), hull_edges, flat, _tame(F), {}


def indexed_predicates(points) -> tuple:
    """``(P, rep, orient, incircle)`` for a point set: :func:`exact_coordinates`, each point's first
    duplicate, and exact orient2d / incircle on point *indices* (float-filtered when the set is
    tame, integers otherwise); prepared once per point list (:func:`_prepared`).

    >>> P, rep, orient, incircle = indexed_predicates([(0.0, 0.0), (2.0, 0.0), (0.0, 2.0), (1.0, 1.0)])
    >>> orient(0, 1, 2), incircle(0, 1, 2, 3), rep
    (1, 1, [0, 1, 2, 3])
    """
    P, F, rep, _, _, _, tame, _ = _prepared(points, "2d", _prepare_2d)
    if tame:
        return (P, rep, lambda a, b, c: orient_filtered(F, P, a, b, c),
                lambda a, b, c, d: incircle_filtered(F, P, a, b, c, d))
    return (P, rep, lambda a, b, c: orient_exact(P[a], P[b], P[c]),
            lambda a, b, c, d: incircle_exact(P[a], P[b], P[c], P[d]))


def _int_rows(triangles, n: int, width: int, check_range: bool = True) -> list | None:
    """The rows when they are ``width`` ints in 0..n-1 each (checked in C loops), else None
    (``check_range=False``: ints of any value, for a caller that checks the range itself)."""
    rows = triangles if type(triangles) is list else _rows(triangles)
    if not rows:
        return rows
    if not set(map(type, rows)) <= {list, tuple} or set(map(len, rows)) != {width}:
        return None
    flat = itertools.chain.from_iterable
    if set(map(type, flat(rows))) != {int} or (check_range and (min(flat(rows)) < 0 or max(flat(rows)) >= n)):
        return None
    return rows


def _delaunay_accepts(points, triangles, bulk=None) -> bool:
    """True only when every check of :func:`_check_delaunay_integers` passes (False: ask it why)."""
    P, F, rep, n_distinct, hull_edges, flat, tame, arrays = _prepared(points, "2d", _prepare_2d)
    use_bulk = bulk is not None and bulk.AVAILABLE and tame and not flat and len(P) < 1 << 31
    if (use_bulk and type(triangles) is bulk.np.ndarray and triangles.ndim == 2 and triangles.shape[1] == 3
            and triangles.dtype.kind == "i" and len(triangles) >= 16):
        return _delaunay_accepts_bulk(bulk, P, F, rep, n_distinct, hull_edges, arrays, triangles)  # no lists
    rows = _int_rows(triangles, len(P), 3, check_range=not use_bulk)
    if rows is None:
        return False
    if use_bulk and len(rows) >= 16:
        return _delaunay_accepts_bulk(bulk, P, F, rep, n_distinct, hull_edges, arrays, rows)
    if use_bulk and rows and (min(itertools.chain.from_iterable(rows)) < 0
                              or max(itertools.chain.from_iterable(rows)) >= len(P)):
        return False
    T = [(rep[a], rep[b], rep[c]) for a, b, c in rows]
    if flat:
        return not T
    orient = orient_filtered if tame else (lambda F, P, a, b, c: orient_exact(P[a], P[b], P[c]))
    if not all(orient(F, P, a, b, c) > 0 for a, b, c in T):
        return False
    opposite: dict = {}
    for a, b, c in T:
        opposite[(a, b)] = c
        opposite[(b, c)] = a
        opposite[(c, a)] = b
    if len(opposite) != 3 * len(T):
        return False  # a directed edge used twice
    if {e for e in opposite if (e[1], e[0]) not in opposite} != hull_edges:
        return False  # the one-sided edges are not exactly the hull cycle
    if len({v for t in T for v in t}) != n_distinct:
        return False  # a point is not a vertex
    incircle = incircle_filtered if tame else (lambda F, P, a, b, c, d: incircle_exact(P[a], P[b], P[c], P[d]))
    get = opposite.get
    for (u, v), w in opposite.items():
        if u < v:
            x = get((v, u))
            if x is not None and incircle(F, P, u, v, w, x) > 0:
                return False
    return True


def _delaunay_accepts_bulk(bulk, P, F, rep, n_distinct, hull_edges, arrays, rows) -> bool:
    """:func:`_delaunay_accepts` for a tame, not collinear set, with numpy: the filters decide
    most signs at once (``bulk``), integers the rest; edges matched by sorting their keys."""
    np = bulk.np
    n = len(P)
    if "hull" not in arrays:  # (flip_replay may have cached x and y alone)
        xy = np.array(F, dtype=np.float64).reshape(-1, 2)
        arrays.update(x=xy[:, 0].copy(), y=xy[:, 1].copy(), rep=np.array(rep, dtype=np.int64),
                      hull=np.sort(np.array([u * n + v for u, v in hull_edges], dtype=np.int64)))
    X, Y = arrays["x"], arrays["y"]
    ids = (rows.astype(np.int64).ravel() if type(rows) is np.ndarray   # rows: lists, or an integer array
           else np.fromiter(itertools.chain.from_iterable(rows), np.int64, 3 * len(rows)))
    if ids.min() < 0 or ids.max() >= n:
        return False
    t = arrays["rep"][ids.reshape(-1, 3)]
    a, b, c = t[:, 0], t[:, 1], t[:, 2]
    s = bulk.orient2d(X[a], Y[a], X[b], Y[b], X[c], Y[c])
    for k in np.flatnonzero(s == 0).tolist():
        s[k] = orient_exact(P[a[k]], P[b[k]], P[c[k]])
    if (s <= 0).any():
        return False
    u, v, w = np.concatenate((a, b, c)), np.concatenate((b, c, a)), np.concatenate((c, a, b))
    if n < _PACKED_MAX_N:
        return _edges_accept_packed(bulk, P, n, n_distinct, arrays, t, u, v, w)
    key = u * n + v
    order = np.argsort(key)
    ks = key[order]
    if (ks[1:] == ks[:-1]).any():
        return False  # a directed edge used twice
    back = v * n + u
    pos = np.minimum(np.searchsorted(ks, back), len(ks) - 1)
    paired = ks[pos] == back
    if not np.array_equal(np.sort(key[~paired]), arrays["hull"]):
        return False  # the one-sided edges are not exactly the hull cycle
    if np.unique(t).size != n_distinct:
        return False  # a point is not a vertex
    inner = paired & (u < v)
    uu, vv, ww, xx = u[inner], v[inner], w[inner], w[order[pos[inner]]]
    s = bulk.incircle(X[uu], Y[uu], X[vv], Y[vv], X[ww], Y[ww], X[xx], Y[xx])
    for k in np.flatnonzero(s == 0).tolist():
        s[k] = incircle_exact(P[uu[k]], P[vv[k]], P[ww[k]], P[xx[k]])
    return not (s > 0).any()


#: below this many points, an edge and its third vertex pack into one int64 (:func:`_edges_accept_packed`)
_PACKED_MAX_N = 1 << 20


def _edges_accept_packed(bulk, P, n, n_distinct, arrays, t, u, v, w) -> bool:
    """The edge half of :func:`_delaunay_accepts_bulk` with one sort: each directed edge (u, v) of a
    triangle whose third vertex is w becomes one integer ((min * n + max) * n + w) * 2 + (u > v)
    (below 2^63 for n < 2^20), so that after sorting, the two sides of an undirected edge sit side
    by side. An edge with three or more sides, or two sides in one direction, is a directed edge
    used twice; a lone side is a one-sided edge; a pair gives the in-circle test of (u, v, w)
    against x, the third vertex across (u < v), the same tests as the searchsorted pairing."""
    np = bulk.np
    lo, hi = np.minimum(u, v), np.maximum(u, v)
    packed = ((lo * n + hi) * n + w) * 2 + (u > v)
    packed.sort()
    k, rest = np.divmod(packed, 2 * n)          # k = lo * n + hi; rest = w * 2 + (u > v)
    third, back = rest >> 1, rest & 1
    same = k[1:] == k[:-1]
    if (same[1:] & same[:-1]).any():
        return False  # three sides of one edge: a directed edge used twice
    first = np.flatnonzero(same)                # pairs (first, first + 1)
    if (back[first] == back[first + 1]).any():
        return False  # both sides in one direction: a directed edge used twice
    lone = np.ones(len(k), dtype=bool)
    lone[first] = False
    lone[first + 1] = False
    kl, bl = k[lone], back[lone]
    one_sided = np.where(bl == 0, kl, (kl % n) * n + kl // n)
    if not np.array_equal(np.sort(one_sided), arrays["hull"]):
        return False  # the one-sided edges are not exactly the hull cycle
    used = np.zeros(n, dtype=bool)
    used[t.ravel()] = True
    if int(used.sum()) != n_distinct:
        return False  # a point is not a vertex
    fwd = back[first] == 0                      # the pair's first side is (lo, hi)
    ww = np.where(fwd, third[first], third[first + 1])
    xx = np.where(fwd, third[first + 1], third[first])
    uu, vv = k[first] // n, k[first] % n
    X, Y = arrays["x"], arrays["y"]
    s = bulk.incircle(X[uu], Y[uu], X[vv], Y[vv], X[ww], Y[ww], X[xx], Y[xx])
    for j in np.flatnonzero(s == 0).tolist():
        s[j] = incircle_exact(P[uu[j]], P[vv[j]], P[ww[j]], P[xx[j]])
    return not (s > 0).any()


def check_triangulation_size(n_distinct: int, n_hull: int, n_triangles: int) -> bool:
    """Euler's count for a triangulation of n points with h on the hull: 2n - 2 - h.

    >>> check_triangulation_size(4, 4, 2)
    True
    """
    return n_triangles == 2 * n_distinct - 2 - n_hull


def brute_force_empty_circles(points, triangles) -> tuple[bool, str]:
    """O(n m) check that no point is strictly inside any triangle's circumcircle.

    Slow but independent of any edge structure; meant for small test inputs.
    """
    P = exact_coordinates(points)
    for k, (a, b, c) in enumerate(_rows(triangles)):
        for i, p in enumerate(P):
            if incircle_exact(P[a], P[b], P[c], p) > 0:
                return False, f"point {i} is inside the circumcircle of triangle {k}"
    return True, "ok"


# ----------------------------------------------------------------------------- 3D
# The exact 3D checker of the ``delaunay-3d`` problem (and the oracle of the 3D tests).  The
# integer predicates below are also the Python fallback of ``predicates3d``.

def exact_coordinates_3d(points: Iterable[Sequence[float]]) -> list[tuple[int, int, int]]:
    """The points as integer triples, all scaled by one common power of two.

    Orientation and in-sphere signs are invariant under a common positive scaling,
    so the integer versions give the exact answers for the doubles.

    >>> exact_coordinates_3d([(0.5, 1.0, 2.0), (0.25, -2.0, 0.0)])
    [(2, 4, 8), (1, -8, 0)]
    """
    ratios = []
    for p in points:
        q = [float(v) for v in p]
        if len(q) != 3 or not all(math.isfinite(v) for v in q):
            raise ValueError(f"point {tuple(p)!r} is not three finite numbers")
        ratios.append([v.as_integer_ratio() for v in q])
    den = 1
    for r in ratios:
        for _, d in r:
            den = max(den, d)   # denominators are powers of two: the max is a common multiple
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def _det3(a, b, c) -> int:
    return (a[2] * (b[0] * c[1] - c[0] * b[1]) + b[2] * (c[0] * a[1] - a[0] * c[1])
            + c[2] * (a[0] * b[1] - b[0] * a[1]))


def orient3d_exact(a, b, c, d) -> int:
    """orient3d on integer (or Fraction) coordinates: sign of det(a - d, b - d, c - d).

    Positive when d lies below the plane of a, b, c seen counter-clockwise from above
    (Shewchuk's convention: the tetrahedron (a, b, c, d) is positively oriented).

    >>> orient3d_exact((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1))
    1
    """
    r = [tuple(p[i] - d[i] for i in range(3)) for p in (a, b, c)]
    v = _det3(*r)
    return (v > 0) - (v < 0)


def insphere_exact(a, b, c, d, e) -> int:
    """insphere on integer (or Fraction) coordinates (+1: e inside, for orient3d(a,b,c,d) > 0).

    >>> insphere_exact((0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, -2), (1, 1, -1))
    1
    """
    r = [tuple(p[i] - e[i] for i in range(3)) for p in (a, b, c, d)]
    lift = [x * x + y * y + z * z for x, y, z in r]
    ra, rb, rc, rd = r
    v = (lift[3] * _det3(ra, rb, rc) - lift[2] * _det3(rd, ra, rb)
         + lift[1] * _det3(rc, rd, ra) - lift[0] * _det3(rb, rc, rd))
    return (v > 0) - (v < 0)


def exact_sign(coords: Sequence[float], dim: int) -> int:
    """The exact predicate sign of points given as one flat sequence of coordinates.

    ``dim`` 2: three points give orient2d, four incircle; ``dim`` 3: four points give
    orient3d, five insphere.  (The numba predicates' Python fallback, in integers.)

    >>> exact_sign([0.0, 0.0, 1.0, 0.0, 0.0, 1.0], 2), exact_sign([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, -1], 3)
    (1, 1)
    """
    flat = [float(x) for x in coords]
    pts = [flat[i:i + dim] for i in range(0, len(flat), dim)]
    if dim == 2:
        P = exact_coordinates(pts)
        return orient_exact(*P) if len(P) == 3 else incircle_exact(*P)
    Q = exact_coordinates_3d(pts)
    return orient3d_exact(*Q) if len(Q) == 4 else insphere_exact(*Q)


def _solid_base(P: list, distinct: list[int]) -> tuple[int, int, int, int] | None:
    """Four distinct points spanning a solid (found in linear time), or None when all are coplanar."""
    if len(distinct) < 4:
        return None
    a, b = distinct[0], distinct[1]
    u = tuple(P[b][i] - P[a][i] for i in range(3))
    c = None
    for k in distinct[2:]:
        v = tuple(P[k][i] - P[a][i] for i in range(3))
        if (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]) != (0, 0, 0):
            c = k
            break
    if c is None:
        return None
    for d in distinct[2:]:
        if orient3d_exact(P[a], P[b], P[c], P[d]) != 0:
            return a, b, c, d
    return None


# the faces of a positively oriented tetrahedron (a0, a1, a2, a3): face k (opposite vertex k)
# listed so that orient3d(face, vertex k) > 0
_FACES3 = ((1, 3, 2), (0, 2, 3), (0, 3, 1), (0, 1, 2))


def check_delaunay_3d(points, tetrahedra, bulk=None) -> tuple[bool, str]:
    """Check exactly that ``tetrahedra`` is a Delaunay tetrahedralisation of ``points``.

    ``points`` is (n, 3) finite floats; ``tetrahedra`` (m, 4) point indices, in either
    orientation; any index of a duplicated point may be used.  Coplanar input (or fewer
    than 4 distinct points) has exactly one valid answer: no tetrahedra.  Returns
    ``(ok, message)``; the message names the first problem found.  Python integers
    only (every float times one common power of two).

    Why these checks are enough: (1) every tetrahedron has positive volume once
    oriented; (2) a face is shared by at most two tetrahedra, and then they lie on
    opposite sides of it; (3) for a face of only one tetrahedron ("boundary face"),
    every vertex of a boundary face lies on that tetrahedron's side of its plane or on
    it.  By (3) every boundary face lies on the boundary of the convex hull K of the
    boundary vertices.  The number of tetrahedra covering a point changes only across
    boundary faces (across a shared face one tetrahedron ends and the other begins), so
    it is constant outside K (there: 0) and constant in K's interior; (4) a point
    covered by exactly one tetrahedron makes it 1, so the tetrahedra tile K without
    overlap.  (5) every distinct point is a vertex, hence lies in K: K is the convex
    hull of all the points, and the tiling is a tetrahedralisation of them.  (6) every
    shared face locally Delaunay (the far apex not strictly inside the sphere of the
    other tetrahedron) makes it Delaunay, by the 3D Delaunay lemma.

    >>> cube = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    >>> check_delaunay_3d(cube, [(0, 1, 3, 7), (0, 1, 5, 7), (0, 4, 5, 7), (0, 2, 3, 7), (0, 2, 6, 7), (0, 4, 6, 7)])
    (True, 'ok')
    >>> check_delaunay_3d(cube, [(0, 1, 2, 4)])[1]
    'point 3 (0, 1, 1) is not a vertex of any tetrahedron'

    ``bulk`` (the module ``reference_impl/exact/bulk.py``, numpy): a fast pass that filters every
    sign at once and accepts a valid answer; anything it does not accept is decided again, with
    the message, in integers only (:func:`_check_delaunay_3d_integers`).
    """
    if bulk is not None and bulk.AVAILABLE and _delaunay_3d_accepts(points, tetrahedra, bulk):
        return True, "ok"
    return _check_delaunay_3d_integers(points, tetrahedra)


def _check_delaunay_3d_integers(points, tetrahedra) -> tuple[bool, str]:
    """:func:`check_delaunay_3d` in Python integers only, naming the first problem found."""
    P = exact_coordinates_3d(points)
    n = len(P)
    first: dict = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    distinct = sorted(first.values())
    rows, message = _index_rows(_rows(tetrahedra), n, 4, "tetrahedron")
    if rows is None:
        return False, message
    T: list[tuple[int, int, int, int]] = []
    for k, ids in enumerate(rows):
        a, b, c, d = (rep[v] for v in ids)
        s = orient3d_exact(P[a], P[b], P[c], P[d])
        if s == 0:
            return False, f"tetrahedron {k} = {ids} is flat (zero volume)"
        T.append((a, b, c, d) if s > 0 else (b, a, c, d))
    if _solid_base(P, distinct) is None:
        if T:
            return False, "the points are all coplanar (or fewer than 4 distinct): no tetrahedron is possible"
        return True, "ok"
    if not T:
        return False, "no tetrahedra, but the points are not coplanar"
    # (2) faces: key = sorted vertex triple -> [(tetrahedron, apex, face listed positively)]
    faces: dict = {}
    for ti, t in enumerate(T):
        for k, (i, j, l) in enumerate(_FACES3):
            f = (t[i], t[j], t[l])
            key = tuple(sorted(f))
            side = faces.setdefault(key, [])
            if len(side) == 2:
                return False, f"face {key} is shared by more than two tetrahedra (they overlap)"
            side.append((ti, t[k], f))
    boundary, bverts = [], set()
    for key, side in faces.items():
        if len(side) == 1:
            boundary.append(side[0])
            bverts.update(key)
            continue
        (t0, x, f0), (t1, y, f1) = side
        # f0 lists the face with x on its positive side; y must be on the other side, which
        # holds exactly when f1 lists the face the other way round (an odd permutation of f0)
        if _same_cycle(f0, f1):
            return False, (f"tetrahedra {t0} and {t1} lie on the same side of their common face {key} "
                           "(they overlap)")
        a, b, c = (P[v] for v in f0)
        if insphere_exact(a, b, c, P[x], P[y]) > 0:
            return False, (f"face {key} is not Delaunay: point {y} is strictly inside the circumsphere of "
                           f"tetrahedron {T[t0]}")
    # (3) boundary faces on the hull: integer plane equations, one dot product per vertex.  A convex
    # hull has at most 2h - 4 triangles (h <= n vertices), which bounds this O(faces x vertices) loop
    if len(boundary) > max(4, 2 * len(bverts) - 4):
        return False, (f"{len(boundary)} faces belong to one tetrahedron only, more than a convex hull of "
                       f"{len(bverts)} vertices has: the tetrahedra leave gaps or overlap")
    bpts = [(q, P[q]) for q in sorted(bverts)]
    for ti, x, f in boundary:
        a, b, c = (P[v] for v in f)
        u = (b[0] - a[0], b[1] - a[1], b[2] - a[2])
        v = (c[0] - a[0], c[1] - a[1], c[2] - a[2])
        nx, ny, nz = u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]
        off = nx * a[0] + ny * a[1] + nz * a[2]
        inner = (nx * P[x][0] + ny * P[x][1] + nz * P[x][2]) - off     # the apex side, nonzero
        for q, p in bpts:
            s = nx * p[0] + ny * p[1] + nz * p[2] - off
            if s * inner < 0:
                return False, (f"face {tuple(sorted(f))} belongs to tetrahedron {T[ti]} only, but it is not on "
                               f"the convex hull: point {q} lies beyond it (the tetrahedra leave gaps or overlap)")
    # (4) the centroid of T[0] (times 4) is covered by exactly one closed tetrahedron
    c4 = tuple(sum(P[v][i] for v in T[0]) for i in range(3))
    covering = 0
    for t in T:
        q = [tuple(4 * x for x in P[v]) for v in t]
        if any(min(p[i] for p in q) > c4[i] or max(p[i] for p in q) < c4[i] for i in range(3)):
            continue
        if all(orient3d_exact(*(c4 if j == k else q[j] for j in range(4))) >= 0 for k in range(4)):
            covering += 1
    if covering != 1:
        return False, f"the centre of tetrahedron {T[0]} is covered by {covering} tetrahedra: they overlap"
    # (5) every distinct point is a vertex
    used = {v for t in T for v in t}
    missing = [i for i in distinct if i not in used]
    if missing:
        return False, f"point {missing[0]} {tuple(points[missing[0]])} is not a vertex of any tetrahedron"
    return True, "ok"


def _prepare_3d(points, np) -> tuple:
    """(P, floats as an (n, 3) array or None when not tame, rep array, number of distinct points, solid?),
    with ``np`` numpy (passed in: this module imports only the standard library)."""
    P = exact_coordinates_3d(points)
    first: dict = {}
    rep = [first.setdefault(p, i) for i, p in enumerate(P)]
    distinct = sorted(first.values())
    F = [tuple(float(v) for v in p) for p in points]
    X = np.array(F, dtype=np.float64).reshape(-1, 3) if _tame(F) else None
    return P, X, np.array(rep, dtype=np.int64), len(distinct), _solid_base(P, distinct) is not None


def _fix_undecided(signs, exact) -> None:
    """Replace each 0 (undecided) of a filter's signs by ``exact(k)``."""
    for k in (signs == 0).nonzero()[0].tolist():
        signs[k] = exact(k)


def _delaunay_3d_accepts(points, tetrahedra, bulk) -> bool:
    """True only when every check of :func:`_check_delaunay_3d_integers` passes (False: ask it why).
    numpy throughout: the filters decide most signs at once, integers the rest; faces are matched by
    sorting their keys."""
    np = bulk.np
    P, X, rep, n_distinct, solid = _prepared(points, "3d", lambda pts: _prepare_3d(pts, np))
    n = len(P)
    rows = _int_rows(tetrahedra, n, 4)
    if rows is None or X is None or not solid or not rows or n >= 1 << 20:
        return False
    t = rep[np.array(rows, dtype=np.int64).reshape(-1, 4)]
    s = bulk.orient3d(X[t[:, 0]], X[t[:, 1]], X[t[:, 2]], X[t[:, 3]])
    _fix_undecided(s, lambda k: orient3d_exact(*(P[v] for v in t[k].tolist())))
    if (s == 0).any():
        return False
    t[s < 0, :2] = t[s < 0, 1::-1]                       # each tetrahedron positively oriented
    faces = np.concatenate([t[:, list(f)] for f in _FACES3])          # listed so the apex is positive
    apex = np.concatenate([t[:, k] for k in range(4)])
    srt = np.sort(faces, axis=1)
    key = (srt[:, 0] * n + srt[:, 1]) * n + srt[:, 2]
    order = np.argsort(key, kind="stable")
    ks = key[order]
    same = ks[1:] == ks[:-1]
    if (same[1:] & same[:-1]).any():
        return False                                      # a face of three tetrahedra
    first = order[:-1][same]
    second = order[1:][same]
    f = faces
    parity = ((f[:, 0] > f[:, 1]).astype(np.int8) + (f[:, 0] > f[:, 2]) + (f[:, 1] > f[:, 2])) & 1
    if (parity[first] == parity[second]).any():
        return False                                      # two tetrahedra on one side of their face
    a, b, c = X[f[first, 0]], X[f[first, 1]], X[f[first, 2]]
    x, y = X[apex[first]], X[apex[second]]
    s = bulk.insphere(a, b, c, x, y)
    _fix_undecided(s, lambda k: insphere_exact(*(P[v] for v in (*f[first[k]].tolist(), int(apex[first[k]]),
                                                                    int(apex[second[k]])))))
    if (s > 0).any():
        return False
    paired = np.zeros(len(key), dtype=bool)
    paired[first] = paired[second] = True
    bfaces, bapex = f[~paired], apex[~paired]
    bverts = np.unique(bfaces)
    if len(bfaces) > max(4, 2 * len(bverts) - 4):
        return False
    # every boundary vertex on the inner side of every boundary face (or on it): orient3d >= 0
    for lo in range(0, len(bfaces), max(1, 200_000 // max(1, len(bverts)))):
        g = bfaces[lo:lo + max(1, 200_000 // max(1, len(bverts)))]
        k, m = len(g), len(bverts)
        sides = bulk.orient3d(np.repeat(X[g[:, 0]], m, 0), np.repeat(X[g[:, 1]], m, 0),
                              np.repeat(X[g[:, 2]], m, 0), np.tile(X[bverts], (k, 1)))
        for j in (sides == 0).nonzero()[0].tolist():
            sides[j] = orient3d_exact(*(P[v] for v in g[j // m].tolist()), P[int(bverts[j % m])])
        if (sides < 0).any():
            return False
    sides = bulk.orient3d(X[bfaces[:, 0]], X[bfaces[:, 1]], X[bfaces[:, 2]], X[bapex])
    _fix_undecided(sides, lambda k: orient3d_exact(*(P[v] for v in (*bfaces[k].tolist(), int(bapex[k])))))
    if (sides <= 0).any():
        return False                                      # (the listing puts every apex on the positive side)
    # the centroid of the first tetrahedron (times 4) covered by exactly one: candidates by a float
    # box widened beyond any rounding, then the integers
    c4 = tuple(sum(P[v][i] for v in t[0].tolist()) for i in range(3))
    cf = X[t[0]].sum(axis=0)
    tol = 1e-9 * (float(np.abs(X).max()) + 1e-300)
    q = 4 * X[t]
    near = ((q.min(axis=1) <= cf + tol) & (q.max(axis=1) >= cf - tol)).all(axis=1)
    covering = 0
    for row in t[near].tolist():
        qq = [tuple(4 * v for v in P[w]) for w in row]
        if any(min(p[i] for p in qq) > c4[i] or max(p[i] for p in qq) < c4[i] for i in range(3)):
            continue
        if all(orient3d_exact(*(c4 if j == k else qq[j] for j in range(4))) >= 0 for k in range(4)):
            covering += 1
    return covering == 1 and np.unique(t).size == n_distinct


def _same_cycle(f: tuple, g: tuple) -> bool:
    """Do the triples f and g (same three vertices) list them in the same cyclic order?"""
    k = g.index(f[0])
    return g[(k + 1) % 3] == f[1]


def brute_force_empty_spheres(points, tetrahedra) -> tuple[bool, str]:
    """O(n m) check that no point is strictly inside any tetrahedron's circumsphere (small inputs).

    >>> brute_force_empty_spheres([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], [(0, 1, 2, 3)])
    (True, 'ok')
    """
    P = exact_coordinates_3d(points)
    for k, t in enumerate(_rows(tetrahedra)):
        a, b, c, d = (P[v] for v in t)
        if orient3d_exact(a, b, c, d) < 0:
            a, b = b, a
        for i, p in enumerate(P):
            if insphere_exact(a, b, c, d, p) > 0:
                return False, f"point {i} is inside the circumsphere of tetrahedron {k}"
    return True, "ok"
