#include "lifted_adaptive.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "cavity/predicates/detail/expansion.h"
#include "double_double.h"
#include "fused_products.h"
#include "scaled_integers.h"
#include "small_expansion.h"
#include "small_integers.h"

namespace cavity::predicates::detail {
namespace {

// Stage C's bound (u = 2^-53). Write each difference as rounded + tail, v = v~ + t with
// |t| <= u |v~| (t from two_diff, exact). Expanded, det has 72 monomials x*y*z*s*s (s a
// coordinate difference, from the lift) and 24 monomials x*y*z*dw; let P = sum |m~| over them,
// evaluated on the rounded differences (the permanent). Then
//   det = B + L + R,
// B the exact determinant of the rounded differences (stage B), L the first-order terms (one tail,
// the other factors rounded; at most 5u |m~| per monomial, so sum|terms of L| <= 5u P), R the
// terms with two or more tails: |R| <= ((1 + u)^5 - 1 - 5u) P <= (10u^2 + 11u^3) P.
// L is evaluated in doubles in the order of stage C below; along any term's path there are at
// most 15 roundings (the tail 2x2 minor 3, the 3x3 tail minor 3 more and 1 to add its tail-of-z
// part, the lift 4, their product 1, the row's two-term sum 1, the final two-level sum 2), so
// |fl(L) - L| <= gamma_15 * 5u P (Higham, Accuracy and Stability, §3.1), gamma_15 = 15u/(1-15u).
// Hence |det - (B + fl(L))| <= (10u^2 + 75u^2 / (1 - 15u) + 11u^3) P <= (85u^2 + 1300u^3) P.
// B + fl(L) is summed exactly and its magnitude bounded from below by
// expansion_magnitude_lower_bound (one rounding). P is computed in doubles with at most 12
// roundings along a path, P <= P~ / (1 - u)^12 <= (1 + 13u) P~, and 88 * P~ rounds once, so
// accepting when fl(lower) > fl(88 * P~) * u^2 needs
//   88 (1 - u) u^2 >= (1 + u)(85u^2 + 1300u^3)(1 + 13u),
// which holds. The comparison is made as fl(lower) * 2^80 > fl(88 * P~) * 2^-26, both exact
// scalings: P~ >= 2^-960 when nonzero keeps the right side normal, and |lower| < 2^917 keeps the
// left side finite.
constexpr double kTailBound = 88.0;
constexpr double kLowerScale = 0x1p80;
constexpr double kBoundScale = 0x1p-26;

enum { kA = 0, kB = 1, kC = 2, kD = 3 };

/// The exact determinant det[x, y, z, x^2 + y^2 + z^2 - w] over four rows of expansions, by the
/// cofactors of the lift column: det = (l_d abc - l_c abd) + (l_b acd - l_a bcd), the 3x3 minors
/// expanded along z over the 2x2 minors of the x, y columns (minor2[i][j] = x_i y_j - x_j y_i,
/// i < j, given). False when a buffer would overflow.
bool lifted_determinant(const SmallExpansion (&minor2)[4][4],
                        const SmallExpansion (&x)[4],
                        const SmallExpansion (&y)[4],
                        const SmallExpansion (&z)[4],
                        const SmallExpansion (&w)[4],
                        SmallExpansion& det) {
    // minor3(i, j, k) = z_i m2(j, k) - z_j m2(i, k) + z_k m2(i, j) for i < j < k.
    auto minor3 = [&](int i, int j, int k, SmallExpansion& out) {
        SmallExpansion first;
        SmallExpansion second;
        SmallExpansion third;
        SmallExpansion partial;
        return multiply(z[i], minor2[j][k], first) && multiply(z[j], minor2[i][k], second) &&
               multiply(z[k], minor2[i][j], third) && subtract(first, second, partial) &&
               add(partial, third, out);
    };
    // term(i) = lift_i * minor, the lift x_i^2 + y_i^2 + z_i^2 - w_i exact.
    auto term = [&](int i, const SmallExpansion& minor, SmallExpansion& out) {
        SmallExpansion xx;
        SmallExpansion yy;
        SmallExpansion zz;
        SmallExpansion xy;
        SmallExpansion xyz;
        SmallExpansion lift;
        return multiply(x[i], x[i], xx) && multiply(y[i], y[i], yy) && multiply(z[i], z[i], zz) &&
               add(xx, yy, xy) && add(xy, zz, xyz) && subtract(xyz, w[i], lift) &&
               multiply(lift, minor, out);
    };
    SmallExpansion abc, abd, acd, bcd;
    if (!minor3(kA, kB, kC, abc) || !minor3(kA, kB, kD, abd) || !minor3(kA, kC, kD, acd) ||
        !minor3(kB, kC, kD, bcd)) {
        return false;
    }
    SmallExpansion d_term, c_term, b_term, a_term, dc, ba;
    return term(kD, abc, d_term) && term(kC, abd, c_term) && term(kB, acd, b_term) &&
           term(kA, bcd, a_term) && subtract(d_term, c_term, dc) && subtract(b_term, a_term, ba) &&
           add(dc, ba, det);
}

/// Rows of expansions from the rounded differences alone (stage B) or with their tails (stage D).
bool lifted_determinant(const LiftedRows& rows, bool with_tails, SmallExpansion& det) {
    SmallExpansion x[4], y[4], z[4], w[4];
    for (int i = 0; i < 4; ++i) {
        set_two_components(x[i], rows.x[i], with_tails ? rows.xt[i] : 0.0);
        set_two_components(y[i], rows.y[i], with_tails ? rows.yt[i] : 0.0);
        set_two_components(z[i], rows.z[i], with_tails ? rows.zt[i] : 0.0);
        set_two_components(w[i], rows.w[i], with_tails ? rows.wt[i] : 0.0);
    }
    SmallExpansion minor2[4][4];
    for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) {
            if (with_tails) {
                if (!product_difference(x[i], y[j], x[j], y[i], minor2[i][j])) {
                    return false;
                }
            } else {
                // One-component rows: Dekker products, at most 4 components, no compression.
                minor2[i][j].size =
                    product_difference(rows.x[i], rows.y[j], rows.x[j], rows.y[i], minor2[i][j].c);
            }
        }
    }
    return lifted_determinant(minor2, x, y, z, w, det);
}

