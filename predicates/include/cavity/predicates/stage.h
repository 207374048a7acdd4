#pragma once

#include <cstdint>
#include <string_view>

#include "cavity/predicates/sign.h"

namespace cavity::predicates {

/// The stage of the evaluation pipeline that decided a predicate's sign.
///  - kFilter:   the floating-point determinant with a certified error bound (inputs in range);
///  - kAdaptive: expansion arithmetic (error-free transformations) on the input differences;
///  - kExact:    exact integer arithmetic, for inputs the first two stages cannot settle or whose
///               intermediate products would overflow or underflow a double.
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
