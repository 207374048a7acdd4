#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace cavity::test {

/// A triangulation as a sorted list of sorted vertex quadruples: equal for equal tetrahedra,
/// whatever the storage order.
inline std::vector<std::array<std::uint32_t, 4>> canonical(std::vector<std::array<std::uint32_t, 4>> tets) {
    for (auto& t : tets) {
        std::sort(t.begin(), t.end());
    }
    std::sort(tets.begin(), tets.end());
    return tets;
}

}  // namespace cavity::test
