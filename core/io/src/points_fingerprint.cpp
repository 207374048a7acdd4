#include "cavity/core/io/points_fingerprint.h"

#include <bit>
#include <charconv>
#include <fstream>
#include <string>

#include "cavity/core/base/error.h"

namespace cavity::core {

namespace {

constexpr std::uint64_t kFnvOffset = 0xcbf2'9ce4'8422'2325ull;
constexpr std::uint64_t kFnvPrime = 0x0000'0100'0000'01b3ull;
constexpr std::string_view kCommentLead = "# cavity: points fingerprint ";

std::uint64_t mix(std::uint64_t h, std::uint64_t word) {
    for (int byte = 0; byte < 8; ++byte) {
        h = (h ^ ((word >> (8 * byte)) & 0xffu)) * kFnvPrime;
    }
    return h;
}

}  // namespace

std::uint64_t points_fingerprint(const PointSet& points) {
    std::uint64_t h = mix(kFnvOffset, points.size());
    for (const Point3& p : points.points) {
        h = mix(h, std::bit_cast<std::uint64_t>(p.x));
        h = mix(h, std::bit_cast<std::uint64_t>(p.y));
        h = mix(h, std::bit_cast<std::uint64_t>(p.z));
    }
    return h;
}

std::string points_fingerprint_comment(std::uint64_t fingerprint) {
    char digits[16];
    const auto end = std::to_chars(digits, digits + sizeof digits, fingerprint, 16).ptr;
    std::string text(kCommentLead);
    text.append(static_cast<std::size_t>(16 - (end - digits)), '0');
    text.append(digits, end);
    return text;
}

std::optional<std::uint64_t> read_points_fingerprint(const std::filesystem::path& ele) {
    std::ifstream in(ele);
    if (!in) {
        throw Error(located_message(ele.string(), std::nullopt, "cannot open"));
    }
    std::string line;
    std::size_t number = 0;
    while (std::getline(in, line)) {
        ++number;
        const std::size_t at = line.find(kCommentLead);
        if (at != std::string::npos) {
            std::uint64_t value = 0;
            const char* first = line.data() + at + kCommentLead.size();
            const char* last = line.data() + line.size();
            const auto [ptr, error] = std::from_chars(first, last, value, 16);
            if (error == std::errc() && ptr - first == 16) {
                return value;
            }
            throw Error(located_message(ele.string(), number, "malformed points fingerprint"));
        }
        if (line.find_first_not_of(" \t\r") != std::string::npos && line[0] != '#') {
            return std::nullopt;  // the header names none
        }
    }
    return std::nullopt;
}

void check_points_fingerprint(const std::filesystem::path& ele,
                              const std::string& node,
                              const PointSet& points) {
    const std::optional<std::uint64_t> named = read_points_fingerprint(ele);
    const std::uint64_t actual = points_fingerprint(points);
    if (named && *named != actual) {
        throw Error(located_message(
            ele.string(),
            std::nullopt,
            "was written for other points than those of " + node + " (" +
                points_fingerprint_comment(*named).substr(2) + ", but " + node + " has " +
                points_fingerprint_comment(actual).substr(kCommentLead.size()) +
                "): the two files come from different runs"));
    }
}

}  // namespace cavity::core
