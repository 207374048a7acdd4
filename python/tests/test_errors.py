"""Bad input raises ValueError naming the offending row; nothing half-built is returned."""

import numpy as np
import pytest

import cavity


def cube():
    return np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_coordinate_names_the_row(bad):
    points = cube()
    points[5, 2] = bad
    with pytest.raises(ValueError, match=r"points row 5 .*non-finite.*column 2"):
        cavity.Delaunay(points)


@pytest.mark.parametrize("shape", [(8,), (8, 2), (8, 4), (2, 4, 3)])
def test_wrong_shape_is_named(shape):
    with pytest.raises(ValueError, match=r"shape \(n, 3\)"):
        cavity.Delaunay(np.zeros(shape))


def test_not_numbers():
    with pytest.raises(ValueError, match="array of numbers"):
        cavity.Delaunay("not points")
    with pytest.raises(ValueError, match="array of numbers, got dtype object"):
        cavity.Delaunay(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, None]], dtype=object))


@pytest.mark.parametrize("make", [lambda p: p + 0j, lambda p: (p + 1j).tolist()])
def test_complex_points_are_refused_not_truncated(make):
    with pytest.raises(ValueError, match="points must be real numbers, got complex"):
        cavity.Delaunay(make(cube()))
    with pytest.raises(ValueError, match="weights must be real numbers, got complex"):
        cavity.Delaunay(cube(), weights=np.zeros(8) + 0j)


class _NoMemory:
    """An array-like whose conversion runs out of memory, as a huge input would."""

    def __array__(self, dtype=None, copy=None):
        raise MemoryError("cannot allocate the points")


def test_memory_error_stays_a_memory_error():
    with pytest.raises(MemoryError, match="cannot allocate the points"):
        cavity.Delaunay(_NoMemory())


@pytest.mark.parametrize("points", [np.zeros((0, 3)), np.ones((7, 3)), cube()[:3]])
def test_fewer_than_four_distinct_points(points):
    with pytest.raises(ValueError, match=r"no points|fewer than 4 distinct points"):
        cavity.Delaunay(points)


def test_coplanar_input_names_the_affine_dimension():
    points = cube()
    points[:, 2] = 0.0
    points = np.vstack([points, [[0.3, 0.7, 0.0]]])
    with pytest.raises(ValueError, match=r"coplanar \(affine dimension 2\)"):
        cavity.Delaunay(points)


def test_collinear_input_names_the_affine_dimension():
    points = np.outer(np.arange(10.0), [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match=r"affine dimension 1"):
        cavity.Delaunay(points)


def test_weights_of_the_wrong_length_or_non_finite():
    with pytest.raises(ValueError, match=r"weights must have shape \(8,\)"):
        cavity.Delaunay(cube(), weights=np.zeros(7))
    w = np.zeros(8)
    w[6] = np.nan
    with pytest.raises(ValueError, match=r"weights row 6 is not finite"):
        cavity.Delaunay(cube(), weights=w)


def test_unknown_option_names():
    with pytest.raises(ValueError, match="unknown insertion order 'spiral'"):
        cavity.Delaunay(cube(), order="spiral")
    with pytest.raises(ValueError, match="unknown point location 'teleport'"):
        cavity.Delaunay(cube(), locate="teleport")
    with pytest.raises(ValueError, match="unknown storage 'disk'"):
        cavity.Delaunay(cube(), storage="disk")


def test_progress_must_be_callable():
    with pytest.raises(TypeError, match="progress must be callable"):
        cavity.Delaunay(cube(), progress=3)


def test_predicate_arguments_are_checked():
    a = np.zeros((4, 3))
    with pytest.raises(ValueError, match=r"b has 3 rows"):
        cavity.orient3d(a, np.zeros((3, 3)), a, a)
    bad = np.zeros((4, 3))
    bad[2, 0] = np.nan
    with pytest.raises(ValueError, match=r"c row 2 has a non-finite value"):
        cavity.orient3d(a, a, bad, a)
    with pytest.raises(ValueError, match=r"e must have shape \(n, 4\)"):
        cavity.orient4d(np.zeros(4), np.zeros(4), np.zeros(4), np.zeros(4), np.zeros(3))
