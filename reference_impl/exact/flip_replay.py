"""Fast acceptance of an edge-flip answer: replay the flips' topology, then decide all their
predicates at once (stdlib only; numpy optional, through ``bulk``).

The ``edge-flip`` checker names this module in ``LIBRARY`` (with ``verify`` and ``bulk``) and
calls :func:`accepts` before its own one-flip-at-a-time replay: when :func:`accepts` returns True,
that replay would have accepted too (same final triangulation, every flip legal at its turn); when
it returns False, nothing is concluded and the checker's integer replay decides and writes the
message. Two passes, one verdict, as in ``verify.check_delaunay``.

Why it agrees (so that nobody has to trust the timings): which triangles share a flipped edge
depends only on the earlier flips, never on the predicates' signs, as long as every earlier flip was
applied. So the topology is replayed alone, on a map ``u * n + v -> w`` (directed edge to the third
vertex of its counter-clockwise triangle), stopping with False at the first flip that is not an
interior edge or that would make the map inconsistent (a repeated vertex, a new edge ``c d``
already present). The map then holds a set of triangles, each directed edge in at most one, before
and after every flip, and equals the map of the checker's replay step by step. Each flip's in-circle
test ``incircle(a, b, c, d)`` and the two orientations ``orient(c, d, b)``, ``orient(d, c, a)`` are
then decided together: with numpy by Shewchuk's filter (``bulk``) and Python integers where it
cannot decide, or one at a time with ``verify``'s filtered predicates. All positive: every flip was
legal at its turn, and the final triangles (the same set as the checker's replay, in another order)
go to ``verify.check_delaunay``, whose verdict does not depend on the order.

On a long answer (``COMPILED_MIN_FLIPS`` flips or more, numpy there) the topology is replayed by
``flip_kernel.replay`` instead, the same replay compiled with numba (about a microsecond a flip in
Python, a few hundredths of one compiled). It is imported only then, and only when it can be: an
exported Kattis validator, without ``reference_impl`` or numba, keeps the Python replay. Both
replays refuse the same answers (``tests/exact/test_flip_kernel.py``), and a refusal concludes
nothing either way: the checker's own replay decides and writes the message.

Run the doctest: ``python -m pytest --doctest-modules reference_impl/exact/flip_replay.py``

>>> import importlib.util
>>> from grader.judging.checker_runtime import library_file
>>> def load(name):
...     spec = importlib.util.spec_from_file_location(name, library_file(name))
...     mod = importlib.util.module_from_spec(spec); spec.loader.exec_module(mod); return mod
>>> verify, bulk = load("verify"), load("bulk")
>>> pts, tris = [[0, 0], [4, 0], [4, 1], [0, 3]], [[0, 1, 3], [1, 2, 3]]
>>> accepts(pts, tris, [[1, 3]], verify, bulk), accepts(pts, tris, [], verify, bulk)
(True, False)
"""
from __future__ import annotations

from itertools import chain

#: answers with at least this many flips replay their topology in compiled code (``flip_kernel``)
COMPILED_MIN_FLIPS = 512
_KERNEL: list = []          # [flip_kernel module or None], filled on first use


def compiled_kernel():
    """``reference_impl.exact.flip_kernel`` (numba), or None: in an exported Kattis validator
    (``STANDALONE``, bound by the loader: it runs only its own embedded code), or where it cannot be
    imported (no numba)."""
    if not _KERNEL:
        flip_kernel = None
        if not globals().get("STANDALONE", False):
            try:
                from reference_impl.exact import flip_kernel
            except (ImportError, OSError, RuntimeError):  # no numba, or no cache numba can use
                flip_kernel = None
        _KERNEL.append(flip_kernel)
    return _KERNEL[0]


def topology(n: int, triangles: list, flips: list) -> tuple[list, list, dict] | None:
    """Replay the flips' topology only: ``(cs, ds, map)`` with each flip's two opposite vertices
    (``c`` left of ``a -> b``, ``d`` right of it) and the final map ``u * n + v -> w``; ``None``
    when a flip is not an interior edge of the current triangles, or anything is inconsistent.
    Indices are in 0..n-1 (the caller checks), duplicated points already mapped to one index.

    >>> topology(4, [[0, 1, 3], [1, 2, 3]], [[1, 3]])[:2]
    ([0], [2])
    """
    opp: dict = {}
    for a, b, c in triangles:
        if a == b or b == c or c == a:
            return None
        opp[a * n + b], opp[b * n + c], opp[c * n + a] = c, a, b
    if len(opp) != 3 * len(triangles):
        return None  # a directed edge in two triangles
    pop = opp.pop
    cs, ds = [], []
    add_c, add_d = cs.append, ds.append
    for a, b in flips:
        an, bn = a * n, b * n
        c, d = pop(an + b, None), pop(bn + a, None)
        if c is None or d is None or c == d:
            return None
        cn, dn = c * n, d * n
        if cn + d in opp or dn + c in opp:
            return None
        # triangles (a, b, c), (b, a, d) -> (c, a, d), (d, b, c); (c, a), (a, d), (d, b), (b, c) stay edges
        opp[cn + a], opp[an + d], opp[dn + c] = d, c, a
        opp[dn + b], opp[bn + c], opp[cn + d] = c, d, b
        add_c(c)
        add_d(d)
    return cs, ds, opp


