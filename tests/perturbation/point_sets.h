#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "cavity/predicates/point.h"

/// Small degenerate point sets and key generators shared by the perturbation tests. Every set has
/// integer coordinates, so its degeneracies (cospherical, coplanar, collinear) are exact.
namespace cavity::perturbation::test {

using predicates::Point3;
using predicates::WeightedPoint3;

/// The corners of the unit cube: eight cospherical points, with coplanar quadruples on each face
/// and each diagonal plane.
inline std::vector<Point3> cube_corners() {
    std::vector<Point3> points;
    points.reserve(8);
    for (int i = 0; i < 8; ++i) {
        points.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    }
    return points;
}

/// The integer points of the sphere x^2 + y^2 + z^2 = r2.
inline std::vector<Point3> sphere_points(int r2) {
    std::vector<Point3> points;
    for (int x = -r2; x <= r2; ++x) {
        for (int y = -r2; y <= r2; ++y) {
            for (int z = -r2; z <= r2; ++z) {
                if (x * x + y * y + z * z == r2) {
                    points.push_back({double(x), double(y), double(z)});
                }
            }
        }
    }
    return points;
}

/// The grid {lo, ..., hi}^3.
inline std::vector<Point3> grid(int lo, int hi) {
    std::vector<Point3> points;
    for (int x = lo; x <= hi; ++x) {
        for (int y = lo; y <= hi; ++y) {
            for (int z = lo; z <= hi; ++z) {
                points.push_back({double(x), double(y), double(z)});
            }
        }
    }
    return points;
}

/// Weights that lift every point onto the hyperplane h = alpha . p + beta, so that every power
/// test among them is zero and the perturbation decides, collinear points included.
inline std::vector<WeightedPoint3> on_hyperplane(const std::vector<Point3>& points,
                                                 const std::array<int, 3>& alpha,
                                                 int beta) {
    std::vector<WeightedPoint3> weighted;
    for (const Point3& p : points) {
        const double h = alpha[0] * p.x + alpha[1] * p.y + alpha[2] * p.z + beta;
        weighted.push_back({p.x, p.y, p.z, p.x * p.x + p.y * p.y + p.z * p.z - h});
    }
    return weighted;
}

inline WeightedPoint3 unweighted(const Point3& p) {
    return {p.x, p.y, p.z, 0};
}

inline Point3 position(const WeightedPoint3& p) {
    return {p.x, p.y, p.z};
}

/// N distinct values below `bound`, in random order.
template <class T, std::size_t N>
std::array<T, N> distinct_values(std::mt19937_64& rng, T bound) {
    std::array<T, N> values{};
    std::size_t n = 0;
    while (n < N) {
        const T v = std::uniform_int_distribution<T>(0, bound - 1)(rng);
        if (std::find(values.begin(), values.begin() + n, v) == values.begin() + n) {
            values[n++] = v;
        }
    }
    return values;
}

/// N distinct perturbation keys below `bound`.
template <std::size_t N>
std::array<std::uint32_t, N> distinct_keys(std::mt19937_64& rng, std::uint32_t bound) {
    return distinct_values<std::uint32_t, N>(rng, bound);
}

/// N distinct indices into a set of `size` points.
template <std::size_t N>
std::array<std::size_t, N> distinct_indices(std::mt19937_64& rng, std::size_t size) {
    return distinct_values<std::size_t, N>(rng, size);
}

}  // namespace cavity::perturbation::test
