"""Exhaustive small inputs: every configuration of a few lattice points, up to symmetry.

The ``exhaustive`` group of every problem and the first inputs ``python -m grader stress`` tries
come from here. A *configuration* is a multiset of points of a tiny lattice (3 x 3 in 2D,
2 x 2 x 2 in 3D), one per orbit of the lattice's symmetries (8 in 2D, 48 in 3D), smallest first.
Each configuration is used twice (:func:`variants`): as its canonical representative, and
mirrored in the diagonal (so vertical lines become horizontal ones and the reverse), each in an
order that is not monotone, so a shortcut that sorts by x alone, trusts the first three points or
assumes an orientation meets both cases. ``cases_for(problem)`` turns them into the problem's generator cases (the case kinds
the generators already know: explicit ``points``, ``box``, ``start``/``goal``, rooms, operations).

    python -m grader.smallcases PROBLEM            # print the group's cases (YAML lines)
    python -m grader.smallcases --write [PROBLEM]  # rewrite them in course.yaml (between markers)
    python -m grader.smallcases --check            # exit 1 when a course.yaml is stale

Example:
    >>> [len(c) for c in lattice_configs(max_n=2, repeats=False)]
    [1, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2]
    >>> cases_for("closest-pair")[0]
    {'kind': 'points', 'points': [[0, 0], [0, 0]], 'shuffle': False}
"""
from __future__ import annotations

import argparse
import itertools
import sys
from pathlib import Path
from typing import Any, Iterable, Sequence

Point = tuple[int, ...]
BEGIN, END = "# BEGIN GENERATED: exhaustive", "# END GENERATED: exhaustive"


def _symmetries_2d(size: int) -> list:
    m = size - 1
    return [lambda p, f=f: f(*p) for f in (
        lambda x, y: (x, y), lambda x, y: (m - x, y), lambda x, y: (x, m - y), lambda x, y: (m - x, m - y),
        lambda x, y: (y, x), lambda x, y: (m - y, x), lambda x, y: (y, m - x), lambda x, y: (m - y, m - x))]


def _symmetries_3d() -> list:
    out = []
    for perm in itertools.permutations(range(3)):
        for flips in itertools.product((0, 1), repeat=3):
            out.append(lambda p, perm=perm, flips=flips: tuple(abs(flips[i] - p[perm[i]]) for i in range(3)))
    return out


def _canonical(config: Sequence[Point], symmetries: list) -> tuple[Point, ...]:
    return min(tuple(sorted(s(p) for p in config)) for s in symmetries)


def lattice_configs(dim: int = 2, size: int = 3, max_n: int = 5, repeats: bool = True,
                    max_repeat_n: int = 3) -> list[tuple[Point, ...]]:
    """One multiset of lattice points per orbit of the lattice's symmetries, by size then
    lexicographically: every set of 1..``max_n`` distinct points, and (``repeats``) every
    multiset of 2..``max_repeat_n`` points with a repeat."""
    lattice = list(itertools.product(range(size), repeat=dim))
    symmetries = _symmetries_2d(size) if dim == 2 else _symmetries_3d()
    found: set[tuple[Point, ...]] = set()
    for n in range(1, max(max_n, max_repeat_n if repeats else 0) + 1):
        combos: Iterable = itertools.combinations(lattice, n) if n <= max_n else ()
        if repeats and n <= max_repeat_n:
            combos = itertools.chain(combos, (c for c in itertools.combinations_with_replacement(lattice, n)
                                              if len(set(c)) < n))
        for c in combos:
            found.add(_canonical(c, symmetries))
    return sorted(found, key=lambda c: (len(c), c))


def _interleave(seq: Sequence) -> list:
    return list(seq[::2]) + list(seq[1::2])


def variants(config: Sequence[Point]) -> list[list[list[int]]]:
    """The orders a configuration is tested in: its points in sorted order with every second one
    moved to the end (a line is not given monotonically: 0, 2, 4, 1, 3), then mirrored in the
    diagonal (x and y swapped: a vertical line becomes horizontal) in the same scheme from the
    reversed order; one order for a single point."""
    first = [list(p) for p in _interleave(config)]
    if len(config) < 2:
        return [first]
    second = [list(p[::-1]) for p in _interleave(config[::-1])]
    return [first] if second == first else [first, second]


