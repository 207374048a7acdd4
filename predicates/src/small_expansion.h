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

/// e = hi + lo, for a rounded difference hi and its tail lo from two_diff (|lo| <= ulp(hi) / 2,
/// so the two do not overlap); lo = 0 gives the rounded difference alone (stage B). Filled in
/// place: a SmallExpansion is too large to return by value on the hot path.
inline void set_two_components(SmallExpansion& e, double hi, double lo) {
    e.size = 0;
    if (lo != 0.0) {
        e.c[e.size++] = lo;
    }
    if (hi != 0.0) {
        e.c[e.size++] = hi;
    }
}

/// e = a - b exactly, as one or two components (none when a == b).
inline void set_exact_difference(SmallExpansion& e, double a, double b) {
    double hi;
    double lo;
    two_diff(a, b, hi, lo);
    set_two_components(e, hi, lo);
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

/// out = a * b (out may not alias a or b): the longer factor scaled by each component of the
/// shorter, the partial products summed by expansion sums. False when an intermediate might not
/// fit.
inline bool multiply(const SmallExpansion& a, const SmallExpansion& b, SmallExpansion& out) {
    const SmallExpansion& longer = a.size >= b.size ? a : b;
    const SmallExpansion& shorter = a.size >= b.size ? b : a;
    if (2 * longer.size * shorter.size > SmallExpansion::kCapacity) {
        return false;
    }
    if (shorter.size <= 1) {
        out.size =
            shorter.size == 0 ? 0 : scale_expansion(longer.size, longer.c, shorter.c[0], out.c);
        out.size = compress(out.size, out.c);
        return true;
    }
    // Ping-pong between two partial sums; the last sum goes straight into out.
    double partial[2][SmallExpansion::kCapacity];
    double scaled[SmallExpansion::kCapacity];
    int len = scale_expansion(longer.size, longer.c, shorter.c[0], partial[0]);
    int current = 0;
    for (int j = 1; j < shorter.size; ++j) {
        const int scaled_len = scale_expansion(longer.size, longer.c, shorter.c[j], scaled);
        double* target = j + 1 == shorter.size ? out.c : partial[1 - current];
        len = expansion_sum(len, partial[current], scaled_len, scaled, target);
        current = 1 - current;
    }
    out.size = compress(len, out.c);
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
