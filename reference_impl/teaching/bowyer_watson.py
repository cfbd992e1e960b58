"""The teaching Bowyer-Watson: readable Python that follows the tutorial's pseudocode, corrected.

Run the examples:  python -m pytest reference_impl/teaching/bowyer_watson.py
Print the dry run: python -c "from reference_impl.teaching.bowyer_watson import dry_run; print(dry_run())"

This is the version students read (the fast one is ``Delaunay`` in
``mesh/delaunay.py``).  It keeps the tutorial's four moves for every point p:

1. find the *bad* triangles: those whose circumcircle contains p;
2. find the *cavity boundary*: the edges around the union of the bad triangles;
3. delete the bad triangles;
4. connect p to every boundary edge.

In pseudocode (compare with the original code in ``tutorial_bugs.py``)::

    triangulation = the two ghost triangles of the first two points   # no super-triangle
    for p in the other points:
        bad = [t for t in triangulation if circumcircle_contains(t, p)]   # exact, ghosts included
        boundary = [edges of exactly one bad triangle]
        remove the bad triangles; add (a, b, p) for every boundary edge (a, b)
    return the triangles that do not touch the vertex at infinity

and fixes the four bugs of the original tutorial's code (reproduced in
``reference_impl/teaching/tutorial_bugs.py``):

Fix 1, orientation.  The in-circle determinant says "inside" only for a
counter-clockwise triangle (for a clockwise one its sign flips).  Every
triangle here is stored counter-clockwise, and ``orient2d`` checks it when the
triangle is created.

Fix 2, cavity boundary.  An edge between two bad triangles lies *inside* the
cavity: it must disappear completely.  The tutorial keeps one copy of it and
so builds overlapping triangles.  Here the boundary is exactly the set of
edges that belong to one bad triangle only (``cavity_boundary``).

Fix 3, no finite super-triangle.  A super-triangle at +-1e5 does not contain
points at 1e6 (the tutorial's own large-coordinate test), and no fixed size is
safe for every input.  Worse, even a huge one loses hull triangles: a thin hull
triangle has a huge circumcircle, which can contain a super-triangle vertex,
so the Delaunay triangulation *with* the super-vertices never has that
triangle, and deleting "everything that touches the super-triangle" at the end
leaves a dent in the hull.  The fix is a *vertex at infinity* (index ``-1``,
``INFINITE``): every convex-hull edge (a, b) gets a *ghost triangle*
(b, a, INFINITE) that covers the outside of that edge.  The ghost triangles
play the super-triangle's role (every point lands in some triangle), but their
in-circle test is decided exactly, without coordinates:

    ghost (u, v, INFINITE) is bad for p  <=>  orient2d(u, v, p) > 0, or
                                              orient2d(u, v, p) == 0 and p lies strictly inside segment uv.

Why: the circle through u, v and a point running off to infinity on the left
of u->v grows into the open half-plane left of the line uv, plus the open
segment uv itself (a chord is inside its circle; the rest of the line is not).
Because the ghosts hug the hull exactly, dropping them at the end drops nothing
real: the convex hull is always fully triangulated, collinear hull points included.

Fix 4, exact predicates.  ``orient2d`` and ``incircle`` (``predicates.py``)
return the exact sign for any finite doubles (1e-300 and 1e300 included).
There is no ``np.linalg.det`` and no epsilon anywhere.

Two details a careful reader will ask about:

* Start-up.  The first two points split the plane along their line into two
  ghost triangles, (a, b, INFINITE) and (b, a, INFINITE).  The third point must
  be off that line, so the insertion order puts the first point off the line
  third.  From then on every step is an ordinary Bowyer-Watson step.
* Insertion order.  Duplicates are dropped first (a duplicate keeps the
  smallest input index, found by exact equality, no tolerance).  By default
  the points are then inserted in a *canonical* order that depends only on the
  *set* of points, so cocircular ties come out the same for any input order:
  the BRIO order of the fast version (``ordering.py``: random rounds, each
  sorted along a Hilbert curve).  The randomness keeps cavities small on
  average; the curve keeps consecutive points close, so the walk below is
  short.  ``order="input"`` inserts in the given order instead (for dry runs
  and click-to-add widgets), with the same tie caveat.

Finding the bad triangles: the tutorial tests every triangle, and so does the
default ``locate="scan"`` (quadratic time on every input: this is the version
the complexity lesson measures).  ``locate="walk"`` finds one bad triangle by
walking from the last new triangle towards p, then collects the others through
neighbours (the bad triangles always form one connected region around p): the
first step towards the fast version.  Both give the same triangles.

>>> bowyer_watson([(0, 0), (1, 0), (0, 1), (1, 1), (0, 0)]).tolist()   # duplicate (0, 0) merged
[[0, 1, 3], [0, 3, 2]]
>>> steps = []
>>> tris = bowyer_watson([(1, 1), (3, 2), (5, 1), (4, 4)], trace=steps)
>>> len(steps), len(tris)
(4, 3)
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Iterable

import numpy as np

from reference_impl.mesh.ordering import insertion_order as brio_order
from reference_impl.validate import as_points
from reference_impl.exact.predicates import incircle, orient2d

__all__ = ["bowyer_watson", "recursive_bowyer_watson", "Step", "dry_run", "cavity_boundary",
           "insertion_order", "INFINITE", "TUTORIAL_POINTS"]

INFINITE = -1
"""Index of the vertex at infinity; ghost triangles are stored as (u, v, INFINITE)."""

TUTORIAL_POINTS = ((1.0, 1.0), (3.0, 2.0), (5.0, 1.0), (4.0, 4.0))
"""The 4-point dry-run example of the lessons."""


Point = tuple[float, float]
Triangle = tuple[int, int, int]
Edge = tuple[int, int]


# ----------------------------------------------------------------------------- the trace
@dataclass(frozen=True, eq=False)
class Step:
    """What happened when one point was inserted (one record of ``bowyer_watson(..., trace=[])``).

    Indices are input indices; ``INFINITE`` (-1) is the vertex at infinity, so
    (u, v, -1) is the ghost triangle outside hull edge v->u.

    * ``index``, ``point``: the inserted point;
    * ``located``: the real triangle that contains the point, or ``None`` when
      the point is outside the current hull (only ghost triangles contain it);
    * ``bad``: the triangles whose circumcircle contains the point, in the order found;
    * ``boundary``: the cavity boundary, directed edges (a, b) in counter-clockwise
      order around the point;
    * ``new``: the triangles created, (a, b, point) for every boundary edge (a, b);
    * ``triangles``: the whole triangulation after the step, real triangles only, (k, 3);
    * ``walked``: the triangles the walk stood on to find the first bad one (1: it started
      in it), a count that does not depend on the machine; 0 with ``locate="scan"`` and for
      the first three points, which are not located by a walk.

    The first two steps are the start-up: the first point creates nothing, the
    second creates the two ghost triangles on either side of the line through
    both (``bad`` and ``boundary`` are then empty).

    >>> steps = []
    >>> _ = bowyer_watson(TUTORIAL_POINTS, trace=steps, order="input")
    >>> print(steps[-1])
    insert (4, 4): 2 bad triangles, cavity boundary of 4 edges, 4 new triangles
    >>> steps[-1].bad, steps[-1].boundary
    ([(0, 1, -1), (1, 2, -1)], [(0, 1), (1, 2), (2, -1), (-1, 0)])
    >>> steps[-1].new
    [(0, 1, 3), (1, 2, 3), (3, 2, -1), (0, 3, -1)]
    """

    index: int
    point: Point
    located: Triangle | None
    bad: list[Triangle]
    boundary: list[Edge]
    new: list[Triangle]
    triangles: np.ndarray
    walked: int = 0

    def __str__(self) -> str:
        head = f"insert {_format_point(self.point)}: "
        if not self.bad:
            if not self.new:
                return head + "first point, no triangle yet"
            return head + ("second point, no triangle yet: the line through the first two points "
                           f"splits the plane into {len(self.new)} ghost triangles")
        return head + (f"{_plural(len(self.bad), 'bad triangle')}, cavity boundary of "
                       f"{_plural(len(self.boundary), 'edge')}, {_plural(len(self.new), 'new triangle')}")


def _plural(k: int, word: str) -> str:
    return f"{k} {word}" if k == 1 else f"{k} {word}s"


def _format_number(x: float) -> str:
    """Integers without '.0', everything else as Python prints it.

    >>> _format_number(3.0), _format_number(0.5), _format_number(1e300)
    ('3', '0.5', '1e+300')
    """
    return str(int(x)) if x.is_integer() and abs(x) < 1e16 else repr(x)


def _format_point(p: Point) -> str:
    return f"({_format_number(p[0])}, {_format_number(p[1])})"


def _format_vertex(v: int) -> str:
    return "inf" if v == INFINITE else str(v)


def _format_triangle(t: Triangle) -> str:
    return "(" + ", ".join(_format_vertex(v) for v in t) + ")"


def _format_edge(e: Edge) -> str:
    return f"{_format_vertex(e[0])}->{_format_vertex(e[1])}"


# ----------------------------------------------------------------------------- small helpers
def _edges(t: Triangle) -> tuple[Edge, Edge, Edge]:
    """The three directed edges of a triangle, in its (counter-clockwise) order."""
    a, b, c = t
    return (a, b), (b, c), (c, a)


def _canonical(t: Triangle) -> Triangle:
    """One name per triangle: rotate (never reflect) so that ghost triangles end with
    INFINITE and real ones start with their smallest index.

    >>> _canonical((3, 1, 2)), _canonical((-1, 4, 5))
    ((1, 2, 3), (4, 5, -1))
    """
    a, b, c = t
    if a == INFINITE:
        return (b, c, a)
    if b == INFINITE:
        return (c, a, b)
    if c == INFINITE:
        return t
    if a < b and a < c:
        return t
    return (b, c, a) if b < c else (c, a, b)


def _is_ghost(t: Triangle) -> bool:
    return t[2] == INFINITE  # canonical form: the vertex at infinity is last


def cavity_boundary(bad: Iterable[Triangle]) -> list[Edge]:
    """Fix 2: the edges that belong to exactly one bad triangle, chained counter-clockwise.

    All triangles are counter-clockwise, so an edge shared by two bad triangles
    appears as a->b in one and b->a in the other.  Such an edge is inside the
    cavity and both copies are dropped (the tutorial kept one, which creates
    overlapping triangles).  What remains is a closed loop around the new point.

    >>> cavity_boundary([(0, 1, 2), (2, 1, 3)])   # edge 1-2 is shared: it disappears
    [(0, 1), (1, 3), (3, 2), (2, 0)]
    """
    bad = list(bad)
    edges_of_bad = {e for t in bad for e in _edges(t)}
    loose = [(a, b) for t in bad for a, b in _edges(t) if (b, a) not in edges_of_bad]
    if not loose:
        return []
    next_edge = {a: (a, b) for a, b in loose}  # each boundary vertex starts exactly one edge
    chain = [loose[0]]
    for _ in range(len(loose) - 1):
        chain.append(next_edge[chain[-1][1]])
    return chain


def insertion_order(points, order: str = "canonical") -> list[int]:
    """The order in which ``bowyer_watson`` inserts the points: input indices of the distinct points.

    Duplicates keep their smallest index.  ``order="canonical"``: the BRIO
    order of ``ordering.insertion_order``, which depends only on the set of
    points; ``order="input"``: the given order.  The start-up needs the third
    point off the line through the first two: the first such point is moved to
    third place.  Returns ``[]`` when there is no triangle to build (fewer than
    three distinct points, or all collinear).

    >>> insertion_order([(0, 0), (1, 1), (2, 2), (0, 0)])             # all collinear
    []
    >>> insertion_order([(0, 0), (1, 0), (2, 0), (0, 0), (5, 5)], order="input")
    [0, 1, 4, 2]
    """
    pts = as_points(points)
    if order not in ("canonical", "input"):
        raise ValueError(f"order must be 'canonical' or 'input', got {order!r}")
    xy: list[Point] = [(x, y) for x, y in pts.tolist()]
    smallest: dict[Point, int] = {}
    for i, p in enumerate(xy):
        smallest.setdefault(p, i)              # exact equality of coordinates, no tolerance
    if order == "canonical":
        with np.errstate(over="ignore"):  # ordering.py computes 1/span; for subnormal spans it
            ranks = brio_order(pts).tolist()  # overflows to inf and falls back on purpose
    else:
        ranks = list(range(len(xy)))
    distinct = list(dict.fromkeys(smallest[xy[i]] for i in ranks))  # first occurrence of each point
    if len(distinct) < 3:
        return []
    a, b = xy[distinct[0]], xy[distinct[1]]
    for k in range(2, len(distinct)):
        if orient2d(a, b, xy[distinct[k]]) != 0:
            return distinct[:2] + [distinct[k]] + distinct[2:k] + distinct[k + 1:]
    return []


# ----------------------------------------------------------------------------- the triangulation
class _Triangulation:
    """Triangles (ghosts included) with O(1) neighbour look-up.

    ``triangles`` plays the tutorial's ``triangulation`` list (a dict used as an
    ordered set).  ``apex[(a, b)] = c`` for every triangle (a, b, c) and each of
    its three rotations: the neighbour across edge a->b is the triangle that
    owns the reversed edge b->a, that is (b, a, apex[(b, a)]).
    """

    def __init__(self, xy: list[Point]) -> None:
        self.xy = xy
        self.triangles: dict[Triangle, None] = {}
        self.apex: dict[Edge, int] = {}
        self.last: Triangle | None = None  # a real triangle at the last inserted point
        self.walked = 0  # triangles the last walk stood on (Step.walked)

    # -- bookkeeping
    def add(self, t: Triangle) -> Triangle:
        t = _canonical(t)
        self.triangles[t] = None
        a, b, c = t
        self.apex[(a, b)] = c
        self.apex[(b, c)] = a
        self.apex[(c, a)] = b
        return t

    def remove(self, t: Triangle) -> None:
        del self.triangles[t]
        for e in _edges(t):
            del self.apex[e]

    def across(self, a: int, b: int) -> Triangle:
        """The neighbour across edge a->b (the triangle that has edge b->a)."""
        return _canonical((b, a, self.apex[(b, a)]))

    def real_triangles(self) -> np.ndarray:
        rows = sorted(t for t in self.triangles if not _is_ghost(t))
        return np.array(rows, dtype=np.int64).reshape(-1, 3)

    # -- predicates
    def in_conflict(self, t: Triangle, p: Point) -> bool:
        """Is ``t`` bad for ``p``: does its circumcircle contain p strictly?"""
        a, b, c = t
        xy = self.xy
        if c != INFINITE:
            return incircle(xy[a], xy[b], xy[c], p) > 0  # Fix 1 + 4: CCW triangle, exact sign
        # Fix 3: ghost triangle (a, b, INFINITE): its "circle" is the open half-plane
        # left of a->b plus the open segment ab.
        side = orient2d(xy[a], xy[b], p)
        if side != 0:
            return side > 0
        (ax, ay), (bx, by) = xy[a], xy[b]
        if ax != bx:
            return min(ax, bx) < p[0] < max(ax, bx)
        return min(ay, by) < p[1] < max(ay, by)

    def contains(self, t: Triangle, p: Point) -> bool:
        """Is p in the closed real triangle t (inside or on its boundary)?"""
        return all(orient2d(self.xy[a], self.xy[b], p) >= 0 for a, b in _edges(t))

    # -- the steps of one insertion
    def walk(self, p: Point) -> Triangle:
        """Find one bad triangle: walk from ``last`` towards p.

        In the current triangle, look for an edge with p strictly on its far
        side and cross it; stop when there is none (p is in this triangle, which
        is then bad) or when we cross the hull into a ghost triangle (p is
        strictly outside that hull edge, so the ghost is bad).  This "visibility
        walk" always ends in a Delaunay triangulation (Edelsbrunner's acyclicity
        theorem); in an arbitrary triangulation it could go round in circles.
        """
        t = self.last
        self.walked = 1
        while not _is_ghost(t):
            for a, b in _edges(t):
                if orient2d(self.xy[a], self.xy[b], p) < 0:
                    t = self.across(a, b)
                    self.walked += 1
                    break
            else:
                return t
        return t

    def grow_cavity(self, first: Triangle, p: Point) -> list[Triangle]:
        """All bad triangles, found from one of them through neighbours.

        The bad triangles form one connected region around p, so a search that
        only steps from bad triangles to their neighbours finds them all (the
        tutorial's test of every triangle finds the same set, only slower).
        """
        bad = [first]
        seen = {first}
        todo = [first]
        while todo:
            t = todo.pop()
            for a, b in _edges(t):
                n = self.across(a, b)
                if n not in seen:
                    seen.add(n)
                    if self.in_conflict(n, p):
                        bad.append(n)
                        todo.append(n)
        return bad

    def new_triangle(self, a: int, b: int, i: int) -> Triangle:
        """Fix 1: create (a, b, i), checked counter-clockwise with the exact orient2d.

        The new point sees every cavity boundary edge from its left side, so the
        check always holds; it is the invariant the in-circle sign relies on.
        """
        if INFINITE not in (a, b) and orient2d(self.xy[a], self.xy[b], self.xy[i]) <= 0:
            raise RuntimeError(f"internal error: new triangle ({a}, {b}, {i}) is not counter-clockwise")
        return self.add((a, b, i))

    def insert(self, i: int, locate: str) -> Step:
        """Insert point i: the tutorial's loop body, corrected."""
        p = self.xy[i]
        self.walked = 0
        # 1. the bad triangles: every triangle whose circumcircle contains p
        if locate == "scan":  # the tutorial's way: test every triangle
            bad = [t for t in self.triangles if self.in_conflict(t, p)]
            located = next((t for t in bad if not _is_ghost(t) and self.contains(t, p)), None)
        else:
            if self.last is None:  # third point: only the two start-up ghost triangles exist
                first = next(t for t in self.triangles if self.in_conflict(t, p))
            else:
                first = self.walk(p)
            located = None if _is_ghost(first) else first
            bad = self.grow_cavity(first, p)
        # 2. the cavity boundary: edges of exactly one bad triangle (Fix 2)
        boundary = cavity_boundary(bad)
        # 3. remove the bad triangles
        for t in bad:
            self.remove(t)
        # 4. connect p to every boundary edge (Fix 1: checked counter-clockwise)
        new = [self.new_triangle(a, b, i) for a, b in boundary]
        # at most two boundary edges touch the vertex at infinity, so a real new triangle exists
        self.last = next(t for t in new if not _is_ghost(t))
        return Step(i, p, located, bad, boundary, new, np.zeros((0, 3), dtype=np.int64), self.walked)

    def start(self, i: int, j: int) -> list[Triangle]:
        """Start-up with two points: two ghost triangles, one on each side of their line."""
        return [self.add((i, j, INFINITE)), self.add((j, i, INFINITE))]


# ----------------------------------------------------------------------------- the algorithm
def bowyer_watson(points, *, trace: list | None = None, locate: str = "scan",
                  order: str = "canonical", snapshots: bool = True) -> np.ndarray:
    """Delaunay triangulation by Bowyer-Watson: (m, 3) int64 counter-clockwise triangles.

    ``points`` is anything ``as_points`` accepts ((n, 2) numbers).  Triangles
    are input indices, each rotated to start at its smallest index, rows sorted.
    Duplicates are merged (triangles use the smallest index among equal points);
    all-collinear input and fewer than three distinct points give an empty
    (0, 3) array; NaN, infinity, a wrong shape or text raise ``ValueError``.

    ``trace``: a list; one ``Step`` per inserted point is appended to it
    (nothing when there is no triangle to build).
    ``snapshots``: with ``False``, each traced ``Step.triangles`` is left empty
    instead of holding a copy of the whole triangulation (the copy makes a traced
    run quadratic; counts of bad and new triangles need no copy).
    ``locate``: ``"scan"`` (default: test every triangle, as the tutorial does;
    quadratic time) or ``"walk"`` (walk to the point, then grow the cavity
    through neighbours: same result, much faster).
    ``order``: ``"canonical"`` (default: the result does not depend on the input
    order, even with cocircular ties) or ``"input"`` (see ``insertion_order``).

    >>> bowyer_watson([(0, 0), (2, 0), (1, 1), (1, 0)]).tolist()    # (1, 0) lies on the hull
    [[0, 3, 2], [1, 2, 3]]
    >>> bowyer_watson([(1e300, 0), (0, 1e300), (0, 0), (1e-300, 1e-300)]).tolist()
    [[0, 1, 3], [0, 3, 2], [1, 2, 3]]
    >>> bowyer_watson([(0, 0), (1, 1), (2, 2)]).shape
    (0, 3)
    >>> bowyer_watson([(0, 0), (1, float("nan")), (2, 0)])
    Traceback (most recent call last):
    ...
    ValueError: points[1] = [1.0, nan] is not finite (NaN or infinity)
    """
    pts = as_points(points)
    if trace is not None and not isinstance(trace, list):
        raise ValueError(f"trace must be a list (or None), got {type(trace).__name__}")
    if locate not in ("walk", "scan"):
        raise ValueError(f"locate must be 'walk' or 'scan', got {locate!r}")
    xy: list[Point] = [(x, y) for x, y in pts.tolist()]
    sequence = insertion_order(pts, order)
    mesh = _Triangulation(xy)
    empty = np.zeros((0, 3), dtype=np.int64)
    for rank, i in enumerate(sequence):
        if rank == 0:
            step = Step(i, xy[i], None, [], [], [], empty)
        elif rank == 1:
            step = Step(i, xy[i], None, [], [], mesh.start(sequence[0], i), empty)
        else:
            step = mesh.insert(i, locate)
        if trace is not None:
            trace.append(replace(step, triangles=mesh.real_triangles()) if snapshots else step)
    return mesh.real_triangles()


def recursive_bowyer_watson(points, *, locate: str = "walk", order: str = "canonical") -> np.ndarray:
    """The tutorial's recursive version (its section 12.1), with its mistakes fixed: same result.

    The tutorial's ``recursive_bowyer_watson(triangulation, points)`` pops the
    first point, inserts it and calls itself on the rest: one Python frame per
    inserted point, so the call stack is as deep as the input is long and a
    few hundred frames short of ``sys.getrecursionlimit()`` (1000 by default)
    is as far as it goes.  The insertion itself is ``bowyer_watson``'s.

    >>> recursive_bowyer_watson(TUTORIAL_POINTS).tolist() == bowyer_watson(TUTORIAL_POINTS).tolist()
    True
    >>> import sys
    >>> recursive_bowyer_watson(np.random.default_rng(0).random((sys.getrecursionlimit() + 10, 2)))
    Traceback (most recent call last):
    ...
    RecursionError: maximum recursion depth exceeded...
    """
    pts = as_points(points)
    if locate not in ("walk", "scan"):
        raise ValueError(f"locate must be 'walk' or 'scan', got {locate!r}")
    xy: list[Point] = [(x, y) for x, y in pts.tolist()]
    sequence = insertion_order(pts, order)
    mesh = _Triangulation(xy)

    def insert_rest(rest: list[int]) -> None:   # the tutorial's shape: pop one point, recurse on the rest
        if not rest:
            return
        mesh.insert(rest.pop(0), locate)
        insert_rest(rest)

    if len(sequence) >= 2:
        mesh.start(sequence[0], sequence[1])
        insert_rest(list(sequence[2:]))
    return mesh.real_triangles()


# ----------------------------------------------------------------------------- the dry run
def dry_run(points=TUTORIAL_POINTS, order: str = "input") -> str:
    """The step-by-step dry run as text (of the original tutorial's 4-point example, done right).

    By default the points are inserted in the given order, as in the tutorial;
    ``order="canonical"`` shows what ``bowyer_watson(points)`` does.

    >>> text = dry_run()
    >>> print(text.splitlines()[-1])
    Result: 3 triangles: (0, 1, 3), (0, 2, 1), (1, 2, 3)
    """
    steps: list[Step] = []
    result = bowyer_watson(points, trace=steps, order=order)
    xy = [tuple(p) for p in as_points(points).tolist()]
    lines = [
        f"Bowyer-Watson dry run on {len(xy)} points: "
        + ", ".join(f"{i}: {_format_point(p)}" for i, p in enumerate(xy)),
        "Triangles are point indices, counter-clockwise.  'inf' is the vertex at infinity:",
        "the ghost triangle (a, b, inf) covers the outside of hull edge b->a.",
        f"Insertion order ({'as given' if order == 'input' else 'canonical'}, duplicates dropped): "
        + (", ".join(str(s.index) for s in steps) or "none: no triangle is possible"),
    ]
    for k, s in enumerate(steps, start=1):
        lines.append("")
        lines.append(f"Step {k} (point {s.index}). {s}")
        if not s.bad:
            if s.new:
                lines.append("   ghost triangles: " + ", ".join(map(_format_triangle, s.new)))
            continue
        where = (f"triangle {_format_triangle(s.located)}" if s.located is not None
                 else "no triangle: the point is outside the hull, only ghost triangles contain it")
        lines.append(f"   lands in: {where}")
        lines.append("   bad triangles (circumcircle contains the point): "
                     + ", ".join(map(_format_triangle, s.bad)))
        lines.append("   cavity boundary (counter-clockwise): " + ", ".join(map(_format_edge, s.boundary)))
        lines.append("   new triangles: " + ", ".join(map(_format_triangle, s.new)))
        now = ", ".join(_format_triangle(tuple(t)) for t in s.triangles.tolist())
        lines.append("   triangulation now: " + (now or "no real triangle"))
    lines.append("")
    listed = ", ".join(_format_triangle(tuple(t)) for t in result.tolist())
    lines.append(f"Result: {_plural(len(result), 'triangle')}" + (f": {listed}" if listed else ""))
    return "\n".join(lines)
