"""scipy.spatial.Delaunay's interface on cavity.Delaunay, checked against scipy on the same points
where scipy's answer is unambiguous (random points: one Delaunay triangulation) and against exact
predicates where it is not (points on shared faces, grids)."""

import pickle

import numpy as np
import pytest

import cavity
from conftest import sorted_rows

spatial = pytest.importorskip("scipy.spatial")


def key(simplex):
    return tuple(sorted(int(v) for v in simplex))


@pytest.fixture(scope="module")
def pair():
    points = np.random.default_rng(11).random((2000, 3))
    return points, cavity.Delaunay(points), spatial.Delaunay(points)


def grid(k):
    axis = np.arange(float(k))
    return np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1).reshape(-1, 3)


def holds(d, simplex, x):
    """Whether x is in the closure of the simplex, decided exactly."""
    s = d.simplices[simplex]
    p = d.points
    for i in range(4):
        q = [p[v] for v in s]
        q[i] = x
        if cavity.orient3d(*q) > 0:  # positive right-hand volume is orient3d == -1
            return False
    return True


def test_find_simplex_agrees_with_scipy_on_random_queries(pair):
    points, ours, theirs = pair
    queries = np.random.default_rng(12).random((3000, 3)) * 1.2 - 0.1  # some outside the hull
    a, b = ours.find_simplex(queries), theirs.find_simplex(queries)
    assert a.dtype == np.int32 and a.shape == (3000,)
    assert np.array_equal(a < 0, b < 0)
    assert (a < 0).sum() > 100 and (a >= 0).sum() > 1000
    inside = a >= 0
    assert [key(s) for s in ours.simplices[a[inside]]] == \
        [key(s) for s in theirs.simplices[b[inside]]]


def test_find_simplex_keeps_the_query_shape_and_refuses_other_widths(pair):
    _, ours, _ = pair
    q = np.random.default_rng(13).random((2, 5, 3))
    assert ours.find_simplex(q).shape == (2, 5)
    assert ours.find_simplex([0.5, 0.5, 0.5]).shape == ()
    assert ours.find_simplex([[np.nan, 0.5, 0.5]])[0] == -1
    with pytest.raises(ValueError, match=r"shape \(\.\.\., 3\)"):
        ours.find_simplex(np.zeros((4, 2)))


def test_on_shared_faces_find_simplex_gives_the_lowest_simplex_holding_the_point():
    d = cavity.Delaunay(grid(4))
    p = d.points
    # Vertices, edge midpoints and face centres of the lattice: exactly on shared faces.
    rng = np.random.default_rng(14)
    queries = np.vstack([p, (p[rng.integers(0, 64, 200)] + p[rng.integers(0, 64, 200)]) / 2,
                         rng.integers(0, 7, (200, 3)) / 2.0])
    found = d.find_simplex(queries)
    for x, f in zip(queries, found):
        holding = [t for t in range(d.nsimplex) if holds(d, t, x)]
        assert f == (min(holding) if holding else -1)


def test_find_simplex_of_each_vertex_is_its_lowest_simplex(pair):
    points, ours, _ = pair
    lowest = np.full(len(points), np.iinfo(np.int32).max)
    for t, s in enumerate(ours.simplices):
        lowest[s] = np.minimum(lowest[s], t)
    assert np.array_equal(ours.find_simplex(points), lowest)


def test_transform_gives_barycentric_coordinates_like_scipy(pair):
    _, ours, theirs = pair
    queries = np.random.default_rng(15).random((500, 3)) * 0.8 + 0.1
    a, b = ours.find_simplex(queries), theirs.find_simplex(queries)
    assert ours.transform.shape == (ours.nsimplex, 4, 3)

    def weights(d, s, x):
        t = d.transform[s]
        c = t[:3] @ (x - t[3])
        return dict(zip(d.simplices[s].tolist(), np.append(c, 1 - c.sum())))

    for x, s, u in zip(queries, a, b):
        w_ours, w_theirs = weights(ours, s, x), weights(theirs, u, x)
        assert w_ours.keys() == w_theirs.keys()
        for v in w_ours:
            assert w_ours[v] == pytest.approx(w_theirs[v], abs=1e-9)
        # The coordinates rebuild the point.
        assert sum(w * ours.points[v] for v, w in w_ours.items()) == pytest.approx(x, abs=1e-12)


def barycentric_interpolate(d, values, x):
    """scipy.interpolate.LinearNDInterpolator's computation, written against the interface."""
    s = d.find_simplex(x)
    t = d.transform[s]
    c = np.einsum("kij,kj->ki", t[:, :3], x - t[:, 3])
    c = np.column_stack([c, 1 - c.sum(axis=1)])
    out = np.einsum("ki,ki->k", c, values[d.simplices[s]])
    out[s < 0] = np.nan
    return out


