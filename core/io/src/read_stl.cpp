// STL (stereolithography), binary or ASCII. STL has no shared vertices: every triangle lists its
// three coordinates, so exactly equal coordinates are merged into one point here.

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "surface_readers.h"
#include "text_input.h"

namespace cavity::core {

namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kTriangleBytes = 50;  // normal and 3 corners (12 floats), 2 attribute bytes

/// Gives each distinct coordinate triple the index of its first appearance (deterministic).
class PointMerger {
public:
    explicit PointMerger(Plc& plc) : plc_(plc) {}

    std::uint32_t index(const Point3& p) {
        // -0.0 == 0.0: the same coordinate, so the key uses +0.0 for both.
        const Key key{std::bit_cast<std::uint64_t>(p.x == 0 ? 0.0 : p.x),
                      std::bit_cast<std::uint64_t>(p.y == 0 ? 0.0 : p.y),
                      std::bit_cast<std::uint64_t>(p.z == 0 ? 0.0 : p.z)};
        const auto [it, inserted] =
            index_.try_emplace(key, static_cast<std::uint32_t>(plc_.points.size()));
        if (inserted) {
            plc_.points.points.push_back(p);
        }
        return it->second;
    }

private:
    using Key = std::array<std::uint64_t, 3>;

    /// The bits of the three coordinates mixed (splitmix64's finalizer on a combination): a
    /// hash table, not an ordered map, since the index of first appearance is all that is kept.
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            std::uint64_t h =
                k[0] * 0x9e3779b97f4a7c15ULL ^ (k[1] + 0x632be59bd9b4e019ULL) ^ std::rotl(k[2], 31);
            h ^= h >> 30;
            h *= 0xbf58476d1ce4e5b9ULL;
            h ^= h >> 27;
            h *= 0x94d049bb133111ebULL;
            h ^= h >> 31;
            return static_cast<std::size_t>(h);
        }
    };

    Plc& plc_;
    std::unordered_map<Key, std::uint32_t, KeyHash> index_;
};

std::uint32_t little_endian_u32(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
    }
    return v;
}

Plc read_binary(const TextSource& source, std::string_view bytes) {
    if (bytes.size() < kHeaderBytes + 4) {
        source.fail("a binary STL file has at least 84 bytes, this one has " +
                    std::to_string(bytes.size()));
    }
    const std::uint64_t count = little_endian_u32(bytes, kHeaderBytes);
    const std::uint64_t expected = kHeaderBytes + 4 + kTriangleBytes * count;
    if (bytes.size() != expected) {
        source.fail("a binary STL file of " + std::to_string(count) + " triangles has " +
                    std::to_string(expected) + " bytes, this one has " +
                    std::to_string(bytes.size()) +
                    " (nor is it ASCII STL, which starts with 'solid' and has no NUL byte)");
    }
    Plc plc;
    PointMerger merger(plc);
    for (std::uint64_t t = 0; t < count; ++t) {
        const std::size_t start = kHeaderBytes + 4 + kTriangleBytes * t;
        std::vector<std::uint32_t> corners;
        for (std::size_t c = 0; c < 3; ++c) {
            std::array<double, 3> xyz{};
            for (std::size_t k = 0; k < 3; ++k) {
                const std::size_t at = start + 12 * (c + 1) + 4 * k;  // after the normal
                xyz[k] = std::bit_cast<float>(little_endian_u32(bytes, at));
                if (!std::isfinite(xyz[k])) {
                    source.fail("triangle " + std::to_string(t) + " corner " + std::to_string(c) +
                                ": not a finite number (byte " + std::to_string(at) + ")");
                }
            }
            corners.push_back(merger.index({xyz[0], xyz[1], xyz[2]}));
        }
        add_surface_face(plc, std::move(corners), 0);
    }
    return plc;
}