/// fl(L), the first-order tail terms, in the evaluation order counted in kTailBound:
/// with C_i the 3x3 cofactor minors and l_i the lifts of the rounded rows,
/// L = (T_d - T_c) + (T_b - T_a), T_i = dl_i * C_i + l_i * dC_i, where dl_i and dC_i are the
/// first-order changes of l_i and C_i caused by the tails.
double first_order_tails(const LiftedRows& r) {
    const double* x = r.x;
    const double* y = r.y;
    const double* z = r.z;
    const double* xt = r.xt;
    const double* yt = r.yt;
    const double* zt = r.zt;
    double m2[4][4];
    double t2[4][4];
    for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) {
            m2[i][j] = x[i] * y[j] - x[j] * y[i];
            t2[i][j] = (x[i] * yt[j] + xt[i] * y[j]) - (x[j] * yt[i] + xt[j] * y[i]);
        }
    }
    auto minor3 = [&](int i, int j, int k) {
        return z[i] * m2[j][k] - z[j] * m2[i][k] + z[k] * m2[i][j];
    };
    auto minor3_tail = [&](int i, int j, int k) {
        return (z[i] * t2[j][k] - z[j] * t2[i][k] + z[k] * t2[i][j]) +
               (zt[i] * m2[j][k] - zt[j] * m2[i][k] + zt[k] * m2[i][j]);
    };
    auto row = [&](int i, int j, int k, int l) {
        // T_l for the minor over rows i < j < k.
        const double lift = ((x[l] * x[l] + y[l] * y[l]) + z[l] * z[l]) - r.w[l];
        const double lift_tail = 2.0 * ((x[l] * xt[l] + y[l] * yt[l]) + z[l] * zt[l]) - r.wt[l];
        return lift_tail * minor3(i, j, k) + lift * minor3_tail(i, j, k);
    };
    return (row(kA, kB, kC, kD) - row(kA, kB, kD, kC)) +
           (row(kA, kC, kD, kB) - row(kB, kC, kD, kA));
}

