#include <limits>

#include "cavity/core/io/mesh_io.h"
#include "text_input.h"

namespace cavity::core {

std::vector<Tet> read_ele(const std::filesystem::path& file, int index_base) {
    const TextSource source(file.string());
    const std::string bytes = read_file_bytes(file);
    LineReader lines(bytes);
    if (!lines.next()) {
        source.fail("empty file: no .ele header");
    }
    const std::size_t header_line = lines.number();
    const auto header = split_whitespace(lines.text());
    if (header.size() < 2 || header.size() > 3) {
        source.fail(header_line, "expected '<#tets> <nodes per tet> [<#attributes>]'");
    }
    // The number of attributes is bounded by the file's size before it is added to anything; the
    // loop below stops where the file ends, whatever the number of tets claims.
    const std::uint64_t count = source.count(header[0], header_line, "number of tets");
    if (source.count(header[1], header_line, "nodes per tet") != 4) {
        source.fail(header_line, "only linear tets (4 nodes per tet) are supported");
    }
    const std::uint64_t attributes = header.size() > 2
                                         ? source.count_at_most(header[2],
                                                                header_line,
                                                                "number of attributes",
                                                                bytes.size(),
                                                                "the file's size in bytes")
                                         : 0;

    const std::uint64_t base = static_cast<std::uint64_t>(index_base);
    const std::uint64_t largest = std::numeric_limits<std::uint32_t>::max() + base;
    std::vector<Tet> tets;
    std::uint64_t first_number = 0;
    for (std::uint64_t t = 0; t < count; ++t) {
        if (!lines.next()) {
            source.fail(
                lines.number(),
                "file ends after " + std::to_string(t) + " of " + std::to_string(count) + " tets");
        }
        const std::size_t line = lines.number();
        const auto tokens = split_whitespace(lines.text());
        if (tokens.size() != 5 + attributes) {
            source.fail(line,
                        "expected " + std::to_string(5 + attributes) + " fields, found " +
                            std::to_string(tokens.size()));
        }
        const std::uint64_t number = source.count(tokens[0], line, "tet number");
        if (t == 0) {
            if (number > 1) {
                source.fail(line, "the first tet number must be 0 or 1");
            }
            first_number = number;
        } else if (number != first_number + t) {
            source.fail(line,
                        "tet number " + std::to_string(number) + " out of sequence, expected " +
                            std::to_string(first_number + t));
        }
        Tet tet{};
        for (int i = 0; i < 4; ++i) {
            const std::uint64_t v = source.count(tokens[1 + i], line, "vertex");
            if (v < base || v > largest) {
                source.fail(line, "vertex " + std::to_string(v) + " outside the point numbering");
            }
            tet[i] = static_cast<std::uint32_t>(v - base);
        }
        tets.push_back(tet);
    }
    if (lines.next()) {
        source.fail(lines.number(),
                    "data after the " + std::to_string(count) + " tets the header declares");
    }
    return tets;
}

}  // namespace cavity::core
