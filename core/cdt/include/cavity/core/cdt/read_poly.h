#pragma once

#include <filesystem>

#include "cavity/core/input/plc.h"

namespace cavity::core {

/// Reads a TetGen `.poly` file (parse_poly) and checks each facet's geometry exactly: the loops of
/// a facet are coplanar, with no two equal consecutive corners, not all collinear; hole points lie
/// in the facet's plane and on no loop side. Whether the result is a PLC (polygons meeting only
/// along shared sides) is checked by plc_violations (plc_validity.h), which needs the Delaunay
/// triangulation of the points. With `exact` (the PREFIX.exact of `cavity cdt`,
/// exact_points_file.h) the implicit Steiner points are read from it and every check is on them.
/// \throws Error naming the file and line of any malformed, truncated or inconsistent entry.
Plc read_poly(const std::filesystem::path& file, const std::filesystem::path& exact = {});

}  // namespace cavity::core
