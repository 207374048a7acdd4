#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cavity/core/geometry/geometry.h"
#include "concurrent_mesh.h"

namespace cavity::core {

/// The solid tetrahedra of `mesh` in the canonical order and rotation (canonical_order.h), as
/// input indices with positive right-hand volume (the form of Triangulation::tets): what
/// store_canonically followed by ArrayStorage::drain gives, without building the storage or
/// renumbering neighbours. Returns the number of hull triangles (ghosts). `mesh` is emptied;
/// `threads` threads share the work.
std::size_t list_canonically(ConcurrentMesh& mesh,
                             const Geometry& geometry,
                             unsigned threads,
                             std::vector<std::array<std::uint32_t, 4>>& tets);

}  // namespace cavity::core