// The double-double stage's bound (u = 2^-53). Every difference is taken exactly as head + tail
// (its two_diff), so the only errors are the roundings of the double-double operations, bounded in
// double_double.h against the magnitudes of their operands: at most beta u^2 |x| |y| for a
// product (beta = 8 + 23u) and alpha u^2 (|x| + |y|) for a sum (alpha = 3 + 6u). By induction over
// the evaluation, a computed value X~ of an exact subexpression X with permanent M (the same
// formula over the magnitudes of the exact differences: M of a sum is M_x + M_y, of a product
// M_x M_y) satisfies |X~ - X| <= eps_X M, with
//   1 + eps = (1 + max(eps_x, eps_y)) (1 + alpha u^2) for a sum,
//   1 + eps = (1 + eps_x) (1 + eps_y) (1 + beta u^2) for a product
// (for the sum: |X~ - X| <= alpha u^2 (|x~| + |y~|) + eps_x M_x + eps_y M_y with
// |x~| <= (1 + eps_x) M_x; for the product: beta u^2 |x~| |y~| + |x~ - x| |y~| + |x| |y~ - y|).
// Counting operations along the evaluation order of lifted_double_double (products, sums):
//   2x2 minor x_i y_j - x_j y_i: (1, 1); the 3x3 minor (z_i m_jk - z_j m_ik) + z_k m_ij: (2, 3);
//   the lift ((x^2 + y^2) + z^2) - dw: (1, 3); lift times minor: (4, 6); the final
//   (T_d - T_c) + (T_b - T_a): (4, 8).
// So eps <= (1 + beta u^2)^4 (1 + alpha u^2)^8 - 1 <= 56u^2 + 140u^3 + 3200u^4 <= 56u^2 (1 + 3u).
// The permanent of the exact differences is at most (1 + u)^5 times P of the heads (degree 5; a
// weight, degree 2, appears in monomials of degree 4), and P <= P~ / (1 - u)^12 for P~
// computed with at most 12 roundings along a path (lifted_permanent; insphere_row_permanent has
// 11), so the error is at most 56u^2 (1 + 3u) (1 + u)^5 / (1 - u)^12 P~
// <= 56u^2 (1 + 21u) P~. The result hi + lo has the sign of hi and |hi + lo| >= (1 - u)|hi|, so
// the sign of hi is certified when (1 - u)|hi| exceeds that. The test fl(|hi| 2^80) >
// fl(58 P~) 2^-26 (both scalings exact, as for stage C's test) gives |hi| > 58 (1 - u) u^2 P~ and
//   58 (1 - u)^2 u^2 >= 56u^2 (1 + 21u).
// No operation underflows or overflows in kLiftedAdaptiveWindow: every value computed, the split
// halves of two_product included, is a multiple of 2^-960 (degree at most 5 in multiples of
// 2^-192; weights, multiples of 2^-332, count as degree 2), hence normal when nonzero, and the
// magnitudes stay below (1 + eps) times the permanent, below 2^917.
constexpr double kDoubleDoubleBound = 58.0;

/// The double-double product x y of a double x and a double-double y: product<K>({x, 0}, y)
/// without the terms of the zero tail (they add nothing, so the value and the bound are the same).
template <ProductKind K>
[[gnu::always_inline]] inline DoubleDouble product_by_double(double x, DoubleDouble y) {
    double p;
    double e;
    exact_product<K>(x, y.hi, p, e);
    const double t = e + x * y.lo;
    DoubleDouble r;
    fast_two_sum(p, t, r.hi, r.lo);
    return r;
}

/// The exact product x y of two doubles as a double-double: product<K>({x, 0}, {y, 0}), whose
/// correction terms vanish and whose final fast_two_sum returns the exact pair (p, e) unchanged
/// (p = fl(x y) is x y rounded, so fl(p + e) = p).
template <ProductKind K>
[[gnu::always_inline]] inline DoubleDouble exact_product_dd(double x, double y) {
    DoubleDouble r;
    exact_product<K>(x, y, r.hi, r.lo);
    return r;
}

/// The products of the stage on differences (double-doubles whose tails are zero with
/// kExactRows): of two differences, of a difference and a double-double, and a difference squared.
template <ProductKind K, bool kExactRows>
[[gnu::always_inline]] inline DoubleDouble pair_product(DoubleDouble a, DoubleDouble b) {
    if constexpr (kExactRows) {
        return exact_product_dd<K>(a.hi, b.hi);
    } else {
        return product<K>(a, b);
    }
}

template <ProductKind K, bool kExactRows>
[[gnu::always_inline]] inline DoubleDouble scaled(DoubleDouble a, DoubleDouble b) {
    if constexpr (kExactRows) {
        return product_by_double<K>(a.hi, b);
    } else {
        return product<K>(a, b);
    }
}

template <ProductKind K, bool kExactRows>
[[gnu::always_inline]] inline DoubleDouble squared(DoubleDouble a) {
    if constexpr (kExactRows) {
        return exact_product_dd<K>(a.hi, a.hi);
    } else {
        return square<K>(a);
    }
}

