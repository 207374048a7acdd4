#include "orient3d_adaptive.h"

#include <cmath>

#include "cavity/predicates/detail/expansion.h"
#include "small_dyadic.h"
#include "small_expansion.h"

namespace cavity::predicates::detail {
namespace {

// Stage C's bound (u = 2^-53). Write each difference as rounded + tail, d = d~ + t with
// |t| <= u |d~| (t from two_diff, exact). The determinant is a sum of 6 signed monomials of degree
// 3; let P = sum |m~| over them, evaluated on the rounded differences (the permanent). Then
//   det = B + L + R,
// B the exact determinant of the rounded differences (stage B's expansion), L the 18 first-order
// terms (one tail and two rounded factors), R the terms with two or three tails:
//   |R| <= ((1 + u)^3 - 1 - 3u) P = (3u^2 + u^3) P.
// L is evaluated in doubles in the order below, with at most 7 roundings along any term's path
// (tail product, the sum of two products, their difference, the product with the z factor, the
// sum with the tail-of-z term, two for the sum of the three rows; the tail-of-z terms have 6), so
// |fl(L) - L| <= gamma_7 * sum|terms| <= gamma_7 * 3u P (Higham, Accuracy and Stability, §3.1;
// each monomial contributes three terms of at most u |m~|), gamma_7 = 7u / (1 - 7u).
// Hence |det - (B + fl(L))| <= (3u^2 + 21u^2 / (1 - 7u) + u^3) P <= (24u^2 + 200u^3) P.
// B + fl(L) is summed exactly (one more expansion sum) and its magnitude bounded from below by
// expansion_magnitude_lower_bound, computed with one rounding. P is computed in doubles with at
// most 5 roundings along a path, P <= P~ / (1 - u)^5 <= (1 + 6u) P~, and the product 26 * P~
// rounds once, so accepting when fl(lower) * 2^106 > fl(26 * P~) needs
//   26 (1 - u) u^2 >= (1 + u)(24u^2 + 200u^3)(1 + 6u),
// which holds with room to spare. The 2^106 scale keeps the comparison clear of underflow: P~ is
// at least 2^-996 when nonzero, so 26 u^2 P~ could be subnormal, but fl(lower) * 2^106 is below
// 2^1017 (no overflow) and exact.
constexpr double kTailBound = 26.0;
constexpr double kTailBoundScale = 0x1p106;

// The double-double stage's bound (u = 2^-53), derived as for the lifted predicates (see
// lifted_adaptive.cpp): with the double-double roundings of double_double.h, beta u^2 |x| |y| for
// a product (beta = 8 + 23u) and alpha u^2 (|x| + |y|) for a sum (alpha = 3 + 6u), a computed
// subexpression errs by at most eps times its permanent over the exact differences, where
// 1 + eps multiplies by (1 + beta u^2) per product and by (1 + alpha u^2) per sum along the
// evaluation. Counting (products, sums) in orient3d_double_double: the 2x2 minor (1, 1), its
// product with the z difference (2, 1), the sum of the three terms (2, 3). So
//   eps <= (1 + beta u^2)^2 (1 + alpha u^2)^3 - 1 <= 25u^2 + 64u^3 + 700u^4 <= 25u^2 (1 + 3u).
// The permanent of the exact differences is at most (1 + u)^3 P of the heads and P <= P~ /
// (1 - u)^5 for P~ as computed in orient3d_adaptive, so the error is at most
// 25u^2 (1 + 3u) (1 + u)^3 / (1 - u)^5 P~ <= 25u^2 (1 + 12u) P~. The result hi + lo has the sign
// of hi and |hi + lo| >= (1 - u)|hi|; the test fl(|hi| 2^106) > fl(26 P~) (exact scaling, as in
// stage C) gives |hi| > 26 (1 - u) u^2 P~, and 26 (1 - u)^2 u^2 >= 25u^2 (1 + 12u).
// No operation underflows or overflows in kOrient3dAdaptiveWindow: every value computed, split
// halves included, is a multiple of 2^-996 (degree at most 3 in multiples of 2^-332), normal
// when nonzero, and the magnitudes stay below (1 + eps) times the permanent, below 2^909.
constexpr double kDoubleDoubleBound = 26.0;

/// P~: the permanent of the rounded differences (the order counted in the bounds above).
double permanent(const double (&x)[3], const double (&y)[3], const double (&z)[3]) {
    return (std::abs(x[1] * y[2]) + std::abs(y[1] * x[2])) * std::abs(z[0]) +
           (std::abs(x[2] * y[0]) + std::abs(y[2] * x[0])) * std::abs(z[1]) +
           (std::abs(x[0] * y[1]) + std::abs(y[0] * x[1])) * std::abs(z[2]);
}

/// The exact determinant with rows of exact differences (stage D): each difference as its one or
/// two components, the 2x2 minors of the x, y columns, then the expansion along z. False when a
/// buffer would overflow.
bool exact_determinant(const SmallExpansion (&x)[3],
                       const SmallExpansion (&y)[3],
                       const SmallExpansion (&z)[3],
                       SmallExpansion& det) {
    // det = z0 (x1 y2 - y1 x2) + z1 (x2 y0 - y2 x0) + z2 (x0 y1 - y0 x1)
    SmallExpansion minor[3];
    SmallExpansion term[3];
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const int k = (i + 2) % 3;
        if (!product_difference(x[j], y[k], y[j], x[k], minor[i]) ||
            !multiply(z[i], minor[i], term[i])) {
            return false;
        }
    }
    SmallExpansion partial;
    return add(term[0], term[1], partial) && add(partial, term[2], det);
}

}  // namespace

