"""Checker for `voronoi`: every received cell must be the site's Voronoi cell clipped to the box,
within a stated tolerance (stdlib only).

Two uses, one logic:

* the grader imports this file and calls ``read_input``, ``from_result`` / ``read_output`` and
  ``check`` in its own process (the reference cells never reach the student's side);
* Kattis / problemtools run the exported copy (``python -m grader export-kattis voronoi OUT``) as an
  output validator: ``python3 checker.py input answer feedback_dir < team_output`` (exit 42
  accept, 43 reject, the reason in ``feedback_dir/judgemessage.txt``).

What is checked, with eps = 1e-9 * D + 1e-14 * M (D the larger side of the box, M the largest
absolute coordinate of the input): each cell is a convex counter-clockwise polygon; each of its
vertices lies in the box and in the true cell (no other site is more than eps closer to it than
its own site: the vertex is equidistant from the sites whose cells meet there); each corner of
the true cell lies within eps of the received polygon; and the areas agree. Both inclusions
together bound the distance between the two polygons by eps, so any vertex order, starting
vertex, or extra vertices on an edge are accepted. With numpy (``bulk``, optional) the cells that
pass all of this with a margin are picked out at once (``_settled``) and only the others are
checked one by one: the same verdicts and messages, in less time. In the grader a long answer
comes as arrays (``from_arrays``: a binary frame of float64 vertices and per-cell counts), which
that pass uses as they are; its cells become lists only where a cell is checked on its own.

Example:
    >>> args = [[[0.0, 0.0], [2.0, 0.0]], [-1.0, -1.0, 3.0, 1.0]]
    >>> ref = [[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]], [[1.0, -1.0], [3.0, -1.0], [3.0, 1.0], [1.0, 1.0]]]
    >>> check(args, ref, ref)
    (True, 'ok')
    >>> check(args, [ref[0], ref[0]], ref)[1][:40]
    'cell 1: vertex (-1.0, -1.0) is not in th'
"""
from __future__ import annotations

import math
from itertools import chain

LIBRARY = ("judge_io", "bulk")  # reference_impl/judge_io.py (points format, PresentationError) and
#                                  reference_impl/exact/bulk.py (numpy, optional), bound by the loader
BULK_MIN = 64         # answers with fewer vertices are checked cell by cell only
PAIRS_MAX = 4096      # a cell whose vertex pairs (received x true) exceed this is checked on its own

REL_TOL = 1e-9    # times the larger side of the box
ABS_TOL = 1e-14   # times the largest absolute coordinate

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages


def read_input(text: str) -> list:
    """Parse the input format into the entry function's arguments ``[points, bbox]``."""
    points = judge_io.read_points(text)  # noqa: F821
    tok = text.split()
    return [points, [float(t) for t in tok[1 + 2 * len(points):5 + 2 * len(points)]]]


def write_input(args: list) -> str:
    points, bbox = args
    return judge_io.write_points(points) + " ".join(repr(float(v)) for v in bbox) + "\n"  # noqa: F821


def write_output(cells: list) -> str:
    return "".join(" ".join([str(len(c))] + [f"{float(x)!r} {float(y)!r}" for x, y in c]) + "\n" for c in cells)


def max_vertices(n: int) -> tuple[int, int]:
    """Bounds on an answer's size, as the statement states them: vertices per cell, and in all.
    A correct answer needs at most n + 8 and 10n + 16 (Voronoi: < 3n vertices, each in at most 3
    cells, plus the box corners and box crossings); the bounds are twice that, so an extra vertex
    in the middle of every edge (which the statement allows) fits."""
    return 2 * n + 16, 20 * n + 32


def _number(v, where: str) -> float:
    return judge_io.number(v, where, "a vertex coordinate")  # noqa: F821 - finite float, never OverflowError