def test_interpolation_in_the_scipy_style():
    interpolate = pytest.importorskip("scipy.interpolate")
    rng = np.random.default_rng(16)
    points = rng.random((1500, 3))
    d = cavity.Delaunay(points)
    x = rng.random((2000, 3)) * 1.1 - 0.05
    # A linear function is reproduced exactly (to rounding) inside the hull; NaN outside.
    linear = points @ [1.5, -2.0, 0.25] + 3
    got = barycentric_interpolate(d, linear, x)
    inside = d.find_simplex(x) >= 0
    assert np.allclose(got[inside], x[inside] @ [1.5, -2.0, 0.25] + 3, atol=1e-12)
    assert np.isnan(got[~inside]).all()
    # Any function: the same interpolant as scipy's, which has the same triangulation.
    values = np.sin(points @ [3.0, 1.0, 2.0])
    got = barycentric_interpolate(d, values, x)
    theirs = interpolate.LinearNDInterpolator(points, values)(x)
    assert np.array_equal(np.isnan(theirs), ~inside)
    assert np.allclose(got[inside], theirs[inside], atol=1e-12)


def test_vertex_neighbor_vertices_agree_with_scipy(pair):
    points, ours, theirs = pair
    (ip, ix), (jp, jx) = ours.vertex_neighbor_vertices, theirs.vertex_neighbor_vertices
    assert ip.dtype == np.int32 and ip.shape == (len(points) + 1,)
    for v in range(len(points)):
        mine = ix[ip[v]:ip[v + 1]]
        assert np.all(np.diff(mine) > 0)
        assert set(mine.tolist()) == set(jx[jp[v]:jp[v + 1]].tolist())


def unscaled(d):
    """Each simplex's lifted hyperplane on the plain paraboloid z = |x|^2, as a unit vector keyed by
    its vertices: scipy's Qhull picks its own paraboloid_scale and shift."""
    e = d.equations
    n = np.column_stack([e[:, :3], e[:, 3] * d.paraboloid_scale,
                         e[:, 4] + e[:, 3] * d.paraboloid_shift])
    n /= np.linalg.norm(n, axis=1)[:, None]
    return {key(s): row for s, row in zip(d.simplices, n)}


def test_equations_are_scipys_lifted_hyperplanes(pair):
    _, ours, theirs = pair
    assert ours.equations.shape == (ours.nsimplex, 5)
    assert np.allclose(np.linalg.norm(ours.equations[:, :4], axis=1), 1)
    assert (ours.equations[:, 3] < 0).all()
    a, b = unscaled(ours), unscaled(theirs)
    assert a.keys() == b.keys()
    worst = max(np.abs(a[k] - b[k]).max() for k in a)
    assert worst < 1e-8


def test_lift_points_and_plane_distance(pair):
    points, ours, _ = pair
    x = np.random.default_rng(17).random((4, 2, 3))
    z = ours.lift_points(x)
    assert z.shape == (4, 2, 4)
    assert np.allclose(z[..., 3], (x ** 2).sum(-1) * ours.paraboloid_scale + ours.paraboloid_shift)
    dist = ours.plane_distance(x)
    assert dist.shape == (4, 2, ours.nsimplex)
    # Positive exactly where x is inside the circumsphere (far from zero: no rounding doubt).
    flat, s = x.reshape(-1, 3), ours.simplices
    for q, row in zip(flat, dist.reshape(-1, ours.nsimplex)):
        sure = np.abs(row) > 1e-9
        p = points[s[sure]]
        inside = cavity.insphere(p[:, 0], p[:, 1], p[:, 2], p[:, 3], q) * \
            cavity.orient3d(p[:, 0], p[:, 1], p[:, 2], p[:, 3]) > 0
        assert np.array_equal(row[sure] > 0, inside)
    # The simplex holding a point has the largest distance (scipy's find_simplex relies on it).
    q = np.array([[0.3, 0.6, 0.4]])
    assert np.argmax(ours.plane_distance(q)[0]) == ours.find_simplex(q)[0]


def test_bounds_hull_and_vertices_agree_with_scipy(pair):
    _, ours, theirs = pair
    assert np.array_equal(ours.min_bound, theirs.min_bound)
    assert np.array_equal(ours.max_bound, theirs.max_bound)
    assert sorted_rows(ours.convex_hull) == sorted_rows(theirs.convex_hull)
    assert ours.furthest_site is False and ours.ndim == 3
    assert ours.good.dtype == theirs.good.dtype and np.array_equal(ours.good, theirs.good)
    with pytest.warns(DeprecationWarning):
        assert ours.vertices is ours.simplices


def test_coplanar_lists_the_repeats_as_scipy_does():
    rng = np.random.default_rng(18)
    base = rng.random((300, 3))
    points = np.vstack([base, base[[3, 7, 7]]])
    ours, theirs = cavity.Delaunay(points), spatial.Delaunay(points)
    assert ours.coplanar.dtype == np.int32 and ours.coplanar.shape == (3, 3)
    assert sorted(ours.coplanar[:, 0].tolist()) == [300, 301, 302]
    for point, simplex, vertex in ours.coplanar:
        assert np.array_equal(points[point], points[vertex])
        assert vertex in ours.simplices[simplex]
    # scipy keeps an arbitrary copy; the groups of equal points left out are the same.
    def groups(c):
        return sorted(tuple(points[i].tolist()) for i in c[:, 0])
    assert groups(ours.coplanar) == groups(theirs.coplanar)


