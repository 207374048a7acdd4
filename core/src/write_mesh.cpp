#include <string>

#include "cavity/core/atomic_file.h"
#include "cavity/core/error.h"
#include "cavity/core/mesh_io.h"
#include "point_writers.h"
#include "text_output.h"

namespace cavity::core {

namespace {

std::filesystem::path with_suffix(const std::filesystem::path& prefix, const char* suffix) {
    return std::filesystem::path(prefix.string() + suffix);
}

// A tet naming a point that does not exist would make a file no reader can use; refuse it
// before anything is committed.
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

void write_ele(AtomicFileGroup::Writer& out, const PointSet& points, std::span<const Tet> tets) {
    const auto base = static_cast<std::uint64_t>(points.index_base);
    std::string text;
    append_uint(text, tets.size());
    text += " 4 0\n";
    for (std::size_t t = 0; t < tets.size(); ++t) {
        append_uint(text, t + base);
        for (const std::uint32_t v : swap_handedness(tets[t])) {
            text += ' ';
            append_uint(text, v + base);
        }
        text += '\n';
        out.write(text);
        text.clear();
    }
}

void write_vtu_body(AtomicFileGroup::Writer& out,
                    const PointSet& points,
                    std::span<const Tet> tets) {
    std::string text =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
        "<UnstructuredGrid>\n<Piece NumberOfPoints=\"";
    append_uint(text, points.size());
    text += "\" NumberOfCells=\"";
    append_uint(text, tets.size());
    text +=
        "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const Point3& p : points.points) {
        append_double(text, p.x);
        text += ' ';
        append_double(text, p.y);
        text += ' ';
        append_double(text, p.z);
        text += '\n';
        out.write(text);
        text.clear();
    }
    text +=
        "</DataArray>\n</Points>\n<Cells>\n"
        "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const Tet& engine_tet : tets) {
        const Tet tet = swap_handedness(engine_tet);
        for (std::size_t i = 0; i < 4; ++i) {
            append_uint(text, tet[i]);
            text += i < 3 ? ' ' : '\n';
        }
        out.write(text);
        text.clear();
    }
    text += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t t = 1; t <= tets.size(); ++t) {
        append_uint(text, 4 * t);
        text += '\n';
        out.write(text);
        text.clear();
    }
    text += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < tets.size(); ++t) {
        text += "10\n";  // VTK_TETRA
    }
    text += "</DataArray>\n</Cells>\n";
    if (points.weighted()) {
        text +=
            "<PointData Scalars=\"weight\">\n"
            "<DataArray type=\"Float64\" Name=\"weight\" format=\"ascii\">\n";
        for (const double w : points.weights) {
            append_double(text, w);
            text += '\n';
        }
        text += "</DataArray>\n</PointData>\n";
    }
    text += "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    out.write(text);
}

}  // namespace

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

void write_vtu(AtomicFileGroup& group,
               const std::filesystem::path& prefix,
               const PointSet& points,
               std::span<const Tet> tets) {
    const auto vtu = with_suffix(prefix, ".vtu");
    check_tets(vtu, points, tets);
    write_vtu_body(group.add(vtu), points, tets);
}

void write_vtu(const std::filesystem::path& prefix,
               const PointSet& points,
               std::span<const Tet> tets) {
    AtomicFileGroup group;
    write_vtu(group, prefix, points, tets);
    group.commit();
}

}  // namespace cavity::core
