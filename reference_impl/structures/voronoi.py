"""Voronoi cells clipped to a box, built from the Delaunay triangulation (its dual).

Use it from Python::

    from reference_impl.structures.voronoi import voronoi
    cells = voronoi(points, bbox=(xmin, ymin, xmax, ymax))   # one polygon per input point

or run the examples: ``python -m pytest --doctest-modules reference_impl/structures/voronoi.py``.

>>> cells = voronoi([(0, 0), (2, 0)], (-1, -1, 3, 1))
>>> cells[0].tolist()
[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]

How.  The Voronoi cell of p is the set of points at least as close to p as to any
other site.  Its vertices are the circumcentres of the Delaunay triangles around
p, in the same counter-clockwise order, and the edge between two consecutive
ones lies on the bisector of p and the vertex the two triangles share.  So each
cell is read off the triangulation (the combinatorics are exact, whatever the
degeneracy); a hull point's cell is unbounded and gets two rays, along the
outward normals of its two hull edges, closed by points so far away that the
box never sees them.  The polygon is then clipped to the box (Sutherland-Hodgman,
four half-planes).  For collinear input there is no triangle: the cells are
slabs, obtained by clipping the box with the bisectors of the neighbours along
the chain.  About O(n) work after the triangulation, compiled with numba.

Accuracy.  Every cell vertex is computed directly from the sites that define it:
a Voronoi vertex is the circumcentre of its triangle (from the triangle's
lexicographically smallest vertex, so every cell sharing it gets the same
double), and a vertex on the box is the intersection of a box side with the
bisector of two sites (not an interpolation between two computed vertices,
which would lose digits when the two are far apart).  All coordinates are first
scaled by one power of two (exact), so 1e-300 and 1e300 inputs behave like 1.
Circumcentres of triangles too flat for their float determinant to be trusted
are computed exactly (rare: nearly collinear hull points).
Vertices that coincide exactly are merged; fewer than three vertices left means
an empty cell.

Conventions: ``bbox = (xmin, ymin, xmax, ymax)`` with finite numbers and
xmin < xmax, ymin < ymax; every cell is a counter-clockwise ``(k, 2)`` float64
array starting at its lowest vertex (smallest y, then smallest x); a site whose
cell misses the box (or only touches it) gets a ``(0, 2)`` array; duplicates get
the same polygon as their representative; one point gets the whole box.  The
neighbours of each site are clipped in the order of their coordinates, so the
result does not depend on the order of the input.
"""
from __future__ import annotations

import math
import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from reference_impl.mesh.delaunay import Delaunay, as_delaunay
from reference_impl.mesh.topology import each_edge_once, slot, vertex_adjacency
from reference_impl.exact.scaling import pow2_exponent
from reference_impl.validate import as_bbox, as_points  # noqa: F401 (as_bbox re-exported)

__all__ = ["voronoi", "as_bbox"]

_FAR = 2.0 ** 900         # circumcentres farther than this (in scaled units) are pulled back to it
_GEN_FAR = -5             # edge generators: >= 0 a bisector with that site, -1..-4 a box side


def delaunay_adjacency(d: Delaunay) -> tuple[np.ndarray, np.ndarray]:
    """The Delaunay graph as CSR arrays ``(ptr, nbr)`` over the input indices.

    The neighbours of point i are ``nbr[ptr[i]:ptr[i + 1]]``, sorted by their
    (x, y) coordinates.  Duplicates have no neighbours (their representative,
    ``d.index_map[i]``, has them).  For flat input the graph is the sorted chain.

    >>> ptr, nbr = delaunay_adjacency(Delaunay([(0, 0), (1, 0), (0, 1), (0, 0)]))
    >>> ptr.tolist(), nbr.tolist()
    ([0, 2, 4, 6, 6], [2, 1, 0, 2, 0, 1])
    """
    pts = d.points
    n = len(pts)
    simp, nbrs = d.simplices, d.neighbors
    if len(simp):
        t, k = each_edge_once(nbrs)
        a, b = simp[t, (k + 1) % 3], simp[t, (k + 2) % 3]
    else:
        chain = d.hull
        a, b = chain[:-1], chain[1:]
    rank = np.empty(n, dtype=np.int64)
    rank[np.lexsort((pts[:, 1], pts[:, 0]))] = np.arange(n)
    return vertex_adjacency(a, b, n, rank)


