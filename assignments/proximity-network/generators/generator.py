"""Seeded test generator for `proximity-network`: the point cases of `emst`, answered by the
Gabriel graph.

``generate(case, seed)`` is ``assignments/emst/generators/generator.py``'s (the Delaunay point kinds
plus clusters, near-ties, vertical lines, offsets), with one more kind, ``squares``: unit squares
in a row, where both diagonals have the two other corners on their diametral circle (the closed
disc rule leaves them out). ``solve(points)`` is ``reference_impl.gabriel_graph`` (grader side only).

    python assignments/proximity-network/generators/generator.py '{"kind": "squares", "n": 3}' 3

Example:
    >>> solve([[1, 1], [3, 2], [5, 1], [4, 4]])
    [[0, 1], [1, 2], [1, 3]]
"""

from __future__ import annotations

import importlib.util
import json
import random
import sys
from pathlib import Path

_spec = importlib.util.spec_from_file_location(
    "_emst_point_cases", Path(__file__).resolve().parents[2] / "emst" / "generators" / "generator.py")
_cases = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_cases)
KINDS = _cases.KINDS + ("squares",)


def generate(case: dict, seed: int) -> list[list[float]]:
    """Points for one case; the same ``(case, seed)`` gives the same points."""
    if case.get("kind") != "squares":
        return _cases.generate(case, seed)
    n = int(case.get("n", 4))  # squares of side 1, 3 apart: 4 corners each
    pts = [[3.0 * k + dx, dy] for k in range(n) for dx, dy in ((0, 0), (1, 0), (1, 1), (0, 1))]
    if case.get("shuffle", True):
        random.Random(seed).shuffle(pts)
    return pts


def solve(points: list[list[float]]) -> list[list[int]]:
    """The Gabriel graph: edges ``[i, j]``, ``i < j``, sorted; repeats merged into the smallest index."""
    from reference_impl import gabriel_graph

    return gabriel_graph(points).tolist() if len(points) >= 2 else []


if __name__ == "__main__":
    pts = generate(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(pts)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in pts))
