"""The parallel construction from Python: the same simplices as the sequential engine, in the
same canonical order for every thread count."""
import numpy as np
import pytest

import cavity


def _as_set(simplices):
    return {tuple(sorted(s)) for s in simplices.tolist()}


@pytest.fixture(scope="module")
def points():
    return np.random.default_rng(3).random((40000, 3))


def test_same_simplices_for_every_thread_count(points):
    sequential = cavity.Delaunay(points)
    one = cavity.Delaunay(points, threads=1)
    assert _as_set(one.simplices) == _as_set(sequential.simplices)
    for threads in (2, 4):
        many = cavity.Delaunay(points, threads=threads)
        np.testing.assert_array_equal(many.simplices, one.simplices)
        np.testing.assert_array_equal(many.neighbors, one.neighbors)
        assert many.stats["engine"] == "parallel"
        assert many.stats["threads"] == threads


def test_queries_and_insertions_after_a_parallel_build(points):
    tri = cavity.Delaunay(points, threads=2, incremental=True)
    reference = cavity.Delaunay(points)
    queries = np.random.default_rng(4).random((500, 3))
    found = tri.find_simplex(queries)
    expected = reference.find_simplex(queries)
    # Different numbering: compare the simplices' vertex sets (-1: outside the hull).
    def located(t, s):
        return [sorted(t.simplices[i]) if i >= 0 else None for i in s]
    assert located(tri, found) == located(reference, expected)
    extra = np.random.default_rng(5).random((1000, 3))
    tri.add_points(extra)
    assert _as_set(tri.simplices) == _as_set(cavity.Delaunay(np.vstack([points, extra])).simplices)


def test_refusals():
    pts = np.random.default_rng(0).random((100, 3))
    with pytest.raises(ValueError):
        cavity.Delaunay(pts, threads=2, count=True)
    with pytest.raises(ValueError):
        cavity.Delaunay(pts, threads=2, locate="conflict-graph")
    with pytest.raises(ValueError):
        cavity.Delaunay(pts, threads=2, storage="hash")
    with pytest.raises(ValueError):
        cavity.Delaunay(pts, threads=500)
