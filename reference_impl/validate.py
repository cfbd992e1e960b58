"""Input validation shared by every public function: turn user input into float64 (or index) arrays.

Bad input raises ``ValueError`` with a message that names the problem (NaN,
infinity, wrong shape, text).  Negative zero is normalised to +0.0 so that
equal points are bit-for-bit equal.

- ``as_points`` / ``as_point``: (n, d) point arrays and single points;
- ``as_xy`` / ``as_xyz``: one point as a tuple of floats (the Python predicates);
- ``as_point_rows``: several (k, d) arrays with the same k (batch predicates);
- ``as_index_rows``: rows of point indices (triangles, segments, flips);
- ``as_bbox``: a box (xmin, ymin, xmax, ymax);  ``as_ring``: a polygon ring;
- ``as_rings``: many rings at once (a polygon and its holes).

(``exact/verify.py`` and ``exact/free_space.py`` keep their own checks: they are stdlib only.)

>>> as_points([(0, 0), (1, 2)]).tolist()
[[0.0, 0.0], [1.0, 2.0]]
>>> as_points([(0, float("nan"))])
Traceback (most recent call last):
...
ValueError: points[0] = [0.0, nan] is not finite (NaN or infinity)
"""
from __future__ import annotations

import math
import numbers
from typing import Sequence

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["as_points", "as_point", "as_queries", "as_xy", "as_xyz", "as_point_rows", "as_index_rows", "as_bbox",
           "as_ring", "as_rings"]


def as_points(points, name: str = "points", dim: int = 2) -> np.ndarray:
    """Validate ``points`` and return a C-contiguous (n, dim) float64 array (a copy)."""
    if type(points) is np.ndarray and points.dtype == np.float64 and points.ndim == 2 \
            and points.shape[1] == dim and points.size:
        # the common case, cheaply (a few us count at 100 points): copy, check, normalise -0.0
        arr = np.array(points, order="C")
        if np.isfinite(arr).all():
            arr += 0.0
            return arr
    if isinstance(points, (str, bytes)):
        raise ValueError(f"{name} must be a sequence of {dim}-D points, got text {points[:40]!r}")
    try:
        raw = np.asarray(points)
    except (ValueError, TypeError) as exc:  # ragged nested lists
        raise ValueError(f"{name} must be an (n, {dim}) array of numbers: {exc}") from None
    if raw.dtype.kind in "USV":
        raise ValueError(f"{name} must contain numbers, got text such as {raw.ravel()[0]!r}")
    if raw.dtype.kind == "c":
        raise ValueError(f"{name} must contain real numbers, got complex values")
    if raw.dtype.kind == "O":
        for v in raw.ravel():
            if not isinstance(v, numbers.Real) or isinstance(v, bool):
                raise ValueError(f"{name} must contain real numbers, got {type(v).__name__} {v!r}")
    if raw.size == 0:
        if raw.ndim == 2 and raw.shape[1] not in (0, dim):
            raise ValueError(f"{name} must have shape (n, {dim}), got {raw.shape}")
        return np.zeros((0, dim), dtype=np.float64)
    if raw.ndim != 2 or raw.shape[1] != dim:
        raise ValueError(f"{name} must have shape (n, {dim}), got {raw.shape}")
    try:
        arr = np.array(raw, dtype=np.float64, order="C")
    except (ValueError, TypeError, OverflowError) as exc:
        raise ValueError(f"{name} must contain real numbers: {exc}") from None
    finite = np.isfinite(arr).all(axis=1)
    if not finite.all():
        i = int(np.flatnonzero(~finite)[0])
        raise ValueError(f"{name}[{i}] = {arr[i].tolist()} is not finite (NaN or infinity)")
    arr += 0.0  # -0.0 -> +0.0
    return arr


def as_point(p, name: str = "point", dim: int = 2) -> np.ndarray:
    """Validate one point and return it as a float64 array of length ``dim``.

    >>> as_point((1, 2)).tolist()
    [1.0, 2.0]
    """
    return as_points([p] if np.ndim(p) == 1 else p, name=name, dim=dim).reshape(dim)


def as_queries(p, dim: int) -> tuple[np.ndarray, tuple[int, ...]]:
    """Validate queries shaped (..., dim): return them as a (k, dim) array and the shape
    ``(...)`` of the answer (``()`` for one point).  Used by ``find_simplex`` in 2D and 3D.

    >>> q, shape = as_queries([[(0, 0), (1, 2)]], 2)
    >>> q.shape, shape
    ((2, 2), (1, 2))
    """
    try:
        shape = None if isinstance(p, (str, bytes)) else np.shape(p)
    except ValueError:   # ragged input: as_points names the problem
        shape = None
    if shape is not None and len(shape) == 1 and shape[0] > 0:
        return as_points([p], name="p", dim=dim), ()
    if shape is not None and len(shape) > 2 and shape[-1] == dim:
        return as_points(np.reshape(np.asarray(p), (-1, dim)), name="p", dim=dim), shape[:-1]
    qs = as_points(p, name="p", dim=dim)
    return qs, (len(qs),)


