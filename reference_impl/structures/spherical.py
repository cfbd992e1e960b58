"""Spherical Delaunay triangulation of points on the sphere (longitude/latitude or directions).

    python -c "from reference_impl.structures.spherical import spherical_delaunay; print(spherical_delaunay([(0, 0), (90, 0), (180, 0), (0, 90), (0, -90)]))"

For points on a sphere, a triangle is spherical-Delaunay (its circumcircle on
the sphere is empty) exactly when the plane through its three points has no
point strictly on the cap side, that is when it is a facet of the 3D convex
hull.  So the triangulation is the convex hull of the unit vectors, and every
decision is an exact ``orient3d`` on the given doubles (the answer is exactly
the hull of the vectors as stored, not of some nearby rounding).

The hull is read off the ghost tetrahedra of ``Delaunay3D``'s kernel run on the
points plus the centre (inserted first).  With the centre present the
tetrahedra are cones from it, whose spheres are far from degenerate; without
it, every point set on a sphere is cospherical and every in-sphere test would
be a near-tie that needs exact arithmetic.  Adding the centre changes no hull
facet that has the centre strictly inside, which are the only ones kept:

* points all around the sphere (the centre strictly inside their hull): every
  hull facet is a triangle; ``covers_sphere`` is True and there are 2n - 4;
* points within a hemisphere (the centre not strictly inside): hull facets
  whose plane has the centre on or beyond their outer side are the "hole", not
  spherical triangles (their circumcap is the big one and holds the other
  points).  They are left out, so the triangles cover the spherical convex hull
  of the points, as a planar Delaunay triangulation covers the convex hull;
* all points on one great circle (or fewer than three distinct): no triangles.

Triangles are counter-clockwise seen from outside the sphere.  Duplicates are
merged (``index_map``), including the same place given with longitudes 360
degrees apart, or a pole given with any longitude: ``lonlat_to_xyz`` is exact
at multiples of 90 degrees and gives antipodes as exact negatives.

>>> sd = SphericalDelaunay([(0, 0), (90, 0), (180, 0), (270, 0), (0, 90), (0, -90)])
>>> len(sd.simplices), sd.covers_sphere
(8, True)
>>> len(spherical_delaunay([(0, 10), (20, 10), (10, 30), (10, 15)]))   # one hemisphere
3
"""
from __future__ import annotations

import numpy as np

from reference_impl.mesh.delaunay3d import Mesh, input_index_map, insertion_order_3d, representatives
from reference_impl.mesh.topology import triangle_neighbors
from reference_impl.validate import as_points
from reference_impl.exact.predicates3d import orient3d_batch
from reference_impl.exact.scaling import pow2_exponent

__all__ = ["SphericalDelaunay", "spherical_delaunay", "lonlat_to_xyz"]


