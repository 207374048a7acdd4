#!/usr/bin/python3
"""Using cavity from Python: the snippet of docs/api.md, run by ctest (python.quickstart)."""

import numpy as np

import cavity

# A degenerate input: a 5 x 5 x 5 grid, where every unit cube's 8 corners are cospherical.
axis = np.arange(5.0)
points = np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1).reshape(-1, 3)

tri = cavity.Delaunay(points, count=True)  # count: the instrumented engine fills tri.stats
print(tri)                                 # <cavity.Delaunay: 125 points, ... tetrahedra>

# scipy's attributes: simplices (positive volume by the right-hand rule, as TetGen and VTK),
# neighbors (-1 on the hull), convex_hull...
p = points[tri.simplices]
assert np.all(np.linalg.det(p[:, 1:] - p[:, :1]) > 0)
# orient3d follows Shewchuk's sign, the opposite of the volume: -1 everywhere, never 0 (flat).
assert np.all(cavity.orient3d(p[:, 0], p[:, 1], p[:, 2], p[:, 3]) == -1)
assert (tri.neighbors == -1).sum() == len(tri.convex_hull)

# Exact point location: a point on a face shared by several tetrahedra gets the lowest-numbered
# one holding it; transform gives its barycentric coordinates there.
x = np.array([[1.5, 2.0, 2.5]])
s = tri.find_simplex(x)
c = tri.transform[s[0], :3] @ (x[0] - tri.transform[s[0], 3])
weights = np.append(c, 1 - c.sum())
assert np.allclose(weights @ points[tri.simplices[s[0]]], x[0]) and np.all(weights >= -1e-12)
print("point", x[0], "in tetrahedron", s[0], "with barycentric coordinates", weights)

# ... and cavity's own: the exact validator and the work the run did.
assert tri.check()
print("tetrahedra created:", tri.stats["tets_created"],
      "| insphere calls settled by the static and semi-static filters:",
      tri.stats["stage_calls"]["insphere"]["static"], tri.stats["stage_calls"]["insphere"]["filter"],
      "| perturbations:", tri.stats["perturbations"])

# Bad input is a ValueError naming the row.
bad = points.copy()
bad[7, 1] = np.nan
try:
    cavity.Delaunay(bad)
except ValueError as error:
    print("ValueError:", error)  # points row 7 has a non-finite value (nan) in column 1