std::optional<Sign> orient3d_double_double(const DoubleDouble (&x)[3],
                                           const DoubleDouble (&y)[3],
                                           const DoubleDouble (&z)[3]) {
    // det = z0 (x1 y2 - y1 x2) + z1 (x2 y0 - y2 x0) + z2 (x0 y1 - y0 x1)
    DoubleDouble term[3];
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const int k = (i + 2) % 3;
        term[i] = product(z[i], difference(product(x[j], y[k]), product(y[j], x[k])));
    }
    const DoubleDouble det = sum(sum(term[0], term[1]), term[2]);
    const double heads_x[3] = {x[0].hi, x[1].hi, x[2].hi};
    const double heads_y[3] = {y[0].hi, y[1].hi, y[2].hi};
    const double heads_z[3] = {z[0].hi, z[1].hi, z[2].hi};
    if (std::abs(det.hi) * kTailBoundScale >
        kDoubleDoubleBound * permanent(heads_x, heads_y, heads_z)) {
        return det.hi > 0.0 ? Sign::kPos : Sign::kNeg;
    }
    return std::nullopt;
}

std::optional<Verdict> orient3d_adaptive(const std::array<Point3, 4>& p) {
    const Point3& a = p[0];
    const Point3& b = p[1];
    const Point3& c = p[2];
    const Point3& d = p[3];
    double adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz;
    double adxt, adyt, adzt, bdxt, bdyt, bdzt, cdxt, cdyt, cdzt;
    two_diff(a.x, d.x, adx, adxt);
    two_diff(a.y, d.y, ady, adyt);
    two_diff(a.z, d.z, adz, adzt);
    two_diff(b.x, d.x, bdx, bdxt);
    two_diff(b.y, d.y, bdy, bdyt);
    two_diff(b.z, d.z, bdz, bdzt);
    two_diff(c.x, d.x, cdx, cdxt);
    two_diff(c.y, d.y, cdy, cdyt);
    two_diff(c.z, d.z, cdz, cdzt);

    // The tails are multiples of 2^-332 below 2^250 here, so this sum of magnitudes is 0 exactly
    // when every tail is: the differences are then exact, and most such queries are exact zeros
    // (coplanar points on a coarse grid), which the stages below prove slowly.
    const double tails = std::abs(adxt) + std::abs(adyt) + std::abs(adzt) + std::abs(bdxt) +
                         std::abs(bdyt) + std::abs(bdzt) + std::abs(cdxt) + std::abs(cdyt) +
                         std::abs(cdzt);
    if (tails == 0.0) {
        const double x[3] = {adx, bdx, cdx};
        const double y[3] = {ady, bdy, cdy};
        const double z[3] = {adz, bdz, cdz};
        if (const std::optional<Sign> s = orient3d_small_dyadic(x, y, z)) {
            return Verdict{*s, Stage::kAdaptive};
        }
    }

    // The double-double stage: almost every in-range query the filter leaves.
    const DoubleDouble exact_x[3] = {{adx, adxt}, {bdx, bdxt}, {cdx, cdxt}};
    const DoubleDouble exact_y[3] = {{ady, adyt}, {bdy, bdyt}, {cdy, cdyt}};
    const DoubleDouble exact_z[3] = {{adz, adzt}, {bdz, bdzt}, {cdz, cdzt}};
    if (const std::optional<Sign> s = orient3d_double_double(exact_x, exact_y, exact_z)) {
        return Verdict{*s, Stage::kAdaptive};
    }

    // Stage B: the exact determinant of the rounded differences (Shewchuk's layout).
    double bc[4];
    double ca[4];
    double ab[4];
    const int bc_len = product_difference(bdx, cdy, bdy, cdx, bc);
    const int ca_len = product_difference(cdx, ady, cdy, adx, ca);
    const int ab_len = product_difference(adx, bdy, ady, bdx, ab);
    double a_term[8];
    double b_term[8];
    double c_term[8];
    const int a_len = scale_expansion(bc_len, bc, adz, a_term);
    const int b_len = scale_expansion(ca_len, ca, bdz, b_term);
    const int c_len = scale_expansion(ab_len, ab, cdz, c_term);
    double ab_sum[16];
    const int ab_sum_len = expansion_sum(a_len, a_term, b_len, b_term, ab_sum);
    double det[25];
    const int det_len = expansion_sum(ab_sum_len, ab_sum, c_len, c_term, det);

    // Exact differences: B is the determinant.
    if (tails == 0.0) {
        return Verdict{static_cast<Sign>(expansion_sign(det_len, det)), Stage::kAdaptive};
    }

    // Stage C: add the first-order tail terms in doubles (the order counted in kTailBound).
    const double first_order = (adz * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt)) +
                                adzt * (bdx * cdy - bdy * cdx)) +
                               (bdz * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt)) +
                                bdzt * (cdx * ady - cdy * adx)) +
                               (cdz * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt)) +
                                cdzt * (adx * bdy - ady * bdx));
    double corrected[26];
    const int corrected_len = expansion_sum(det_len, det, 1, &first_order, corrected);
    const double lower = expansion_magnitude_lower_bound(corrected_len, corrected);
    if (lower * kTailBoundScale >
        kTailBound * permanent({adx, bdx, cdx}, {ady, bdy, cdy}, {adz, bdz, cdz})) {
        return Verdict{static_cast<Sign>(expansion_sign(corrected_len, corrected)),
                       Stage::kAdaptive};
    }

    // Stage D: the exact determinant of the two-component differences.
    SmallExpansion x[3], y[3], z[3];
    for (int i = 0; i < 3; ++i) {
        set_exact_difference(x[i], p[i].x, d.x);
        set_exact_difference(y[i], p[i].y, d.y);
        set_exact_difference(z[i], p[i].z, d.z);
    }
    SmallExpansion exact;
    if (!exact_determinant(x, y, z, exact)) {
        return std::nullopt;
    }
    return Verdict{static_cast<Sign>(sign(exact)), Stage::kExact};
}

}  // namespace cavity::predicates::detail
