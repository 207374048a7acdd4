#pragma once

#include <cstdint>
#include <optional>

#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/point.h"

/// Whether the point a + (k / 2^j)(b - a) of a segment between double points has double
/// coordinates, decided in 128-bit integers: split_point asks it of up to ten dyadic parameters per
/// split, and answering in GMP rationals (three conversions of an implicit point, each with gcds)
/// was most of the cost of choosing a split.
namespace cavity::core {

using predicates::Point3;

/// The answer: `decided` false when the integers cannot hold the question (the coordinates of a
/// and b differ by more than 2^60 in their binades' spacings); then ask the rationals.
struct DyadicPoint {
    bool decided;
    bool is_double;
    Point3 point;  ///< the exact point, when is_double
};

/// For finite a, b, 0 < j <= 10 and 0 < k < 2^j. Per coordinate, 2^j (a + (k / 2^j)(b - a)) =
/// (2^j - k) a + k b is an integer times the finer spacing of a's and b's: exact in 128 bits.
DyadicPoint dyadic_point(const Point3& a, const Point3& b, std::int64_t k, int j);

/// The doubles nearest to the coordinates of s, an implicit split point whose parameter is
/// n / 2^j (0 < n < 2^j, an integer): (2^j - n) a + n b in 128-bit integers, rounded once. Edge
/// protection rounds every implicit point it makes, and the GMP rationals took some 24 k
/// instructions a point. nullopt when the integers cannot hold it, when a coordinate lies exactly
/// halfway between two doubles (the rationals' rounding breaks that tie), or below the normal
/// range: then ask the rationals.
std::optional<Point3> rounded_dyadic_point(const predicates::SegmentParameterPoint& s);

}  // namespace cavity::core