def test_add_points_equals_one_construction_of_all_points():
    rng = np.random.default_rng(19)
    points = rng.random((900, 3))
    points[850] = points[10]  # a repeat in a later batch
    points[851] = points[860]  # a repeat inside one batch
    d = cavity.Delaunay(points[:300], incremental=True)
    d.add_points(points[300:700])
    d.add_points(points[700:])
    whole = cavity.Delaunay(points)
    assert d.npoints == 900
    assert sorted_rows(d.simplices) == sorted_rows(whole.simplices)
    assert d.duplicates.tolist() == whole.duplicates.tolist()
    assert d.stats["points_added"] == 600
    assert d.check()
    # scipy's incremental mode on the same batches (random points: the same triangulation).
    s = spatial.Delaunay(points[:300], incremental=True)
    s.add_points(points[300:])
    assert sorted_rows(d.simplices) == sorted_rows(s.simplices)


def test_add_points_weighted_and_restart():
    rng = np.random.default_rng(20)
    points, weights = rng.random((400, 3)), rng.random(400) * 0.01
    d = cavity.Delaunay(points[:200], weights=weights[:200], incremental=True)
    d.add_points(points[200:], weights=weights[200:])
    whole = cavity.Delaunay(points, weights=weights)
    assert sorted_rows(d.simplices) == sorted_rows(whole.simplices)
    assert d.redundant.tolist() == whole.redundant.tolist()
    with pytest.raises(ValueError, match="needs weights"):
        d.add_points(points[:3])
    with pytest.raises(ValueError, match="needs weights"):
        d.add_points(points[:3], restart=True)
    d.add_points(points[:0], restart=True, weights=weights[:0])
    assert sorted_rows(d.simplices) == sorted_rows(whole.simplices)
    e = cavity.Delaunay(points[:200], incremental=True)
    e.add_points(points[200:], restart=True)
    assert sorted_rows(e.simplices) == sorted_rows(cavity.Delaunay(points).simplices)
    with pytest.raises(ValueError, match="takes no weights"):
        e.add_points(points[:3], restart=True, weights=weights[:3])


def test_add_points_needs_incremental_mode_and_stops_after_close():
    points = np.random.default_rng(21).random((50, 3))
    with pytest.raises(RuntimeError, match="incremental mode not enabled"):
        cavity.Delaunay(points).add_points(points[:2] + 2)
    d = cavity.Delaunay(points, incremental=True)
    d.close()
    assert d.nsimplex > 0
    with pytest.raises(RuntimeError, match="already closed"):
        d.add_points(points[:2] + 2)
    with pytest.raises(ValueError, match="storage=\"array\""):
        cavity.Delaunay(points, incremental=True, storage="hash")


def test_add_points_refuses_bad_rows_and_changes_nothing():
    points = np.random.default_rng(22).random((50, 3))
    d = cavity.Delaunay(points, incremental=True)
    before = d.simplices.copy()
    bad = np.random.default_rng(23).random((5, 3))
    bad[3, 1] = np.inf
    with pytest.raises(ValueError, match="points row 3"):
        d.add_points(bad)
    assert np.array_equal(d.simplices, before) and d.npoints == 50


@pytest.mark.parametrize("incremental", [False, True])
def test_pickling_gives_the_same_arrays(incremental):
    points = np.random.default_rng(24).random((500, 3))
    d = cavity.Delaunay(points[:300], incremental=True, order="hilbert", seed=3)
    d.add_points(points[300:])
    if not incremental:
        d.close()
    e = pickle.loads(pickle.dumps(d))
    for name in ("points", "simplices", "neighbors", "convex_hull", "vertex_to_simplex",
                 "duplicates"):
        assert np.array_equal(getattr(d, name), getattr(e, name)), name
    if incremental:
        more = np.random.default_rng(25).random((10, 3))
        d.add_points(more)
        e.add_points(more)
        assert np.array_equal(d.simplices, e.simplices)
    else:
        with pytest.raises(RuntimeError):
            e.add_points(points[:1] + 2)


def test_scipy_options_it_cannot_honour_are_refused_clearly():
    points = np.random.default_rng(26).random((20, 3))
    with pytest.raises(ValueError, match="furthest_site=True"):
        cavity.Delaunay(points, furthest_site=True)
    with pytest.raises(ValueError, match="does not run Qhull.*'QJ'"):
        cavity.Delaunay(points, qhull_options="QJ")
    with pytest.raises(ValueError, match="for 2-D points use scipy.spatial.Delaunay"):
        cavity.Delaunay(points[:, :2])
    # scipy's positional arguments keep their meaning.
    assert cavity.Delaunay(points, False, False, None).nsimplex > 0


def test_help_reads_like_scipys():
    doc = cavity.Delaunay.__doc__
    for section in ("Parameters", "Attributes", "Raises", "Notes", "Examples", "find_simplex",
                    "transform", "shape (nsimplex, 4, 3)", "vertex_neighbor_vertices"):
        assert section in doc
    for method in ("find_simplex", "add_points", "plane_distance", "lift_points", "close"):
        assert getattr(cavity.Delaunay, method).__doc__
