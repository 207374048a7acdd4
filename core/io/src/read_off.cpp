// OFF (Geomview's Object File Format): a keyword, the counts, the vertices, the faces.

#include <algorithm>
#include <string>
#include <vector>

#include "surface_readers.h"
#include "text_input.h"

namespace cavity::core {

namespace {

/// A corner of a face: a point index.
std::uint32_t corner(const TextSource& source,
                     std::string_view token,
                     std::size_t line,
                     const Plc& plc) {
    const std::uint64_t c = source.count(token, line, "vertex index");
    if (c >= plc.points.size()) {
        source.fail(line, not_a_point(static_cast<std::int64_t>(c), plc));
    }
    return static_cast<std::uint32_t>(c);
}

}  // namespace

Plc read_off(const std::string& file, std::string_view bytes, std::size_t* unread_line) {
    const TextSource source(file);
    LineReader lines(bytes);
    if (!lines.next()) {
        source.fail("empty file");
    }
    auto fields = split_whitespace(lines.text());
    const std::string_view keyword = fields[0];
    // The prefixes C (colours) and N (normals) add fields to each vertex line, read and skipped.
    const bool extra_vertex_fields = keyword != "OFF";
    if (keyword != "OFF" && keyword != "COFF" && keyword != "NOFF" && keyword != "CNOFF") {
        source.fail(lines.number(), "not an OFF file: the first word must be OFF");
    }
    fields.erase(fields.begin());
    if (fields.empty()) {
        if (!lines.next()) {
            source.fail(lines.number(), "file ends before the counts");
        }
        fields = split_whitespace(lines.text());
    }
    if (fields.size() < 2 || fields.size() > 3) {
        source.fail(lines.number(), "the counts are `<#vertices> <#faces> [<#edges>]`");
    }
    const std::uint64_t limit = bytes.size();
    const std::uint64_t vertices = source.count_at_most(
        fields[0], lines.number(), "number of vertices", limit, "the file's size in bytes");
    const std::uint64_t faces = source.count_at_most(
        fields[1], lines.number(), "number of faces", limit, "the file's size in bytes");
    if (fields.size() == 3) {
        source.count(fields[2], lines.number(), "number of edges");
    }
    Plc plc;
    plc.points.index_base = 0;
    // Sized once (growing them copied every point and face again), but never beyond what the
    // file can hold: a vertex line takes 6 bytes at least, a face line 8.
    plc.points.points.reserve(std::min(vertices, limit / 6));
    plc.facets.reserve(std::min(faces, limit / 8));
    // One vector of fields for every line.
    std::vector<std::string_view> xyz;
    std::vector<std::string_view> tokens;
    for (std::uint64_t v = 0; v < vertices; ++v) {
        if (!lines.next()) {
            source.fail(lines.number(),
                        "file ends in vertex " + std::to_string(v) + " of the " +
                            std::to_string(vertices) + " declared");
        }
        split_whitespace(lines.text(), xyz);
        if (xyz.size() < 3 || (!extra_vertex_fields && xyz.size() != 3)) {
            source.fail(lines.number(),
                        "vertex " + std::to_string(v) + ": expected x y z, found " +
                            std::to_string(xyz.size()) + " fields");
        }
        for (std::size_t k = 3; k < xyz.size(); ++k) {
            source.number(xyz[k], lines.number(), "vertex field");
        }
        plc.points.points.push_back({source.number(xyz[0], lines.number(), "x"),
                                     source.number(xyz[1], lines.number(), "y"),
                                     source.number(xyz[2], lines.number(), "z")});
    }
    for (std::uint64_t f = 0; f < faces; ++f) {
        if (!lines.next()) {
            source.fail(lines.number(),
                        "file ends in face " + std::to_string(f) + " of the " +
                            std::to_string(faces) + " declared");
        }
        split_whitespace(lines.text(), tokens);
        const std::uint64_t n = source.count_at_most(
            tokens[0], lines.number(), "number of corners", limit, "the file's size in bytes");
        if (n < 3) {
            source.fail(lines.number(),
                        "face " + std::to_string(f) + " has " + std::to_string(n) +
                            " corners; a face needs at least 3");
        }
        if (tokens.size() < n + 1) {
            source.fail(lines.number(),
                        "face " + std::to_string(f) + " declares " + std::to_string(n) +
                            " corners but lists " + std::to_string(tokens.size() - 1));
        }
        // What follows the corners is the face's colour.
        for (std::size_t k = n + 1; k < tokens.size(); ++k) {
            source.number(tokens[k], lines.number(), "face colour");
        }
        std::vector<std::uint32_t> corners;
        for (std::size_t k = 1; k <= n; ++k) {
            corners.push_back(corner(source, tokens[k], lines.number(), plc));
        }
        add_surface_face(plc, std::move(corners), lines.number());
    }
    // The counts delimit the mesh, as CGAL's and TetGen's readers take them: what follows is
    // left unread (CGAL's own prim.off lists a stray triangle after the cube its counts declare),
    // and the caller is told where it begins.
    if (unread_line != nullptr) {
        *unread_line = lines.next() ? lines.number() : 0;
    }
    return plc;
}

}  // namespace cavity::core
