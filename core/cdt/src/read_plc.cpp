#include "cavity/core/cdt/read_plc.h"

#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/cdt/surface_validity.h"
#include "cavity/core/io/surface_mesh.h"
#include "warped_facets.h"

namespace cavity::core {

Plc read_plc(const std::filesystem::path& file, std::size_t* warped_faces) {
    if (!is_surface_mesh_file(file)) {
        return read_poly(file);
    }
    Plc plc = read_surface_mesh(file);
    const std::size_t split = split_warped_facets(plc);
    if (warped_faces != nullptr) {
        *warped_faces = split;
    }
    require_valid_surface(plc);
    return plc;
}

}  // namespace cavity::core
