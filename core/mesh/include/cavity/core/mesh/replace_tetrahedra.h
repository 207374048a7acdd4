#pragma once

#include <span>
#include <vector>

#include "cavity/core/mesh/array_storage.h"

namespace cavity::core {

/// Replaces a set of live tetrahedra by new tetrahedra with the same boundary: the step every
/// bistellar flip and every retriangulated cavity ends with. New tetrahedra must be positively
/// oriented with the ghost vertex (if any) in slot 3. Each facet of a new tetrahedron is glued
/// either to the outside tetrahedron across the same boundary triangle or to the one other new
/// tetrahedron holding it, and each pair must see the triangle with opposite orientations.
///
/// Returns the ids of the new tetrahedra (in the order given), or an empty vector, with the storage
/// untouched, when the new set does not close up exactly on the old boundary (a triangle left
/// over, used twice, or glued with matching orientations).
std::vector<TetId> replace_tetrahedra(ArrayStorage& storage,
                                      std::span<const TetId> old_tets,
                                      std::span<const TetVertices> new_tets);

}  // namespace cavity::core
