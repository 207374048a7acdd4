#pragma once

// Whether the double-double stages may find products' rounding errors with a fused multiply-add
// (double_double.h: ProductKind). The library is built for the baseline of its architecture, so
// on x86-64 the fused variants are compiled for the FMA extension alone ([[gnu::target("fma")]])
// and chosen at run time when the processor has it; they give the same results bit for bit, and
// on rounded spheres, where most in-sphere tests reach the double-double stage, they take about
// half its instructions.
namespace cavity::predicates::detail {

#if defined(__x86_64__) && defined(__GNUC__)
#define CAVITY_FUSED_PRODUCTS 1

/// True when this processor executes FMA instructions. Asked once: the answer cannot change
/// while the program runs.
inline bool fused_products_available() {
    static const bool available = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("fma") != 0;
    }();
    return available;
}

#else
#define CAVITY_FUSED_PRODUCTS 0

inline bool fused_products_available() {
    return false;
}

#endif

}  // namespace cavity::predicates::detail