/// The determinant of the double-double stage, its products' errors found the K way. With
/// kExactRows (every difference exact: the tails are zero), the products of differences skip the
/// terms of the zero tails; the values are those of the general evaluation (but for the sign of
/// a zero), so its error bound holds unchanged. On a rounded sphere most rows are exact.
template <ProductKind K, bool kExactRows>
[[gnu::always_inline]] inline DoubleDouble lifted_determinant_dd(const LiftedRows& r) {
    DoubleDouble x[4], y[4], z[4], w[4];
    for (int i = 0; i < 4; ++i) {
        x[i] = {r.x[i], r.xt[i]};
        y[i] = {r.y[i], r.yt[i]};
        z[i] = {r.z[i], r.zt[i]};
        w[i] = {r.w[i], r.wt[i]};
    }
    DoubleDouble m2[4][4];
    for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) {
            m2[i][j] = difference(pair_product<K, kExactRows>(x[i], y[j]),
                                  pair_product<K, kExactRows>(x[j], y[i]));
        }
    }
    // Loops rather than lambdas: a lambda not inlined would be compiled outside the FMA target,
    // where __builtin_fma is a library call. Unrolled, so that the rows are indexed by constants
    // (1.57 G -> 1.39 G instructions for the stage on a 10^5-point sphere).
    DoubleDouble minor3[4];  // abc, abd, acd, bcd
    constexpr int kMinor[4][3] = {{kA, kB, kC}, {kA, kB, kD}, {kA, kC, kD}, {kB, kC, kD}};
#pragma GCC unroll 4
    for (int m = 0; m < 4; ++m) {
        const int i = kMinor[m][0], j = kMinor[m][1], k = kMinor[m][2];
        minor3[m] = sum(difference(scaled<K, kExactRows>(z[i], m2[j][k]),
                                   scaled<K, kExactRows>(z[j], m2[i][k])),
                        scaled<K, kExactRows>(z[k], m2[i][j]));
    }
    DoubleDouble term[4];  // lift_l times the minor of the other three rows, l = d, c, b, a
    constexpr int kLift[4] = {kD, kC, kB, kA};
#pragma GCC unroll 4
    for (int m = 0; m < 4; ++m) {
        const int l = kLift[m];
        const DoubleDouble lift =
            difference(sum(sum(squared<K, kExactRows>(x[l]), squared<K, kExactRows>(y[l])),
                           squared<K, kExactRows>(z[l])),
                       w[l]);
        term[m] = product<K>(lift, minor3[m]);
    }
    return sum(difference(term[0], term[1]), difference(term[2], term[3]));
}

#if CAVITY_FUSED_PRODUCTS
[[gnu::target("fma")]] DoubleDouble lifted_determinant_fused(const LiftedRows& r) {
    return r.differences_exact ? lifted_determinant_dd<ProductKind::kFused, true>(r)
                               : lifted_determinant_dd<ProductKind::kFused, false>(r);
}
#endif

}  // namespace

// Along a monomial's path: the 2x2 term (2 roundings), the 3x3 term (3), the lift (4: three
// additions after the squares, the fourth with |dw|), their product (1), the final sum (2): 12.
double lifted_permanent(const LiftedRows& r) {
    const double* x = r.x;
    const double* y = r.y;
    const double* z = r.z;
    auto perm2 = [&](int i, int j) { return std::abs(x[i] * y[j]) + std::abs(x[j] * y[i]); };
    auto perm3 = [&](int i, int j, int k) {
        return std::abs(z[i]) * perm2(j, k) + std::abs(z[j]) * perm2(i, k) +
               std::abs(z[k]) * perm2(i, j);
    };
    auto lift = [&](int i) {
        return ((x[i] * x[i] + y[i] * y[i]) + z[i] * z[i]) + std::abs(r.w[i]);
    };
    return (lift(kD) * perm3(kA, kB, kC) + lift(kC) * perm3(kA, kB, kD)) +
           (lift(kB) * perm3(kA, kC, kD) + lift(kA) * perm3(kB, kC, kD));
}

DoubleDouble lifted_double_double_determinant(const LiftedRows& rows, ProductKind kind) {
#if CAVITY_FUSED_PRODUCTS
    if (kind == ProductKind::kFused) {
        return lifted_determinant_fused(rows);
    }
#endif
    (void)kind;
    return rows.differences_exact ? lifted_determinant_dd<ProductKind::kDekker, true>(rows)
                                  : lifted_determinant_dd<ProductKind::kDekker, false>(rows);
}

std::optional<Sign> lifted_double_double(const LiftedRows& r, double permanent) {
    const DoubleDouble det = lifted_double_double_determinant(
        r, fused_products_available() ? ProductKind::kFused : ProductKind::kDekker);
    if (std::abs(det.hi) * kLowerScale > (kDoubleDoubleBound * permanent) * kBoundScale) {
        return det.hi > 0.0 ? Sign::kPos : Sign::kNeg;
    }
    return std::nullopt;
}

