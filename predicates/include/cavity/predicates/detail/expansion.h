#pragma once

#include <cmath>

// Error-free transformations and expansion arithmetic (Dekker 1971; Knuth, TAOCP vol. 2 §4.2.2;
// Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
// DCG 18, 1997). An expansion is an array of doubles, nonoverlapping and sorted by increasing
// magnitude, whose exact sum is the represented value; length 0 represents zero.
//
// Valid only under the conditions the proofs assume: binary64 with round-to-nearest-even, every
// operation rounded on its own (no FMA contraction, no x87 extended precision), and no overflow or
// underflow. The callers check the last condition on the exponents of their inputs first.
namespace cavity::predicates::detail {

/// 2^ceil(53/2) + 1: splits a double into two halves of at most 26 significant bits each.
inline constexpr double kSplitter = 134217729.0;

/// x + y == a + b exactly, with x = fl(a + b) (Knuth's branch-free TwoSum).
inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double b_virtual = x - a;
    const double a_virtual = x - b_virtual;
    y = (a - a_virtual) + (b - b_virtual);
}

/// As two_sum, but needs |a| >= |b| (or a == 0): three operations instead of six (Dekker).
inline void fast_two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    y = b - (x - a);
}

/// x + y == a - b exactly, with x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) {
    x = a - b;
    const double b_virtual = a - x;
    const double a_virtual = x + b_virtual;
    y = (a - a_virtual) + (b_virtual - b);
}

/// hi + lo == a, each with at most 26 significant bits, so the products of halves are exact.
inline void split(double a, double& hi, double& lo) {
    const double c = kSplitter * a;
    const double big = c - a;
    hi = c - big;
    lo = a - hi;
}

/// x + y == a * b exactly, with x = fl(a * b); b is given already split into b_hi + b_lo.
inline void two_product_presplit(
    double a, double b, double b_hi, double b_lo, double& x, double& y) {
    x = a * b;
    double a_hi;
    double a_lo;
    split(a, a_hi, a_lo);
    const double err1 = x - a_hi * b_hi;
    const double err2 = err1 - a_lo * b_hi;
    const double err3 = err2 - a_hi * b_lo;
    y = a_lo * b_lo - err3;
}

/// x + y == a * b exactly, with x = fl(a * b) (Dekker's product).
inline void two_product(double a, double b, double& x, double& y) {
    double b_hi;
    double b_lo;
    split(b, b_hi, b_lo);
    two_product_presplit(a, b, b_hi, b_lo, x, y);
}

/// h = e + f (Shewchuk's fast expansion sum with zero elimination): merge the components by
/// increasing magnitude and carry the running sum with two_sum, emitting the nonzero errors. The
/// result is nonoverlapping and increasing when the rounding is to nearest-even. h needs room for
/// elen + flen components and must not alias e or f. Returns the length of h.
inline int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) {
    int i = 0;
    int j = 0;
    auto next_smallest = [&]() {
        if (j >= flen || (i < elen && std::abs(e[i]) < std::abs(f[j]))) {
            return e[i++];
        }
        return f[j++];
    };
    if (elen + flen == 0) {
        return 0;
    }
    int n = 0;
    double q = next_smallest();
    while (i < elen || j < flen) {
        const double g = next_smallest();
        double sum;
        double err;
        two_sum(q, g, sum, err);
        if (err != 0.0) {
            h[n++] = err;
        }
        q = sum;
    }
    if (q != 0.0) {
        h[n++] = q;
    }
    return n;
}

/// h = e * b with zero elimination (Shewchuk's scale_expansion_zeroelim). h needs room for
/// 2 * elen components and must not alias e. Returns the length of h.
inline int scale_expansion(int elen, const double* e, double b, double* h) {
    if (elen == 0) {
        return 0;
    }
    double b_hi;
    double b_lo;
    split(b, b_hi, b_lo);
    int n = 0;
    double q;
    double err;
    two_product_presplit(e[0], b, b_hi, b_lo, q, err);
    if (err != 0.0) {
        h[n++] = err;
    }
    for (int i = 1; i < elen; ++i) {
        double p_hi;
        double p_lo;
        two_product_presplit(e[i], b, b_hi, b_lo, p_hi, p_lo);
        double sum;
        two_sum(q, p_lo, sum, err);
        if (err != 0.0) {
            h[n++] = err;
        }
        // |p_hi| >= |sum| here (Shewchuk, Theorem 19), so the cheaper transform is exact.
        fast_two_sum(p_hi, sum, q, err);
        if (err != 0.0) {
            h[n++] = err;
        }
    }
    if (q != 0.0) {
        h[n++] = q;
    }
    return n;
}

/// a * b - c * d exactly, as an expansion of at most 4 components in h. Returns the length.
inline int product_difference(double a, double b, double c, double d, double* h) {
    double ab[2];
    double cd[2];
    two_product(a, b, ab[1], ab[0]);
    two_product(c, d, cd[1], cd[0]);
    cd[0] = -cd[0];
    cd[1] = -cd[1];
    return expansion_sum(2, ab, 2, cd, h);
}

/// The sign of an expansion: the sign of its largest component, which dominates the others.
inline int expansion_sign(int elen, const double* e) {
    if (elen == 0) {
        return 0;
    }
    return e[elen - 1] > 0.0 ? 1 : -1;
}

/// A lower bound on |e| for a nonoverlapping expansion: |e_n| - 2|e_(n-1)|, computed with one
/// rounding (so the true bound is at least the result divided by 1 + u). Why 2|e_(n-1)|: the
/// components below e_(n-1) have all their bits under the lowest set bit of e_(n-1), so their sum
/// is below |e_(n-1)|, and the n-1 lower components sum to less than 2|e_(n-1)|. (Only the
/// nonoverlapping property is used: a single-bit top component, e.g. 2^k - 0.75 * 2^k, can be
/// nearly cancelled by the rest, so |e_n| alone is no lower bound.)
inline double expansion_magnitude_lower_bound(int elen, const double* e) {
    if (elen == 0) {
        return 0.0;
    }
    if (elen == 1) {
        return std::abs(e[0]);
    }
    return std::abs(e[elen - 1]) - 2.0 * std::abs(e[elen - 2]);
}

/// Shewchuk's compress: rewrites the nonoverlapping expansion e (in place, the same value) as a
/// nonadjacent one with as few components as the two sweeps find, largest last. Products of
/// expansions grow quadratically in the number of components, so the exact stages compress every
/// intermediate result; a compressed exact minor of 53-bit inputs has only a handful. Returns the
/// new length.
inline int compress(int elen, double* e) {
    if (elen <= 1) {
        return elen;
    }
    // Downward sweep: carry the running sum from the top, parking each settled sum at the top of
    // the array (bottom moves down). Each fast_two_sum is exact because the running sum is at
    // least as large as the next smaller component (Shewchuk, Theorem 23).
    double q = e[elen - 1];
    int bottom = elen - 1;
    for (int i = elen - 2; i >= 0; --i) {
        double sum;
        double err;
        fast_two_sum(q, e[i], sum, err);
        if (err != 0.0) {
            e[bottom--] = sum;
            q = err;
        } else {
            q = sum;
        }
    }
    // Upward sweep: fold the parked sums back from the smallest, emitting nonzero errors.
    int top = 0;
    for (int i = bottom + 1; i < elen; ++i) {
        double sum;
        double err;
        fast_two_sum(e[i], q, sum, err);
        if (err != 0.0) {
            e[top++] = err;
        }
        q = sum;
    }
    if (q != 0.0) {
        e[top++] = q;
    }
    return top;
}

}  // namespace cavity::predicates::detail
