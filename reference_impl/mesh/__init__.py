"""The mesh kernels: Delaunay triangulations in flat arrays, and the classes that own them.

- ``ordering``: the insertion order (BRIO rounds along a Hilbert curve).
- ``kernel``: the 2D Bowyer-Watson kernel on 8-int triangle records (numba).
- ``removal``: vertex removal from that mesh (numba).
- ``kernel3d``: the 3D kernel on tetrahedra (numba).
- ``delaunay`` (``Delaunay``) and ``delaunay3d`` (``Delaunay3D``): the public classes.

Imports only ``reference_impl.exact`` and ``reference_impl.validate``.
"""
