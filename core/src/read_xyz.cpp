#include "point_readers.h"
#include "text_input.h"

namespace cavity::core {

PointSet read_xyz(const std::string& file, std::string_view bytes, bool weighted) {
    const TextSource source(file);
    LineReader lines(bytes);
    const std::size_t fields = weighted ? 4 : 3;
    PointSet result;
    result.source = file;
    while (lines.next()) {
        const std::size_t line = lines.number();
        const auto tokens = split_fields(lines.text());
        if (tokens.size() != fields) {
            source.fail(line,
                        "expected " + std::to_string(fields) + " numbers, found " +
                            std::to_string(tokens.size()));
        }
        result.points.push_back({source.number(tokens[0], line, "x"),
                                 source.number(tokens[1], line, "y"),
                                 source.number(tokens[2], line, "z")});
        if (weighted) {
            result.weights.push_back(source.number(tokens[3], line, "weight"));
        }
    }
    if (result.points.empty()) {
        source.fail("empty file: no points");
    }
    if (result.points.size() > 0xFFFF'FFFFu) {
        source.fail(lines.number(), "more points than 32-bit indices can number");
    }
    return result;
}

}  // namespace cavity::core
