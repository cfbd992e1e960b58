"""Named point sets for tests: random, and the degenerate families every algorithm must survive.

    from tests.pointsets import DEGENERATE, degenerate_sets
    for name, pts in degenerate_sets(): ...

Each generator is deterministic (seeded) and returns an (n, 2) float64 array.
The degenerate families (see the foundation issue): integer grids straight and
rotated, points on a circle with and without its centre, collinear runs,
duplicates, 1e-300 and 1e300 scales, offsets of 1e9, clusters of very different
sizes, nearly collinear hulls.
"""
from __future__ import annotations

import numpy as np


def uniform(n: int, seed: int = 0) -> np.ndarray:
    return np.random.default_rng(seed).random((n, 2))


def grid(k: int, m: int | None = None) -> np.ndarray:
    m = k if m is None else m
    return np.array([(i, j) for i in range(k) for j in range(m)], dtype=float)


def rotated_grid(k: int, angle: float = 0.5) -> np.ndarray:
    g = grid(k)
    c, s = np.cos(angle), np.sin(angle)
    return g @ np.array([[c, s], [-s, c]])


def circle(n: int, centre: bool = False, radius: float = 1.0) -> np.ndarray:
    t = 2 * np.pi * np.arange(n) / n
    pts = np.c_[radius * np.cos(t), radius * np.sin(t)]
    return np.vstack([pts, [[0.0, 0.0]]]) if centre else pts


def integer_circle() -> np.ndarray:
    """The 12 integer points on x^2 + y^2 = 25, plus the centre: exactly cocircular."""
    pts = {(x, y) for x in range(-5, 6) for y in range(-5, 6) if x * x + y * y == 25}
    return np.array(sorted(pts) + [(0, 0)], dtype=float)


def collinear(n: int, seed: int = 0) -> np.ndarray:
    """Exactly collinear points on y = 2x + 1 (dyadic x, so no rounding)."""
    t = np.random.default_rng(seed).integers(-1000, 1000, n) / 1024.0
    return np.c_[t, 2 * t + 1]


def with_duplicates(n: int, seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    base = rng.random((n, 2))
    return np.vstack([base, base[rng.integers(0, n, n // 2)]])


def clusters(seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return np.vstack([rng.random((60, 2)) * 1e-6, rng.random((60, 2)) * 1e6 - 5e5,
                      rng.random((60, 2)) + 3.0])


def nearly_collinear_hull(n: int = 40) -> np.ndarray:
    """Points on a line nudged by one ulp, plus a few points far off the line."""
    x = np.linspace(0.0, 1.0, n)
    y = x * 0.3
    y[1::2] = np.nextafter(y[1::2], np.inf)
    return np.vstack([np.c_[x, y], [[0.5, 2.0], [0.2, -1.5]]])


def degenerate_sets() -> list[tuple[str, np.ndarray]]:
    """(name, points) for every degenerate family; small enough for O(n^2) code."""
    return [
        ("grid", grid(12)),
        ("grid-rect", grid(3, 17)),
        ("rotated-grid", rotated_grid(10)),
        ("circle", circle(40)),
        ("circle+centre", circle(40, centre=True)),
        ("integer-circle", integer_circle()),
        ("collinear+1", np.vstack([collinear(20), [[0.3, 5.0]]])),
        ("duplicates", with_duplicates(60)),
        ("grid-duplicates", np.vstack([grid(6), grid(6)])),
        ("tiny-1e-300", uniform(80, 1) * 1e-300),
        ("huge-1e300", uniform(80, 2) * 1e300),
        ("grid-1e-300", grid(7) * 1e-300),
        ("grid-1e300", grid(7) * 1e300),
        ("offset-1e9", uniform(80, 3) + 1e9),
        ("clusters", clusters()),
        ("nearly-collinear-hull", nearly_collinear_hull()),
        ("tutorial", np.array([(1, 1), (3, 2), (5, 1), (4, 4)], dtype=float)),
    ]


def flat_sets() -> list[tuple[str, np.ndarray]]:
    """Inputs with no triangle at all: collinear, or fewer than 3 distinct points."""
    return [
        ("empty", np.zeros((0, 2))),
        ("one", np.array([[1.0, 2.0]])),
        ("two", np.array([[0.0, 0.0], [1.0, 1.0]])),
        ("collinear", collinear(15)),
        ("vertical", np.c_[np.zeros(9), np.arange(9.0)]),
        ("tutorial-collinear", np.array([(0, 0), (1, 1), (2, 2)], dtype=float)),
        ("tutorial-duplicates", np.array([(1, 1), (1, 1), (2, 2), (3, 3)], dtype=float)),
        ("all-same", np.ones((5, 2))),
    ]
