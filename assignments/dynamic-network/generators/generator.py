"""Seeded test generator for `dynamic-network`: sequences of joins, failures and queries.

``generate_args(case, seed)`` returns ``[operations]`` (the entry function's one argument):

* ``ops``: the literal ``operations`` of the case;
* ``network``: the positions of a point case of ``emst`` (``points``: e.g. ``{kind: grid, w: 8}``;
  ``assignments/emst/generators/generator.py``) joined in order, and after each join, with the
  given probabilities: a ``neighbors`` query of a random id (``query``; dead or unknown ids too),
  a ``fail`` of a random live node (``fail``), a ``join`` at the position of an earlier node
  (``rejoin``: coincident nodes), a ``count`` (``count``); at the end every id is queried once
  (``final_queries``) in random order;
* ``ring``: ``k`` integer points exactly on a circle of radius ``r`` (on ``x^2 + y^2 = r^2``) and
  its centre: the centre is linked to all of them, then fails (the ring is cocircular: no
  diagonals), rejoins twice at the same spot, and one copy fails again.

``solve(operations)`` is ``reference_impl.structures.dynamic.process`` (grader side only).

    python assignments/dynamic-network/generators/generator.py '{"kind": "ring", "r": 5}' 3

Example:
    >>> solve([["join", 0, 0], ["join", 1, 0], ["join", 1, 1], ["join", 0, 1], ["neighbors", 0]])
    [0, 1, 2, 3, [1, 3]]
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
KINDS = ("ops", "network", "ring")


def _network(case: dict, seed: int) -> list:
    rng = random.Random(seed)
    pts = _cases.generate(dict(case.get("points", {"kind": "uniform", "n": 20})), seed)
    p_query, p_fail = float(case.get("query", 1.0)), float(case.get("fail", 0.3))
    p_rejoin, p_count = float(case.get("rejoin", 0.0)), float(case.get("count", 0.05))
    ops, pos, live = [], [], []
    for x, y in pts:
        ops.append(["join", x, y])
        pos.append((x, y))
        live.append(len(pos) - 1)
        if rng.random() < p_rejoin:
            x2, y2 = pos[rng.randrange(len(pos))]
            ops.append(["join", x2, y2])
            pos.append((x2, y2))
            live.append(len(pos) - 1)
        if rng.random() < p_fail and live:
            k = rng.randrange(len(live))
            live[k], live[-1] = live[-1], live[k]
            ops.append(["fail", live.pop()])
        if rng.random() < p_query:
            ops.append(["neighbors", rng.randrange(len(pos) + 1)])  # sometimes dead or not yet joined
        if rng.random() < p_count:
            ops.append(["count"])
    if case.get("final_queries", True):
        ids = list(range(len(pos)))
        rng.shuffle(ids)
        ops += [["neighbors", i] for i in ids] + [["fail", ids[0]] if ids else ["count"], ["count"]]
    return ops


def _ring(case: dict) -> list:
    r = int(case.get("r", 5))
    ring = [[float(x), float(y)] for x, y in _cases.generate({"kind": "cocircular", "r": r, "shuffle": False}, 0)]
    ops = [["join", x, y] for x, y in ring] + [["join", 0.0, 0.0]]
    c = len(ring)
    ops += [["neighbors", c], ["neighbors", 0], ["fail", c], ["fail", c]] + [["neighbors", i] for i in range(c)]
    ops += [["join", 0.0, 0.0], ["join", 0.0, 0.0], ["neighbors", c + 1], ["neighbors", 1], ["fail", c + 2],
            ["neighbors", c + 1], ["neighbors", c + 2], ["neighbors", 1], ["count"]]
    return ops


def generate_args(case: dict, seed: int) -> list:
    """``[operations]`` for one case; the same ``(case, seed)`` gives the same operations."""
    kind = case.get("kind")
    if kind == "ops":
        return [[list(op) for op in case["operations"]]]
    if kind == "network":
        return [_network(case, seed)]
    if kind == "ring":
        return [_ring(case)]
    raise ValueError(f"unknown case kind {kind!r}; expected one of {', '.join(KINDS)}")


def solve(operations: list) -> list:
    """The answers of ``reference_impl.structures.dynamic.process`` (ids, "ok"/"error", sorted lists, counts)."""
    from reference_impl.structures.dynamic import process

    return process(operations)


if __name__ == "__main__":
    (ops,) = generate_args(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(ops)}\n" + "".join(" ".join(map(str, op)) + "\n" for op in ops))
