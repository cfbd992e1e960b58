"""The mesh kernels: Delaunay triangulations in flat arrays, and the classes that own them.

- ``ordering``: the insertion order (BRIO rounds along a Hilbert curve).
- ``kernel``: the 2D Bowyer-Watson kernel on 8-int triangle records (numba).
- ``removal``: vertex removal from that mesh (numba).
- ``kernel3d``: the 3D kernel on tetrahedra (numba).
- ``delaunay`` (``Delaunay``) and ``delaunay3d`` (``Delaunay3D``): the public classes.
- ``topology``: the helpers of the public 2D layout (``tri``/``nbr`` arrays): slots, edge flip,
  edge search, neighbours, each edge once, vertex adjacency (CSR), union-find.

Imports only ``reference_impl.exact`` and ``reference_impl.validate``.
"""
