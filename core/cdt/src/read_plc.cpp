#include "cavity/core/cdt/read_plc.h"

#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/cdt/surface_validity.h"
#include "cavity/core/io/surface_mesh.h"
#include "coplanar_facets.h"
#include "warped_facets.h"

namespace cavity::core {

SurfaceReading prepare_surface_mesh(Plc& plc, bool merge_coplanar_faces) {
    SurfaceReading made;
    made.warped_faces = split_warped_facets(plc);
    // Checked face by face, before merging: the defects are named by the file's faces.
    require_valid_surface(plc);
    if (merge_coplanar_faces) {
        const CoplanarMerge merge = merge_coplanar_facets(plc);
        made.merged_faces = merge.faces;
        made.merged_polygons = merge.polygons;
    }
    return made;
}

Plc read_plc(const std::filesystem::path& file,
             SurfaceReading* reading,
             bool merge_coplanar_faces) {
    if (!is_surface_mesh_file(file)) {
        return read_poly(file);
    }
    Plc plc = read_surface_mesh(file);
    const SurfaceReading made = prepare_surface_mesh(plc, merge_coplanar_faces);
    if (reading != nullptr) {
        *reading = made;
    }
    return plc;
}

}  // namespace cavity::core
