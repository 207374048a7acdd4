"""cavity.Delaunay on ordinary input: attributes, options, stats, check()."""

import threading

import numpy as np
import pytest

import cavity
from conftest import assert_well_formed, sorted_rows


def test_random_points_are_well_formed_and_valid(rng):
    d = cavity.Delaunay(rng.random((500, 3)))
    assert_well_formed(d)
    assert d.check() is True
    assert d.points.shape == (500, 3) and d.points.dtype == np.float64
    assert d.simplices.dtype == np.int32 and d.neighbors.dtype == np.int32
    assert d.nsimplex == len(d.simplices) and d.npoints == 500 and d.ndim == 3
    assert d.duplicates.shape == (0, 2) and d.redundant.shape == (0,)
    assert d.weights is None


@pytest.mark.parametrize("order", ["brio", "hilbert", "zorder", "random", "input"])
@pytest.mark.parametrize("locate", ["walk", "conflict-graph", "conflict-graph-all", "straight-walk"])
def test_every_order_and_locator_gives_the_same_tetrahedra(rng, order, locate):
    points = rng.random((300, 3))
    reference = sorted_rows(cavity.Delaunay(points).simplices)
    d = cavity.Delaunay(points, order=order, locate=locate, seed=7, count=True)
    assert sorted_rows(d.simplices) == reference
    assert d.stats["order"] == order and d.stats["locate"] == locate
    # Only the full conflict graph keeps (and so counts) every conflict; all are freed by the end.
    assert (d.stats["conflicts_created"] > 0) == (locate == "conflict-graph-all")
    assert (d.stats["conflicts_created"] + d.stats["ghost_conflicts_created"] ==
            d.stats["conflicts_deleted"] + d.stats["ghost_conflicts_deleted"])


def test_hash_storage_gives_the_same_tetrahedra(rng):
    points = rng.random((300, 3))
    a = cavity.Delaunay(points)
    b = cavity.Delaunay(points, storage="hash", count=True)
    assert sorted_rows(a.simplices) == sorted_rows(b.simplices)
    assert b.stats["hash_probes"] > 0


def test_stats_hold_the_counters_and_timings(rng):
    d = cavity.Delaunay(rng.random((400, 3)), count=True)
    st = d.stats
    assert st["engine"] == "counting"
    assert st["insertions"] == 396  # the first four are the bootstrap tetrahedron
    assert st["tets"] == d.nsimplex
    assert st["tets_created"] - st["tets_deleted"] == d.nsimplex
    assert st["walk_steps"] > 0 and st["dig_tests"] > 0
    # The static filter decides most in-sphere tests of uniform points; every stage is a key.
    insphere = st["stage_calls"]["insphere"]
    assert set(insphere) == {"static", "filter", "adaptive", "exact"}
    assert insphere["static"] > 0
    # Each conflict test makes one in-sphere call (solid) or at least one orient3d call (ghost).
    calls = st["stage_calls"]
    assert sum(calls["insphere"].values()) + sum(calls["orient3d"].values()) >= st["dig_tests"]
    assert set(st["timings"]) == {"order_s", "triangulate_s", "adjacency_s", "order_cpu_s",
                                  "triangulate_cpu_s", "adjacency_cpu_s"}
    assert all(t >= 0 for t in st["timings"].values())


def test_duplicates_are_reported_not_inserted(rng):
    points = rng.random((100, 3))
    points = np.vstack([points, points[[3, 50]], [points[3]]])
    d = cavity.Delaunay(points)
    assert sorted(map(tuple, d.duplicates.tolist())) == [(100, 3), (101, 50), (102, 3)]
    assert_well_formed(d)
    assert d.check()


def test_weighted_points_report_redundant_ones(rng):
    points = rng.random((200, 3))
    centre = int(np.argmin(np.linalg.norm(points - 0.5, axis=1)))
    weights = np.zeros(200)
    weights[centre] = -1.0  # an interior point lifted far above the others: never a vertex
    d = cavity.Delaunay(points, weights=weights)
    assert centre in d.redundant
    assert np.all(d.vertex_to_simplex[d.redundant] == -1)
    assert d.weights.shape == (200,)
    assert_well_formed(d)
    assert d.check()


def test_zero_weights_give_the_unweighted_triangulation(rng):
    points = rng.random((200, 3))
    assert sorted_rows(cavity.Delaunay(points, weights=np.zeros(200)).simplices) == sorted_rows(
        cavity.Delaunay(points).simplices)


def test_integer_and_float32_input_are_converted():
    cube = [[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    d = cavity.Delaunay(np.array(cube, dtype=np.int64))
    assert d.points.dtype == np.float64
    assert d.check()
    e = cavity.Delaunay(np.array(cube, dtype=np.float32))
    assert sorted_rows(e.simplices) == sorted_rows(d.simplices)


def test_results_are_read_only(rng):
    d = cavity.Delaunay(rng.random((50, 3)))
    with pytest.raises(ValueError):
        d.simplices[0, 0] = 1


def test_progress_is_called_with_done_and_total(rng):
    calls = []
    cavity.Delaunay(rng.random((5000, 3)), progress=lambda done, total: calls.append((done, total)))
    assert calls and calls[-1][0] == calls[-1][1] == 5000
    assert all(a <= b for (a, _), (b, _) in zip(calls, calls[1:]))


def test_an_exception_in_progress_propagates_and_builds_nothing(rng):
    def stop(done, total):
        raise KeyError("stop")

    with pytest.raises(KeyError):
        cavity.Delaunay(rng.random((5000, 3)), progress=stop)


def test_concurrent_triangulations_in_threads_agree(rng):
    points = rng.random((3000, 3))
    results = [None] * 4

    def work(i):
        results[i] = sorted_rows(cavity.Delaunay(points, seed=i).simplices)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(r == results[0] for r in results)
