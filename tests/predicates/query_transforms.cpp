#include "query_transforms.h"

#include <cmath>
#include <utility>

namespace cavity::predicates::testing {

namespace {

// True when x + t is a double, i.e. the rounding error of the sum (Knuth's two-sum) is zero.
bool sum_is_exact(double x, double t) {
    const double s = x + t;
    const double t_part = s - x;
    const double x_part = s - t_part;
    return (x - x_part) + (t - t_part) == 0.0 && std::isfinite(s);
}

}  // namespace

Permuted randomly_permuted(const Query& q, Rng& rng) {
    const std::size_t n = point_count(q.kind);
    const std::size_t st = stride(q.kind);
    std::array<std::size_t, 5> order{0, 1, 2, 3, 4};
    int parity = 1;
    for (std::size_t i = n - 1; i > 0; --i) {  // Fisher-Yates; each real swap is a transposition
        const auto j = static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(i)));
        if (j != i) {
            std::swap(order[i], order[j]);
            parity = -parity;
        }
    }
    Permuted result{Query{q.kind}, parity};
    for (std::size_t p = 0; p < n; ++p) {
        for (std::size_t j = 0; j < st; ++j) {
            result.query.v[st * p + j] = q.v[st * order[p] + j];
        }
    }
    return result;
}

std::optional<Query> translated_by_powers_of_two(const Query& q, Rng& rng) {
    const std::size_t st = stride(q.kind);
    Query result = q;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        const double direction = rng.coin() ? 1.0 : -1.0;
        // Try 2^40 down to 2^0 from a random start; integer-based queries admit the large ones.
        bool exact = false;
        for (auto e = static_cast<int>(rng.integer(0, 40)); e >= 0 && !exact; --e) {
            const double t = std::ldexp(direction, e);
            exact = true;
            for (std::size_t p = 0; p < point_count(q.kind); ++p) {
                exact = exact && sum_is_exact(q.v[st * p + axis], t);
            }
            if (exact) {
                for (std::size_t p = 0; p < point_count(q.kind); ++p) {
                    result.v[st * p + axis] = q.v[st * p + axis] + t;
                }
            }
        }
        if (!exact) {
            return std::nullopt;
        }
    }
    return result;
}

}  // namespace cavity::predicates::testing