def _cells(rows: list, n: int) -> list:
    if len(rows) != n:
        raise PresentationError(f"expected one cell per input point ({n}), got {len(rows)}")
    per_cell, total = max_vertices(n)
    if sum(len(c) for c in rows) > total:
        raise PresentationError(f"{sum(len(c) for c in rows)} vertices in all: a correct answer has at most {total}")
    if max(map(len, rows), default=0) <= per_cell:
        vertices = list(chain.from_iterable(rows))
        if set(map(type, vertices)) <= {list} and set(map(len, vertices)) <= {2}:
            coords = list(chain.from_iterable(vertices))
            if set(map(type, coords)) <= {float} and all(map(math.isfinite, coords)):
                return rows                  # the common case, checked in C loops (never changed here)
    out = []
    for i, cell in enumerate(rows):
        if len(cell) > per_cell:
            raise PresentationError(f"cell {i} has {len(cell)} vertices: a correct one has at most {per_cell}")
        out.append([[_number(x, f"cell {i}, vertex {k}, x"), _number(y, f"cell {i}, vertex {k}, y")]
                    for k, (x, y) in enumerate(cell)])
    return out


def from_result(value, args: list) -> list:
    """Type-check what ``voronoi_cells`` returned: one list of ``[x, y]`` pairs per input point."""
    points = args[0]
    if not isinstance(value, list):
        raise PresentationError(f"expected a list of cells (polygons), got {type(value).__name__}: {show(value, 60)}")
    head, per_cell = value[:len(points) + 1], max_vertices(len(points))[0] + 1
    if set(map(type, head)) <= {list} and max(map(len, head), default=0) <= per_cell:
        vertices = list(chain.from_iterable(head))                # the common case, in C loops
        if set(map(type, vertices)) <= {list} and set(map(len, vertices)) <= {2}:
            return _cells(value, len(points))
    for i, cell in enumerate(head):
        if not isinstance(cell, list) or not all(isinstance(p, list) and len(p) == 2
                                                 for p in cell[:max_vertices(len(points))[0] + 1]):
            raise PresentationError(f"cell {i} should be a list of [x, y] vertices, got {show(cell, 60)}")
    return _cells(value, len(points))


class _Cells:
    """An answer read by :func:`from_arrays`: cell ``i`` is ``rows[starts[i]:starts[i] + counts[i]]``
    of an (m, 2) float64 array; a cell is made a list of ``[x, y]`` only when it is asked for."""

    __slots__ = ("rows", "counts", "starts")

    def __init__(self, rows, counts):
        self.rows, self.counts = rows, counts
        self.starts = bulk.np.cumsum(counts) - counts  # noqa: F821 - bound by the loader

    def __len__(self) -> int:
        return len(self.counts)

    def __getitem__(self, i: int) -> list:
        start = int(self.starts[i])
        return self.rows[start:start + int(self.counts[i])].tolist()

    def __iter__(self):
        return (self[i] for i in range(len(self)))


def from_arrays(value, args: list):
    """The grader's reading of an answer that came as a binary frame (``value.rows``: (m, 2)
    float64 vertices, ``value.counts``: vertices per cell, as int64): accepted here exactly when
    :func:`from_result` accepts the same value as lists (one cell per point, within the size
    bounds, every coordinate finite), without making the lists; anything else is handed to
    :func:`from_result` as lists, which raises the same ``PresentationError`` as without frames."""
    n = len(args[0])
    counts, rows = value.counts, value.rows
    if bulk.AVAILABLE and counts is not None and len(counts) == n and rows.ndim == 2 and rows.shape[1] == 2:  # noqa: F821
        per_cell, total = max_vertices(n)
        if len(rows) <= total and (n == 0 or int(counts.max()) <= per_cell) and bool(bulk.np.isfinite(rows).all()):  # noqa: F821
            return _Cells(rows, counts)
    return from_result(value.tolist(), args)


def read_output(text: str, args: list) -> list:
    """Parse program output: one line per input point, ``k x1 y1 ... xk yk``."""
    n = len(args[0]) if args is not None else None
    lines = [ln for ln in text.split("\n") if ln.strip()]
    if n is not None and len(lines) != n:
        raise PresentationError(f"expected one line per input point ({n}), got {len(lines)} lines")
    per_cell = max_vertices(len(lines) if n is None else n)[0]
    rows = []
    for i, ln in enumerate(lines):
        tok = ln.split()
        if len(tok) > 1 + 2 * per_cell:   # bound the work before converting anything
            raise PresentationError(f"line {i + 1}: {len(tok)} numbers, more than any correct cell needs")
        k = judge_io.parse_int(tok[0], f"line {i + 1}", "the number of vertices k")  # noqa: F821
        vals = [judge_io.parse_float(t, f"line {i + 1}", "a vertex coordinate") for t in tok[1:]]  # noqa: F821
        if k < 0 or len(vals) != 2 * k:
            raise PresentationError(f"line {i + 1}: announced {k} vertices but {len(vals)} numbers follow")
        rows.append([[vals[2 * j], vals[2 * j + 1]] for j in range(k)])
    return _cells(rows, len(rows) if n is None else n)


