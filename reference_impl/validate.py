"""Input validation shared by every public function: turn user input into an (n, d) float64 array.

Bad input raises ``ValueError`` with a message that names the problem (NaN,
infinity, wrong shape, text).  Negative zero is normalised to +0.0 so that
equal points are bit-for-bit equal.

>>> as_points([(0, 0), (1, 2)]).tolist()
[[0.0, 0.0], [1.0, 2.0]]
>>> as_points([(0, float("nan"))])
Traceback (most recent call last):
...
ValueError: points[0] = [0.0, nan] is not finite (NaN or infinity)
"""
from __future__ import annotations

import numbers

import numpy as np

__all__ = ["as_points", "as_point", "as_queries", "as_index_rows"]


def as_points(points, name: str = "points", dim: int = 2) -> np.ndarray:
    """Validate ``points`` and return a C-contiguous (n, dim) float64 array (a copy)."""
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
