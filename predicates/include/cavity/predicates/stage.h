#pragma once

#include <cstdint>
#include <string_view>

#include "cavity/predicates/sign.h"

namespace cavity::predicates {

/// The stage of the evaluation pipeline that decided a predicate's sign.
///  - kFilter:   the floating-point determinant with a certified error bound (inputs in range);
///  - kAdaptive: for insphere with exact differences first the plain determinant under a bound
///               proportional to its permanent (Shewchuk's stage A); then
///               the determinant of the exact differences (rounded + tail) in double-double
///               arithmetic under a certified bound; when that is too close to call, Shewchuk's
///               stages B and C: the exact expansion of the determinant of the rounded input
///               differences, then (when a difference was inexact) that plus the first-order
///               terms of the difference tails in doubles, under a certified bound;
///  - kExact:    the exact determinant: expansions of the two-component differences, or GMP
///               integers for inputs whose exponents spread too wide for expansions.
enum class Stage : std::uint8_t { kFilter = 0, kAdaptive = 1, kExact = 2 };

inline constexpr int kStageCount = 3;

constexpr std::string_view stage_name(Stage s) {
    switch (s) {
        case Stage::kFilter:
            return "filter";
        case Stage::kAdaptive:
            return "adaptive";
        case Stage::kExact:
            return "exact";
    }
    return "?";
}

/// A sign together with the stage that decided it (what the staged predicates return).
struct Verdict {
    Sign sign;
    Stage stage;
};

}  // namespace cavity::predicates
