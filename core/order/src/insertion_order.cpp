#include "cavity/core/order/insertion_order.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/order/spatial_sort.h"

namespace cavity::core {

namespace {

// With a ratio ρ near 1 the number of rounds, about ln(n) / (1 - ρ), would explode.
constexpr std::uint32_t kMaxBrioRounds = 4096;

std::vector<std::uint32_t> identity(std::size_t n) {
    std::vector<std::uint32_t> sequence(n);
    std::iota(sequence.begin(), sequence.end(), std::uint32_t{0});
    return sequence;
}

std::vector<std::uint32_t> random_order(std::size_t n, std::uint64_t seed) {
    std::vector<std::uint32_t> sequence = identity(n);
    Random random(seed);
    for (std::size_t i = n; i > 1; --i) {
        const auto j = static_cast<std::size_t>(random.below(i));
        std::swap(sequence[i - 1], sequence[j]);
    }
    return sequence;
}

// The last round R is the first whose expected occupancy of round 0, n ρ^R, is at most one point;
// for ρ = 1/2 that is R = ceil(log2 n), the book's round count.
std::uint32_t brio_last_round(std::size_t n, double ratio) {
    std::uint32_t last = 0;
    for (double share = static_cast<double>(n); share > 1.0; share *= ratio) {
        if (++last > kMaxBrioRounds) {
            throw Error("brio_ratio " + std::to_string(ratio) + " needs more than " +
                        std::to_string(kMaxBrioRounds) + " rounds");
        }
    }
    return last;
}

InsertionOrder brio_order(std::span<const Point3> points, const OrderOptions& options) {
    const double ratio = options.brio_ratio;
    if (!(ratio >= 0.0 && ratio < 1.0)) {
        throw Error("brio_ratio must be in [0, 1), got " + std::to_string(ratio));
    }
    const std::size_t n = points.size();
    InsertionOrder order;
    if (n == 0) {
        return order;
    }
    const std::uint32_t last = brio_last_round(n, ratio);
    Random random(options.seed);
    std::vector<std::uint32_t> round_of(n);
    std::vector<std::uint32_t> round_size(last + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        std::uint32_t round = last;
        // Down a round with probability ρ; written so that ρ = 1/2 draws the same rounds from the
        // same seed as before the ratio took the literature's meaning.
        while (round > 0 && !(random.uniform01() < 1.0 - ratio)) {
            --round;
        }
        round_of[i] = round;
        ++round_size[round];
    }
    // Counting sort by round; within a round the input order is kept until the curve sort.
    order.round_begin.resize(last + 1);
    std::uint32_t begin = 0;
    for (std::uint32_t r = 0; r <= last; ++r) {
        order.round_begin[r] = begin;
        begin += round_size[r];
    }
    order.sequence.resize(n);
    std::vector<std::uint32_t> fill = order.round_begin;
    for (std::size_t i = 0; i < n; ++i) {
        order.sequence[fill[round_of[i]]++] = static_cast<std::uint32_t>(i);
    }
    // Round by round, each with every thread: the last round holds most of the points.
    for (std::uint32_t r = 0; r <= last; ++r) {
        const std::span<std::uint32_t> round(order.sequence.data() + order.round_begin[r],
                                             round_size[r]);
        hilbert_sort(points, round, options.threads);
        if (options.reverse_alternate_rounds && r % 2 == 0) {
            std::reverse(round.begin(), round.end());
        }
    }
    return order;
}

}  // namespace

OrderKind parse_order_kind(std::string_view name) {
    return parse_kind(kOrderKinds, name, "insertion order");
}

InsertionOrder make_insertion_order(std::span<const Point3> points, const OrderOptions& options) {
    if (points.size() > 0xFFFF'FFFFu) {
        throw Error("more than 2^32-1 points cannot be numbered by 32-bit indices");
    }
    InsertionOrder order;
    switch (options.kind) {
        case OrderKind::kInput:
            order.sequence = identity(points.size());
            break;
        case OrderKind::kRandom:
            order.sequence = random_order(points.size(), options.seed);
            break;
        case OrderKind::kBrio:
            order = brio_order(points, options);
            break;
        case OrderKind::kHilbert:
            order.sequence = identity(points.size());
            hilbert_sort(points, order.sequence, options.threads);
            break;
        case OrderKind::kZOrder:
            order.sequence = identity(points.size());
            morton_sort(points, order.sequence, options.threads);
            break;
    }
    return order;
}

}  // namespace cavity::core
