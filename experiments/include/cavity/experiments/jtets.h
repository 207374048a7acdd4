#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "cavity/predicates/point.h"

/// j-tetrahedra (Cheng, Dey & Shewchuk §5.4): a j-tetrahedron of a point set S is a non-flat
/// tetrahedron with vertices in S whose open circumball holds exactly j points of S. f_j counts
/// them and F_j = f_0 + ... + f_j; Proposition 5.1 bounds F_j by O(j^3 n) when Delaunay
/// triangulations of random subsets are linear and by O(j^2 n^2) always.
namespace cavity::experiments {

using predicates::Point3;

/// f[j] = number of j-tetrahedra, for j = 0 .. n-4 (trailing zeros kept).
struct JTetCounts {
    std::vector<std::uint64_t> f;

    /// F_j = f_0 + ... + f_j.
    std::vector<std::uint64_t> cumulative() const;
};

/// Exact f_j by the pencil sweep: for every non-collinear triangle abc, the spheres through a, b,
/// c form a pencil ordered by the signed offset λ of their centre along abc's normal, and each
/// other point x closes the tetrahedron abcx with the sphere λ(x). A point above abc lies in
/// ball(λ) iff λ > λ(y), a point below iff λ < λ(y), a coplanar point iff it is inside abc's
/// circumcircle. Sorting the points by λ gives every tetrahedron on abc its j by prefix counts.
/// λ is sorted in double first and the order then repaired by insertion sort with the exact
/// comparison (insphere and orient3d), so ties and near-ties are decided exactly. Each
/// tetrahedron is counted once, from the triangle of its three lowest indices.
/// Cost O(n^4) exact predicate calls in the worst case, O(n^4) double operations typically:
/// n = 200 takes seconds.
/// `progress`, when set, is called now and then with (triangles swept, all triangles): the ETA.
using JTetProgress = std::function<void(std::uint64_t done, std::uint64_t total)>;
JTetCounts count_jtets(std::span<const Point3> points, const JTetProgress& progress = {});

/// Exact f_j by brute force over all 4-subsets, O(n^5): the reference for tests.
JTetCounts count_jtets_brute_force(std::span<const Point3> points);

/// The closed form for two skew lines with m1 and m2 points in increasing order on each:
/// the open circumball of a_i a_i' b_l b_l' holds exactly the points strictly between on each
/// line, so f_j = sum over s + t = j of (m1 - 1 - s)_+ (m2 - 1 - t)_+.
JTetCounts skew_lines_jtets(std::uint64_t m1, std::uint64_t m2);

/// The number of points of `points` strictly inside the circumball of tetrahedron `tet`
/// (indices into points, any orientation, not flat), exactly; with `perturbed`, inside the
/// circumball under cavity's symbolic perturbation keyed on the index (the engine's conflict
/// test), so the count is that of the triangulator even on degenerate input.
std::size_t circumball_count(std::span<const Point3> points,
                             std::array<std::uint32_t, 4> tet,
                             bool perturbed);

}  // namespace cavity::experiments
