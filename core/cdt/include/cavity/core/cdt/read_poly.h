#pragma once

#include <filesystem>

#include "cavity/core/input/plc.h"

namespace cavity::core {

/// Reads a TetGen `.poly` file (parse_poly) and checks each facet's geometry exactly: the loops of
/// a facet are coplanar, with no two equal consecutive corners, not all collinear; hole points lie
/// in the facet's plane and on no loop side. Whether the result is a PLC (polygons meeting only
/// along shared sides) is checked by plc_violations (plc_validity.h), which needs the Delaunay
/// triangulation of the points.
/// \throws Error naming the file and line of any malformed, truncated or inconsistent entry.
Plc read_poly(const std::filesystem::path& file);

}  // namespace cavity::core