def point_lists(dim: int = 2, min_n: int = 1, **kw: Any) -> list[list[list[int]]]:
    """Every tested point list: each configuration of :func:`lattice_configs` in each of its
    :func:`variants`, smallest first."""
    return [v for c in lattice_configs(dim, **kw) if len(c) >= min_n for v in variants(c)]


def _collinear(points: Sequence[Sequence[int]]) -> bool:
    a = points[0]
    return all((b[0] - a[0]) * (c[1] - a[1]) == (b[1] - a[1]) * (c[0] - a[0]) for b in points for c in points)


def _points(pts: list) -> dict:
    return {"kind": "points", "points": pts, "shuffle": False}


#: start and goal of ``obstacle-clearance``, cycled over the configurations: a gap, outside the
#: lattice on both sides, two lattice points (obstacles or not), the same point twice.
CLEARANCE_ENDS = ([[0.5, 0.5], [1.5, 1.5]], [[-1, 1], [3, 1]], [[0, 0], [2, 2]], [[1, 1], [1, 1]],
                  [[0, 1], [2, 1]])
#: the boxes of ``voronoi``: the lattice itself (sites on the box's edges and corners) or wider.
VORONOI_BOXES = ([0, 0, 2, 2], [-1, -1, 3, 3], [-0.5, 0, 4, 2])


def _rooms() -> list[dict]:
    """Small ``navmesh`` rooms: a 4 x 4 square and an L-shaped room, each ring in both
    orientations, with no hole, a square hole, a triangle, or both; start and goal on boundary
    vertices and walls, on hole vertices and walls, inside a hole, outside, in the free space."""
    square = [[0, 0], [4, 0], [4, 4], [0, 4]]
    ell = [[0, 0], [4, 0], [4, 2], [2, 2], [2, 4], [0, 4]]
    hole_sq = [[1, 1], [2, 1], [2, 2], [1, 2]]
    hole_tri = [[3, 3], [3.5, 3], [3, 3.5]]
    hole_ell = [[1, 0.5], [2, 0.5], [2, 1.5], [1, 1.5]]
    spots = {"vertex": [0, 0], "wall": [2, 0], "free": [3, 1], "free2": [0.5, 3], "hole_vertex": [2, 2],
             "hole_wall": [1.5, 1], "in_hole": [1.5, 1.5], "outside": [5, 2], "far": [3.5, 3.5]}
    ell_spots = {**spots, "hole_vertex": [2, 1.5], "hole_wall": [1.5, 0.5], "in_hole": [1.5, 1],
                 "far": [1, 3], "outside": [3, 3]}
    pairs = [("free", "free2"), ("vertex", "far"), ("wall", "free2"), ("hole_vertex", "free2"),
             ("hole_wall", "far"), ("in_hole", "free"), ("free", "outside"), ("outside", "outside"),
             ("vertex", "vertex"), ("hole_wall", "hole_wall"), ("in_hole", "in_hole"), ("wall", "hole_vertex")]
    cases = []
    for boundary, holesets, where in ((square, ([], [hole_sq], [hole_sq, hole_tri]), spots),
                                      (ell, ([], [hole_ell]), ell_spots)):
        for holes in holesets:
            for flip in (False, True):
                b = boundary[::-1] if flip else boundary
                hs = [h if flip else h[::-1] for h in holes]    # holes in the other orientation
                for s, g in pairs:
                    cases.append({"kind": "room", "boundary": b, "holes": hs, "start": where[s], "goal": where[g]})
    return cases


