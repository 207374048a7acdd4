"""The same triangulation as scipy.spatial.Delaunay where Qhull's is unique (random points)."""

import numpy as np
import pytest

import cavity
from conftest import assert_well_formed, sorted_rows

spatial = pytest.importorskip("scipy.spatial")


@pytest.mark.parametrize("n, seed", [(50, 1), (1000, 2), (5000, 3)])
def test_same_tetrahedra_as_scipy(n, seed):
    points = np.random.default_rng(seed).random((n, 3))
    ours = cavity.Delaunay(points)
    theirs = spatial.Delaunay(points)
    assert sorted_rows(ours.simplices) == sorted_rows(theirs.simplices)
    assert sorted_rows(ours.convex_hull) == sorted_rows(theirs.convex_hull)


def test_same_neighbor_relation_as_scipy():
    points = np.random.default_rng(4).normal(size=(800, 3))
    ours = cavity.Delaunay(points)
    theirs = spatial.Delaunay(points)

    def relation(d):
        key = [tuple(sorted(t)) for t in d.simplices.tolist()]
        out = set()
        for t, row in enumerate(d.neighbors.tolist()):
            for i, u in enumerate(row):
                opposite = int(d.simplices[t, i])
                out.add((key[t], opposite, key[u] if u >= 0 else None))
        return out

    assert relation(ours) == relation(theirs)


def test_vertex_to_simplex_agrees_with_scipy_on_which_points_are_vertices():
    points = np.random.default_rng(5).random((500, 3))
    ours = cavity.Delaunay(points)
    theirs = spatial.Delaunay(points)
    assert np.array_equal(ours.vertex_to_simplex >= 0, theirs.vertex_to_simplex >= 0)


def test_on_a_grid_cavity_has_no_flat_tetrahedron():
    axis = np.arange(5.0)
    grid = np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1).reshape(-1, 3)
    d = cavity.Delaunay(grid)
    assert_well_formed(d)
    assert d.check()
