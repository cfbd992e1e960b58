"""Structures built on a Delaunay mesh: Voronoi cells, hulls, proximity graphs, empty circles,
clearance, constrained triangulations (``constrained``), polygons with holes (``polygon``), the
funnel (``funnel``) and navigation meshes (``navmesh``), edge flips, a dynamic network and the
spherical Delaunay triangulation.

Each may import ``reference_impl.exact``, ``reference_impl.mesh``, ``reference_impl.validate``
and the shared 2D helpers (``reference_impl.mesh.topology``); none imports the teaching code.
"""
