#pragma once

#include <optional>

#include "cavity/predicates/sign.h"
#include "staged_pipeline.h"

// The expansion stage shared by insphere and orient4d: both are det[p - e, |p - e|^2 - dw_p] over
// the rows p = a..d, with dw_p = w_p - w_e (zero for insphere).
namespace cavity::predicates::detail {

// Inputs with exponents in [-140, 180] (weights at half their exponent): differences are
// multiples of 2^-192 and below 2^182, weight differences multiples of 2^-332 and below 2^363, so
// every product of degree 5 (and of the splits in it) lies between 2^-960 and 2^915: the
// expansion arithmetic neither underflows nor overflows.
inline constexpr ExponentWindow kLiftedAdaptiveWindow = {-140, 180};

/// The rounded differences to e of the four other points, and whether every rounding was exact.
struct LiftedRows {
    double x[4];
    double y[4];
    double z[4];
    double w[4];
    bool differences_exact;
};

/// The exact determinant of the rounded differences (Shewchuk's stage B for insphere): the exact
/// answer when the differences were exact, otherwise accepted when it dominates the error caused
/// by rounding them; none when neither holds. Requires inputs in kLiftedAdaptiveWindow.
std::optional<Sign> lifted_adaptive(const LiftedRows& rows);

/// The exact sign when the points are integers below 2^50 (checked by the caller; the rows are
/// then exact differences) with coordinate differences of at most 2^16; none otherwise.
std::optional<Sign> lifted_small_integers(const LiftedRows& rows);

}  // namespace cavity::predicates::detail
