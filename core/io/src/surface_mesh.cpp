#include "cavity/core/io/surface_mesh.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "cavity/core/base/error.h"
#include "file_extension.h"
#include "surface_readers.h"
#include "text_input.h"

namespace cavity::core {

bool is_surface_mesh_file(const std::filesystem::path& file) {
    const std::string extension = lower_extension(file);
    return extension == ".off" || extension == ".stl" || extension == ".obj" || extension == ".ply";
}

void add_surface_face(Plc& plc, std::vector<std::uint32_t> corners, std::size_t line) {
    PlcFacet facet;
    facet.loops.push_back(std::move(corners));
    facet.line = line;
    facet.number = plc.facets.size() + static_cast<std::size_t>(plc.points.index_base);
    plc.facets.push_back(std::move(facet));
}

std::string not_a_point(std::int64_t index, const Plc& plc) {
    const std::string what = "vertex index " + std::to_string(index) + " is not a point";
    if (plc.points.size() == 0) {
        return what + " (there are no points)";
    }
    const auto base = static_cast<std::size_t>(plc.points.index_base);
    return what + " (points are numbered " + std::to_string(base) + " to " +
           std::to_string(base + plc.points.size() - 1) + ")";
}

Plc read_surface_mesh(const std::filesystem::path& file, std::size_t* unread_line) {
    const std::string extension = lower_extension(file);
    const std::string name = file.string();
    const std::string bytes = read_file_bytes(file);
    Plc plc;
    std::size_t unread = 0;
    if (extension == ".off") {
        plc = read_off(name, bytes, &unread);
    } else if (extension == ".stl") {
        plc = read_stl(name, bytes);
    } else if (extension == ".obj") {
        plc = read_obj(name, bytes);
    } else if (extension == ".ply") {
        plc = read_ply_surface(name, bytes);
    } else {
        throw Error(located_message(
            name, std::nullopt, "not a surface mesh: expected .off, .stl, .obj or .ply"));
    }
    if (plc.facets.empty()) {
        throw Error(located_message(name, std::nullopt, "the surface mesh has no faces"));
    }
    plc.source = name;
    plc.points.source = name;
    if (unread_line != nullptr) {
        *unread_line = unread;
    }
    return plc;
}

}  // namespace cavity::core
