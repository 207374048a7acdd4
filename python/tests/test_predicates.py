"""cavity.orient3d / insphere / orient4d against exact rational arithmetic (fractions)."""

from fractions import Fraction

import numpy as np

import cavity


def det(m):
    """Exact determinant of a small square matrix of Fractions (Laplace expansion)."""
    if len(m) == 1:
        return m[0][0]
    return sum((-1) ** j * m[0][j] * det([row[:j] + row[j + 1:] for row in m[1:]])
               for j in range(len(m)))


def sign(x):
    return (x > 0) - (x < 0)


def exact_orient3d(a, b, c, d):
    rows = [[Fraction(p[i]) - Fraction(d[i]) for i in range(3)] for p in (a, b, c)]
    return sign(det(rows))


def exact_insphere(a, b, c, d, e):
    rows = []
    for p in (a, b, c, d):
        diff = [Fraction(p[i]) - Fraction(e[i]) for i in range(3)]
        rows.append(diff + [sum(x * x for x in diff)])
    return sign(det(rows))


def exact_orient4d(a, b, c, d, e):
    def lift(p):
        return sum(Fraction(p[i]) ** 2 for i in range(3)) - Fraction(p[3])

    rows = [[Fraction(p[i]) - Fraction(e[i]) for i in range(3)] + [lift(p) - lift(e)]
            for p in (a, b, c, d)]
    return sign(det(rows))


def near_plane(rng, k):
    """Points rounded onto the plane z = 0.3 x + 0.7 y: nearly coplanar, often exactly."""
    xy = rng.random((k, 2)) * 10
    return np.column_stack([xy, 0.3 * xy[:, 0] + 0.7 * xy[:, 1]])


def near_sphere(rng, k):
    """Points rounded onto the unit sphere: nearly cospherical."""
    v = rng.normal(size=(k, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def test_orient3d_matches_exact_arithmetic_on_nearly_coplanar_points(rng):
    args = [near_plane(rng, 300) for _ in range(4)]
    got = cavity.orient3d(*args)
    assert got.dtype == np.int8 and got.shape == (300,)
    want = [exact_orient3d(*(a[k] for a in args)) for k in range(300)]
    assert got.tolist() == want
    assert 0 in want or -1 in want  # the batch is hard: not all one sign


def test_insphere_matches_exact_arithmetic_on_nearly_cospherical_points(rng):
    args = [near_sphere(rng, 200) for _ in range(5)]
    got = cavity.insphere(*args)
    want = [exact_insphere(*(a[k] for a in args)) for k in range(200)]
    assert got.tolist() == want


def test_orient4d_matches_exact_arithmetic_with_weights(rng):
    args = []
    for _ in range(5):
        p = near_sphere(rng, 200)
        args.append(np.column_stack([p, rng.integers(-1, 2, 200) * 1e-17]))
    got = cavity.orient4d(*args)
    want = [exact_orient4d(*(a[k] for a in args)) for k in range(200)]
    assert got.tolist() == want


def test_orient4d_with_zero_weights_is_insphere(rng):
    pts = [near_sphere(rng, 100) for _ in range(5)]
    weighted = [np.column_stack([p, np.zeros(100)]) for p in pts]
    assert cavity.orient4d(*weighted).tolist() == cavity.insphere(*pts).tolist()


def test_conventions_on_the_unit_tetrahedron():
    o, x, y, z = [0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]
    # d below the plane of a, b, c (counter-clockwise from above): positive.
    assert cavity.orient3d(o, x, y, [0, 0, -1]) == 1
    assert cavity.orient3d(o, x, y, z) == -1
    assert cavity.orient3d(o, x, y, [5, 5, 0]) == 0
    assert cavity.orient3d(o, x, y, z).shape == ()
    # (o, y, x, z) is positively oriented: its circumcentre (0.5, 0.5, 0.5) is inside.
    assert cavity.insphere(o, y, x, z, [0.5, 0.5, 0.5]) == 1
    assert cavity.insphere(o, y, x, z, [1, 1, 1]) == 0
    assert cavity.insphere(o, y, x, z, [2, 2, 2]) == -1


def test_single_points_broadcast_over_the_queries():
    d = np.array([[0, 0, -1], [0, 0, 1], [0, 0, 0]], dtype=float)
    assert cavity.orient3d([0, 0, 0], [1, 0, 0], [0, 1, 0], d).tolist() == [1, -1, 0]


def test_exact_on_extreme_magnitudes():
    tiny = 1e-300
    a, b, c = [0, 0, 0], [tiny, 0, 0], [0, tiny, 0]
    assert cavity.orient3d(a, b, c, [0, 0, -tiny * 1e-10]) == 1
    huge = 1e300
    assert cavity.orient3d([0, 0, 0], [huge, 0, 0], [0, huge, 0], [0, 0, -huge]) == 1