def circumcentres(simp: np.ndarray, X: np.ndarray, Y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Circumcentres of counter-clockwise triangles (rows of ``simp`` index X, Y).

    Each is computed from the vertex with the largest angle (opposite the longest
    edge; ties: the lexicographically smallest vertex): the float error of the
    formula relative to vertex a grows like |cot(angle at a)|, which the largest
    angle minimises, and the choice depends only on the triangle, not on how its
    vertices are listed, so every cell sharing it gets the same doubles.  The edge
    vectors are scaled by a power of two first (exact), so tiny triangles do not
    underflow.  A triangle so flat that the sign of its float determinant is not
    certain is computed exactly (Python integers), and a centre beyond 2**900 is pulled
    back to that distance along its direction.

    >>> cx, cy = circumcentres(np.array([[0, 1, 2]]), np.array([0.0, 2.0, 0.0]), np.array([0.0, 0.0, 2.0]))
    >>> cx.tolist(), cy.tolist()
    ([1.0], [1.0])
    """
    rows = np.arange(len(simp))
    xs, ys = X[simp], Y[simp]
    ex = np.stack([xs[:, (j + 1) % 3] - xs[:, (j + 2) % 3] for j in range(3)], axis=1)   # edge opposite j
    ey = np.stack([ys[:, (j + 1) % 3] - ys[:, (j + 2) % 3] for j in range(3)], axis=1)
    e = pow2_exponent(ex, ey, axis=1)
    opp = np.ldexp(ex, -e[:, None]) ** 2 + np.ldexp(ey, -e[:, None]) ** 2
    first = np.zeros(len(simp), dtype=np.int64)
    for j in (1, 2):
        cur = opp[rows, first]
        bx, by = xs[rows, first], ys[rows, first]
        better = (opp[:, j] > cur) | ((opp[:, j] == cur) & ((xs[:, j] < bx) | ((xs[:, j] == bx) & (ys[:, j] < by))))
        first = np.where(better, j, first)
    a, b, c = (simp[rows, (first + j) % 3] for j in range(3))
    ax, ay = X[a], Y[a]
    bx, by = np.ldexp(X[b] - ax, -e), np.ldexp(Y[b] - ay, -e)
    cx, cy = np.ldexp(X[c] - ax, -e), np.ldexp(Y[c] - ay, -e)
    bb = bx * bx + by * by
    cc = cx * cx + cy * cy
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        den = 2.0 * (bx * cy - by * cx)
        ok = den > 32.0 * np.finfo(float).eps * (np.abs(bx * cy) + np.abs(by * cx))
        px = ax + np.ldexp(np.where(ok, (cy * bb - by * cc) / den, 0.0), e)
        py = ay + np.ldexp(np.where(ok, (bx * cc - cx * bb) / den, 0.0), e)
        ok &= np.isfinite(px) & np.isfinite(py) & (np.maximum(np.abs(px), np.abs(py)) < _FAR)
    for t in np.flatnonzero(~ok):
        px[t], py[t] = _exact_circumcentre(*(float(v) for v in (X[a[t]], Y[a[t]], X[b[t]], Y[b[t]],
                                                                   X[c[t]], Y[c[t]])))
    return px, py


def _exact_circumcentre(ax: float, ay: float, bx: float, by: float, cx: float, cy: float) -> tuple[float, float]:
    """The circumcentre in exact integer arithmetic, correctly rounded (pulled back to
    distance 2**900 along its direction if farther, or if the points are collinear)."""
    ratios = [v.as_integer_ratio() for v in (ax, ay, bx, by, cx, cy)]
    one = max(d for _, d in ratios)                  # a power of two: a common denominator
    Ax, Ay, Bx, By, Cx, Cy = (n * (one // d) for n, d in ratios)
    ux, uy, vx, vy = Bx - Ax, By - Ay, Cx - Ax, Cy - Ay
    uu, vv = ux * ux + uy * uy, vx * vx + vy * vy
    nx, ny = vy * uu - uy * vv, ux * vv - vx * uu
    den = 2 * (ux * vy - uy * vx)
    far = 2 ** 900
    if den > 0:
        X, Y, W = Ax * den + nx, Ay * den + ny, den * one        # the centre is (X / W, Y / W)
        if max(abs(X), abs(Y)) < far * W:
            return X / W, Y / W                                  # int / int rounds correctly
    m = max(abs(nx), abs(ny)) or 1
    return ax + _FAR * (nx / m), ay + _FAR * (ny / m)


@njit(cache=True, inline="always")
def _side_value(x, y, side, box):
    """<= 0 inside box side ``side`` (0: y >= ymin, 1: x <= xmax, 2: y <= ymax, 3: x >= xmin)."""
    if side == 0:
        return box[1] - y
    if side == 1:
        return x - box[2]
    if side == 2:
        return y - box[3]
    return box[0] - x


@njit(cache=True)
def _cross_point(ax, ay, bx, by, gen, side, p, X, Y, box):
    """Where the edge a -> b (lying on generator ``gen``) meets the line of box side ``side``.

    Computed from the generator itself when it is a bisector or another box side;
    interpolated only for the far closing edges (which never reach the box).
    """
    vertical = side == 1 or side == 3
    c = box[2] if side == 1 else box[0] if side == 3 else box[3] if side == 2 else box[1]
    if gen >= 0:
        px, py, qx, qy = X[p], Y[p], X[gen], Y[gen]
        mx = 0.5 * px + 0.5 * qx
        my = 0.5 * py + 0.5 * qy
        if vertical and qy != py:
            return c, my - (qx - px) * (c - mx) / (qy - py)
        if not vertical and qx != px:
            return mx - (qy - py) * (c - my) / (qx - px), c
    elif gen != _GEN_FAR:
        other = -1 - gen
        oc = box[2] if other == 1 else box[0] if other == 3 else box[3] if other == 2 else box[1]
        if vertical and (other == 0 or other == 2):
            return c, oc
        if not vertical and (other == 1 or other == 3):
            return oc, c
    ha = _side_value(ax, ay, side, box)
    hb = _side_value(bx, by, side, box)
    t = ha / (ha - hb)
    if vertical:
        return c, ay + t * (by - ay)
    return ax + t * (bx - ax), c


@njit(cache=True)
def _clip_box(vx, vy, vg, m, side, p, X, Y, box, tx, ty, tg):
    """Sutherland-Hodgman step: clip (vx, vy)[:m] (vg[i]: generator of edge i -> i+1) to one
    box side; write to (tx, ty, tg); return the new count."""
    k = 0
    for i in range(m):
        j = (i + 1) % m
        hs = _side_value(vx[i], vy[i], side, box)
        he = _side_value(vx[j], vy[j], side, box)
        if hs <= 0.0:
            tx[k] = vx[i]
            ty[k] = vy[i]
            tg[k] = vg[i] if not (hs == 0.0 and he > 0.0) else -1 - side
            k += 1
        if (hs < 0.0 < he) or (he < 0.0 < hs):
            x, y = _cross_point(vx[i], vy[i], vx[j], vy[j], vg[i], side, p, X, Y, box)
            tx[k] = x
            ty[k] = y
            tg[k] = -1 - side if hs < 0.0 else vg[i]
            k += 1
    return k


@njit(cache=True)
def _emit(ax, ay, k, out_x, out_y, pos):
    """Merge exactly equal neighbours, drop polygons of < 3 vertices, rotate to the lowest
    vertex (smallest y, then x) and append at ``pos``; return the new end."""
    n = 0
    for j in range(k):
        if n == 0 or ax[j] != ax[n - 1] or ay[j] != ay[n - 1]:
            ax[n] = ax[j]
            ay[n] = ay[j]
            n += 1
    while n > 1 and ax[n - 1] == ax[0] and ay[n - 1] == ay[0]:
        n -= 1
    if n < 3:
        return pos
    low = 0
    for j in range(1, n):
        if ay[j] < ay[low] or (ay[j] == ay[low] and ax[j] < ax[low]):
            low = j
    for j in range(n):
        out_x[pos + j] = ax[(low + j) % n]
        out_y[pos + j] = ay[(low + j) % n]
    return pos + n


@njit(cache=True)
def _unit(x, y):
    h = math.hypot(x, y)
    return x / h, y / h


@njit(cache=True)
def _dual_cells(X, Y, simp, nbrs, CX, CY, sites, start, box, size, out_x, out_y, out_ptr):
    """Cells of a triangulated set: circumcentres around each site (plus rays on the
    hull), clipped to the box.  ``start[p] = 3 t + i``: p is vertex i of triangle t,
    and for a hull site edge (p, simp[t, i+1]) is a hull edge."""
    vx = np.empty(size)
    vy = np.empty(size)
    vg = np.empty(size, dtype=np.int64)
    wx = np.empty(size)
    wy = np.empty(size)
    wg = np.empty(size, dtype=np.int64)
    ox = 0.5 * box[0] + 0.5 * box[2]
    oy = 0.5 * box[1] + 0.5 * box[3]
    half_diag = math.hypot(0.5 * box[2] - 0.5 * box[0], 0.5 * box[3] - 0.5 * box[1])
    pos = 0
    out_ptr[0] = 0
    for s in range(sites.shape[0]):
        p = sites[s]
        t0 = start[p] // 3
        i0 = start[p] % 3
        on_hull = nbrs[t0, (i0 + 2) % 3] < 0
        t, i, m = t0, i0, 0
        while True:
            vx[m] = CX[t]
            vy[m] = CY[t]
            vg[m] = simp[t, (i + 2) % 3]          # the edge to the next centre is on this bisector
            m += 1
            t = nbrs[t, (i + 1) % 3]
            if t < 0 or t == t0:
                break
            i = slot(simp, t, p)
        if on_hull:
            nxt = simp[t0, (i0 + 1) % 3]
            prv = vg[m - 1]
            in_x, in_y = _unit(Y[nxt] - Y[p], X[p] - X[nxt])        # outward normals
            out_x_, out_y_ = _unit(Y[p] - Y[prv], X[prv] - X[p])
            ax_, ay_ = in_x + out_x_, in_y + out_y_
            ux, uy = _unit(X[nxt] - X[p], Y[nxt] - Y[p])
            wx_, wy_ = _unit(X[prv] - X[p], Y[prv] - Y[p])
            bx_, by_ = -(ux + wx_), -(uy + wy_)
            if math.hypot(ax_, ay_) >= math.hypot(bx_, by_):
                mx_, my_ = _unit(ax_, ay_)
            else:
                mx_, my_ = _unit(bx_, by_)
            reach = max(math.hypot(vx[0] - ox, vy[0] - oy), math.hypot(vx[m - 1] - ox, vy[m - 1] - oy),
                        math.hypot(X[p] - ox, Y[p] - oy))
            L = 4.0 * (half_diag + reach) + 1.0
            vx[m] = vx[m - 1] + L * out_x_
            vy[m] = vy[m - 1] + L * out_y_
            vg[m] = _GEN_FAR
            vx[m + 1] = X[p] + 2.0 * L * mx_
            vy[m + 1] = Y[p] + 2.0 * L * my_
            vg[m + 1] = _GEN_FAR
            vx[m + 2] = vx[0] + L * in_x
            vy[m + 2] = vy[0] + L * in_y
            vg[m + 2] = nxt
            m += 3
        for side in range(4):
            outside = False
            for j in range(m):
                if _side_value(vx[j], vy[j], side, box) > 0.0:
                    outside = True
                    break
            if not outside:
                continue
            m = _clip_box(vx, vy, vg, m, side, p, X, Y, box, wx, wy, wg)
            vx, wx = wx, vx
            vy, wy = wy, vy
            vg, wg = wg, vg
            if m == 0:
                break
        pos = _emit(vx, vy, m, out_x, out_y, pos)
        out_ptr[s + 1] = pos
    return pos


@njit(cache=True, inline="always")
def _clip_bisector(sx, sy, m, nx, ny, mx, my, tx, ty):
    """Clip polygon (sx, sy)[:m] to {x : n . (x - mid) <= 0}; write to (tx, ty); return count."""
    k = 0
    if m == 0:
        return 0
    px = sx[m - 1]
    py = sy[m - 1]
    hp = nx * (px - mx) + ny * (py - my)
    for i in range(m):
        cx = sx[i]
        cy = sy[i]
        hc = nx * (cx - mx) + ny * (cy - my)
        if (hp < 0.0 < hc) or (hc < 0.0 < hp):
            t = hp / (hp - hc)
            tx[k] = px + t * (cx - px)
            ty[k] = py + t * (cy - py)
            k += 1
        if hc <= 0.0:
            tx[k] = cx
            ty[k] = cy
            k += 1
        px = cx
        py = cy
        hp = hc
    return k


@njit(cache=True)
def _slab_cells(X, Y, sites, ptr, nbr, box, out_x, out_y, out_ptr):
    """Flat input: clip the box by the bisectors with each site's chain neighbours (the
    bisectors are parallel, so every vertex is a box side met by one bisector)."""
    ax = np.empty(16)
    ay = np.empty(16)
    bx = np.empty(16)
    by = np.empty(16)
    pos = 0
    out_ptr[0] = 0
    for i in range(sites.shape[0]):
        p = sites[i]
        ax[0] = box[0]; ay[0] = box[1]
        ax[1] = box[2]; ay[1] = box[1]
        ax[2] = box[2]; ay[2] = box[3]
        ax[3] = box[0]; ay[3] = box[3]
        m = 4
        for j in range(ptr[p], ptr[p + 1]):
            q = nbr[j]
            m = _clip_bisector(ax, ay, m, X[q] - X[p], Y[q] - Y[p],
                               0.5 * X[p] + 0.5 * X[q], 0.5 * Y[p] + 0.5 * Y[q], bx, by)
            ax, bx = bx, ax
            ay, by = by, ay
        pos = _emit(ax, ay, m, out_x, out_y, pos)
        out_ptr[i + 1] = pos
    return pos


def voronoi(points: ArrayLike | Delaunay, bbox: ArrayLike) -> list[np.ndarray]:
    """Voronoi cell of every input point, clipped to ``bbox = (xmin, ymin, xmax, ymax)``.

    ``points``: the (n, 2) sites, or a ``Delaunay`` of them (its mesh is used as it
    is: no re-triangulation; also ``Delaunay.voronoi(bbox)``).
    Returns a list with one counter-clockwise ``(k, 2)`` float64 polygon per
    input point (starting at its lowest vertex); ``(0, 2)`` when the clipped
    cell is empty (and for a point removed from the ``Delaunay``); duplicates
    share their representative's polygon.  Raises ``ValueError`` for bad points
    or a bad box.

    >>> [c.tolist() for c in voronoi([(1, 1), (1, 1)], (0, 0, 2, 2))]
    [[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]], [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]]
    >>> voronoi([(0, 0), (1, 0), (0, 1)], (-2, -2, 2, 2))[0].tolist()
    [[-2.0, -2.0], [0.5, -2.0], [0.5, 0.5], [-2.0, 0.5]]
    >>> voronoi([(0, 0), (9, 9)], (-1, -1, 1, 1))[1].shape       # cell misses the box
    (0, 2)
    """
    d = as_delaunay(points)
    box = as_bbox(bbox)
    pts = d.points
    n = len(pts)
    if n == 0:
        return []
    rep = d.index_map
    sites = np.unique(rep[rep >= 0])
    k = pow2_exponent(pts, box)
    X = np.ldexp(pts[:, 0], -k)
    Y = np.ldexp(pts[:, 1], -k)
    sbox = np.ldexp(box, -k)
    simp, nbrs = d.simplices, d.neighbors
    out_ptr = np.empty(len(sites) + 1, dtype=np.int64)
    if len(simp) == 0:
        ptr, nbr = delaunay_adjacency(d)
        cap = 8 * len(sites)
        out_x, out_y = np.empty(cap), np.empty(cap)
        total = _slab_cells(X, Y, sites, ptr, nbr, sbox, out_x, out_y, out_ptr)
    else:
        CX, CY = circumcentres(simp, X, Y)
        start = np.full(n, -1, dtype=np.int64)
        start[simp.ravel()] = np.arange(simp.size)
        hull_edge = nbrs[:, [2, 0, 1]] < 0        # edge (simp[t, k], simp[t, k+1]) is on the hull
        start[simp[hull_edge]] = np.flatnonzero(hull_edge.ravel())
        sites = sites[np.argsort(start[sites], kind="stable")]   # triangle order: memory locality
        degree = np.bincount(simp.ravel(), minlength=n)
        size = int(degree.max()) + 12
        cap = int(degree[sites].sum()) + 8 * len(sites)
        out_x, out_y = np.empty(cap), np.empty(cap)
        total = _dual_cells(X, Y, simp, nbrs, CX, CY, sites, start, sbox, size, out_x, out_y, out_ptr)
    verts = np.ldexp(np.stack([out_x[:total], out_y[:total]], axis=1), k)
    lo = np.zeros(n, dtype=np.int64)
    hi = np.zeros(n, dtype=np.int64)
    lo[sites] = out_ptr[:-1]
    hi[sites] = out_ptr[1:]
    return [verts[lo[r]:hi[r]] if r == i else verts[lo[r]:hi[r]].copy() if r >= 0 else np.zeros((0, 2))
            for i, r in enumerate(rep.tolist())]
