"""Exact integer oracles for tests, written independently of reference_impl.

    from exact_oracle import exact, orient, incircle

Coordinates are scaled by one common power of two into Python integers, so every sign
below is exact; nothing here calls the library's predicates.
"""
from __future__ import annotations

import numpy as np


def exact(points) -> list[tuple[int, int]]:
    """Every coordinate times one common power of two, as Python integers."""
    ratios = [[float(v).as_integer_ratio() for v in p] for p in np.asarray(points, dtype=float).reshape(-1, 2)]
    den = max([d for r in ratios for _, d in r], default=1)
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def orient(a, b, c) -> int:
    """+1 when a, b, c turn counter-clockwise, -1 clockwise, 0 collinear."""
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def incircle(a, b, c, d) -> int:
    """+1 when d is strictly inside the circle through counter-clockwise a, b, c."""
    m = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    l2 = [x * x + y * y for x, y in m]
    det = (l2[0] * (m[1][0] * m[2][1] - m[2][0] * m[1][1])
           - l2[1] * (m[0][0] * m[2][1] - m[2][0] * m[0][1])
           + l2[2] * (m[0][0] * m[1][1] - m[1][0] * m[0][1]))
    return (det > 0) - (det < 0)


def canon(tris) -> set[tuple[int, int, int]]:
    """Triangles as a set, each rotated to start at its smallest index (orientation kept),
    so that two triangulations compare equal whatever the order of rows and rotations."""
    out = set()
    for t in np.asarray(tris).reshape(-1, 3).tolist():
        k = t.index(min(t))
        out.add(tuple(t[k:] + t[:k]))
    return out
