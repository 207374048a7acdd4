#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>

#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// New slot s of a record holds old slot perm[s].
using Perm = std::array<std::uint8_t, 4>;

/// The order of ids the canonical order sorts by: the ghost vertex below every vertex.
constexpr std::uint32_t rank_of(VertexId v) {
    return v == kGhostVertex ? 0 : v + 1;
}

/// The canonical rotation of a record (canonical_order.h): an even permutation that brings the
/// lowest rank first and the lowest of the other three second; a ghost keeps the ghost vertex in
/// slot 3 and starts at its lowest vertex.
inline Perm canonical_perm(const TetVertices& v) {
    const auto lowest = [&](std::initializer_list<std::uint8_t> slots) {
        std::uint8_t best = *slots.begin();
        for (std::uint8_t s : slots) {
            if (rank_of(v[s]) < rank_of(v[best])) {
                best = s;
            }
        }
        return best;
    };
    if (is_ghost(v)) {
        const std::uint8_t m = lowest({0, 1, 2});
        return {
            m, static_cast<std::uint8_t>((m + 1) % 3), static_cast<std::uint8_t>((m + 2) % 3), 3};
    }
    // The even permutations that bring each slot first (double transpositions), then a 3-cycle of
    // the last three: both keep the orientation.
    constexpr std::array<Perm, 4> kFirst{{{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}}};
    Perm p = kFirst[lowest({0, 1, 2, 3})];
    const std::uint8_t k = rank_of(v[p[2]]) < rank_of(v[p[1]])
                               ? (rank_of(v[p[3]]) < rank_of(v[p[2]]) ? 3 : 2)
                               : (rank_of(v[p[3]]) < rank_of(v[p[1]]) ? 3 : 1);
    if (k == 2) {
        p = {p[0], p[2], p[3], p[1]};
    } else if (k == 3) {
        p = {p[0], p[3], p[1], p[2]};
    }
    return p;
}

}  // namespace cavity::core
