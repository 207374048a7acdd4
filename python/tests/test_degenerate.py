"""Degenerate inputs (cospherical, coplanar subsets, repeats, extreme magnitudes) get a valid
triangulation with no flat tetrahedron, as the exact validator confirms."""

import itertools

import numpy as np
import pytest

import cavity
from conftest import assert_well_formed


def grid(k, spacing=1.0):
    axis = np.arange(k, dtype=float) * spacing
    return np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1).reshape(-1, 3)


def lattice_sphere(r2):
    """Every integer point with x^2 + y^2 + z^2 = r2: exactly cospherical."""
    r = int(np.ceil(np.sqrt(r2)))
    pts = [p for p in itertools.product(range(-r, r + 1), repeat=3) if sum(c * c for c in p) == r2]
    return np.array(pts, dtype=float)


def corpus():
    rng = np.random.default_rng(3)
    layers = np.column_stack([rng.random(300), rng.random(300), rng.integers(0, 3, 300)])
    t = rng.random(100)
    skew_lines = np.vstack([np.column_stack([t, np.zeros(100), np.zeros(100)]),
                            np.column_stack([np.zeros(100), t, np.ones(100)])])
    moment = np.column_stack([t, t**2, t**3])
    paraboloid = grid(5)
    paraboloid[:, 2] = paraboloid[:, 0] ** 2 + paraboloid[:, 1] ** 2
    return {
        "grid 7^3": grid(7),
        "grid 4^3 tiny spacing": grid(4, 1e-300),
        "grid 4^3 huge spacing": grid(4, 1e300),
        "lattice sphere r2=50": lattice_sphere(50),
        "lattice sphere r2=27 plus centre": np.vstack([lattice_sphere(27), [[0.0, 0.0, 0.0]]]),
        "three layers": layers,
        "two skew lines": skew_lines,
        "moment curve": moment,
        "paraboloid grid": paraboloid,
        "grid with repeats": np.vstack([grid(4), grid(4)[::3]]),
    }


CORPUS = corpus()


@pytest.mark.parametrize("name", sorted(CORPUS))
def test_degenerate_input_is_triangulated_validly(name):
    points = CORPUS[name]
    d = cavity.Delaunay(points)
    assert d.check() is True
    assert_well_formed(d)


def test_grid_has_the_expected_volume():
    d = cavity.Delaunay(grid(6))
    p = d.points[d.simplices]
    volume = np.abs(np.linalg.det(p[:, :3] - p[:, 3:4])).sum() / 6
    assert volume == pytest.approx(125.0)


def test_the_result_does_not_depend_on_the_order_even_when_degenerate():
    from conftest import sorted_rows

    points = lattice_sphere(50)
    reference = sorted_rows(cavity.Delaunay(points).simplices)
    for order in ("random", "input", "hilbert"):
        for seed in (1, 2):
            assert sorted_rows(cavity.Delaunay(points, order=order, seed=seed).simplices) == reference