def _cos_sin_degrees(deg: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """cos and sin of angles in degrees, exact at multiples of 90 and symmetric by quadrant."""
    r = np.fmod(deg, 360.0)                 # exact
    q = np.round(r / 90.0)
    a = np.radians(r - 90.0 * q)            # r - 90 q is exact, in [-45, 45] degrees
    c, s = np.cos(a), np.sin(a)
    quad = np.mod(q, 4).astype(np.int64)
    cos = np.choose(quad, [c, -s, -c, s])
    sin = np.choose(quad, [s, c, -s, -c])
    return cos + 0.0, sin + 0.0             # + 0.0 turns -0.0 into 0.0


def lonlat_to_xyz(lonlat) -> np.ndarray:
    """(n, 2) longitude, latitude in degrees -> (n, 3) unit vectors (x towards lon 0, lat 0;
    z towards the north pole).  Latitudes must be within [-90, 90].

    >>> lonlat_to_xyz([(0, 0), (90, 0), (180, 0), (123.4, 90), (-90, -90)]).tolist()
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]]
    """
    ll = as_points(lonlat, name="lonlat", dim=2)
    bad = np.flatnonzero(np.abs(ll[:, 1]) > 90.0)
    if len(bad):
        raise ValueError(f"latitude of point {bad[0]} is {ll[bad[0], 1]}, outside [-90, 90] degrees")
    clon, slon = _cos_sin_degrees(ll[:, 0])
    clat, slat = _cos_sin_degrees(ll[:, 1])
    return np.c_[clat * clon, clat * slon, slat] + 0.0


def _directions(points) -> np.ndarray:
    """(n, 2) lon/lat degrees or (n, 3) vectors -> (n, 3) unit vectors (validated)."""
    if isinstance(points, (str, bytes)):
        raise ValueError("points must be (n, 2) longitude/latitude or (n, 3) vectors, got text")
    try:
        shape = np.shape(points)
    except ValueError:
        shape = ()
    if len(shape) == 2 and shape[1] == 2:
        return lonlat_to_xyz(points)
    if len(shape) == 2 and shape[0] == 0:
        return np.zeros((0, 3))
    v = as_points(points, dim=3)
    m = np.abs(v).max(axis=1)
    zero = np.flatnonzero(m == 0)
    if len(zero):
        raise ValueError(f"points[{zero[0]}] is the zero vector: it has no direction")
    v = np.ldexp(v, -pow2_exponent(v, axis=1)[:, None])   # exact rescale: no overflow in the norm
    return v / np.linalg.norm(v, axis=1, keepdims=True) + 0.0


class SphericalDelaunay:
    """Delaunay triangulation on the unit sphere.

    ``points``: (n, 2) longitude/latitude in degrees, or (n, 3) vectors (only their
    direction counts: each is scaled to unit length).

    Attributes: ``xyz`` (the unit vectors used), ``simplices`` (m, 3) counter-clockwise
    seen from outside, ``neighbors`` (m, 3) (across the edge opposite vertex k, -1 on the
    boundary of a hemisphere set), ``index_map``, ``covers_sphere``, ``missing``.

    Known limitation: the triangles are the exact convex hull of the *rounded* unit
    vectors.  Points closer than about 1e-5 degrees to their neighbours (centimetres on
    the Earth) can round to a vector strictly inside the hull of the others; such a point
    cannot be a vertex, and it is listed in ``missing`` instead of being dropped silently.

    >>> SphericalDelaunay([(1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, -1, -1)]).simplices.shape
    (4, 3)
    """

    def __init__(self, points) -> None:
        self.xyz = _directions(points)
        n = len(self.xyz)
        order = insertion_order_3d(self.xyz)
        mesh = Mesh(np.vstack([np.zeros((1, 3)), self.xyz[order]]))   # the centre first
        dup = mesh.dup[1:n + 1]
        dup = np.where(dup > 0, dup - 1, -1)
        rep = representatives(dup, order)
        self._order, self._rep = order, rep
        if mesh.flat:
            self._tri = np.zeros((0, 3), dtype=np.int64)
            self._covers = False
        else:
            facets = mesh.extract()[3]
            hull = facets[(facets > 0).all(axis=1)]                    # not through the centre
            a, b, c = (self.xyz[order[hull[:, j] - 1]] for j in range(3))
            keep = orient3d_batch(a, b, c, np.zeros_like(a)) > 0       # centre strictly inside
            self._covers = bool(keep.all()) and len(hull) == len(facets)
            self._tri = rep[hull[keep] - 1]
        self._nbr = None

    @property
    def simplices(self) -> np.ndarray:
        """(m, 3) point indices of the spherical triangles, counter-clockwise from outside."""
        return self._tri

    @property
    def covers_sphere(self) -> bool:
        """True when the triangles cover the whole sphere (the centre is inside the hull)."""
        return self._covers

    @property
    def missing(self) -> np.ndarray:
        """Sorted indices of distinct points that are in no triangle (see the class note).

        Empty unless points nearly coincide, or the input is flat (one great circle).

        >>> SphericalDelaunay([(1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, -1, -1)]).missing.tolist()
        []
        """
        reps = np.unique(self._rep)
        return np.setdiff1d(reps, self._tri.ravel()) if len(self._tri) else reps

    @property
    def index_map(self) -> np.ndarray:
        """``index_map[i]``: the index point i was merged into (i itself unless a duplicate)."""
        return input_index_map(self._order, self._rep)

    @property
    def neighbors(self) -> np.ndarray:
        """(m, 3): the triangle across the edge opposite vertex k, -1 where there is none."""
        if self._nbr is None:
            self._nbr = triangle_neighbors(self._tri, len(self.xyz))
        return self._nbr

    def __repr__(self) -> str:
        return f"SphericalDelaunay(n={len(self.xyz)}, triangles={len(self._tri)})"


def spherical_delaunay(points) -> np.ndarray:
    """(m, 3) triangles of the Delaunay triangulation on the sphere, counter-clockwise from
    outside; ``points`` is (n, 2) longitude/latitude in degrees or (n, 3) vectors.

    >>> spherical_delaunay([(0, 0), (120, 0), (240, 0)]).shape   # one great circle
    (0, 3)
    """
    return SphericalDelaunay(points).simplices
