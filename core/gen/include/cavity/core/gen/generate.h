#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

/// How generated points are weighted.
struct WeightSpec {
    enum class Kind { kNone, kZero, kEqual, kUniform };
    Kind kind = Kind::kNone;
    double a = 0.0;  ///< kEqual: the weight; kUniform: lower bound
    double b = 0.0;  ///< kUniform: upper bound (exclusive)
};

/// "none", "zero", "equal:W" or "uniform:A:B" (A < B, finite). \throws Error otherwise.
WeightSpec parse_weight_spec(std::string_view spec);

struct Distribution {
    std::string_view name;
    std::string_view description;
};

/// Every distribution generate_points() knows, in a fixed order (for help texts).
std::span<const Distribution> distributions();

/// Generates points of a named distribution (see distributions() for the list and the exact
/// construction of each). Most make exactly n points; `grid` makes k^3 with k = round(cbrt n),
/// `paraboloid` k^2 with k = round(sqrt n). The result depends only on the arguments: the random
/// streams are Random(seed) (positions) and Random(~seed) (weights), and every transform uses
/// exactly rounded arithmetic, so the points are the same on every platform. index_base is 0.
/// \throws Error for an unknown distribution, n = 0, n >= 2^32, a `moment` curve whose t^3
/// would not be an exact double (n > 208064), or `cospherical` beyond 30000 points.
PointSet generate_points(std::string_view distribution,
                         std::size_t n,
                         std::uint64_t seed,
                         const WeightSpec& weights = {});

}  // namespace cavity::core