def as_xy(p: ArrayLike, name: str = "point") -> tuple[float, float]:
    """One 2D point as a pair of finite floats (``-0.0`` kept: the predicates do not care).

    >>> as_xy((1, 2))
    (1.0, 2.0)
    >>> as_xy("ab", "a")
    Traceback (most recent call last):
    ...
    ValueError: a must be a pair of numbers, got 'ab'
    """
    try:
        x, y = p
        x, y = float(x), float(y)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a pair of numbers, got {p!r}") from None
    if not (math.isfinite(x) and math.isfinite(y)):
        raise ValueError(f"{name} = {p!r} is not finite (NaN or infinity)")
    return x, y


def as_xyz(p: ArrayLike, name: str = "point") -> tuple[float, float, float]:
    """One 3D point as a triple of finite floats.

    >>> as_xyz((1, 2, 3))
    (1.0, 2.0, 3.0)
    """
    if isinstance(p, (str, bytes)) or np.ndim(p) != 1:
        raise ValueError(f"{name} must be three numbers, got {p!r}")
    q = as_points([p], name=name, dim=3)[0]
    return float(q[0]), float(q[1]), float(q[2])


def as_point_rows(arrays: Sequence, names: Sequence[str], dim: int = 3) -> list[np.ndarray]:
    """Validate several (k, dim) arrays (a single point counts as k = 1) with the same k.

    >>> [a.tolist() for a in as_point_rows(([0, 0, 1], [[1, 2, 3]]), ("a", "b"))]
    [[[0.0, 0.0, 1.0]], [[1.0, 2.0, 3.0]]]
    """
    out = [as_points(np.atleast_2d(x) if np.ndim(x) == 1 else x, name=nm, dim=dim)
           for x, nm in zip(arrays, names)]
    k = len(out[0])
    for x, nm in zip(out, names):
        if len(x) != k:
            raise ValueError(f"{nm} has {len(x)} points but {names[0]} has {k}")
    return out


def as_index_rows(rows, n: int, width: int, name: str, allow_integral_floats: bool = False) -> np.ndarray:
    """Validate rows of point indices (triangles, segments, flips): an (m, width) int64 array.

    Every index must lie in 0..n-1.  Integer dtypes and Python ints are accepted; floats
    only when ``allow_integral_floats`` and every value is a whole number (JSON input).

    >>> as_index_rows([(0, 1), (1, 2)], 3, 2, "segments").tolist()
    [[0, 1], [1, 2]]
    >>> as_index_rows([(0, 3)], 3, 2, "segments")
    Traceback (most recent call last):
    ...
    ValueError: segments[0] = [0, 3] has an index outside 0..2
    """
    kind = f"an (m, {width}) array of point indices"
    if isinstance(rows, (str, bytes)):
        raise ValueError(f"{name} must be {kind}, got text {rows[:40]!r}")
    try:
        raw = np.asarray(rows)
    except (ValueError, TypeError) as exc:
        raise ValueError(f"{name} must be {kind}: {exc}") from None
    if raw.size == 0:
        return np.zeros((0, width), dtype=np.int64)
    if raw.ndim != 2 or raw.shape[1] != width:
        raise ValueError(f"{name} must have shape (m, {width}), got {raw.shape}")
    if raw.dtype.kind == "O" and all(isinstance(v, (int, np.integer)) and not isinstance(v, bool)
                                     for v in raw.ravel()):
        raw = raw.astype(np.int64)
    if (allow_integral_floats and raw.dtype.kind == "f" and np.isfinite(raw).all()
            and (raw == np.round(raw)).all()):
        raw = raw.astype(np.int64)
    if raw.dtype.kind not in "iu":
        raise ValueError(f"{name} must contain integer point indices, got dtype {raw.dtype}")
    idx = raw.astype(np.int64)
    bad = np.flatnonzero(((idx < 0) | (idx >= n)).any(axis=1))
    if len(bad):
        raise ValueError(f"{name}[{bad[0]}] = {idx[bad[0]].tolist()} has an index outside 0..{n - 1}")
    return idx


