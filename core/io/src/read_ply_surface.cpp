// A PLY surface: the x, y, z of the vertex element and the corner list of the face element.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ply_format.h"
#include "surface_readers.h"
#include "text_input.h"

namespace cavity::core {

namespace {

std::size_t scalar_property(const TextSource& source,
                            const ply::Element& vertex,
                            std::string_view name) {
    const auto index = ply::find_property(vertex, name);
    if (!index || vertex.properties[*index].list_count_type) {
        source.fail(vertex.line, "the vertex element has no scalar '" + std::string(name) + "'");
    }
    return *index;
}

/// The face element's corner list: `vertex_indices` (or `vertex_index`), of an integer type.
std::size_t corner_list(const TextSource& source, const ply::Element& face) {
    auto index = ply::find_property(face, "vertex_indices");
    if (!index) {
        index = ply::find_property(face, "vertex_index");
    }
    if (!index || !face.properties[*index].list_count_type) {
        source.fail(face.line, "the face element has no 'vertex_indices' list");
    }
    if (!ply::is_integer(face.properties[*index].type)) {
        source.fail(face.line, "the face's vertex indices must have an integer type");
    }
    return *index;
}

void read_vertices(ply::Cursor& data,
                   const TextSource& source,
                   const ply::Element& vertex,
                   Plc& plc) {
    if (vertex.count > 0xFFFF'FFFFu) {
        source.fail(vertex.line, "more points than 32-bit indices can number");
    }
    const std::size_t axes[3] = {scalar_property(source, vertex, "x"),
                                 scalar_property(source, vertex, "y"),
                                 scalar_property(source, vertex, "z")};
    const std::uint64_t least =
        std::max<std::uint64_t>(ply::min_instance_bytes(vertex, data.ascii()), 1);
    plc.points.points.reserve(std::min<std::uint64_t>(vertex.count, data.data_size() / least + 1));
    for (std::uint64_t i = 0; i < vertex.count; ++i) {
        double xyz[3] = {0.0, 0.0, 0.0};
        for (std::size_t p = 0; p < vertex.properties.size(); ++p) {
            const auto axis = std::find(std::begin(axes), std::end(axes), p) - std::begin(axes);
            if (axis < 3) {
                xyz[axis] = data.scalar(vertex.properties[p], vertex, i);
            } else {
                data.skip_property(vertex.properties[p], vertex, i);
            }
        }
        plc.points.points.push_back({xyz[0], xyz[1], xyz[2]});
    }
}

void read_faces(ply::Cursor& data, const TextSource& source, const ply::Element& face, Plc& plc) {
    const std::size_t list = corner_list(source, face);
    for (std::uint64_t i = 0; i < face.count; ++i) {
        std::vector<std::uint32_t> corners;
        std::size_t line = 0;
        for (std::size_t p = 0; p < face.properties.size(); ++p) {
            const ply::Property& property = face.properties[p];
            if (p != list) {
                data.skip_property(property, face, i);
                continue;
            }
            const std::uint64_t n = data.list_length(property, face, i);
            line = data.line();
            if (n < 3) {
                data.fail("face " + std::to_string(i) + " has " + std::to_string(n) +
                          " corners; a face needs at least 3");
            }
            for (std::uint64_t k = 0; k < n; ++k) {
                const double c = data.scalar(property, face, i);
                if (c < 0 || c >= static_cast<double>(plc.points.size())) {
                    data.fail("face " + std::to_string(i) + ": " +
                              not_a_point(static_cast<std::int64_t>(c), plc));
                }
                corners.push_back(static_cast<std::uint32_t>(c));
            }
        }
        add_surface_face(plc, std::move(corners), line);
    }
}

}  // namespace

Plc read_ply_surface(const std::string& file, std::string_view bytes) {
    const TextSource source(file);
    const ply::Header header = ply::parse_header(source, bytes);
    ply::Cursor data(source, header, bytes);
    data.check_counts();
    Plc plc;
    plc.points.index_base = 0;
    bool have_vertices = false;
    bool have_faces = false;
    for (const ply::Element& element : header.elements) {
        if (element.name == "vertex" && !have_vertices) {
            read_vertices(data, source, element, plc);
            have_vertices = true;
        } else if (element.name == "face" && !have_faces) {
            if (!have_vertices) {
                source.fail(element.line, "the face element comes before the vertex element");
            }
            read_faces(data, source, element, plc);
            have_faces = true;
        } else {
            data.skip_element(element);
        }
    }
    if (!have_vertices || !have_faces) {
        source.fail(
            std::string("a PLY surface needs a vertex and a face element; this file has no ") +
            (have_vertices ? "face" : "vertex") + " element");
    }
    data.refuse_trailing_data();
    return plc;
}

}  // namespace cavity::core
