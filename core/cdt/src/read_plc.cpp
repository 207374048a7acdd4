#include "cavity/core/cdt/read_plc.h"

#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/cdt/surface_validity.h"
#include "cavity/core/io/surface_mesh.h"

namespace cavity::core {

Plc read_plc(const std::filesystem::path& file) {
    if (!is_surface_mesh_file(file)) {
        return read_poly(file);
    }
    Plc plc = read_surface_mesh(file);
    require_valid_surface(plc);
    return plc;
}

}  // namespace cavity::core
