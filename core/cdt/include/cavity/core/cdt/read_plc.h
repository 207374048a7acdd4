#pragma once

#include <cstddef>
#include <filesystem>

#include "cavity/core/input/plc.h"

namespace cavity::core {

/// What read_plc changed in a surface mesh's faces (all zero for a .poly, which is read as is).
struct SurfaceReading {
    std::size_t warped_faces = 0;     ///< polygon faces cut into triangles
    std::size_t merged_faces = 0;     ///< faces merged into larger polygons
    std::size_t merged_polygons = 0;  ///< the polygons they were merged into
    std::size_t unread_line = 0;      ///< an OFF file's data after its declared faces (0: none)
};

/// The input of `cavity cdt`, by extension (case-insensitive): a surface mesh (`.off`, `.stl`,
/// `.obj`, `.ply`: read_surface_mesh) must bound a solid and is refused otherwise, naming its
/// defects (require_valid_surface); anything else is a TetGen `.poly` (read_poly), which may
/// also hold internal and dangling facets. A surface mesh's polygon faces whose corners are not
/// exactly coplanar are cut into triangles first (each keeps the face's number); then, unless
/// `merge_coplanar_faces` is false, its exactly coplanar neighbouring faces are merged into
/// polygons (merge_coplanar_facets: the flat faces of the solid, as TetGen does without -M).
/// `reading`, when given, receives how many faces were cut and merged, and where an OFF file's
/// data after the faces its counts declare, which is not read, begins.
/// \throws Error naming the file and the line, facet or defects of an unusable input.
Plc read_plc(const std::filesystem::path& file,
             SurfaceReading* reading = nullptr,
             bool merge_coplanar_faces = true);

/// What read_plc does to a surface mesh once its faces are read, for faces made in memory (each
/// facet one loop; facet_name names them in messages): warped faces cut into triangles, the
/// surface checked (require_valid_surface), then, unless `merge_coplanar_faces` is false, exactly
/// coplanar neighbouring faces merged into polygons. Returns how many faces were cut and merged.
/// \throws Error naming the defects of a surface that does not bound a solid.
SurfaceReading prepare_surface_mesh(Plc& plc, bool merge_coplanar_faces = true);

}  // namespace cavity::core