def _network_batches(per_test: int = 12) -> list[dict]:
    """``dynamic-network`` operations: each configuration joined in order, every node queried, the
    count, one node failed, its former neighbours queried, then the rest failed; many
    configurations per test (the format allows it)."""
    ops_all, batch, next_id = [], [], 0
    configs = point_lists(max_n=5)
    for k, pts in enumerate(configs):
        ids = list(range(next_id, next_id + len(pts)))
        next_id += len(pts)
        batch += [["join", float(x), float(y)] for x, y in pts]
        batch += [["neighbors", i] for i in ids] + [["count"]]
        victim = ids[k % len(ids)]
        batch += [["fail", victim], ["neighbors", victim]] + [["neighbors", i] for i in ids if i != victim]
        batch += [["fail", i] for i in ids if i != victim] + [["count"]]
        if (k + 1) % per_test == 0 or k == len(configs) - 1:
            ops_all.append({"kind": "ops", "operations": batch})
            batch, next_id = [], 0
    return ops_all


def cases_for(problem: str) -> list[dict]:
    """The ``exhaustive`` group's generator cases of ``problem``."""
    if problem in ("delaunay", "bowyer-watson-timed", "emst", "proximity-network"):
        return [_points(p) for p in point_lists()]
    if problem == "closest-pair":
        return [_points(p) for p in point_lists(min_n=2)]
    if problem == "largest-empty-circle":
        return [_points(p) for p in point_lists(min_n=3) if not _collinear(p)]
    if problem == "delaunay-3d":
        return [_points(p) for p in point_lists(dim=3, size=2, max_n=8, max_repeat_n=3)]
    if problem == "edge-flip":
        return [{**_points(p), "start": "sweep"} for p in point_lists()]
    if problem == "voronoi":
        return [{**_points(p), "box": VORONOI_BOXES[k % len(VORONOI_BOXES)]} for k, p in enumerate(point_lists())]
    if problem == "obstacle-clearance":
        out = []
        for k, p in enumerate(point_lists()):
            start, goal = CLEARANCE_ENDS[k % len(CLEARANCE_ENDS)]
            out.append({**_points(p), "start": start, "goal": goal})
        return out
    if problem == "navmesh":
        return _rooms()
    if problem == "dynamic-network":
        return _network_batches()
    raise ValueError(f"no exhaustive cases for problem {problem!r}")


def _flow(value: Any) -> str:
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k}: {_flow(v)}" for k, v in value.items()) + "}"
    if isinstance(value, list):
        return "[" + ", ".join(_flow(v) for v in value) + "]"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return value
    return repr(value)


def yaml_lines(problem: str, indent: int = 6) -> list[str]:
    """The group's cases as YAML flow lines (one case a line)."""
    return [" " * indent + "- " + _flow(c) for c in cases_for(problem)]


def rewrite(course_yaml: Path, problem: str) -> str:
    """``course_yaml``'s text with the lines between the markers replaced by the cases."""
    lines = course_yaml.read_text().splitlines()
    try:
        b = next(i for i, s in enumerate(lines) if s.strip() == BEGIN)
        e = next(i for i, s in enumerate(lines) if s.strip() == END)
    except StopIteration:
        raise ValueError(f"{course_yaml}: no '{BEGIN}' / '{END}' lines") from None
    indent = len(lines[b]) - len(lines[b].lstrip())
    return "\n".join(lines[:b + 1] + yaml_lines(problem, indent) + lines[e:]) + "\n"


def main(argv: list[str] | None = None) -> int:
    """The command line (see the module docstring)."""
    from .package import problems_root

    ap = argparse.ArgumentParser(prog="python -m grader.smallcases", description=__doc__.splitlines()[0])
    ap.add_argument("problems", nargs="*")
    ap.add_argument("--write", action="store_true", help="rewrite the cases in course.yaml")
    ap.add_argument("--check", action="store_true", help="exit 1 when a course.yaml is stale")
    a = ap.parse_args(argv)
    root = problems_root()
    ids = a.problems or sorted(d.name for d in root.iterdir() if (d / "course.yaml").is_file())
    stale = []
    for pid in ids:
        f = root / pid / "course.yaml"
        if not (a.write or a.check):
            print("\n".join(yaml_lines(pid)))
            continue
        new = rewrite(f, pid)
        if new != f.read_text():
            stale.append(pid)
            if a.write:
                f.write_text(new)
    if a.check and stale:
        print(f"stale exhaustive cases in: {', '.join(stale)} (run python -m grader.smallcases --write)",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
