"""reference_impl: the course's robust geometry library (answer key and teaching code).

>>> from reference_impl import Delaunay, orient2d
>>> orient2d((0, 0), (1, 0), (0, 1))
1
"""
from .delaunay import Delaunay
from .predicates import incircle, orient2d

__all__ = ["Delaunay", "orient2d", "incircle"]