def _area(poly: list) -> float:
    """Signed area (shoelace formula around the first vertex: no cancellation far from 0)."""
    ox, oy = poly[0]
    return 0.5 * sum((x0 - ox) * (y1 - oy) - (x1 - ox) * (y0 - oy)
                     for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]))


def _outside(poly: list, q: list) -> float:
    """How far q lies outside the polygon ``poly`` (0.0 inside or on it): a crossing test, then
    the distance to the nearest edge. Robust to very short edges (a few ulps long), whose
    direction is meaningless."""
    x, y = q
    inside = False
    best = math.inf
    for (ax, ay), (bx, by) in zip(poly, poly[1:] + poly[:1]):
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            inside = not inside
        dx, dy = bx - ax, by - ay
        L = dx * dx + dy * dy
        t = 0.0 if L == 0.0 else min(1.0, max(0.0, ((x - ax) * dx + (y - ay) * dy) / L))
        best = min(best, math.hypot(x - ax - t * dx, y - ay - t * dy))
    return 0.0 if inside else best


def _near_vertex(poly: list, x: float, y: float, d: float) -> bool:
    """Is (x, y) within d of a vertex of ``poly`` in both coordinates (so within d*sqrt(2) of the
    polygon)? A cheap first test before :func:`_outside`, which a matching vertex usually passes."""
    return any(abs(px - x) <= d and abs(py - y) <= d for px, py in poly)


def _merge_close(poly: list, eps: float) -> list:
    """Drop each vertex within eps of the previous one kept (and of the first, cyclically)."""
    out = []
    for p in poly:
        if not out or math.dist(p, out[-1]) > eps:
            out.append(p)
    while len(out) > 1 and math.dist(out[-1], out[0]) <= eps:
        out.pop()
    return out


def _convexity_fault(poly: list, eps: float) -> str:
    """'' for a convex counter-clockwise polygon (collinear and repeated vertices allowed)."""
    pts = _merge_close(poly, eps)
    if len(pts) < 3:
        return f"it has {len(pts)} distinct vertices, not a polygon"
    if _area(pts) <= 0.0:
        return "it is not counter-clockwise (its signed area is not positive)"
    turning = 0.0
    for a, b, c in zip(pts, pts[1:] + pts[:1], pts[2:] + pts[:2]):
        ux, uy, vx, vy = b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]
        cross = ux * vy - uy * vx
        if cross < -eps * (math.hypot(ux, uy) + math.hypot(vx, vy)):
            return "it turns clockwise at a vertex: not convex"
        turning += math.atan2(cross, ux * vx + uy * vy)
    if abs(turning - 2 * math.pi) > 1.0:
        return "it winds around more than once"
    return ""


