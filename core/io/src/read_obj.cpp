// Wavefront OBJ: `v` vertices and `f` faces; textures, normals, groups and materials are skipped.

#include <string>
#include <vector>

#include "surface_readers.h"
#include "text_input.h"

namespace cavity::core {

namespace {

/// A face as read: corners as the file wrote them, resolved once every vertex is known (a
/// positive index may name a vertex defined further down).
struct RawFace {
    std::vector<std::int64_t> corners;  ///< 0-based; negative when it names no point
    std::vector<std::int64_t> written;  ///< the index as the file wrote it, for messages
    std::size_t line = 0;
};

/// The vertex of one corner token `i`, `i/t`, `i//n` or `i/t/n`, 0-based: positive indices count
/// from 1, negative ones back from the last vertex read so far.
void add_corner(const TextSource& source,
                std::string_view token,
                std::size_t line,
                std::size_t vertices_so_far,
                RawFace& face) {
    const std::string_view index = token.substr(0, token.find('/'));
    const std::int64_t i = source.integer(index, line, "vertex index");
    if (i == 0) {
        source.fail(line, "vertex index 0: OBJ numbers vertices from 1");
    }
    face.written.push_back(i);
    face.corners.push_back(i > 0 ? i - 1 : static_cast<std::int64_t>(vertices_so_far) + i);
}

}  // namespace

Plc read_obj(const std::string& file, std::string_view bytes) {
    const TextSource source(file);
    Plc plc;
    plc.points.index_base = 1;
    std::vector<RawFace> faces;
    LineReader lines(bytes);
    while (lines.next()) {
        const auto fields = split_whitespace(lines.text());
        if (fields[0] == "v") {
            // `v x y z`, or with a colour `v x y z r g b`; a homogeneous weight w other than 1
            // would make the point x/w, which is not a double in general.
            if (fields.size() != 4 && fields.size() != 5 && fields.size() != 7) {
                source.fail(lines.number(),
                            "a vertex is `v x y z [w]` or `v x y z r g b`, found " +
                                std::to_string(fields.size() - 1) + " numbers");
            }
            for (std::size_t k = 4; k < fields.size(); ++k) {
                source.number(fields[k], lines.number(), "vertex field");
            }
            if (fields.size() == 5 && source.number(fields[4], lines.number(), "w") != 1) {
                source.fail(lines.number(), "a vertex weight w other than 1 is not supported");
            }
            plc.points.points.push_back({source.number(fields[1], lines.number(), "x"),
                                         source.number(fields[2], lines.number(), "y"),
                                         source.number(fields[3], lines.number(), "z")});
        } else if (fields[0] == "f") {
            if (fields.size() < 4) {
                source.fail(lines.number(),
                            "a face has " + std::to_string(fields.size() - 1) +
                                " corners; a face needs at least 3");
            }
            RawFace face;
            face.line = lines.number();
            for (std::size_t k = 1; k < fields.size(); ++k) {
                add_corner(source, fields[k], lines.number(), plc.points.size(), face);
            }
            faces.push_back(std::move(face));
        }
    }
    if (plc.points.size() > 0xFFFF'FFFFu) {
        source.fail("more points than 32-bit indices can number");
    }
    for (const RawFace& face : faces) {
        std::vector<std::uint32_t> corners;
        for (std::size_t k = 0; k < face.corners.size(); ++k) {
            if (face.corners[k] < 0 ||
                face.corners[k] >= static_cast<std::int64_t>(plc.points.size())) {
                source.fail(face.line, not_a_point(face.written[k], plc));
            }
            corners.push_back(static_cast<std::uint32_t>(face.corners[k]));
        }
        add_surface_face(plc, std::move(corners), face.line);
    }
    return plc;
}

}  // namespace cavity::core
