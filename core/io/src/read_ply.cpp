#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "ply_format.h"
#include "point_readers.h"
#include "text_input.h"

namespace cavity::core {

namespace {

/// Positions of the properties read from the vertex element.
struct VertexLayout {
    std::size_t x, y, z;
    std::optional<std::size_t> weight;
};

VertexLayout vertex_layout(const TextSource& source, const ply::Element& vertex, bool weighted) {
    VertexLayout layout{};
    std::size_t* targets[3] = {&layout.x, &layout.y, &layout.z};
    const char* names[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        const auto index = ply::find_property(vertex, names[axis]);
        if (!index) {
            source.fail(vertex.line,
                        std::string("the vertex element has no '") + names[axis] + "' property");
        }
        if (vertex.properties[*index].list_count_type) {
            source.fail(vertex.line,
                        std::string("the vertex property '") + names[axis] + "' is a list");
        }
        *targets[axis] = *index;
    }
    if (weighted) {
        layout.weight = ply::find_property(vertex, "weight");
        if (!layout.weight) {
            layout.weight = ply::find_property(vertex, "w");
        }
        if (!layout.weight || vertex.properties[*layout.weight].list_count_type) {
            source.fail(vertex.line, "weighted input needs a 'weight' or 'w' vertex property");
        }
    }
    return layout;
}

}  // namespace

PointSet read_ply(const std::string& file, std::string_view bytes, bool weighted) {
    const TextSource source(file);
    const ply::Header header = ply::parse_header(source, bytes);
    ply::Cursor data(source, header, bytes);
    data.check_counts();
    const ply::Element* vertex = nullptr;
    std::size_t vertex_position = 0;
    for (const ply::Element& element : header.elements) {
        if (element.name == "vertex") {
            vertex = &element;
            break;
        }
        data.skip_element(element);
        ++vertex_position;
    }
    if (vertex == nullptr) {
        source.fail("the PLY file has no vertex element");
    }
    if (vertex->count == 0) {
        source.fail(vertex->line, "the vertex element is empty: no points");
    }
    if (vertex->count > 0xFFFF'FFFFu) {
        source.fail(vertex->line, "more points than 32-bit indices can number");
    }
    const VertexLayout layout = vertex_layout(source, *vertex, weighted);
    PointSet result;
    result.source = source.file();
    const std::uint64_t least =
        std::max<std::uint64_t>(ply::min_instance_bytes(*vertex, data.ascii()), 1);
    result.points.reserve(std::min<std::uint64_t>(vertex->count, data.data_size() / least + 1));
    for (std::uint64_t i = 0; i < vertex->count; ++i) {
        double values[4] = {0.0, 0.0, 0.0, 0.0};  // x, y, z, weight
        for (std::size_t p = 0; p < vertex->properties.size(); ++p) {
            const int slot = p == layout.x                            ? 0
                             : p == layout.y                          ? 1
                             : p == layout.z                          ? 2
                             : (layout.weight && p == *layout.weight) ? 3
                                                                      : -1;
            if (slot < 0) {
                data.skip_property(vertex->properties[p], *vertex, i);
            } else {
                values[slot] = data.scalar(vertex->properties[p], *vertex, i);
            }
        }
        result.points.push_back({values[0], values[1], values[2]});
        if (weighted) {
            result.weights.push_back(values[3]);
        }
    }
    for (std::size_t e = vertex_position + 1; e < header.elements.size(); ++e) {
        data.skip_element(header.elements[e]);
    }
    data.refuse_trailing_data();
    return result;
}

}  // namespace cavity::core