/// Splits the next data line into `fields`, which must start with the keyword `what`.
void expect(const TextSource& source,
            LineReader& lines,
            std::string_view what,
            std::vector<std::string_view>& fields) {
    if (!lines.next()) {
        source.fail(lines.number(), "file ends where '" + std::string(what) + "' was expected");
    }
    split_whitespace(lines.text(), fields);
    if (fields[0] != what) {
        source.fail(lines.number(),
                    "expected '" + std::string(what) + "', found '" + std::string(fields[0]) + "'");
    }
}

Plc read_ascii(const TextSource& source, std::string_view bytes) {
    Plc plc;
    PointMerger merger(plc);
    LineReader lines(bytes);
    bool in_solid = false;
    // One buffer of fields for every line: a file has seven lines a triangle.
    std::vector<std::string_view> fields;
    while (lines.next()) {
        split_whitespace(lines.text(), fields);
        if (!in_solid) {
            if (fields[0] != "solid") {
                source.fail(lines.number(),
                            "expected 'solid', found '" + std::string(fields[0]) + "'");
            }
            in_solid = true;
            continue;
        }
        if (fields[0] == "endsolid") {
            in_solid = false;
            continue;
        }
        if (fields[0] != "facet") {
            source.fail(lines.number(),
                        "expected 'facet' or 'endsolid', found '" + std::string(fields[0]) + "'");
        }
        const std::size_t facet_line = lines.number();
        if (fields.size() != 5 || fields[1] != "normal") {
            source.fail(facet_line, "a facet starts with 'facet normal nx ny nz'");
        }
        // The normal is not used (the corners' order gives the orientation), and exporters write
        // "nan" for it on degenerate triangles: such a file is refused by the surface check, which
        // names the facet, rather than here for a number nothing reads.
        expect(source, lines, "outer", fields);
        if (fields.size() != 2 || fields[1] != "loop") {
            source.fail(lines.number(), "expected 'outer loop'");
        }
        std::vector<std::uint32_t> corners;
        for (;;) {
            if (!lines.next()) {
                source.fail(lines.number(),
                            "file ends in the facet of line " + std::to_string(facet_line));
            }
            split_whitespace(lines.text(), fields);
            const auto& v = fields;
            if (v[0] == "endloop") {
                break;
            }
            if (v[0] != "vertex" || v.size() != 4) {
                source.fail(lines.number(), "expected 'vertex x y z' or 'endloop'");
            }
            corners.push_back(merger.index({source.number(v[1], lines.number(), "x"),
                                            source.number(v[2], lines.number(), "y"),
                                            source.number(v[3], lines.number(), "z")}));
        }
        if (corners.size() < 3) {
            source.fail(lines.number(),
                        "the facet of line " + std::to_string(facet_line) + " has " +
                            std::to_string(corners.size()) + " vertices; a facet needs 3");
        }
        expect(source, lines, "endfacet", fields);
        add_surface_face(plc, std::move(corners), facet_line);
    }
    if (in_solid) {
        source.fail(lines.number(), "file ends before 'endsolid'");
    }
    return plc;
}

bool starts_with_solid(std::string_view bytes) {
    LineReader lines(bytes);
    return lines.next() && split_whitespace(lines.text())[0] == "solid";
}

}  // namespace

Plc read_stl(const std::string& file, std::string_view bytes) {
    const TextSource source(file);
    if (bytes.empty()) {
        source.fail("empty file");
    }
    // Many binary writers start the header with "solid" too, so a size that agrees with the
    // binary triangle count decides first; a file with NUL bytes is no ASCII STL either (a
    // truncated binary one is then refused by its size, not parsed as text).
    const bool binary_size =
        bytes.size() >= kHeaderBytes + 4 &&
        bytes.size() == kHeaderBytes + 4 +
                            kTriangleBytes * std::uint64_t{little_endian_u32(bytes, kHeaderBytes)};
    const bool text = starts_with_solid(bytes) && bytes.find('\0') == std::string_view::npos;
    Plc plc = binary_size || !text ? read_binary(source, bytes) : read_ascii(source, bytes);
    plc.points.index_base = 0;
    return plc;
}

}  // namespace cavity::core
