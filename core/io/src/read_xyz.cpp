#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string>

#include "point_readers.h"
#include "text_input.h"

namespace cavity::core {

namespace {

/// Where x, y, z (and the weight) are among a line's fields.
struct Columns {
    std::array<std::size_t, 3> xyz{0, 1, 2};
    std::size_t weight = 3;
};

std::string lowercase(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) {
        return static_cast<char>(std::tolower(c));
    });
    return out;
}

/// A name, not a malformed number: starts with a letter or '_', and is not NaN or infinity.
bool is_name(std::string_view field) {
    if (field.empty() || !(std::isalpha(static_cast<unsigned char>(field[0])) || field[0] == '_')) {
        return false;
    }
    const std::string lower = lowercase(field);
    return lower != "nan" && lower != "inf" && lower != "infinity";
}

/// A first line made of names only is a header row ("x,y,z", "X Y Z nx ny nz", "x,y,z,weight"):
/// named columns are taken by name, otherwise by position. A line mixing numbers and words is
/// data, and its bad number is reported.
std::optional<Columns> header_columns(const std::vector<std::string_view>& fields) {
    if (!std::all_of(fields.begin(), fields.end(), is_name)) {
        return std::nullopt;
    }
    Columns columns;
    const auto find =
        [&fields](std::initializer_list<const char*> names) -> std::optional<std::size_t> {
        for (std::size_t i = 0; i < fields.size(); ++i) {
            for (const char* name : names) {
                if (lowercase(fields[i]) == name) {
                    return i;
                }
            }
        }
        return std::nullopt;
    };
    const auto x = find({"x"});
    const auto y = find({"y"});
    const auto z = find({"z"});
    if (x && y && z) {
        columns.xyz = {*x, *y, *z};
    }
    if (const auto w = find({"w", "weight"})) {
        columns.weight = *w;
    }
    return columns;
}

}  // namespace

PointSet read_xyz(const std::string& file, std::string_view bytes, bool weighted) {
    const TextSource source(file);
    LineReader lines(bytes);
    PointSet result;
    result.source = file;
    Columns columns;
    std::size_t width = 0;  // fields per line, fixed by the first data line
    bool first = true;
    while (lines.next()) {
        const std::size_t line = lines.number();
        const auto tokens = split_fields(lines.text());
        if (first) {
            first = false;
            if (const auto named = header_columns(tokens)) {
                columns = *named;
                continue;
            }
        }
        if (width == 0) {
            // Extra columns (normals, colours) are allowed and skipped; the point is in the
            // first three (or the named ones), the weight in the fourth (or "w"/"weight").
            width = tokens.size();
            const std::size_t needed = std::max({columns.xyz[0],
                                                 columns.xyz[1],
                                                 columns.xyz[2],
                                                 weighted ? columns.weight : std::size_t{0}}) +
                                       1;
            if (width < needed) {
                source.fail(line,
                            "expected at least " + std::to_string(needed) + " numbers" +
                                (weighted ? " (x y z weight)" : " (x y z)") + ", found " +
                                std::to_string(width));
            }
        } else if (tokens.size() != width) {
            source.fail(line,
                        "expected " + std::to_string(width) +
                            " fields, as on the first data line, found " +
                            std::to_string(tokens.size()));
        }
        result.points.push_back({source.number(tokens[columns.xyz[0]], line, "x"),
                                 source.number(tokens[columns.xyz[1]], line, "y"),
                                 source.number(tokens[columns.xyz[2]], line, "z")});
        if (weighted) {
            result.weights.push_back(source.number(tokens[columns.weight], line, "weight"));
        }
        if (result.points.size() > 0xFFFF'FFFFu) {
            source.fail(line, "more points than 32-bit indices can number");
        }
    }
    if (result.points.empty()) {
        source.fail("empty file: no points");
    }
    return result;
}

}  // namespace cavity::core
