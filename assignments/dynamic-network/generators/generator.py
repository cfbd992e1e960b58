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

``solve(operations)`` is ``process(operations)`` below: the problem's adapter on
``reference_impl.DynamicNetwork`` (grader side only).

    python assignments/dynamic-network/generators/generator.py '{"kind": "ring", "r": 5}' 3

Example:
    >>> solve([["join", 0, 0], ["join", 1, 0], ["join", 1, 1], ["join", 0, 1], ["neighbors", 0]])
    [0, 1, 2, 3, [1, 3]]
"""

from __future__ import annotations

import importlib.util
import json
import math
import numbers
import random
import sys
from pathlib import Path
from typing import Any, Iterable, Sequence

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
    """The reference answers: ``process(operations)`` (ids, "ok"/"error", sorted lists, counts)."""
    return process(operations)


# ----------------------------------------------------------------------------- the problem's adapter
# JSON operations in, answers out, on ``reference_impl.DynamicNetwork`` (the library speaks arrays
# and objects; this adapter is the problem's).  Tests load it with ``load_problem("dynamic-network")
# .generator.process``.
def _number(v: Any, what: str) -> float:
    if isinstance(v, bool) or not isinstance(v, numbers.Real):
        raise ValueError(f"{what} must be a number, got {v!r}")
    try:
        f = float(v)
    except OverflowError:
        f = math.inf
    if not math.isfinite(f):
        raise ValueError(f"{what} must be finite, got {v!r}")
    return f


def process(operations: Iterable[Sequence[Any]]) -> list[Any]:
    """Run a list of network operations; return one answer per operation.

    Operations (JSON-native lists; the first element names the operation):

    ========================  =================================================================
    operation                 answer
    ========================  =================================================================
    ``["join", x, y]``        the new node's id (int): the number of joins before this one
    ``["fail", id]``          ``"ok"``; ``"error"`` if ``id`` never joined or already failed
    ``["neighbors", id]``     the sorted list of ids of the node's Delaunay neighbours among
                              the live nodes (see ``DynamicNetwork``); ``"error"`` if ``id``
                              never joined or has failed
    ``["count"]``             the number of live nodes (int)
    ========================  =================================================================

    Each operation is a list (or tuple); ``x``, ``y`` are finite numbers; ids are
    integers.  Anything else (an unknown
    operation, a wrong number of arguments, text or NaN coordinates) is malformed input
    and raises ``ValueError`` naming the operation's position.

    >>> process([["join", 0, 0], ["join", 1, 0], ["neighbors", 1], ["count"]])
    [0, 1, [0], 2]
    >>> process([["join", 0, 0], ["leave", 0]])
    Traceback (most recent call last):
    ...
    ValueError: operations[1]: unknown operation 'leave' (expected join, fail, neighbors, count)
    """
    from reference_impl import DynamicNetwork    # grader side only

    net = DynamicNetwork()
    answers: list[Any] = []
    arity = {"join": 3, "fail": 2, "neighbors": 2, "count": 1}
    for k, op in enumerate(operations):
        if not isinstance(op, (list, tuple)) or not op:
            raise ValueError(f"operations[{k}] must be a non-empty list, got {op!r}")
        name = op[0]
        if name not in arity:
            raise ValueError(f"operations[{k}]: unknown operation {name!r} "
                             "(expected join, fail, neighbors, count)")
        if len(op) != arity[name]:
            raise ValueError(f"operations[{k}]: {name!r} takes {arity[name] - 1} argument(s), "
                             f"got {list(op[1:])!r}")
        if name == "join":
            answers.append(net.join(_number(op[1], f"operations[{k}] x"),
                                    _number(op[2], f"operations[{k}] y")))
        elif name == "count":
            answers.append(len(net))
        else:
            node = op[1]
            if isinstance(node, bool) or not isinstance(node, numbers.Integral):
                raise ValueError(f"operations[{k}]: node id must be an integer, got {node!r}")
            try:
                if name == "fail":
                    net.fail(node)
                    answers.append("ok")
                else:
                    answers.append(net.neighbors(node))
            except ValueError:
                answers.append("error")
    return answers


if __name__ == "__main__":
    (ops,) = generate_args(json.loads(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    sys.stdout.write(f"{len(ops)}\n" + "".join(" ".join(map(str, op)) + "\n" for op in ops))
