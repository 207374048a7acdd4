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

}  // namespace cavity::test
