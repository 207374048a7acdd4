#pragma once

#include <cstddef>
#include <filesystem>

#include "cavity/core/input/plc.h"

namespace cavity::core {

/// The input of `cavity cdt`, by extension (case-insensitive): a surface mesh (`.off`, `.stl`,
/// `.obj`, `.ply`: read_surface_mesh) must bound a solid and is refused otherwise, naming its
/// defects (require_valid_surface); anything else is a TetGen `.poly` (read_poly), which may
/// also hold internal and dangling facets. A surface mesh's polygon faces whose corners are not
/// exactly coplanar are cut into triangles first (each keeps the face's number); `warped_faces`,
/// when given, receives how many were.
/// \throws Error naming the file and the line, facet or defects of an unusable input.
Plc read_plc(const std::filesystem::path& file, std::size_t* warped_faces = nullptr);

}  // namespace cavity::core
