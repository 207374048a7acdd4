"""Scripts written for scipy.spatial.Delaunay, run unchanged except for the import: each is run
once with scipy and once with cavity on the same random points (one Delaunay triangulation, so
the answers must agree), and on a grid, where Qhull's answer is not unique, checked on its own."""

import numpy as np
import pytest

pytest.importorskip("scipy.spatial")

INTERPOLATION = """
import numpy as np
from {module} import Delaunay

rng = np.random.default_rng(1)
points = rng.random((400, 3))
values = np.cos(points).sum(axis=1)
tri = Delaunay(points)
xi = rng.random((200, 3))
simplex = tri.find_simplex(xi)
X = tri.transform[simplex, :3]
Y = xi - tri.transform[simplex, 3]
b = np.einsum('ijk,ik->ij', X, Y)
bary = np.c_[b, 1 - b.sum(axis=1)]
result = np.einsum('ij,ij->i', values[tri.simplices[simplex]], bary)
result[simplex < 0] = np.nan
"""

NEIGHBOURS = """
import numpy as np
from {module} import Delaunay

points = np.random.default_rng(2).normal(size=(300, 3))
tri = Delaunay(points)
indptr, indices = tri.vertex_neighbor_vertices
result = [sorted(indices[indptr[k]:indptr[k + 1]].tolist()) for k in range(len(points))]
degree = np.diff(indptr)
edges = {{tuple(sorted((s[i], s[j]))) for s in tri.simplices.tolist()
         for i in range(4) for j in range(i + 1, 4)}}
result.append(len(edges) * 2 == indices.size == degree.sum())
"""

HULL = """
import numpy as np
from {module} import Delaunay

points = np.random.default_rng(3).random((500, 3))
tri = Delaunay(points)
hull_vertices = np.unique(tri.convex_hull)
on_hull = (tri.neighbors == -1).sum()
inside = tri.find_simplex(np.array([[0.5, 0.5, 0.5], [2.0, 0.0, 0.0]])) >= 0
result = (hull_vertices.tolist(), int(on_hull), len(tri.convex_hull), inside.tolist(),
          tri.min_bound.tolist(), tri.max_bound.tolist(), tri.npoints, tri.ndim)
"""

GRID_LOCATION = """
import numpy as np
from {module} import Delaunay

axis = np.arange(5.0)
grid = np.stack(np.meshgrid(axis, axis, axis, indexing='ij'), axis=-1).reshape(-1, 3)
tri = Delaunay(grid)
queries = np.vstack([grid, grid[(grid < 4).all(axis=1)] + 0.5, [[10.0, 0, 0]]])
simplex = tri.find_simplex(queries)
T = tri.transform[simplex]
c = np.einsum('ijk,ik->ij', T[:, :3], queries - T[:, 3])
bary = np.c_[c, 1 - c.sum(axis=1)]
result = (simplex, bary)
"""


def run(script, module):
    scope = {}
    exec(script.format(module=module), scope)
    return scope


def test_interpolation_script():
    a = run(INTERPOLATION, "scipy.spatial")["result"]
    b = run(INTERPOLATION, "cavity")["result"]
    assert np.array_equal(np.isnan(a), np.isnan(b)) and np.isnan(a).any()
    assert np.allclose(a[~np.isnan(a)], b[~np.isnan(b)], atol=1e-12)


def test_neighbour_script():
    a = run(NEIGHBOURS, "scipy.spatial")["result"]
    b = run(NEIGHBOURS, "cavity")["result"]
    assert a == b and bool(b[-1])


def test_hull_script():
    assert run(HULL, "scipy.spatial")["result"] == run(HULL, "cavity")["result"]


def test_grid_location_script():
    """Qhull's grid triangulation has flat simplices (NaN transforms); cavity's locates every
    lattice point and cell centre with finite barycentric coordinates in [0, 1]."""
    scope = run(GRID_LOCATION, "cavity")
    simplex, bary = scope["result"]
    assert (simplex[:-1] >= 0).all() and simplex[-1] == -1
    inside = bary[:-1]
    assert np.isfinite(inside).all()
    assert (inside > -1e-12).all() and (inside < 1 + 1e-12).all()
    tri, queries = scope["tri"], scope["queries"]
    rebuilt = np.einsum("ij,ijk->ik", inside, tri.points[tri.simplices[simplex[:-1]]])
    assert np.allclose(rebuilt, queries[:-1], atol=1e-12)