def _settled(cells: list, expected: list, k: int, box: tuple, eps: float, near_eps: float) -> list | None:
    """Which cells pass every test of :func:`check` with a margin, decided for all cells at once
    with numpy (``bulk``); ``None`` without numpy or for a small answer. The others (a vertex not
    close to one of the other cell's, a short edge, a nearly flat turn, ...) are left to ``check``.

    Why a settled cell passes ``check``'s own tests: the vertices are scaled the same way
    (``ldexp``, exact); the box, closeness and turn tests use the same differences and products
    (IEEE operations, the same in numpy), against half the tolerance; edge lengths (``hypot``) may
    differ in the last bit, so no edge is within 1.000001 eps; the turning sum and the areas are
    summed in another order, so the turning must be within 0.5 of 2 pi (not 1.0) and the areas carry
    a bound on any summation's error (4 k 2^-53 times the sum of the terms' magnitudes)."""
    if not (bulk.AVAILABLE and len(cells) == len(expected)):  # noqa: F821 - bound by the loader
        return None
    np = bulk.np  # noqa: F821
    n = len(cells)
    arrays = isinstance(cells, _Cells)
    kC = cells.counts if arrays else np.fromiter(map(len, cells), np.int64, n)
    kR = np.fromiter(map(len, expected), np.int64, n)
    if int(kC.sum()) + int(kR.sum()) < BULK_MIN:
        return None
    x0, y0, x1, y1 = box

    def flat(rows, kk):
        return np.fromiter(chain.from_iterable(chain.from_iterable(rows)), np.float64, 2 * int(kk.sum())).reshape(-1, 2)

    with np.errstate(all="ignore"):
        C = np.ldexp(cells.rows if arrays else flat(cells, kC), -k)
        R = np.ldexp(flat(expected, kR), -k)
        ok = (kC >= 3) & (kR >= 3) & (kC * kR <= PAIRS_MAX)
        rings = []
        for V, kk in ((C, kC), (R, kR)):
            start = np.cumsum(kk) - kk
            cell = np.repeat(np.arange(n), kk)
            nxt = np.arange(len(V)) + 1
            full = kk > 0
            nxt[(start + kk - 1)[full]] = start[full]
            x, y = V[:, 0], V[:, 1]
            ox, oy = x[start[cell]], y[start[cell]]
            t = (x - ox) * (y[nxt] - oy) - (x[nxt] - ox) * (y - oy)
            area = 0.5 * np.bincount(cell, t, n)
            err = np.bincount(cell, np.abs(t), n) * kk * 2.0 ** -51
            rings.append((x, y, cell, start, nxt, area, err))
        x, y, cell, start, nxt, areaC, errC = rings[0]
        rx, ry, cellR, startR, nxtR, areaR, errR = rings[1]
        ux, uy = x[nxt] - x, y[nxt] - y
        vx, vy = ux[nxt], uy[nxt]
        cross = ux * vy - uy * vx
        hu = np.hypot(ux, uy)
        bad = ~(hu > eps * 1.000001)                                      # no vertex merged away
        bad |= ~(cross >= -0.5 * eps * (hu + hu[nxt]))                    # no clockwise turn
        bad |= ~((x >= x0 - 0.5 * eps) & (x <= x1 + 0.5 * eps) & (y >= y0 - 0.5 * eps) & (y <= y1 + 0.5 * eps))
        turning = np.bincount(cell, np.arctan2(cross, ux * vx + uy * vy), n)
        ok &= (np.abs(turning - 2 * math.pi) < 0.5) & (areaC > errC)
        # every received vertex close to a true one and every true corner close to a received one
        g = np.where(ok, kR, 0)[cell]
        pc = np.repeat(np.arange(len(x)), g)
        pr = startR[cell[pc]] + np.arange(len(pc)) - np.repeat(np.cumsum(g) - g, g)
        d = 0.5 * near_eps
        close = (np.abs(rx[pr] - x[pc]) <= d) & (np.abs(ry[pr] - y[pc]) <= d)
        seenC, seenR = np.zeros(len(x), dtype=bool), np.zeros(len(rx), dtype=bool)
        seenC[pc[close]] = True
        seenR[pr[close]] = True
        bad |= ~seenC
        ok &= (np.bincount(cell, bad, n) == 0) & (np.bincount(cellR, ~seenR, n) == 0)
        perimeter = np.bincount(cellR, np.hypot(rx[nxtR] - rx, ry[nxtR] - ry), n)
        ok &= np.abs(areaC - areaR) + errC + errR <= 0.5 * (2 * eps * perimeter + eps * eps)
    return ok.tolist()


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "but the true cell has": "a cell is empty or missing",
    "not a polygon": "a cell is not a polygon",
    "counter-clockwise": "a cell is not counter-clockwise",
    "not convex": "a cell is not convex",
    "winds around": "a cell winds around more than once",
    "outside the box": "a cell vertex is outside the box",
    "is not in the cell": "a cell vertex is not in the true cell",
    "too small": "a cell is too small",
    "area": "a cell has the wrong area",
}


