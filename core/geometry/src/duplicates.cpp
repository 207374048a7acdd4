#include "cavity/core/geometry/duplicates.h"

#include <algorithm>
#include <bit>

#include "cavity/core/base/on_threads.h"

namespace cavity::core {

namespace {

/// Below this many points per thread, threads cost more than they save.
constexpr std::size_t kPointsPerThread = std::size_t{1} << 16;
constexpr std::uint32_t kEmpty = 0xFFFF'FFFFu;

std::uint64_t bits(double x) {
    return std::bit_cast<std::uint64_t>(x + 0.0);
}  // -0.0 -> +0.0

std::uint64_t mix(std::uint64_t h, double x) {
    h ^= bits(x) + 0x9E37'79B9'7F4A'7C15ull + (h << 6) + (h >> 2);
    h *= 0xBF58'476D'1CE4'E5B9ull;
    return h ^ (h >> 31);
}

/// An open-addressing table of point indices, at most half full.
std::vector<std::uint32_t> empty_table(std::size_t points) {
    std::size_t size = 16;
    while (size < 2 * points) {
        size *= 2;
    }
    return std::vector<std::uint32_t>(size, kEmpty);
}

}  // namespace

std::vector<std::uint32_t> first_occurrences(std::span<const predicates::Point3> points,
                                             std::span<const double> weights,
                                             unsigned threads) {
    const std::size_t n = points.size();
    std::vector<std::uint32_t> first(n);
    const auto hash = [&](std::size_t i) {
        std::uint64_t h = mix(mix(mix(0, points[i].x), points[i].y), points[i].z);
        if (!weights.empty()) {
            h = mix(h, weights[i]);
        }
        return h;
    };
    const auto same = [&](std::size_t a, std::size_t b) {
        const auto& p = points[a];
        const auto& q = points[b];
        return p.x == q.x && p.y == q.y && p.z == q.z &&
               (weights.empty() || weights[a] == weights[b]);
    };
    // Points are taken in index order, so a repeat always finds its first occurrence there.
    const auto place = [&](std::vector<std::uint32_t>& table, std::size_t i, std::uint64_t h) {
        const std::size_t mask = table.size() - 1;
        std::size_t s = static_cast<std::size_t>(h) & mask;
        while (table[s] != kEmpty && !same(table[s], i)) {
            s = (s + 1) & mask;
        }
        if (table[s] == kEmpty) {
            table[s] = static_cast<std::uint32_t>(i);
        }
        first[i] = table[s];
    };
    const unsigned parts = static_cast<unsigned>(
        std::clamp<std::size_t>(n / kPointsPerThread, 1, std::max(1u, threads)));
    if (parts == 1) {
        std::vector<std::uint32_t> table = empty_table(n);
        for (std::size_t i = 0; i < n; ++i) {
            place(table, i, hash(i));
        }
        return first;
    }
    // The high half of a hash picks one of `parts` tables, the low half a slot in it. Equal
    // points hash alike, so each table is filled by one thread going through the points of its
    // part in index order: the result is the one-table result, and each thread's random
    // accesses stay in its own table. A first pass hashes the points and counts each part's.
    const auto part_of = [parts](std::uint64_t h) {
        return static_cast<unsigned>((h >> 32) * parts >> 32);
    };
    std::vector<std::uint64_t> hashes(n);
    std::vector<std::size_t> count(std::size_t{parts} * parts, 0);
    on_threads(parts, [&](unsigned k) {
        for (std::size_t i = n * k / parts; i < n * (k + 1) / parts; ++i) {
            hashes[i] = hash(i);
            ++count[std::size_t{k} * parts + part_of(hashes[i])];
        }
    });
    std::vector<std::vector<std::uint32_t>> tables(parts);
    for (unsigned p = 0; p < parts; ++p) {
        std::size_t in_part = 0;
        for (unsigned k = 0; k < parts; ++k) {
            in_part += count[std::size_t{k} * parts + p];
        }
        tables[p] = empty_table(in_part);
    }
    on_threads(parts, [&](unsigned p) {
        for (std::size_t i = 0; i < n; ++i) {
            if (part_of(hashes[i]) == p) {
                place(tables[p], i, hashes[i]);
            }
        }
    });
    return first;
}

}  // namespace cavity::core
