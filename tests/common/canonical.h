#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <vector>

#include "cavity/core/live/triangulate.h"

namespace cavity::test {

/// A triangulation as a sorted list of sorted vertex quadruples: equal for equal tetrahedra,
/// whatever the storage order.
inline std::vector<std::array<std::uint32_t, 4>> canonical(
    std::vector<std::array<std::uint32_t, 4>> tets) {
    for (auto& t : tets) {
        std::sort(t.begin(), t.end());
    }
    std::sort(tets.begin(), tets.end());
    return tets;
}

/// Bowyer–Watson in input order with the default options: the reference other constructions
/// (gift-wrapping, deletion) are compared with.
inline core::Triangulation triangulate_in_input_order(const core::PointSet& points) {
    std::vector<std::uint32_t> sequence(points.size());
    std::iota(sequence.begin(), sequence.end(), 0u);
    return core::triangulate(points, sequence, core::TriangulateOptions{});
}

/// Bowyer-Watson on the points not deleted, mapped back to the original indices. Dropping points
/// keeps the relative order of the others' keys, so the perturbation decides the same way.
inline core::Triangulation rebuilt_without(const core::PointSet& ps,
                                           const std::vector<bool>& gone) {
    core::PointSet kept;
    std::vector<std::uint32_t> original;
    for (std::uint32_t i = 0; i < ps.size(); ++i) {
        if (!gone[i]) {
            original.push_back(i);
            kept.points.push_back(ps.points[i]);
            if (ps.weighted()) {
                kept.weights.push_back(ps.weights[i]);
            }
        }
    }
    core::Triangulation t = triangulate_in_input_order(kept);
    for (auto& tet : t.tets) {
        for (auto& v : tet) {
            v = original[v];
        }
    }
    for (auto& r : t.redundant) {
        r = original[r];
    }
    return t;
}

}  // namespace cavity::test
