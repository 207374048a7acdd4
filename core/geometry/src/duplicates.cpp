#include "cavity/core/geometry/duplicates.h"

#include <bit>

namespace cavity::core {

namespace {

std::uint64_t bits(double x) {
    return std::bit_cast<std::uint64_t>(x + 0.0);
}  // -0.0 -> +0.0

std::uint64_t mix(std::uint64_t h, double x) {
    h ^= bits(x) + 0x9E37'79B9'7F4A'7C15ull + (h << 6) + (h >> 2);
    h *= 0xBF58'476D'1CE4'E5B9ull;
    return h ^ (h >> 31);
}

}  // namespace

std::vector<std::uint32_t> first_occurrences(std::span<const predicates::Point3> points,
                                             std::span<const double> weights) {
    const std::size_t n = points.size();
    std::vector<std::uint32_t> first(n);
    std::size_t size = 16;
    while (size < 2 * n) {
        size *= 2;
    }
    constexpr std::uint32_t kEmpty = 0xFFFF'FFFFu;
    std::vector<std::uint32_t> table(size, kEmpty);
    const auto same = [&](std::size_t a, std::size_t b) {
        const auto& p = points[a];
        const auto& q = points[b];
        return p.x == q.x && p.y == q.y && p.z == q.z &&
               (weights.empty() || weights[a] == weights[b]);
    };
    for (std::size_t i = 0; i < n; ++i) {
        std::uint64_t h = mix(mix(mix(0, points[i].x), points[i].y), points[i].z);
        if (!weights.empty()) {
            h = mix(h, weights[i]);
        }
        std::size_t s = static_cast<std::size_t>(h) & (size - 1);
        while (table[s] != kEmpty && !same(table[s], i)) {
            s = (s + 1) & (size - 1);
        }
        if (table[s] == kEmpty) {
            table[s] = static_cast<std::uint32_t>(i);
        }
        first[i] = table[s];
    }
    return first;
}

}  // namespace cavity::core
