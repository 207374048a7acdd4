#pragma once

#include <cstdint>
#include <random>

#include "query.h"

/// Seeded, reproducible query families for the oracle agreement tests (predicates.md §6):
/// random, exactly degenerate, near-degenerate and extreme-magnitude inputs.
namespace cavity::predicates::testing {

/// A deterministic random source; the same seed gives the same queries on every run.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : engine_(seed) {}

    std::uint64_t bits() { return engine_(); }

    /// Uniform in [lo, hi].
    std::int64_t integer(std::int64_t lo, std::int64_t hi);

    /// Uniform in [-1, 1) with 53 random bits (every double of the grid 2^-52 Z equally likely).
    double unit();

    bool coin() { return (engine_() & 1) != 0; }

private:
    std::mt19937_64 engine_;
};

/// Coordinates and weights uniform in [-1, 1).
Query random_query(Kind k, Rng& rng);

/// Exactly degenerate, from small integers: coplanar points (orient3d), points of the integer
/// sphere x^2 + y^2 + z^2 = 882 about an integer centre (insphere), weights w = |p|^2 - h(p) for an
/// integer affine h, so that the lifted points are cohyperplanar (orient4d). The oracle says 0.
Query degenerate_query(Kind k, Rng& rng);

/// A degenerate query moved 1-4 ulps in a few entries with nextafter, or scaled by a decimal step
/// such as 0.1 that rounds every entry (the "i * 0.1 grid").
Query near_degenerate_query(Kind k, Rng& rng);

/// A random, degenerate or near-degenerate query scaled by 2^+-1000 or 10^+-300, made subnormal,
/// scaled per point by unrelated powers of two, or offset by 1e6..1e15 with small spacing.
Query extreme_query(Kind k, Rng& rng);

/// One of the four families above, chosen at random.
Query any_query(Kind k, Rng& rng);

}  // namespace cavity::predicates::testing