@judge_io.mistake_kinds(MISTAKES, "a cell is wrong")  # noqa: F821 - bound by the loader
def check(args: list, cells: list, expected: list) -> tuple[bool, str]:
    """Each cell against the reference cell (see the module docstring)."""
    points, bbox = args
    big = max(chain(map(abs, chain.from_iterable(points)), map(abs, bbox)))   # in C loops
    k = math.frexp(big)[1] if big > 0 else 0

    def s(v: float) -> float:                            # work at unit scale: no overflow at 1e300
        try:
            return math.ldexp(v, -k)
        except OverflowError:
            return math.copysign(math.inf, v)

    def u(v: float) -> float:                            # back to the input's scale, for messages
        return math.ldexp(v, k)

    x0, y0, x1, y1 = (s(v) for v in bbox)
    eps = REL_TOL * max(x1 - x0, y1 - y0) + ABS_TOL * s(big)
    near_eps = eps * 0.7  # a vertex this close in x and in y is within eps (0.7 * sqrt(2) < 1) of it
    settled = _settled(cells, expected, k, (x0, y0, x1, y1), eps, near_eps)
    for i in range(min(len(cells), len(expected))):
        if settled is not None and settled[i]:
            continue                                     # passes every test below, with a margin
        cell, ref = cells[i], expected[i]                # (from arrays: this cell made a list only now)
        C = [[s(x), s(y)] for x, y in cell]
        R = [[s(x), s(y)] for x, y in ref]
        if not C or not R:
            if (C and _area(C) > eps * eps) or (R and _area(R) > eps * eps):
                return False, f"cell {i}: {len(cell)} vertices, but the true cell has {len(ref)}"
            continue
        fault = _convexity_fault(C, eps)
        if fault:
            return False, f"cell {i} of point {i} {points[i]}: {fault}"
        for vx, vy in C:
            if not (x0 - eps <= vx <= x1 + eps and y0 - eps <= vy <= y1 + eps):
                return False, f"cell {i}: vertex ({u(vx)!r}, {u(vy)!r}) is outside the box {bbox}"
            if not _near_vertex(R, vx, vy, near_eps) and _outside(R, [vx, vy]) > eps:
                P = [[s(x), s(y)] for x, y in points]    # the sites at unit scale, for the message
                own = math.hypot(vx - P[i][0], vy - P[i][1])
                j = min(range(len(P)), key=lambda m: math.hypot(vx - P[m][0], vy - P[m][1]))
                near = math.hypot(vx - P[j][0], vy - P[j][1])
                return False, (f"cell {i}: vertex ({u(vx)!r}, {u(vy)!r}) is not in the cell of point {i} "
                               f"{points[i]}: it is {u(own):.6g} from it but {u(near):.6g} from point {j} {points[j]}")
        for rx, ry in R:
            if not _near_vertex(C, rx, ry, near_eps) and _outside(C, [rx, ry]) > eps:
                return False, (f"cell {i} of point {i} {points[i]} is too small: it misses the corner "
                               f"({u(rx)!r}, {u(ry)!r}) of the true cell")
        a, b = _area(C), _area(R)
        perimeter = sum(math.dist(p, q) for p, q in zip(R, R[1:] + R[:1]))
        if abs(a - b) > 2 * eps * perimeter + eps * eps:
            return False, f"cell {i}: area {u(u(a)):.9g}, but the true cell has area {u(u(b)):.9g}"
    return True, "ok"


def draw(axes, args: list, received: list, expected: list) -> None:
    """Picture for reports: the box, the sites and the expected cells (left) and received ones
    (right). ``axes`` is a pair of matplotlib Axes."""
    points, (x0, y0, x1, y1) = args
    for ax, cells, title, colour in ((axes[0], expected, "expected", "tab:blue"),
                                     (axes[1], received, "received", "tab:red")):
        ax.plot([x0, x1, x1, x0, x0], [y0, y0, y1, y1, y0], color="0.6", lw=0.8)
        for cell in cells or []:
            if cell:
                cyc = cell + cell[:1]
                ax.plot([p[0] for p in cyc], [p[1] for p in cyc], color=colour, lw=0.8)
        ax.scatter([p[0] for p in points], [p[1] for p in points], s=10, color="black", zorder=3)
        ax.set_title(f"{title}: {len(cells or [])} cells", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
