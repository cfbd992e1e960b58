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

__all__ = ["as_points", "as_point"]


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
