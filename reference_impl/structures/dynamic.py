"""Dynamic Delaunay network: nodes join and fail, and each node talks to its Delaunay neighbours.

This is the answer key of the ``dynamic-network`` problem (the tutorial's system-design
exercise 20.2): a wireless or peer-to-peer network where every node keeps links to its
Delaunay neighbours, nodes arrive and crash, and the links must be repaired locally
instead of recomputed for the whole network.  ``DynamicNetwork`` wraps the fast
``Delaunay`` (exact predicates): a join is one Bowyer-Watson insertion, a failure one
vertex removal (the star of the node is deleted and its hole re-triangulated, in time
proportional to the node's degree), a neighbour query a walk around the node.

What the original Bowyer-Watson tutorial claims wrongly here:

* Delaunay neighbours are **not "the nearest three nodes"**.  A node has on average
  fewer than six Delaunay neighbours in the plane, but any number is possible (the
  centre of a ring of k nodes has k); the nearest node is always among them, but the
  second or third nearest need not be, while a far node can be one.  Below, node 2 is
  the second nearest of node 0 and is not its neighbour (node 1 lies between them),
  while node 3, five times farther away than node 1, is a neighbour.
* The Delaunay graph is **not a minimal network**: it is planar with up to 3n - 6
  edges and contains many cycles.  The Euclidean minimum spanning tree (n - 1 edges, the
  cheapest network that connects everything) is a *subgraph* of it, which is why the
  Delaunay graph is the right place to search for the EMST, not the EMST itself.

>>> net = DynamicNetwork()
>>> [net.join(x, y) for x, y in [(0, 0), (1, 0), (2, 0), (0, 5)]]
[0, 1, 2, 3]
>>> net.neighbors(0)            # nearest three would be 1, 2, 3: node 2 is not a neighbour
[1, 3]
>>> len(net.links()), len(net) - 1      # Delaunay links vs the n - 1 of a spanning tree
(5, 3)
>>> net.fail(1); net.neighbors(0)      # the hole is repaired: 0 and 2 are now linked
[2, 3]

The problem's adapter (JSON operations in, answers out: ``process(operations)``) is not
library code: it lives with the problem, in ``assignments/dynamic-network/generators/generator.py``.
"""
from __future__ import annotations

import numbers

import numpy as np

from reference_impl.mesh.delaunay import Delaunay

__all__ = ["DynamicNetwork"]


class DynamicNetwork:
    """A set of nodes in the plane under joins and failures, linked by their Delaunay graph.

    Node ids are the join order, starting at 0; an id is never reused (a node that
    fails and comes back joins again under a new id).

    Neighbours (``neighbors(node)``, sorted ids): the live nodes joined to ``node`` in the
    *Delaunay graph* of the live positions: u and v are neighbours when some circle through
    both has every other live position strictly outside; equivalently, their Voronoi cells
    share an edge of positive length.  This graph is unique.  In general position it is
    the edge set of the Delaunay triangulation; when four or more nodes are cocircular
    with no node inside, the triangulation must add diagonals that are ties (any of them
    would do), and these are *not* links: the four corners of a square have 4 links, not 5.
    So answers never depend on how an implementation breaks ties.  Special cases:

    * all positions on one line (or fewer than three): each node's neighbours are the
      one or two nodes next to it along the line (two nodes: each other; one node: none);
    * several live nodes at the same position count as one Delaunay vertex: each of them
      has that vertex's neighbours (every live node at each neighbouring position), and
      nodes at the same position are also neighbours of one another (distance 0).

    Cost: ``join`` is one point location (a walk from the last change: a few steps when
    consecutive joins are near each other, about sqrt(n) for random positions) and one
    Bowyer-Watson insertion; ``fail`` and ``neighbors`` are proportional to the node's
    degree (about 6 on average); none of them rebuilds the triangulation.  ``fail`` and ``neighbors`` raise ``ValueError`` for an id
    that never joined or has failed.

    >>> net = DynamicNetwork()
    >>> a, b, c = net.join(0, 0), net.join(1, 0), net.join(0, 1)
    >>> net.neighbors(a), net.join(0, 0), net.neighbors(a)
    ([1, 2], 3, [1, 2, 3])
    """

    def __init__(self) -> None:
        self._d = Delaunay(np.zeros((0, 2)))
        self._alive: list[bool] = []
        self._pos: list[tuple[float, float]] = []              # position of every node
        self._count = 0
        self._at: dict[tuple[float, float], list[int]] = {}   # live ids at each position
        self._shared = 0            # live nodes that share their position with another

    def __len__(self) -> int:
        """Number of live nodes."""
        return self._count

    @property
    def delaunay(self) -> Delaunay:
        """The underlying triangulation (point i is node i; failed nodes are removed)."""
        return self._d

    def join(self, x: float, y: float) -> int:
        """Add a node at (x, y); return its id."""
        node = self._d.insert((x, y))          # validates: finite numbers
        px, py = self._d.points[node]
        self._pos.append((float(px), float(py)))
        self._alive.append(True)
        self._count += 1
        group = self._at.setdefault(self._pos[node], [])
        group.append(node)
        if len(group) > 1:
            self._shared += 2 if len(group) == 2 else 1
        return node

    def fail(self, node: int) -> None:
        """Remove a live node; its neighbours are re-linked."""
        node = self._check(node)
        self._d.remove(node)
        self._alive[node] = False
        self._count -= 1
        key = self._key(node)
        group = self._at[key]
        group.remove(node)
        if group:
            self._shared -= 2 if len(group) == 1 else 1
        else:
            del self._at[key]

    def neighbors(self, node: int) -> list[int]:
        """Sorted ids of the Delaunay neighbours of a live node (see the class docstring)."""
        node = self._check(node)
        reps = self._d.vertex_neighbors(node, strict=True).tolist()
        if not self._shared:
            return reps                         # one node per position: ids are the vertices
        out = [j for r in reps for j in self._at[self._key(r)]]
        out.extend(j for j in self._at[self._key(node)] if j != node)
        return sorted(out)

    def links(self) -> list[tuple[int, int]]:
        """Every link (i, j), i < j, sorted: the whole Delaunay graph (O(n) neighbour queries)."""
        return sorted((i, j) for i in self.nodes() for j in self.neighbors(i) if i < j)

    def nodes(self) -> list[int]:
        """Ids of the live nodes, increasing."""
        return [i for i, a in enumerate(self._alive) if a]

    def _key(self, node: int) -> tuple[float, float]:
        return self._pos[node]

    def _check(self, node) -> int:
        if isinstance(node, bool) or not isinstance(node, numbers.Integral):
            raise ValueError(f"node id must be an integer, got {node!r}")
        node = int(node)
        if not 0 <= node < len(self._alive):
            raise ValueError(f"node {node} never joined (ids so far: 0..{len(self._alive) - 1})")
        if not self._alive[node]:
            raise ValueError(f"node {node} has failed")
        return node
