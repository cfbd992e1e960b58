"""Seeded test generator for `closest-pair`: the point cases of `emst`, answered by the closest pair.

``generate(case, seed)`` is ``assignments/emst/generators/generator.py``'s (the Delaunay point kinds
plus clusters, near-ties, vertical lines, offsets); ``solve(points)`` is
``reference_impl.closest_pair`` (grader side only).

    python assignments/closest-pair/generators/generator.py '{"kind": "vertical", "n": 5}' 3

Example:
    >>> solve([[1, 1], [3, 2], [5, 1], [4, 4], [3, 2]])
    [1, 4]
"""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

_spec = importlib.util.spec_from_file_location(
    "_emst_point_cases", Path(__file__).resolve().parents[2] / "emst" / "generators" / "generator.py")
_cases = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_cases)
KINDS = _cases.KINDS
generate = _cases.generate


def solve(points: list[list[float]]) -> list[int]:
    """A closest pair ``[i, j]`` (exact; distance 0 when a point repeats)."""
    from reference_impl import closest_pair

    return list(closest_pair(points))


if __name__ == "__main__":
    pts = generate(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(pts)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in pts))
