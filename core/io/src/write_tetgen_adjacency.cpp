#include <string>

#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/tet_adjacency.h"
#include "mesh_checks.h"
#include "point_writers.h"
#include "text_output.h"

namespace cavity::core {

namespace {

/// A tetrahedron or point number as the files print it: shifted by the index base, -1 kept.
void append_ref(std::string& text, std::int64_t id, int base) {
    if (id < 0) {
        text += "-1";
    } else {
        append_uint(text, static_cast<std::uint64_t>(id + base));
    }
}

void write_neigh(AtomicFileGroup::Writer& out, const Adjacency& adjacency, int base) {
    const std::size_t m = adjacency.simplices.size();
    std::string text;
    append_uint(text, m);
    text += " 4\n";
    for (std::size_t t = 0; t < m; ++t) {
        append_ref(text, static_cast<std::int64_t>(t), base);
        for (std::size_t i = 0; i < 4; ++i) {
            text += ' ';
            append_ref(text, adjacency.neighbors[4 * t + i], base);
        }
        text += '\n';
        if (text.size() > (1u << 16)) {
            out.write(text);
            text.clear();
        }
    }
    out.write(text);
}

void write_hull_faces(AtomicFileGroup::Writer& out, const Adjacency& adjacency, int base) {
    std::string text;
    append_uint(text, adjacency.hull.size());
    text += " 0\n";
    for (std::size_t f = 0; f < adjacency.hull.size(); ++f) {
        append_ref(text, static_cast<std::int64_t>(f), base);
        for (const std::int32_t v : adjacency.hull[f]) {
            text += ' ';
            append_ref(text, v, base);
        }
        text += '\n';
        if (text.size() > (1u << 16)) {
            out.write(text);
            text.clear();
        }
    }
    out.write(text);
}

}  // namespace

void write_tetgen(AtomicFileGroup& group,
                  const std::filesystem::path& prefix,
                  const PointSet& points,
                  const Adjacency& adjacency,
                  const TetgenExtras& extras) {
    const auto ele = with_suffix(prefix, ".ele");
    check_tets(ele, points, adjacency.simplices);
    write_node(group.add(with_suffix(prefix, ".node")), points);
    write_ele(group.add(ele), points, adjacency.simplices);
    if (extras.neighbors) {
        write_neigh(group.add(with_suffix(prefix, ".neigh")), adjacency, points.index_base);
    }
    if (extras.hull_faces) {
        write_hull_faces(group.add(with_suffix(prefix, ".face")), adjacency, points.index_base);
    }
}

}  // namespace cavity::core
