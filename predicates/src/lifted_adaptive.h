#pragma once

#include <array>
#include <cmath>
#include <optional>

#include "cavity/predicates/detail/expansion.h"
#include "cavity/predicates/point.h"
#include "cavity/predicates/stage.h"
#include "double_double.h"
#include "staged_pipeline.h"

// The expansion stages shared by insphere and orient4d: both are det[p - e, |p - e|^2 - dw_p] over
// the rows p = a..d, with dw_p = w_p - w_e (zero for insphere). First the determinant of the
// exact differences in double-double arithmetic under a certified bound (it settles almost every
// in-range query the filter leaves, rounded spheres and decimal grids included); then Shewchuk's
// insphereadapt scheme with bounds derived for this evaluation order: B, the exact determinant of
// the rounded differences; C, B plus the first-order terms of the difference tails in floating
// point under a certified bound; D, the exact determinant of the two-component differences.
namespace cavity::predicates::detail {

// Inputs with exponents in [-140, 180] (weights at half their exponent): differences and their
// tails are multiples of 2^-192 below 2^182, weight differences and tails multiples of 2^-332
// below 2^363, so every product of degree 5 (a weight counting 2), and every partial product and
// 26-bit half on the way, is a multiple of 2^-960 (normal when nonzero) and below 2^917: neither
// the floating-point stage C nor the expansion arithmetic underflows or overflows.
inline constexpr ExponentWindow kLiftedAdaptiveWindow = {-140, 180};

/// The rounded differences to e of the four other points and their tails (exact: rounded + tail
/// is the difference), and whether every tail is zero.
struct LiftedRows {
    double x[4];
    double y[4];
    double z[4];
    double w[4];
    double xt[4];
    double yt[4];
    double zt[4];
    double wt[4];
    bool differences_exact;
};

/// insphere's rows (no weights): the differences of a..d to e with their tails. The tails are
/// multiples of 2^-192 below 2^130 in kLiftedAdaptiveWindow, so the sum of their magnitudes is 0
/// exactly when every tail is.
inline LiftedRows insphere_rows(const std::array<Point3, 5>& p) {
    LiftedRows rows{};
    double tails = 0.0;
    for (int i = 0; i < 4; ++i) {
        two_diff(p[i].x, p[4].x, rows.x[i], rows.xt[i]);
        two_diff(p[i].y, p[4].y, rows.y[i], rows.yt[i]);
        two_diff(p[i].z, p[4].z, rows.z[i], rows.zt[i]);
        tails += std::abs(rows.xt[i]) + std::abs(rows.yt[i]) + std::abs(rows.zt[i]);
    }
    rows.differences_exact = tails == 0.0;
    return rows;
}

/// P~, the permanent of the rounded rows (every monomial of the determinant by its magnitude,
/// |dw| for -dw), with at most 12 roundings along any monomial's path. The bounds of the stages
/// below take it as an argument and hold for any P~ computed with at most 12 roundings along a
/// path, so that a caller which has one already (insphere's stage A) computes it once.
double lifted_permanent(const LiftedRows& rows);

/// The double-double stage that runs before stage B: the sign of the determinant evaluated in
/// double-double arithmetic over the exact differences (rounded + tail), when certified by its
/// error bound; none otherwise. `permanent` as for lifted_permanent. Requires inputs in
/// kLiftedAdaptiveWindow. Exposed for the tests that probe the bound.
std::optional<Sign> lifted_double_double(const LiftedRows& rows, double permanent);

/// The determinant that stage evaluates, with the products' errors found the given way (kFused
/// only where fused_products_available(); the two agree bit for bit, which the tests check).
DoubleDouble lifted_double_double_determinant(const LiftedRows& rows, ProductKind kind);

/// The verdict of the double-double stage or stages B and C (kAdaptive) or D (kExact); none when
/// D's expansions would outgrow their buffers. `permanent` as for lifted_permanent. Requires
/// inputs in kLiftedAdaptiveWindow.
std::optional<Verdict> lifted_adaptive(const LiftedRows& rows, double permanent);

/// The same for insphere's rows of `points` (insphere_rows): where a stage evaluates the exact
/// determinant (B of exact differences, D), the scaled integers (scaled_integers.h) are tried
/// first, with the same verdict at the same stage and several times faster.
std::optional<Verdict> lifted_adaptive(const LiftedRows& rows,
                                       double permanent,
                                       const std::array<Point3, 5>& points);

/// The exact sign when the points are integers below 2^50 (checked by the caller; the rows are
/// then exact differences) with coordinate differences of at most 2^16; none otherwise.
std::optional<Sign> lifted_small_integers(const LiftedRows& rows);

}  // namespace cavity::predicates::detail
