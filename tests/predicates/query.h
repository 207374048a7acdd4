#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "cavity/predicates/sign.h"

/// A predicate query as the flat list of numbers `cavity sign` reads, so that every query a test
/// draws can be printed as a replayable line.
namespace cavity::predicates::testing {

enum class Kind { kOrient3d, kInsphere, kOrient4d };

struct Query {
    Kind kind;
    std::array<double, 20> v{};  ///< points one after another: x y z (and w for orient4d)
};

/// Numbers per point: 3, or 4 for orient4d (x y z w).
constexpr std::size_t stride(Kind k) {
    return k == Kind::kOrient4d ? 4 : 3;
}

constexpr std::size_t point_count(Kind k) {
    return k == Kind::kOrient3d ? 4 : 5;
}

constexpr std::size_t value_count(Kind k) {
    return stride(k) * point_count(k);
}

/// True when entry i of a query of kind k is a weight rather than a coordinate.
constexpr bool is_weight(Kind k, std::size_t i) {
    return k == Kind::kOrient4d && i % 4 == 3;
}

const char* kind_name(Kind k);

/// The query as a `cavity sign` input line with every number in C99 hex-float (bit-exact).
std::string to_line(const Query& q);

/// The signs of the three evaluations under test.
struct Signs {
    Sign fast;    ///< orient3d / insphere / orient4d
    Sign staged;  ///< the sign of the _staged variant
};

Signs evaluate(const Query& q);

Sign evaluate_oracle(const Query& q);

}  // namespace cavity::predicates::testing
