#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

/// Triangulations compared tetrahedron by tetrahedron, whatever the order and orientation in which
/// an algorithm lists them (private to the experiments layer).
namespace cavity::experiments::detail {

using TetList = std::vector<std::array<std::uint32_t, 4>>;

/// Each tetrahedron's vertices sorted, then the list sorted: equal for equal triangulations.
inline TetList canonical(TetList tets) {
    for (auto& t : tets) {
        std::sort(t.begin(), t.end());
    }
    std::sort(tets.begin(), tets.end());
    return tets;
}

/// FNV-1a over canonical(tets).
inline std::uint64_t canonical_hash(const TetList& tets) {
    std::uint64_t hash = 1469598103934665603ull;
    for (const auto& t : canonical(tets)) {
        for (std::uint32_t v : t) {
            for (int byte = 0; byte < 4; ++byte) {
                hash ^= (v >> (8 * byte)) & 0xFFu;
                hash *= 1099511628211ull;
            }
        }
    }
    return hash;
}

}  // namespace cavity::experiments::detail