def as_bbox(bbox: ArrayLike) -> np.ndarray:
    """Validate a box ``(xmin, ymin, xmax, ymax)`` and return it as a float64 array.

    >>> as_bbox((0, 0, 2, 1)).tolist()
    [0.0, 0.0, 2.0, 1.0]
    >>> as_bbox((0, 0, 0, 1))
    Traceback (most recent call last):
    ...
    ValueError: bbox must have xmin < xmax and ymin < ymax, got (0.0, 0.0, 0.0, 1.0)
    """
    if isinstance(bbox, (str, bytes)):
        raise ValueError(f"bbox must be 4 numbers (xmin, ymin, xmax, ymax), got text {bbox!r}")
    try:
        box = np.asarray(bbox, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"bbox must be 4 numbers (xmin, ymin, xmax, ymax), got {bbox!r}") from None
    if box.shape != (4,):
        raise ValueError(f"bbox must be 4 numbers (xmin, ymin, xmax, ymax), got shape {box.shape}")
    if not np.isfinite(box).all():
        raise ValueError(f"bbox must be finite, got {tuple(box.tolist())}")
    if not (box[0] < box[2] and box[1] < box[3]):
        raise ValueError(f"bbox must have xmin < xmax and ymin < ymax, got {tuple(box.tolist())}")
    return box + 0.0


def as_ring(ring: ArrayLike, name: str) -> np.ndarray:
    """Validated (k, 2) polygon ring without repeated consecutive vertices or a closing copy
    of the first; at least 3 vertices.

    >>> as_ring([(0, 0), (1, 0), (1, 0), (0, 1), (0, 0)], "boundary").tolist()
    [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
    """
    pts = as_points(ring, name=name)
    if len(pts):
        keep = np.ones(len(pts), dtype=bool)
        keep[1:] = (pts[1:] != pts[:-1]).any(axis=1)
        pts = pts[keep]
        if len(pts) > 1 and (pts[0] == pts[-1]).all():
            pts = pts[:-1]
    if len(pts) < 3:
        raise ValueError(f"{name} needs at least 3 distinct vertices, got {len(pts)}")
    return pts


def as_rings(rings: Sequence[ArrayLike], names: Sequence[str]) -> tuple[np.ndarray, np.ndarray]:
    """``as_ring`` of every ring (``names[i]`` naming ring i), concatenated: the (n, 2) float64
    vertices, ring after ring, and the number of vertices of each ring.

    Same answers and same errors (the first bad ring's) as ``as_ring`` ring by ring.  Rings
    given as clean numeric (k, 2) arrays are checked together in a few vectorised steps,
    which is what keeps a polygon with thousands of small holes cheap (``as_ring`` costs
    some 20 us per call); any other ring, or one that needs cleaning, goes through
    ``as_ring``.

    >>> pts, sizes = as_rings([np.array([(0, 0), (4, 0), (0, 4)]), [(1, 1), (1, 1), (2, 1), (1, 2)]],
    ...                       ["boundary", "holes[0]"])
    >>> pts.tolist(), sizes.tolist()
    ([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [1.0, 1.0], [2.0, 1.0], [1.0, 2.0]], [3, 3])
    """
    if len(rings) == 0:
        return np.zeros((0, 2)), np.zeros(0, dtype=np.int64)
    fast = [i for i, r in enumerate(rings) if isinstance(r, np.ndarray) and r.dtype.kind in "fiu"
            and r.ndim == 2 and r.shape[0] >= 3 and r.shape[1] == 2]
    clean = np.zeros(len(rings), dtype=bool)
    if fast:
        arr = np.concatenate([rings[i] for i in fast], dtype=np.float64)
        size = np.array([len(rings[i]) for i in fast])
        first = np.concatenate([[0], np.cumsum(size)[:-1]])
        last = first + size - 1
        x, y = arr[:, 0], arr[:, 1]                                 # (per column: 3x faster
        bad_row = ~(np.isfinite(x) & np.isfinite(y))                #  than .all(axis=1))
        bad_row[1:] |= (x[1:] == x[:-1]) & (y[1:] == y[:-1])        # a repeated vertex ...
        bad_row[first] = (((x[first] == x[last]) & (y[first] == y[last]))
                          | ~(np.isfinite(x[first]) & np.isfinite(y[first])))
        ok = np.add.reduceat(bad_row, first) == 0                   # ... or a closing copy
        clean[np.asarray(fast)[ok]] = True
    out = []
    for i, r in enumerate(rings):
        if clean[i]:
            continue
        out.append((i, as_ring(r, names[i])))                      # raises for the first bad ring
    if not out:
        arr += 0.0                                                   # -0.0 -> +0.0
        return arr, size
    pieces = [None] * len(rings)
    for i, a in out:
        pieces[i] = a
    for j, i in enumerate(fast):
        if clean[i]:
            pieces[i] = arr[first[j]:last[j] + 1]
    sizes = np.array([len(a) for a in pieces])
    pts = np.concatenate(pieces) + 0.0
    return pts, sizes