def _all_positive_bulk(bulk, verify, P, F, arrays, A, B, C, D) -> bool:
    """Are incircle(a, b, c, d), orient(c, d, b) and orient(d, c, a) positive for every flip
    (numpy filters, integers where they cannot decide)? ``arrays``: the point list's cached numpy
    copies (``verify._prepared``; the coordinates are added when missing)."""
    np = bulk.np
    if "x" not in arrays:
        xy = np.array(F, dtype=np.float64).reshape(-1, 2)
        arrays.update(x=xy[:, 0].copy(), y=xy[:, 1].copy())
    X, Y = arrays["x"], arrays["y"]
    a, b, c, d = (np.asarray(v, dtype=np.int64) for v in (A, B, C, D))
    checks = ((bulk.incircle(X[a], Y[a], X[b], Y[b], X[c], Y[c], X[d], Y[d]),
               lambda k: verify.incircle_exact(P[A[k]], P[B[k]], P[C[k]], P[D[k]])),
              (bulk.orient2d(X[c], Y[c], X[d], Y[d], X[b], Y[b]),
               lambda k: verify.orient_exact(P[C[k]], P[D[k]], P[B[k]])),
              (bulk.orient2d(X[d], Y[d], X[c], Y[c], X[a], Y[a]),
               lambda k: verify.orient_exact(P[D[k]], P[C[k]], P[A[k]])))
    for signs, exact in checks:
        if (signs < 0).any():
            return False
        if any(exact(k) <= 0 for k in np.flatnonzero(signs == 0).tolist()):
            return False
    return True


def accepts(points, triangles, flips, verify, bulk=None) -> bool:
    """True only when the checker's replay accepts: every flip legal at its turn and the final
    triangulation Delaunay (False: nothing concluded, ask the checker's replay why).

    ``verify`` and ``bulk`` are the library modules ``reference_impl/exact/verify.py`` and
    ``bulk.py`` (passed in: library modules are bound into a checker, not imported).
    """
    n = len(points)
    if n == 0 or type(flips) is not list:
        return False
    if flips:
        if set(map(type, flips)) != {list} or set(map(len, flips)) != {2}:
            return False
        flat = list(chain.from_iterable(flips))
        if set(map(type, flat)) != {int} or min(flat) < 0 or max(flat) >= n:
            return False
    else:
        flat = []
    P, rep, orient, incircle = verify.indexed_predicates(points)
    rows = verify._int_rows(triangles, n, 3)
    if rows is None:
        return False
    if rep != list(range(n)):               # duplicated points: work on each one's first index
        flat = [rep[v] for v in flat]
        flips = [flat[k:k + 2] for k in range(0, len(flat), 2)]
        rows = [[rep[a], rep[b], rep[c]] for a, b, c in rows]
    numpy = bulk is not None and bulk.AVAILABLE and n < 1 << 31
    kernel = compiled_kernel() if numpy and len(flips) >= COMPILED_MIN_FLIPS else None
    if kernel is not None:
        np = bulk.np
        pairs = np.array(flat, dtype=np.int64).reshape(-1, 2)
        ok, cs, ds, final = kernel.replay(n, np.fromiter(chain.from_iterable(rows), np.int64, 3 * len(rows)).reshape(-1, 3),
                                          pairs)
        if not ok:
            return False
        A, B = pairs[:, 0], pairs[:, 1]      # final: an int64 array, which check_delaunay's numpy pass takes as is
    else:
        replayed = topology(n, rows, flips)
        if replayed is None:
            return False
        cs, ds, opp = replayed
        A, B = flat[0::2], flat[1::2]
        final = [[key // n, key % n, w] for key, w in opp.items() if key // n < key % n and key // n < w]
    _, F, _, _, _, _, tame, arrays = verify._prepared(points, "2d", verify._prepare_2d)
    if numpy and tame and len(flips) >= 16:
        if not _all_positive_bulk(bulk, verify, P, F, arrays, A, B, cs, ds):
            return False
    elif not all(incircle(a, b, c, d) > 0 and orient(c, d, b) > 0 and orient(d, c, a) > 0
                 for a, b, c, d in zip(*(v if type(v) is list else v.tolist() for v in (A, B, cs, ds)))):
        return False
    return verify.check_delaunay(points, final, bulk)[0]
