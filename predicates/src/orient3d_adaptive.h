#pragma once

#include <array>
#include <optional>

#include "cavity/predicates/point.h"
#include "cavity/predicates/stage.h"
#include "staged_pipeline.h"

// The expansion stages of orient3d (Shewchuk's orient3dadapt, with bounds derived for this
// evaluation order): B, the exact determinant of the rounded differences; C, B plus the
// first-order terms of the difference tails in floating point, under a certified bound; D, the
// exact determinant of the two-component differences.
namespace cavity::predicates::detail {

// Inputs with exponents in [-280, 300]: differences and their tails are multiples of 2^-332 below
// 2^302, so every product of up to three of them (and of their 26-bit halves) is a multiple of
// 2^-996, a normal number when nonzero, and below 2^910: neither the floating-point stage C nor
// the expansion arithmetic underflows or overflows.
inline constexpr ExponentWindow kOrient3dAdaptiveWindow = {-280, 300};

/// The verdict of stages B and C (kAdaptive) or D (kExact); none when D's expansions would outgrow
/// their buffers. Requires inputs in kOrient3dAdaptiveWindow.
std::optional<Verdict> orient3d_adaptive(const std::array<Point3, 4>& p);

}  // namespace cavity::predicates::detail
