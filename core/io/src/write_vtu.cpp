#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#include "cavity/core/base/error.h"
#include "cavity/core/io/atomic_file.h"
#include "cavity/core/io/mesh_io.h"
#include "mesh_checks.h"
#include "text_output.h"
#include "vtk_binary.h"

namespace cavity::core {

namespace {

/// Writes one <DataArray> of `T` values, `components` per tuple, produced by fill(sink), in the
/// chosen encoding. ASCII prints `per_line` values a line (a point, a tetrahedron), with doubles
/// that read back exactly.
template <typename T, typename Fill>
void data_array(AtomicFileGroup::Writer& out,
                VtuEncoding encoding,
                const char* type,
                const char* name,
                int components,
                int per_line,
                Fill fill) {
    // A scalar array leaves NumberOfComponents out (VTK's default, 1): meshio then reads it as
    // a flat array, not as n tuples of one.
    std::string text = std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\"";
    if (components != 1) {
        text += " NumberOfComponents=\"" + std::to_string(components) + "\"";
    }
    text += std::string(" format=\"") + (encoding == VtuEncoding::kAscii ? "ascii" : "binary") +
            "\">\n";
    if (encoding == VtuEncoding::kAscii) {
        int in_tuple = 0;
        fill([&](T value) {
            if constexpr (std::is_floating_point_v<T>) {
                append_double(text, value);
            } else if constexpr (std::is_signed_v<T>) {
                if (value < 0) {
                    text += '-';
                    append_uint(text,
                                static_cast<std::uint64_t>(-static_cast<std::int64_t>(value)));
                } else {
                    append_uint(text, static_cast<std::uint64_t>(value));
                }
            } else {
                append_uint(text, value);
            }
            if (++in_tuple == per_line) {
                in_tuple = 0;
                text += '\n';
                if (text.size() > (1u << 16)) {
                    out.write(text);
                    text.clear();
                }
            } else {
                text += ' ';
            }
        });
    } else {
        // Coordinates repeat where models were made on a grid or in single precision; indices
        // rarely repeat as strings of bytes (vtk_binary.h has the measurements).
        VtkBinaryArray array(std::is_floating_point_v<T> ? VtkPacking::kSearch
                                                         : VtkPacking::kHuffmanOnly);
        fill([&](T value) { array.append(value); });
        text += array.encode();
        text += '\n';
    }
    text += "</DataArray>\n";
    out.write(text);
}

/// An array of non-negative indices (connectivity, offsets, ids) whose largest value is
/// `largest`: Int32 when that fits, else Int64. VTK and meshio read either (VTK converts to its id
/// type); half the raw bytes saved 4% of the compression's instructions on refined_elephant.off
/// (zlib's search skips the zero high halves quickly), and Huffman-only packing the rest.
template <typename Fill>
void index_array(AtomicFileGroup::Writer& out,
                 VtuEncoding encoding,
                 const char* name,
                 int per_line,
                 std::uint64_t largest,
                 Fill fill) {
    if (largest <= static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max())) {
        data_array<std::int32_t>(out, encoding, "Int32", name, 1, per_line, [&](auto sink) {
            fill([&](std::uint64_t v) { sink(static_cast<std::int32_t>(v)); });
        });
    } else {
        data_array<std::int64_t>(out, encoding, "Int64", name, 1, per_line, [&](auto sink) {
            fill([&](std::uint64_t v) { sink(static_cast<std::int64_t>(v)); });
        });
    }
}

void write_vtu_body(AtomicFileGroup::Writer& out,
                    const PointSet& points,
                    std::span<const Tet> tets,
                    const VtuOptions& options) {
    const VtuEncoding enc = options.encoding;
    std::string text =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\"";
    if (enc == VtuEncoding::kBinary) {
        text += " compressor=\"vtkZLibDataCompressor\"";
    }
    text += ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"";
    append_uint(text, points.size());
    text += "\" NumberOfCells=\"";
    append_uint(text, tets.size());
    text += "\">\n<Points>\n";
    out.write(text);
    data_array<double>(out, enc, "Float64", "Points", 3, 3, [&](auto sink) {
        for (const Point3& p : points.points) {
            sink(p.x);
            sink(p.y);
            sink(p.z);
        }
    });
    out.write("</Points>\n<Cells>\n");
    // VTK reads connectivity as a flat array (one component); the text shows a cell a line.
    // Every vertex is a point (checked before writing), so below the point count.
    index_array(out, enc, "connectivity", 4, std::uint64_t{points.size()}, [&](auto sink) {
        for (const Tet& tet : tets) {
            for (const std::uint32_t v : tet) {
                sink(v);
            }
        }
    });
    index_array(out, enc, "offsets", 1, 4 * std::uint64_t{tets.size()}, [&](auto sink) {
        for (std::size_t t = 1; t <= tets.size(); ++t) {
            sink(4 * std::uint64_t{t});
        }
    });
    data_array<std::uint8_t>(out, enc, "UInt8", "types", 1, 1, [&](auto sink) {
        for (std::size_t t = 0; t < tets.size(); ++t) {
            sink(std::uint8_t{10});  // VTK_TETRA
        }
    });
    out.write("</Cells>\n<CellData Scalars=\"tet_id\">\n");
    // The number the tetrahedron has in the .ele file of the same run (same index base).
    const auto base = static_cast<std::uint64_t>(points.index_base);
    index_array(out, enc, "tet_id", 1, tets.size() + base, [&](auto sink) {
        for (std::size_t t = 0; t < tets.size(); ++t) {
            sink(std::uint64_t{t} + base);
        }
    });
    if (!options.regions.empty()) {
        data_array<std::int32_t>(out, enc, "Int32", "region", 1, 1, [&](auto sink) {
            for (const std::int32_t r : options.regions) {
                sink(r);
            }
        });
    }
    out.write("</CellData>\n");
    if (points.weighted()) {
        out.write("<PointData Scalars=\"weight\">\n");
        data_array<double>(out, enc, "Float64", "weight", 1, 1, [&](auto sink) {
            for (const double w : points.weights) {
                sink(w);
            }
        });
        out.write("</PointData>\n");
    }
    out.write("</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
}

}  // namespace

void write_vtu(AtomicFileGroup& group,
               const std::filesystem::path& prefix,
               const PointSet& points,
               std::span<const Tet> tets,
               const VtuOptions& options) {
    const std::filesystem::path vtu(prefix.string() + ".vtu");
    check_tets(vtu, points, tets);
    if (!options.regions.empty() && options.regions.size() != tets.size()) {
        throw InternalError(vtu.string() + ": " + std::to_string(options.regions.size()) +
                            " region markers for " + std::to_string(tets.size()) + " tetrahedra");
    }
    write_vtu_body(group.add(vtu), points, tets, options);
}

void write_vtu(const std::filesystem::path& prefix,
               const PointSet& points,
               std::span<const Tet> tets,
               const VtuOptions& options) {
    AtomicFileGroup group;
    write_vtu(group, prefix, points, tets, options);
    group.commit();
}

}  // namespace cavity::core
