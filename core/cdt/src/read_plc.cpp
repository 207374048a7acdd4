#include "cavity/core/cdt/read_plc.h"

#include <algorithm>

#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/cdt/surface_validity.h"
#include "cavity/core/io/surface_mesh.h"
#include "coplanar_facets.h"
#include "warped_facets.h"

namespace cavity::core {

namespace {

/// The faces of a surface mesh as its readers make them: one loop each, no hole points, and no
/// segments (which require_valid_surface does not look at). Only such a PLC is marked
/// Plc::surface_checked once the surface passes.
bool only_faces(const Plc& plc) {
    return plc.segments.empty() &&
           std::all_of(plc.facets.begin(), plc.facets.end(), [](const PlcFacet& f) {
               return f.loops.size() == 1 && f.holes.empty();
           });
}

}  // namespace

SurfaceReading prepare_surface_mesh(Plc& plc, bool merge_coplanar_faces) {
    SurfaceReading made;
    const bool faces = only_faces(plc);
    plc.surface_checked = false;
    made.warped_faces = split_warped_facets(plc);
    // Checked face by face, before merging: the defects are named by the file's faces.
    require_valid_surface(plc);
    if (merge_coplanar_faces) {
        const CoplanarMerge merge = merge_coplanar_facets(plc);
        made.merged_faces = merge.faces;
        made.merged_polygons = merge.polygons;
    }
    plc.surface_checked = faces;
    return made;
}

Plc read_plc(const std::filesystem::path& file,
             SurfaceReading* reading,
             bool merge_coplanar_faces) {
    if (!is_surface_mesh_file(file)) {
        return read_poly(file);
    }
    std::size_t unread_line = 0;
    Plc plc = read_surface_mesh(file, &unread_line);
    SurfaceReading made = prepare_surface_mesh(plc, merge_coplanar_faces);
    made.unread_line = unread_line;
    if (reading != nullptr) {
        *reading = made;
    }
    return plc;
}

}  // namespace cavity::core
