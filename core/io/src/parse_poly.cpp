#include "cavity/core/io/parse_poly.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <string>

#include "cavity/core/base/error.h"
#include "point_readers.h"
#include "text_input.h"

namespace cavity::core {

namespace {

/// Reads the lines of one .poly file in order, failing with FILE:LINE.
class PolyParser {
public:
    PolyParser(const std::string& file, std::string_view bytes)
        : source_(file), lines_(bytes), size_(bytes.size()) {}

    /// The fields of the next data line; `what` says what was expected, for the truncation error.
    std::vector<std::string_view> next(const std::string& what) {
        if (!lines_.next()) {
            source_.fail(what.empty() ? "file ends early" : "file ends before " + what);
        }
        return split_whitespace(lines_.text());
    }

    bool more() {
        if (!lines_.next()) {
            return false;
        }
        pending_ = true;
        return true;
    }

    std::vector<std::string_view> next_or_pending(const std::string& what) {
        if (pending_) {
            pending_ = false;
            return split_whitespace(lines_.text());
        }
        return next(what);
    }

    std::size_t line() const { return lines_.number(); }

    const TextSource& source() const { return source_; }

    std::uint64_t count(std::string_view token, std::string_view what) const {
        return source_.count(token, line(), what);
    }

    /// A count no larger than the file's size in bytes (each item takes at least one): a
    /// larger one is refused before any arithmetic or loop uses it.
    std::uint64_t bounded_count(std::string_view token, std::string_view what) const {
        return source_.count_at_most(token, line(), what, size_, "the file's size in bytes");
    }

    double number(std::string_view token, std::string_view what) const {
        return source_.number(token, line(), what);
    }

