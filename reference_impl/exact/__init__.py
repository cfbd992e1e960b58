"""Exact arithmetic: the predicates every geometric decision goes through, and the checkers.

- ``expansion``: Shewchuk's floating-point expansions (two_sum, two_product, ...,
  compress, accumulate, the sign of an expansion, the float filter ``certain_sign``), numba.
- ``scaling``: scaling by powers of two (exact), numba and numpy.
- ``predicates``: ``orient2d`` and ``incircle``, adaptive and exact for any finite doubles.
- ``predicates3d`` with ``stages3d``: ``orient3d`` and ``insphere``, the same way.
- ``distance``: exact comparisons of squared distances and dot products, and the exact
  sort of edges by length (the proximity graphs' arithmetic).
- ``verify``: exact checkers in Python integers (stdlib only: the judge's checkers load it).
- ``free_space``: exact point, segment and path tests in a polygon with holes (stdlib only).
- ``flip_replay`` with ``flip_kernel``: the ``edge-flip`` checker's fast pass (stdlib only) and
  its optional compiled replay of the flips' topology (numba).

Nothing here imports the mesh or the structures built on it; the Python entry points
(``orient2d``, ``orient3d``, ...) validate their input with ``reference_impl.validate``.
"""
