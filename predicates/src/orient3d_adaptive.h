#pragma once

#include <array>
#include <optional>

#include "cavity/predicates/point.h"
#include "cavity/predicates/stage.h"
#include "double_double.h"
#include "staged_pipeline.h"

// The stages of orient3d after the filter: when the coordinate differences are exact, their
// determinant in 64- and 128-bit integers if they lie on coarse grids (small_dyadic.h, the exact
// zeros of coplanar grid points); the determinant of the exact differences (rounded + tail) in
// double-double arithmetic under a certified bound, which settles almost every in-range query;
// then Shewchuk's orient3dadapt, with bounds derived for this evaluation order: B, the exact
// determinant of the rounded differences; C, B plus the first-order terms of the difference tails
// in floating point, under a certified bound; D, the exact determinant of the two-component
// differences.
namespace cavity::predicates::detail {

// Inputs with exponents in [-280, 300]: differences and their tails are multiples of 2^-332 below
// 2^302, so every product of up to three of them (and of their 26-bit halves) is a multiple of
// 2^-996, a normal number when nonzero, and below 2^910: neither the floating-point stage C nor
// the expansion arithmetic underflows or overflows.
inline constexpr ExponentWindow kOrient3dAdaptiveWindow = {-280, 300};

/// The double-double stage alone: the sign of det[x; y; z] (the rows the exact differences of a,
/// b, c to d as double-doubles, from exact_difference) when certified by its error bound; none
/// otherwise. Requires inputs in kOrient3dAdaptiveWindow. Exposed for the tests that probe the
/// bound.
std::optional<Sign> orient3d_double_double(const DoubleDouble (&x)[3],
                                           const DoubleDouble (&y)[3],
                                           const DoubleDouble (&z)[3]);

/// The verdict of the small-dyadic evaluation, the double-double stage or stages B and C
/// (kAdaptive), or D (kExact); none when D's expansions would outgrow their buffers. Requires
/// inputs in kOrient3dAdaptiveWindow.
std::optional<Verdict> orient3d_adaptive(const std::array<Point3, 4>& p);

}  // namespace cavity::predicates::detail
