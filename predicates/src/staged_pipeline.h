#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"
#include "cavity/predicates/stage.h"

// The stages after the filter, shared by the three predicates: a range check on the exponents of
// the inputs (the expansion arithmetic is exact only without overflow and underflow), an exact
// rescaling by a power of two when the inputs are out of range but not too spread out, and the
// fall-through to exact integers.
namespace cavity::predicates::detail {

/// Input exponents (std::ilogb, so |v| in [2^e, 2^(e+1))) between which a predicate's expansion
/// stage is exact. Weights, of degree 2, count at half their exponent.
struct ExponentWindow {
    int min;
    int max;
};

/// The range of exponents of the nonzero inputs of one query (empty when all are zero).
class ExponentRange {
public:
    void add(const Point3& p) {
        add_exponent(p.x);
        add_exponent(p.y);
        add_exponent(p.z);
    }

    void add(const WeightedPoint3& p) {
        add_exponent(p.x);
        add_exponent(p.y);
        add_exponent(p.z);
        if (p.w != 0.0) {
            // |w| in [2^e, 2^(e+1)) lies in [2^(2h), 2^(2h+2)) for h = floor(e / 2): a weight is
            // in range exactly when a coordinate of exponent h would be.
            const int e = exponent_of(p.w);
            include(e >= 0 ? e / 2 : -((1 - e) / 2));
        }
    }

    /// A shift k moving every exponent into the window, centred in the admissible interval so
    /// that the filter's range guards also hold; none when the exponents spread wider than the
    /// window.
    std::optional<int> shift_into(ExponentWindow w) const {
        const int k_min = w.min - lo_;
        const int k_max = w.max - hi_;
        if (k_min > k_max) {
            return std::nullopt;
        }
        return k_min + (k_max - k_min) / 2;
    }

private:
    void add_exponent(double v) {
        if (v != 0.0) {
            include(exponent_of(v));
        }
    }

    /// std::ilogb of a nonzero v, read from the exponent field (a libm call only for subnormals).
    static int exponent_of(double v) {
        const int biased = static_cast<int>((std::bit_cast<std::uint64_t>(v) >> 52) & 0x7ff);
        return biased != 0 ? biased - 1023 : std::ilogb(v);
    }

    void include(int e) {
        lo_ = std::min(lo_, e);
        hi_ = std::max(hi_, e);
    }

    int lo_ = INT_MAX;
    int hi_ = INT_MIN;
};

/// 2^k for a normal power of two (k in [-1022, 1023]), from its bits.
constexpr double power_of_two(int k) {
    return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
}

/// True when the exponent of every nonzero input lies in the window (a weight's at half its
/// exponent, as ExponentRange counts it): |v| in [2^min, 2^(max+1)), a weight's in
/// [2^(2 min), 2^(2 max + 2)). Magnitude comparisons without a branch per value: every query past
/// the filter asks this, and almost all are in the window. Infinities, NaNs and subnormals are
/// outside. The window's bounds must be normal powers of two.
template <typename P, std::size_t N>
bool within(const std::array<P, N>& points, ExponentWindow w) {
    bool in = true;
    const auto check = [&in](double v, double lo, double hi) {
        const double a = std::abs(v);
        in &= (a == 0.0) | ((a >= lo) & (a < hi));
    };
    const double lo = power_of_two(w.min);
    const double hi = power_of_two(w.max + 1);
    for (const P& p : points) {
        check(p.x, lo, hi);
        check(p.y, lo, hi);
        check(p.z, lo, hi);
        if constexpr (std::is_same_v<P, WeightedPoint3>) {
            check(p.w, power_of_two(2 * w.min), power_of_two(2 * w.max + 2));
        }
    }
    return in;
}

// Scaling by 2^k (weights by 2^2k) is exact here: every scaled value lands in the window, far
// inside the normal range, so it keeps all its significant bits. The determinants are
// homogeneous (degree 3 or 5, weights of degree 2), so the sign is unchanged.
inline Point3 scaled(const Point3& p, int k) {
    return {std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k)};
}

inline WeightedPoint3 scaled(const WeightedPoint3& p, int k) {
    return {std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k), std::ldexp(p.w, 2 * k)};
}

/// Runs the stages after a failed filter on the query `points`. `filter(points)` returns +1, -1
/// or 0 (undecided); `adaptive(points)`, valid only for inputs in `window`, the verdict of the
/// expansion stages (kAdaptive for stages B and C, kExact for the exact expansion with the
/// difference tails) or none when its expansions would outgrow their buffers; `exact(points)` the
/// exact Sign by GMP for any input (the inputs too spread out for any power-of-two shift to bring
/// them into the window, and the rare overflow of the expansion buffers).
template <typename P, std::size_t N, typename Filter, typename Adaptive, typename Exact>
Verdict run_after_filter(
    std::array<P, N> points, ExponentWindow window, Filter filter, Adaptive adaptive, Exact exact) {
    if (!within(points, window)) {
        ExponentRange range;
        for (const P& p : points) {
            range.add(p);
        }
        const std::optional<int> shift = range.shift_into(window);
        if (!shift) {
            return {exact(points), Stage::kExact};
        }
        for (P& p : points) {
            p = scaled(p, *shift);
        }
        // The filter failed on the original inputs by its range guards; it usually succeeds now.
        if (const int s = filter(points)) {
            return {static_cast<Sign>(s), Stage::kFilter};
        }
    }
    if (const std::optional<Verdict> v = adaptive(points)) {
        return *v;
    }
    return {exact(points), Stage::kExact};
}

}  // namespace cavity::predicates::detail
