"""Shared helpers for the cavity Python tests (the module comes from PYTHONPATH: ctest sets it to
the build's python/ directory)."""

import numpy as np
import pytest

import cavity


def sorted_rows(simplices):
    """The rows of an (m, k) index array, each sorted, as a set of tuples."""
    return set(map(tuple, np.sort(np.asarray(simplices), axis=1).tolist()))


def assert_well_formed(d):
    """Everything scipy users rely on, checked against the definitions."""
    p = d.points
    s = d.simplices
    assert s.ndim == 2 and s.shape[1] == 4
    # Never a flat or inverted tetrahedron: positive volume by the right-hand rule (TetGen's and
    # VTK's convention), which is orient3d < 0 in Shewchuk's sign convention, decided exactly.
    signs = cavity.orient3d(p[s[:, 0]], p[s[:, 1]], p[s[:, 2]], p[s[:, 3]])
    assert np.all(signs == -1)
    # neighbors[t, i] shares the facet opposite vertex i, and the relation is symmetric.
    nb = d.neighbors
    for t in range(len(s)):
        for i in range(4):
            u = nb[t, i]
            facet = set(s[t]) - {s[t, i]}
            if u < 0:
                continue
            assert facet <= set(s[u])
            assert t in nb[u]
    # Hull triangles are the facets without a neighbor, counter-clockwise seen from outside.
    hull_count = int(np.count_nonzero(nb < 0))
    assert len(d.convex_hull) == hull_count == d.stats["hull_triangles"]
    inside = p[np.unique(s)].mean(axis=0)
    h = d.convex_hull
    assert np.all(cavity.orient3d(p[h[:, 0]], p[h[:, 1]], p[h[:, 2]], inside) == 1)
    # vertex_to_simplex points at a tetrahedron holding the vertex, -1 for non-vertices.
    v2s = d.vertex_to_simplex
    vertices = np.unique(s)
    assert np.all(v2s[vertices] >= 0)
    for v in vertices:
        assert v in s[v2s[v]]
    others = np.setdiff1d(np.arange(len(p)), vertices)
    assert np.all(v2s[others] == -1)
    assert set(others) == set(d.duplicates[:, 0]) | set(d.redundant)


@pytest.fixture
def rng():
    return np.random.default_rng(12345)
