#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cavity/core/base/handedness.h"
#include "cavity/core/cdt/cdt.h"

namespace cavity::core {

/// The region marker of every tetrahedron of a CDT (TetGen's region attributes): from the
/// tetrahedron holding each of plc.regions' points (exactly: the point is in its closure), every
/// tetrahedron reachable without crossing a polygon triangle (`faces`) takes the region's marker;
/// the first region to reach a tetrahedron keeps it. Unreached tetrahedra get 0, TetGen's "no
/// region". `tets` have positive volume, as Cdt::tets. O(T) with hashing, plus O(T) exact
/// orientation tests per region point.
/// \throws Error naming the .poly line of a region point outside every tetrahedron.
std::vector<std::int32_t> region_markers(const Plc& plc,
                                         std::span<const Tet> tets,
                                         std::span<const CdtFace> faces);

}  // namespace cavity::core
