"""reference_impl: the course's robust geometry library (answer key and teaching code).

Every geometric decision uses exact predicates, so degenerate input (grids,
cocircular or collinear points, duplicates, coordinates from 1e-300 to 1e300)
gives exact answers.  Points are (n, 2) float64 arrays; triangles are (m, 3)
counter-clockwise point indices, as in scipy.spatial and Delaunator.

The public names below load on first use (importing the package compiles and
imports nothing else); ``reference_impl/README.md`` maps the packages behind them.

Return values (one convention for the whole library).  Results are numpy
arrays, or NamedTuples of plain values or arrays (still tuples: they unpack and
compare like the tuples they replaced):

* point indices and index rows: int64 arrays, e.g. ``Delaunay.simplices`` (m, 3),
  edges (k, 2) with i < j and rows sorted, ``convex_hull`` (h,);
* ``closest_pair`` -> ``Pair(i, j)``; ``largest_empty_circle`` ->
  ``Circle(x, y, r)``; ``max_clearance`` -> a float;
* ``voronoi`` -> a list with one (k, 2) float64 polygon per point (cells differ in size);
* queries are shaped like their input, as in scipy: ``find_simplex`` of an
  (..., 2) array gives an (...) array, of one point a Python int (0-d);
* adjacency as scipy has it: ``Delaunay.vertex_neighbor_vertices`` is
  ``(indptr, indices)`` in CSR form, ``Delaunay.vertex_to_simplex`` an (n,) array
  (-1: in no triangle); both lazy, cached, and refreshed after ``insert``/``remove``.

Not yet converted (kept for their callers): ``lawson_flip`` returns ``(triangles,
flips)`` and ``flip_to_delaunay`` the flips as a list of ``(a, b)`` tuples (tests and
the edge-flip problem compare them with lists); ``mesh_quality`` returns a dict;
``NavMesh.shortest_path`` a list of ``(x, y)`` tuples or None (the navmesh problem's form).

Derived structures compose as in d3-delaunay: ``voronoi``, ``euclidean_mst``,
``closest_pair``, ``gabriel_graph``, ``relative_neighborhood_graph``,
``largest_empty_circle``, ``max_clearance`` and ``convex_hull`` take the points or a
``Delaunay`` of them, and then reuse its mesh (no second triangulation):

>>> from reference_impl import Delaunay, closest_pair, largest_empty_circle
>>> d = Delaunay([(0, 0), (4, 0), (0, 3), (5, 5), (4, 1)])
>>> d.euclidean_mst().tolist(), closest_pair(d), largest_empty_circle(d).r > 0
([[0, 1], [0, 2], [1, 4], [3, 4]], Pair(i=1, j=4), True)

>>> from reference_impl import Delaunay, bowyer_watson, orient2d
>>> orient2d((0, 0), (1, 0), (0, 1))
1
>>> Delaunay([(0, 0), (1, 0), (0, 1), (1, 1)]).simplices.shape
(2, 3)
>>> bowyer_watson([(1, 1), (3, 2), (5, 1), (4, 4)]).tolist()
[[0, 1, 3], [0, 2, 1], [1, 2, 3]]
"""
from __future__ import annotations

import importlib
from typing import Any

_WHERE = {  # public name -> the module that defines it
    "orient2d": "exact.predicates", "incircle": "exact.predicates",
    "orient3d": "exact.predicates3d", "insphere": "exact.predicates3d",
    "Delaunay": "mesh.delaunay",
    "Delaunay3D": "mesh.delaunay3d", "delaunay_3d": "mesh.delaunay3d",
    "bowyer_watson": "teaching.bowyer_watson", "Step": "teaching.bowyer_watson",
    "dry_run": "teaching.bowyer_watson",
    "voronoi": "structures.voronoi",
    "convex_hull": "structures.hull",
    "euclidean_mst": "structures.proximity", "closest_pair": "structures.proximity", "Pair": "structures.proximity",
    "gabriel_graph": "structures.proximity", "relative_neighborhood_graph": "structures.proximity",
    "largest_empty_circle": "structures.empty_circle", "Circle": "structures.empty_circle",
    "max_clearance": "structures.clearance",
    "ConstrainedDelaunay": "structures.constrained", "constrained_delaunay": "structures.constrained",
    "NavMesh": "structures.navmesh", "PolygonTriangulation": "structures.polygon",
    "funnel": "structures.funnel", "polygon_triangulation": "structures.polygon",
    "shortest_path": "structures.navmesh",
    "validate_triangulation": "structures.flips", "lawson_flip": "structures.flips",
    "flip_to_delaunay": "structures.flips", "apply_flips": "structures.flips",
    "laplacian_smooth": "structures.flips", "mesh_quality": "structures.flips",
    "DynamicNetwork": "structures.dynamic",
    "SphericalDelaunay": "structures.spherical", "spherical_delaunay": "structures.spherical",
    "lonlat_to_xyz": "structures.spherical",
}

__all__ = list(_WHERE)


def __getattr__(name: str) -> Any:
    """Load a public name from its module on first use (PEP 562)."""
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module 'reference_impl' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"reference_impl.{module}"), name)
    globals()[name] = value  # later look-ups skip this function
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
