"""reference_impl: the course's robust geometry library (answer key and teaching code).

Note: ``reference_impl.voronoi`` is the function (the module is
``importlib.import_module("reference_impl.voronoi")``), as with scipy's names.

Every geometric decision uses exact predicates, so degenerate input (grids,
cocircular or collinear points, duplicates, coordinates from 1e-300 to 1e300)
gives exact answers.  Points are (n, 2) float64 arrays; triangles are (m, 3)
counter-clockwise point indices, as in scipy.spatial and Delaunator.

>>> from reference_impl import Delaunay, bowyer_watson, orient2d
>>> orient2d((0, 0), (1, 0), (0, 1))
1
>>> Delaunay([(0, 0), (1, 0), (0, 1), (1, 1)]).simplices.shape
(2, 3)
>>> bowyer_watson([(1, 1), (3, 2), (5, 1), (4, 4)]).tolist()
[[0, 1, 3], [0, 2, 1], [1, 2, 3]]
"""
from ._jitcache import purge_stale_cache

purge_stale_cache()

from .bowyer_watson import Step, bowyer_watson, dry_run  # noqa: E402
from .clearance import max_clearance  # noqa: E402
from .constrained import ConstrainedDelaunay, constrained_delaunay  # noqa: E402
from .delaunay import Delaunay  # noqa: E402
from .delaunay3d import Delaunay3D, delaunay_3d  # noqa: E402
from .dynamic import DynamicNetwork  # noqa: E402
from .empty_circle import largest_empty_circle  # noqa: E402
from .flips import (apply_flips, flip_to_delaunay, laplacian_smooth, lawson_flip,  # noqa: E402
                    mesh_quality, validate_triangulation)
from .hull import convex_hull  # noqa: E402
from .navmesh import NavMesh, PolygonTriangulation, funnel, polygon_triangulation, shortest_path  # noqa: E402
from .predicates import incircle, orient2d  # noqa: E402
from .predicates3d import insphere, orient3d  # noqa: E402
from .proximity import (closest_pair, euclidean_mst, gabriel_graph,  # noqa: E402
                        relative_neighborhood_graph)
from .spherical import SphericalDelaunay, lonlat_to_xyz, spherical_delaunay  # noqa: E402
from .voronoi import voronoi  # noqa: E402

__all__ = [
    "Delaunay", "bowyer_watson", "Step", "dry_run", "orient2d", "incircle",
    "ConstrainedDelaunay", "constrained_delaunay",
    "NavMesh", "PolygonTriangulation", "funnel", "polygon_triangulation", "shortest_path",
    "convex_hull", "voronoi", "largest_empty_circle", "max_clearance",
    "orient3d", "insphere", "Delaunay3D", "delaunay_3d",
    "SphericalDelaunay", "spherical_delaunay", "lonlat_to_xyz", "DynamicNetwork",
    "euclidean_mst", "closest_pair", "gabriel_graph", "relative_neighborhood_graph",
    "validate_triangulation", "lawson_flip", "flip_to_delaunay", "apply_flips",
    "laplacian_smooth", "mesh_quality",
]