    [[noreturn]] void fail(const std::string& what) const { source_.fail(line(), what); }

private:
    TextSource source_;
    LineReader lines_;
    std::size_t size_;
    bool pending_ = false;
};

void read_points_part(PolyParser& in, Plc& plc, const std::filesystem::path& file) {
    const auto header = in.next("the point header");
    if (header.empty() || header.size() > 4) {
        in.fail("the point header needs 1 to 4 fields");
    }
    const std::uint64_t count = in.bounded_count(header[0], "number of points");
    const std::uint64_t dim = header.size() > 1 ? in.count(header[1], "dimension") : 3;
    const std::uint64_t attributes =
        header.size() > 2 ? in.bounded_count(header[2], "number of attributes") : 0;
    const std::uint64_t markers = header.size() > 3 ? in.count(header[3], "number of markers") : 0;
    if (dim != 3) {
        in.fail("dimension is " + std::to_string(dim) + ", expected 3");
    }
    if (markers > 1) {
        in.fail("number of boundary markers must be 0 or 1");
    }
    if (count == 0) {
        // TetGen: the points are in the .node file beside the .poly.
        std::filesystem::path node = file;
        node.replace_extension(".node");
        plc.points = read_node(node.string(), read_file_bytes(node), false);
        return;
    }
    if (count > 0xFFFF'FFFFu) {
        in.fail("more points than 32-bit indices can number");
    }
    plc.points.source = plc.source;
    for (std::uint64_t i = 0; i < count; ++i) {
        const auto tokens =
            in.next(std::to_string(count) + " points (found " + std::to_string(i) + ")");
        if (tokens.size() != 4 + attributes + markers) {
            in.fail("expected " + std::to_string(4 + attributes + markers) + " fields, found " +
                    std::to_string(tokens.size()));
        }
        const std::uint64_t index = in.count(tokens[0], "point index");
        if (i == 0) {
            if (index > 1) {
                in.fail("the first point index must be 0 or 1, found " + std::to_string(index));
            }
            plc.points.index_base = static_cast<int>(index);
        } else if (index != plc.points.index_base + i) {
            in.fail("point index " + std::to_string(index) + " out of sequence, expected " +
                    std::to_string(plc.points.index_base + i));
        }
        plc.points.points.push_back(
            {in.number(tokens[1], "x"), in.number(tokens[2], "y"), in.number(tokens[3], "z")});
    }
}

/// A corner reference in the file's numbering, as a 0-based index.
std::uint32_t corner(PolyParser& in, const Plc& plc, std::string_view token) {
    const std::uint64_t c = in.count(token, "corner index");
    const auto base = static_cast<std::uint64_t>(plc.points.index_base);
    if (c < base || c - base >= plc.points.size()) {
        in.fail("corner " + std::string(token) + " is not a point index (points are numbered " +
                std::to_string(base) + " to " + std::to_string(base + plc.points.size() - 1) + ")");
    }
    return static_cast<std::uint32_t>(c - base);
}

Point3 hole_point(PolyParser& in, const std::vector<std::string_view>& tokens) {
    if (tokens.size() != 4) {
        in.fail("a hole is `<index> x y z`, found " + std::to_string(tokens.size()) + " fields");
    }
    return {in.number(tokens[1], "x"), in.number(tokens[2], "y"), in.number(tokens[3], "z")};
}

/// `<index> x y z <attribute> [<volume bound>]`: the attribute becomes the region marker, so it
/// must be an integer that fits VTK's Int32 cell data; the volume bound (a mesher's) is ignored.
PlcRegion region_seed(PolyParser& in, const std::vector<std::string_view>& tokens) {
    if (tokens.size() != 5 && tokens.size() != 6) {
        in.fail("a region is `<index> x y z <attribute> [<volume bound>]`, found " +
                std::to_string(tokens.size()) + " fields");
    }
    const double attribute = in.number(tokens[4], "region attribute");
    if (!(attribute >= -2147483648.0 && attribute <= 2147483647.0) ||
        attribute != static_cast<double>(static_cast<std::int32_t>(attribute))) {
        in.fail("region attribute '" + std::string(tokens[4]) +
                "' is not an integer between -2147483648 and 2147483647 (it becomes the cell "
                "data `region`)");
    }
    if (tokens.size() == 6) {
        in.number(tokens[5], "volume bound");
    }
    return {{in.number(tokens[1], "x"), in.number(tokens[2], "y"), in.number(tokens[3], "z")},
            static_cast<std::int32_t>(attribute),
            in.line()};
}

/// A facet's boundary marker, which must fit an int.
int facet_marker(PolyParser& in, std::string_view token) {
    const std::int64_t marker = in.source().integer(token, in.line(), "facet marker");
    if (marker < std::numeric_limits<int>::min() || marker > std::numeric_limits<int>::max()) {
        in.fail("facet marker " + std::to_string(marker) + " is outside the range of int");
    }
    return static_cast<int>(marker);
}

/// The polygon `<#corners> c1 c2 ...` of `tokens` (the count checked by the caller): a loop of the
/// facet, or with two corners an explicit segment.
void add_polygon(PolyParser& in,
                 Plc& plc,
                 const std::vector<std::string_view>& tokens,
                 std::uint64_t corners,
                 PlcFacet& facet) {
    std::vector<std::uint32_t> loop;
    for (std::size_t c = 1; c <= corners; ++c) {
        loop.push_back(corner(in, plc, tokens[c]));
    }
    if (corners == 2) {
        if (loop[0] == loop[1]) {
            in.fail("a segment joins a point to itself");
        }
        plc.segments.push_back({loop[0], loop[1]});
    } else if (corners >= 3) {
        auto sorted = loop;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
            in.fail("a polygon lists a corner twice");
        }
        facet.loops.push_back(std::move(loop));
    }
}

/// A facet of TetGen's .smesh: one polygon on one line, `<#corners> c1 c2 ... [<marker>]`.
void read_smesh_facet(PolyParser& in, Plc& plc, bool markers, PlcFacet facet) {
    const auto tokens = in.next("facet " + std::to_string(*facet.number));
    facet.line = in.line();
    const std::uint64_t corners = in.bounded_count(tokens[0], "number of corners");
    if (tokens.size() != corners + 1 && !(markers && tokens.size() == corners + 2)) {
        in.fail("the facet declares " + std::to_string(corners) + " corners but lists " +
                std::to_string(tokens.size() - 1) + " numbers");
    }
    if (tokens.size() == corners + 2) {
        facet.marker = facet_marker(in, tokens.back());
    }
    add_polygon(in, plc, tokens, corners, facet);
    if (!facet.loops.empty()) {
        plc.facets.push_back(std::move(facet));
    }
}

void read_facets_part(PolyParser& in, Plc& plc, bool smesh) {
    const auto header = in.next("the facet header");
    if (header.empty() || header.size() > 2) {
        in.fail("the facet header is `<#facets> [<markers 0|1>]`");
    }
    const std::uint64_t count = in.bounded_count(header[0], "number of facets");
    const bool markers = header.size() > 1 && in.count(header[1], "markers") != 0;
    for (std::uint64_t f = 0; f < count; ++f) {
        PlcFacet facet;
        facet.number = f + static_cast<std::uint64_t>(plc.points.index_base);
        if (smesh) {
            read_smesh_facet(in, plc, markers, std::move(facet));
            continue;
        }
        const auto fh = in.next("facet " + std::to_string(f));
        if (fh.empty() || fh.size() > 3) {
            in.fail("a facet header is `<#polygons> [<#holes> [<marker>]]`");
        }
        facet.line = in.line();
        const std::uint64_t polygons = in.bounded_count(fh[0], "number of polygons");
        const std::uint64_t holes = fh.size() > 1 ? in.bounded_count(fh[1], "number of holes") : 0;
        if (markers && fh.size() > 2) {
            facet.marker = facet_marker(in, fh[2]);
        }
        for (std::uint64_t p = 0; p < polygons; ++p) {
            const auto tokens = in.next("polygon " + std::to_string(p) + " of a facet");
            const std::uint64_t corners = in.bounded_count(tokens[0], "number of corners");
            if (tokens.size() != corners + 1) {
                in.fail("the polygon declares " + std::to_string(corners) + " corners but lists " +
                        std::to_string(tokens.size() - 1));
            }
            add_polygon(in, plc, tokens, corners, facet);
        }
        for (std::uint64_t h = 0; h < holes; ++h) {
            facet.holes.push_back(hole_point(in, in.next("a facet hole")));
        }
        if (!facet.loops.empty()) {
            plc.facets.push_back(std::move(facet));
        }
    }
}

/// TetGen's .smesh differs from .poly only in its facets (one polygon each, no facet holes).
bool is_smesh(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) {
        return static_cast<char>(std::tolower(c));
    });
    return extension == ".smesh";
}

}  // namespace

Plc parse_poly(const std::filesystem::path& file) {
    const std::string bytes = read_file_bytes(file);
    PolyParser in(file.string(), bytes);
    Plc plc;
    plc.source = file.string();
    read_points_part(in, plc, file);
    read_facets_part(in, plc, is_smesh(file));
    if (in.more()) {
        const auto header = in.next_or_pending("the hole header");
        const std::uint64_t holes = in.bounded_count(header[0], "number of holes");
        for (std::uint64_t h = 0; h < holes; ++h) {
            const Point3 point = hole_point(in, in.next("a volume hole"));
            plc.volume_holes.push_back({point, in.line()});
        }
    }
    if (in.more()) {
        const auto header = in.next_or_pending("the region header");
        const std::uint64_t regions = in.bounded_count(header[0], "number of regions");
        for (std::uint64_t r = 0; r < regions; ++r) {
            plc.regions.push_back(region_seed(in, in.next("a region")));
        }
    }
    return plc;
}

}  // namespace cavity::core