namespace {

/// lifted_adaptive's stages; with `points` (insphere's query), every stage that would evaluate
/// the exact determinant of the differences (B when they are exact, D) first tries the scaled
/// integers, which give the same sign at the same stage.
std::optional<Verdict> adaptive_stages(const LiftedRows& rows,
                                       double permanent,
                                       const std::array<Point3, 5>* points) {
    // The double-double stage: almost every in-range query the filter leaves, at a fraction of
    // the cost of stage B's exact expansion.
    if (const std::optional<Sign> s = lifted_double_double(rows, permanent)) {
        return Verdict{*s, Stage::kAdaptive};
    }
    // Stage B: exact already when the differences are.
    if (rows.differences_exact && points != nullptr) {
        if (const std::optional<Sign> s = insphere_scaled_integers(*points)) {
            return Verdict{*s, Stage::kAdaptive};
        }
    }
    SmallExpansion det;
    if (!lifted_determinant(rows, false, det)) {
        return std::nullopt;
    }
    if (rows.differences_exact) {
        return Verdict{static_cast<Sign>(sign(det)), Stage::kAdaptive};
    }
    // Stage C.
    const double first_order = first_order_tails(rows);
    double corrected[SmallExpansion::kCapacity + 1];
    const int corrected_len = expansion_sum(det.size, det.c, 1, &first_order, corrected);
    const double lower = expansion_magnitude_lower_bound(corrected_len, corrected);
    if (lower * kLowerScale > (kTailBound * permanent) * kBoundScale) {
        return Verdict{static_cast<Sign>(expansion_sign(corrected_len, corrected)),
                       Stage::kAdaptive};
    }
    // Stage D.
    if (points != nullptr) {
        if (const std::optional<Sign> s = insphere_scaled_integers(*points)) {
            return Verdict{*s, Stage::kExact};
        }
    }
    SmallExpansion exact;
    if (!lifted_determinant(rows, true, exact)) {
        return std::nullopt;
    }
    return Verdict{static_cast<Sign>(sign(exact)), Stage::kExact};
}

}  // namespace

std::optional<Verdict> lifted_adaptive(const LiftedRows& rows, double permanent) {
    return adaptive_stages(rows, permanent, nullptr);
}

std::optional<Verdict> lifted_adaptive(const LiftedRows& rows,
                                       double permanent,
                                       const std::array<Point3, 5>& points) {
    return adaptive_stages(rows, permanent, &points);
}

}  // namespace cavity::predicates::detail

namespace cavity::predicates::detail {

std::optional<Sign> lifted_small_integers(const LiftedRows& rows) {
    const double* x = rows.x;
    const double* y = rows.y;
    const double* z = rows.z;
    const double* w = rows.w;
    double max = 0.0;
    for (int i = 0; i < 4; ++i) {
        max = std::max({max, std::abs(x[i]), std::abs(y[i]), std::abs(z[i])});
    }
    if (max > 0x1p16) {
        return std::nullopt;
    }
    // With differences of at most 2^16: the 2x2 minors are below 2^33 and the 3x3 minors below
    // 2^51, exact in doubles; the lifts x^2 + y^2 + z^2 - dw (|dw| < 2^51 for weights below 2^50)
    // are below 2^52, exact too; the four products lift * minor, below 2^103, and their sum are
    // exact in 128-bit integers.
    const double ab = x[0] * y[1] - x[1] * y[0];
    const double bc = x[1] * y[2] - x[2] * y[1];
    const double cd = x[2] * y[3] - x[3] * y[2];
    const double da = x[3] * y[0] - x[0] * y[3];
    const double ac = x[0] * y[2] - x[2] * y[0];
    const double bd = x[1] * y[3] - x[3] * y[1];
    const auto abc = static_cast<std::int64_t>(z[0] * bc - z[1] * ac + z[2] * ab);
    const auto bcd = static_cast<std::int64_t>(z[1] * cd - z[2] * bd + z[3] * bc);
    const auto cda = static_cast<std::int64_t>(z[2] * da + z[3] * ac + z[0] * cd);
    const auto dab = static_cast<std::int64_t>(z[3] * ab + z[0] * bd + z[1] * da);
    std::int64_t lift[4];
    for (int i = 0; i < 4; ++i) {
        lift[i] = static_cast<std::int64_t>(x[i] * x[i] + y[i] * y[i] + z[i] * z[i] - w[i]);
    }
    const Int128 det = (Int128{lift[3]} * abc - Int128{lift[2]} * dab) +
                       (Int128{lift[1]} * cda - Int128{lift[0]} * bcd);
    return sign_of(det);
}

}  // namespace cavity::predicates::detail
