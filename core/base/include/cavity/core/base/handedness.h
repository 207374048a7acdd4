#pragma once

#include <array>
#include <cstdint>

namespace cavity::core {

/// A tetrahedron as four 0-based input indices.
using Tet = std::array<std::uint32_t, 4>;

/// Two conventions meet at the engine's boundary. Inside, a stored tetrahedron (TetVertices in a
/// storage) has orient3d(a, b, c, d) > 0, Shewchuk's sign, which is det[b−a, c−a, d−a] < 0: a
/// negative volume by the right-hand rule. Every list of tetrahedra the API hands out or takes
/// (triangulate, gift_wrap, Cdt::tets, solid_tets, complex_from_tets, validate, validate_cdt,
/// build_adjacency, the writers, Python) has positive right-hand volume instead, as TetGen's files,
/// VTK's cells and scipy's users expect. Swapping the first two vertices converts either way; the
/// engine does it where a list is filled from a storage or a storage from a list.
constexpr Tet swap_handedness(const Tet& t) {
    return {t[1], t[0], t[2], t[3]};
}

}  // namespace cavity::core
