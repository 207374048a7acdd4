#include <algorithm>

#include "point_readers.h"
#include "text_input.h"

namespace cavity::core {

PointSet read_node(const std::string& file, std::string_view bytes, bool weighted) {
    const TextSource source(file);
    LineReader lines(bytes);
    if (!lines.next()) {
        source.fail("empty file: no .node header");
    }
    // TetGen lets the header stop after any field; missing fields take these defaults.
    const auto header = split_whitespace(lines.text());
    const std::size_t header_line = lines.number();
    if (header.size() > 4) {
        source.fail(header_line, "the .node header has more than 4 fields");
    }
    // Every count is bounded before it is used: no header field can exceed the file's size in
    // bytes, so no sum of counts wraps, and memory is reserved for no more points than the file
    // can hold; a count nearer the truth fails later, naming the line where the file ends.
    const std::uint64_t count = source.count_at_most(
        header[0], header_line, "number of points", 0xFFFF'FFFFu, "32-bit indices can number");
    const std::uint64_t dim =
        header.size() > 1 ? source.count(header[1], header_line, "dimension") : 3;
    const std::uint64_t attributes = header.size() > 2
                                         ? source.count_at_most(header[2],
                                                                header_line,
                                                                "number of attributes",
                                                                bytes.size(),
                                                                "the file's size in bytes")
                                         : 0;
    const std::uint64_t markers =
        header.size() > 3 ? source.count(header[3], header_line, "number of boundary markers") : 0;
    if (count == 0) {
        source.fail(header_line, "the header declares no points");
    }
    if (dim != 3) {
        source.fail(header_line, "dimension is " + std::to_string(dim) + ", expected 3");
    }
    if (markers > 1) {
        source.fail(header_line, "number of boundary markers must be 0 or 1");
    }
    if (weighted && attributes == 0) {
        source.fail(header_line, "weighted input needs the weight as the first attribute");
    }

    PointSet result;
    result.source = file;
    result.attribute_count = attributes;
    // A point line takes at least 7 + 2 * attributes bytes.
    const std::uint64_t room =
        std::min<std::uint64_t>(count, bytes.size() / (7 + 2 * attributes) + 1);
    result.attributes.reserve(room * attributes);
    result.points.reserve(room);
    if (weighted) {
        result.weights.reserve(room);
    }
    const std::size_t fields = 4 + attributes + markers;
    for (std::uint64_t i = 0; i < count; ++i) {
        if (!lines.next()) {
            source.fail(lines.number(),
                        "file ends after " + std::to_string(i) + " of " + std::to_string(count) +
                            " points");
        }
        const std::size_t line = lines.number();
        const auto tokens = split_whitespace(lines.text());
        if (tokens.size() != fields) {
            source.fail(line,
                        "expected " + std::to_string(fields) + " fields, found " +
                            std::to_string(tokens.size()));
        }
        const std::uint64_t index = source.count(tokens[0], line, "point index");
        if (i == 0) {
            if (index > 1) {
                source.fail(line,
                            "the first point index must be 0 or 1, found " + std::to_string(index));
            }
            result.index_base = static_cast<int>(index);
        } else if (index != result.index_base + i) {
            source.fail(line,
                        "point index " + std::to_string(index) + " out of sequence, expected " +
                            std::to_string(result.index_base + i));
        }
        result.points.push_back({source.number(tokens[1], line, "x"),
                                 source.number(tokens[2], line, "y"),
                                 source.number(tokens[3], line, "z")});
        for (std::size_t a = 0; a < attributes; ++a) {
            result.attributes.push_back(source.number(tokens[4 + a], line, "attribute"));
        }
        if (weighted) {
            result.weights.push_back(result.attributes[i * attributes]);
        }
        if (markers == 1) {
            result.markers.push_back(
                source.integer(tokens[4 + attributes], line, "boundary marker"));
        }
    }
    if (lines.next()) {
        source.fail(lines.number(),
                    "data after the " + std::to_string(count) + " points the header declares");
    }
    return result;
}

}  // namespace cavity::core
