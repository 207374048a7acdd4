#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "cavity/predicates/point.h"

/// The seeded random doubles the predicate suites that build their own inputs share: uniform
/// values, exponent spreads, ulp moves and directions. The same seed gives the same inputs.
namespace cavity::predicates::testing {

class RandomSource {
public:
    explicit RandomSource(std::uint64_t seed) : rng_(seed) {}

    /// Uniform in [lo, hi].
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

    /// Uniform in [-1, 1).
    double unit() { return std::uniform_real_distribution<double>(-1.0, 1.0)(rng_); }

    /// Moves v by 1-4 ulps up or down.
    double nudged(double v) {
        const double toward = integer(0, 1) == 0 ? std::numeric_limits<double>::infinity()
                                                 : -std::numeric_limits<double>::infinity();
        for (int step = integer(1, 4); step > 0; --step) {
            v = std::nextafter(v, toward);
        }
        return v;
    }

    /// A random double of magnitude 2^-20..2^40, so that differences of two are mostly inexact.
    double spread() { return std::ldexp(unit(), integer(-20, 40)); }

    /// A random point: every coordinate 2^k times a uniform [-1, 1), k in [lo, hi]; with
    /// lo = -1074 and hi = 1023 it spans every finite double's magnitude.
    Point3 point(int lo, int hi) {
        return {std::ldexp(unit(), integer(lo, hi)),
                std::ldexp(unit(), integer(lo, hi)),
                std::ldexp(unit(), integer(lo, hi))};
    }

    /// A unit vector, rounded.
    std::array<double, 3> direction() {
        std::normal_distribution<double> normal;
        const double x = normal(rng_), y = normal(rng_), z = normal(rng_);
        const double n = std::sqrt(x * x + y * y + z * z);
        return {x / n, y / n, z / n};
    }

private:
    std::mt19937_64 rng_;
};

}  // namespace cavity::predicates::testing
