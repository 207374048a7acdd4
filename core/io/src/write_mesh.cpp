#include <charconv>
#include <string>
#include <string_view>

#include "cavity/core/base/error.h"
#include "cavity/core/io/atomic_file.h"
#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/points_fingerprint.h"
#include "mesh_checks.h"
#include "point_writers.h"
#include "text_output.h"

namespace cavity::core {

std::filesystem::path with_suffix(const std::filesystem::path& prefix, const char* suffix) {
    return std::filesystem::path(prefix.string() + suffix);
}

void write_ele(AtomicFileGroup::Writer& out, const PointSet& points, std::span<const Tet> tets) {
    const auto base = static_cast<std::uint64_t>(points.index_base);
    // TetGen and every .ele reader skip '#' comments; `cavity check` reads this one, at the end of
    // the header line so that line-oriented tools still find the tetrahedra from line 2, to tell
    // a .node and a .ele of two different runs apart.
    std::string header;
    append_uint(header, tets.size());
    header += " 4 0  " + points_fingerprint_comment(points_fingerprint(points)) + '\n';
    out.write(header);
    // Each line is formatted in place and handed over whole: appending its five numbers to a
    // string one by one cost about 650 instructions a tetrahedron.
    char line[5 * 21];
    for (std::size_t t = 0; t < tets.size(); ++t) {
        char* end = std::to_chars(line, line + sizeof line, t + base).ptr;
        for (const std::uint32_t v : tets[t]) {
            *end++ = ' ';
            end = std::to_chars(end, line + sizeof line, v + base).ptr;
        }
        *end++ = '\n';
        out.write(std::string_view(line, static_cast<std::size_t>(end - line)));
    }
}

void write_tetgen(AtomicFileGroup& group,
                  const std::filesystem::path& prefix,
                  const PointSet& points,
                  std::span<const Tet> tets) {
    const auto node = with_suffix(prefix, ".node");
    const auto ele = with_suffix(prefix, ".ele");
    check_tets(ele, points, tets);
    write_node(group.add(node), points);
    write_ele(group.add(ele), points, tets);
}

void write_tetgen(const std::filesystem::path& prefix,
                  const PointSet& points,
                  std::span<const Tet> tets) {
    AtomicFileGroup group;
    write_tetgen(group, prefix, points, tets);
    group.commit();
}

void check_tets(const std::filesystem::path& file,
                const PointSet& points,
                std::span<const Tet> tets) {
    for (std::size_t t = 0; t < tets.size(); ++t) {
        for (const std::uint32_t v : tets[t]) {
            if (v >= points.size()) {
                throw Error(located_message(file.string(),
                                            std::nullopt,
                                            "tet " + std::to_string(t) + " names point " +
                                                std::to_string(v) + " of " +
                                                std::to_string(points.size())));
            }
        }
    }
}

}  // namespace cavity::core
