#pragma once

#include <cstdint>
#include <string_view>

#include "cavity/predicates/sign.h"

namespace cavity::predicates {

/// The stage of the evaluation pipeline that decided a predicate's sign, in the order they run.
///  - kStatic:   the static filter (insphere_static_filter.h, orient3d_static_filter.h): the
///               floating-point determinant under one error bound fixed by the bounding box of
///               all the points. Only the engine's tests run it, for points known to lie in that
///               box; a predicate called alone starts at kFilter. Its bound is never below the
///               filter's for the same query, so what it decides the filter would decide too
///               (but for the filter's underflow guard), and the adaptive and exact counts are
///               the same with it or without it;
///  - kFilter:   the floating-point determinant with a certified error bound computed from the
///               query's own points (semi-static; inputs in range);
///  - kAdaptive: for insphere with exact differences first the plain determinant under a bound
///               proportional to its permanent (Shewchuk's stage A); then
///               the determinant of the exact differences (rounded + tail) in double-double
///               arithmetic under a certified bound; when that is too close to call, Shewchuk's
///               stages B and C: the exact expansion of the determinant of the rounded input
///               differences, then (when a difference was inexact) that plus the first-order
///               terms of the difference tails in doubles, under a certified bound;
///  - kExact:    the exact determinant: expansions of the two-component differences, or GMP
///               integers for inputs whose exponents spread too wide for expansions.
enum class Stage : std::uint8_t { kStatic = 0, kFilter = 1, kAdaptive = 2, kExact = 3 };

inline constexpr int kStageCount = 4;

constexpr std::string_view stage_name(Stage s) {
    switch (s) {
        case Stage::kStatic:
            return "static";
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
