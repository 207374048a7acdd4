#pragma once

#include <array>
#include <optional>

#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"

// The exact insphere of doubles that are all integer multiples of one power of two below 2^61
// times it: the common case of the queries that reach the exact stages of the expansion
// predicates. A CAD model's vertices have coordinates of a few nearby magnitudes, and its many
// cospherical sets make exact zeros, each of which those stages prove with a full exact
// expansion. Here the coordinates are scaled to 64-bit integers and the determinant is evaluated
// in fixed-width integers of up to 320 bits: on cheese.off's CDT, about 3.2 k instructions per
// query against 13 k for the expansion stage it stands in for. (orient3d's exact stages cost
// about what the scaling alone does, so it has no such path.)
namespace cavity::predicates::detail {

/// The largest magnitude, exclusive, of a scaled coordinate: with |X| < 2^61 every difference is
/// below 2^62 and the determinant below 2^317 (see the .cpp).
inline constexpr int kScaledIntegerBits = 61;

/// The exact sign of insphere(p[0], ..., p[4]) when some 2^E makes every coordinate an integer
/// times 2^E below 2^kScaledIntegerBits in magnitude; none otherwise (then the exponents of the
/// coordinates, trailing zeros of their significands counted, span more than 61 bits). Every
/// finite double is accepted as input; non-finite ones give none.
std::optional<Sign> insphere_scaled_integers(const std::array<Point3, 5>& p);

/// The bit length, exclusive, of a scaled coordinate of a generic query below.
inline constexpr int kWideScaledIntegerBits = 124;

/// The exact sign of insphere on generic points when each is explicit or a segment point with a
/// dyadic parameter (a power of two for denominator, as edge protection makes them), their
/// defining doubles span at most 61 bits as above, and the exact coordinates, scaled by one power
/// of two, are integers below 2^kWideScaledIntegerBits (then evaluated in up to 640 bits); none
/// otherwise (and for any LinePlanePoint).
std::optional<Sign> insphere_scaled_integers(const std::array<const GenericPoint3*, 5>& g);

}  // namespace cavity::predicates::detail
