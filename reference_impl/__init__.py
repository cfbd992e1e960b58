"""reference_impl: the course's robust geometry library (answer key and teaching code).

Every geometric decision uses exact predicates, so degenerate input (grids,
cocircular or collinear points, duplicates, coordinates from 1e-300 to 1e300)
gives exact answers.  Points are (n, 2) float64 arrays; triangles are (m, 3)
counter-clockwise point indices, as in scipy.spatial and Delaunator.

The public names below load on first use (importing the package compiles and
imports nothing else); ``reference_impl/README.md`` maps the packages behind them.

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
    "euclidean_mst": "structures.proximity", "closest_pair": "structures.proximity",
    "gabriel_graph": "structures.proximity", "relative_neighborhood_graph": "structures.proximity",
    "largest_empty_circle": "structures.empty_circle",
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
