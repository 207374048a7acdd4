"""Exact, instrumented 3D Delaunay triangulation.

Bowyer-Watson with exact predicates and symbolic perturbation: never a flat or inverted
tetrahedron, whatever the input. ``cavity.Delaunay`` has the interface of
``scipy.spatial.Delaunay`` for 3-D points; ``cavity.cdt`` builds the constrained Delaunay
tetrahedralization of polygons (a closed surface mesh, say); ``cavity.orient3d``,
``cavity.insphere`` and ``cavity.orient4d`` are the exact predicates over arrays of queries.
"""

from ._cavity import (
    CDT,
    ValidationError,
    __version__,
    cdt,
    insphere,
    orient3d,
    orient4d,
)
from ._delaunay import Delaunay

__all__ = [
    "CDT",
    "Delaunay",
    "ValidationError",
    "__version__",
    "cdt",
    "insphere",
    "orient3d",
    "orient4d",
]
