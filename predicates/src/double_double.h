#pragma once

#include "cavity/predicates/detail/expansion.h"

// Double-double arithmetic with error bounds stated against the magnitudes of the operands, the
// form a determinant's error analysis over its permanent needs (Dekker 1971; the "sloppy"
// addition and the product of Li et al., "Design, implementation and testing of extended and
// mixed precision BLAS", ACM TOMS 28, 2002, with the bounds derived below for exactly this code).
//
// A value is hi + lo with |lo| <= u |hi| (u = 2^-53) and lo = 0 when hi = 0: every result below
// comes out of an exact two_sum or fast_two_sum, whose error term is at most half an ulp of the
// rounded sum. Hence (1 - u)|hi| <= |hi + lo| <= (1 + u)|hi|.
//
// Valid under the conditions of expansion.h (binary64, round to nearest, no contraction) and when
// no operation underflows or overflows: every nonzero intermediate must be a normal number. The
// callers guarantee it by the exponent windows of their inputs.
namespace cavity::predicates::detail {

struct DoubleDouble {
    double hi;
    double lo;
};

/// How a product's rounding error is found: by Dekker's splitting (any binary64 arithmetic), or by
/// one fused multiply-add, fma(a, b, -fl(a b)), which rounds once and so returns the error
/// exactly when it does not underflow (the callers' exponent windows keep every value normal).
/// The error is unique, so both give the same pair bit for bit; the fused one in 2 operations
/// instead of 17. kFused may only be instantiated inside functions compiled for a target with
/// FMA (fused_products.h), where __builtin_fma is one instruction; the build never contracts
/// a * b + c on its own (-ffp-contract=off; tests/predicates/check_no_fma.cmake).
enum class ProductKind { kDekker, kFused };

template <ProductKind K>
[[gnu::always_inline]] inline void exact_product(double a, double b, double& p, double& e) {
    if constexpr (K == ProductKind::kFused) {
        p = a * b;
        e = __builtin_fma(a, b, -p);
    } else {
        two_product(a, b, p, e);
    }
}

/// a - b exactly (two_diff: the tail is the rounding error of the head, so the invariant holds).
inline DoubleDouble exact_difference(double a, double b) {
    DoubleDouble d;
    two_diff(a, b, d.hi, d.lo);
    return d;
}

// Product. With p + e = xh * yh exact (two_product), c = fl(fl(xh yl) + fl(xl yh)),
// t = fl(e + c) and the result p + t (fast_two_sum is exact: |t| <= 4u |p| when p != 0, and
// t = 0 when p = 0, since then xh or yh is 0 and so is its lo). With H = |xh| |yh|:
//   |e| <= u H, |fl(xh yl) - xh yl| <= u^2 H (and the same for xl yh),
//   |c - (fl(xh yl) + fl(xl yh))| <= 2u^2 (1 + u) H, |c| <= 2u (1 + u)^2 H,
//   |t - (e + c)| <= u (u + 2u (1 + u)^2) H = (3u^2 + 4u^3 + 2u^4) H,
// and the dropped xl yl is at most u^2 H. The result minus x y is
//   (t - e - c) + (c - fl(xh yl) - fl(xl yh)) + (fl(xh yl) - xh yl) + (fl(xl yh) - xl yh) - xl yl,
// at most (8u^2 + 6u^3 + 2u^4) H <= (8u^2 + 6u^3 + 2u^4) |x| |y| / (1 - u)^2, so
//   |result - x y| <= beta u^2 |x| |y|,  beta = 8 + 23u.
template <ProductKind K = ProductKind::kDekker>
[[gnu::always_inline]] inline DoubleDouble product(DoubleDouble x, DoubleDouble y) {
    double p;
    double e;
    exact_product<K>(x.hi, y.hi, p, e);
    const double t = e + (x.hi * y.lo + x.lo * y.hi);
    DoubleDouble r;
    fast_two_sum(p, t, r.hi, r.lo);
    return r;
}

/// product(x, x) bit for bit: fl(xh xl) + fl(xl xh) = 2 fl(xh xl) exactly, so the bound holds.
template <ProductKind K = ProductKind::kDekker>
[[gnu::always_inline]] inline DoubleDouble square(DoubleDouble x) {
    double p;
    double e;
    exact_product<K>(x.hi, x.hi, p, e);
    const double t = e + 2.0 * (x.hi * x.lo);
    DoubleDouble r;
    fast_two_sum(p, t, r.hi, r.lo);
    return r;
}

// Sum. With s + e = xh + yh exact (two_sum), c = fl(xl + yl), t = fl(e + c) and the result
// s + t (two_sum, exact whatever the magnitudes: s may cancel below t). With G = |xh| + |yh|:
//   |e| <= u G, |xl + yl| <= u G, |c - (xl + yl)| <= u^2 G, |c| <= u (1 + u) G,
//   |t - (e + c)| <= u (2u + u^2) G.
// The result minus x + y is (t - e - c) + (c - xl - yl), at most (3u^2 + u^3) G
// <= (3u^2 + u^3) (|x| + |y|) / (1 - u), so
//   |result - (x + y)| <= alpha u^2 (|x| + |y|),  alpha = 3 + 6u.
inline DoubleDouble sum(DoubleDouble x, DoubleDouble y) {
    double s;
    double e;
    two_sum(x.hi, y.hi, s, e);
    const double t = e + (x.lo + y.lo);
    DoubleDouble r;
    two_sum(s, t, r.hi, r.lo);
    return r;
}

/// sum(x, -y): negation is exact, so the bound of sum holds.
inline DoubleDouble difference(DoubleDouble x, DoubleDouble y) {
    return sum(x, {-y.hi, -y.lo});
}

}  // namespace cavity::predicates::detail
