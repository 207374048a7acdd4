#pragma once

#include "cavity/predicates/detail/expansion.h"

// Arithmetic on short, compressed expansions: the building block of the exact stages that work on
// two-component differences (a - b = hi + lo exactly). Every result is compressed, so that the
// exact minors of 53-bit inputs stay a handful of components long and their products stay cheap.
// Each operation checks its worst-case output length against the capacity and reports failure
// instead of overflowing the buffer; the caller then falls back to GMP (correct, just slower).
//
// The expansion arithmetic is exact only without overflow and underflow; the callers guarantee it
// by the exponent windows of their inputs (see staged_pipeline.h).
namespace cavity::predicates::detail {

/// A nonoverlapping expansion, increasing magnitude, no zero components, at most kCapacity long.
struct SmallExpansion {
    static constexpr int kCapacity = 96;
    int size = 0;
    double c[kCapacity];
};

/// hi + lo as an expansion, for a rounded difference hi and its tail lo from two_diff
/// (|lo| <= ulp(hi) / 2, so the two do not overlap).
inline SmallExpansion two_components(double hi, double lo) {
    SmallExpansion e;
    if (lo != 0.0) {
        e.c[e.size++] = lo;
    }
    if (hi != 0.0) {
        e.c[e.size++] = hi;
    }
    return e;
}

/// The exact difference a - b as an expansion of one or two components (none when a == b).
inline SmallExpansion exact_difference(double a, double b) {
    double hi;
    double lo;
    two_diff(a, b, hi, lo);
    return two_components(hi, lo);
}

/// The expansion of one double (its rounded difference with the tail dropped, for stage B).
inline SmallExpansion single(double v) {
    SmallExpansion e;
    if (v != 0.0) {
        e.c[e.size++] = v;
    }
    return e;
}

/// out = a + b (out may not alias a or b); false when out might not fit.
inline bool add(const SmallExpansion& a, const SmallExpansion& b, SmallExpansion& out) {
    if (a.size + b.size > SmallExpansion::kCapacity) {
        return false;
    }
    out.size = compress(expansion_sum(a.size, a.c, b.size, b.c, out.c), out.c);
    return true;
}

/// out = a - b (out may not alias a or b); false when out might not fit.
inline bool subtract(const SmallExpansion& a, const SmallExpansion& b, SmallExpansion& out) {
    SmallExpansion minus_b;
    minus_b.size = b.size;
    for (int i = 0; i < b.size; ++i) {
        minus_b.c[i] = -b.c[i];
    }
    return add(a, minus_b, out);
}

/// out = a * b (out may not alias a or b): the sum over b's components of a scaled by each,
/// accumulated by expansion sums. False when an intermediate might not fit.
inline bool multiply(const SmallExpansion& a, const SmallExpansion& b, SmallExpansion& out) {
    out.size = 0;
    if (2 * a.size * b.size > SmallExpansion::kCapacity) {
        return false;
    }
    double scaled[SmallExpansion::kCapacity];
    double sum[SmallExpansion::kCapacity];
    for (int j = 0; j < b.size; ++j) {
        const int scaled_len = scale_expansion(a.size, a.c, b.c[j], scaled);
        const int sum_len = expansion_sum(out.size, out.c, scaled_len, scaled, sum);
        for (int i = 0; i < sum_len; ++i) {
            out.c[i] = sum[i];
        }
        out.size = sum_len;
    }
    out.size = compress(out.size, out.c);
    return true;
}

/// out = a * b - c * d; false when an intermediate might not fit.
inline bool product_difference(const SmallExpansion& a,
                               const SmallExpansion& b,
                               const SmallExpansion& c,
                               const SmallExpansion& d,
                               SmallExpansion& out) {
    SmallExpansion ab;
    SmallExpansion cd;
    return multiply(a, b, ab) && multiply(c, d, cd) && subtract(ab, cd, out);
}

inline int sign(const SmallExpansion& e) {
    return expansion_sign(e.size, e.c);
}

}  // namespace cavity::predicates::detail
