#pragma once

#include <array>
#include <cstdint>

#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// New slot s of a record holds old slot perm[s].
using Perm = std::array<std::uint8_t, 4>;

/// The order of ids the canonical order sorts by: the ghost vertex below every vertex.
constexpr std::uint32_t rank_of(VertexId v) {
    return v == kGhostVertex ? 0 : v + 1;
}

/// The canonical rotation of a solid record, its vertices compared by `rank` (any increasing
/// function of the id): an even permutation that brings the lowest first and the lowest of the
/// other three second.
template <class Rank>
Perm solid_perm(const TetVertices& v, Rank rank) {
    std::uint8_t m = 0;
    for (std::uint8_t s = 1; s < 4; ++s) {
        if (rank(v[s]) < rank(v[m])) {
            m = s;
        }
    }
    // The even permutations that bring each slot first (double transpositions), then a 3-cycle of
    // the last three: both keep the orientation.
    constexpr std::array<Perm, 4> kFirst{{{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}}};
    Perm p = kFirst[m];
    const std::uint8_t k = rank(v[p[2]]) < rank(v[p[1]]) ? (rank(v[p[3]]) < rank(v[p[2]]) ? 3 : 2)
                                                         : (rank(v[p[3]]) < rank(v[p[1]]) ? 3 : 1);
    if (k == 2) {
        p = {p[0], p[2], p[3], p[1]};
    } else if (k == 3) {
        p = {p[0], p[3], p[1], p[2]};
    }
    return p;
}

/// The canonical rotation of a record (canonical_order.h): solid_perm by rank; a ghost keeps the
/// ghost vertex in slot 3 and starts at its lowest vertex.
inline Perm canonical_perm(const TetVertices& v) {
    if (is_ghost(v)) {
        std::uint8_t m = 0;
        for (std::uint8_t s = 1; s < 3; ++s) {
            if (rank_of(v[s]) < rank_of(v[m])) {
                m = s;
            }
        }
        return {
            m, static_cast<std::uint8_t>((m + 1) % 3), static_cast<std::uint8_t>((m + 2) % 3), 3};
    }
    return solid_perm(v, rank_of);
}

}  // namespace cavity::core
