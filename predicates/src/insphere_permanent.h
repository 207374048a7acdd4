#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "cavity/predicates/detail/insphere_filter.h"
#include "cavity/predicates/sign.h"
#include "lifted_adaptive.h"

// The first adaptive stage for insphere (Shewchuk's stage A): when every difference to e is exact
// (nearby points, Sterbenz), the plain double determinant of the differences under an error bound
// proportional to its permanent, the determinant with every term made nonnegative. The
// semi-static filter bounds the same evaluation by the worst case of its column maxima, 1224u
// maxx maxy maxz m^2; on near-cospherical points the 3x3 minors cancel but their terms do not, and
// the permanent, computed from the actual terms, is typically far below that worst case. It costs
// a second pass of about 60 flops, against the double-double stage's few hundred.
namespace cavity::predicates::detail {

// Error bound (u = 2^-53). The differences are exact, so the only roundings are those of
// insphere_determinant. For an expression of sums, differences and products, |fl(E) - E| <=
// gamma_k |E|, where |E| is E with every input replaced by its magnitude and every subtraction by
// an addition, and k bounds the roundings accumulated by any of its terms (Higham, Accuracy and
// Stability, §3.1). A term of det passes through the lift (the square, two additions: 3), the
// 3x3 minor (the 2x2 product, its subtraction, the product with z, two additions: 5), their
// product (1) and the final two-level sum (2): k = 11. |E| is the permanent
//   P = sum over rows i of lift_i * sum |z_j| (|x_k y_l| + |x_l y_k|)   (the 3x3 minor's terms),
// computed below in the same shape with the same 11 roundings along any term, so
// P <= P~ / (1 - u)^11 <= (1 + 12u) P~ and the error is at most
//   gamma_11 (1 + 12u) P~ <= 11u (1 + 24u) P~.
// Accepting when |det~| > fl(12u P~) (one rounding, down by at most (1 - u) when normal) leaves
// 12u (1 - u) - 11u (1 + 24u) > 0.9u P~ for what follows.
//
// Underflow. The inputs are in kLiftedAdaptiveWindow, so a nonzero difference is a multiple of
// 2^-192 (and below 2^182). Then a nonzero product of two differences is at least 2^-384, a
// multiple of 2^-436 once rounded; a 2x2 minor, a difference of two such, is 0 or at least
// 2^-436; its product with z at least 2^-628, rounded a multiple of 2^-680, so a 3x3 minor is 0 or
// at least 2^-680; a lift 0 or at least 2^-384. Only the four products lift * minor (and the four
// of P~) can fall below 2^-1022, each then losing at most 2^-1075 absolutely; sums of subnormals
// are exact. Together with their propagation through the final sums that is below 2^-1071 for
// det~ and for P~ (times 12u, negligible). Accepting also requires |det~| > 2^-1000: when
// fl(12u P~) >= 2^-1000, the 0.9u P~ left above is at least 2^-1004 and covers 2^-1071; when it
// is below, the error is below 2^-1000 (11/12 of it plus 2^-1071) and so below |det~|.
// Overflow: differences below 2^182 keep every term below 2^910 and det~, P~ below 2^917.
inline constexpr double kInspherePermanentBound = 12.0 * 0x1p-53;
inline constexpr double kInspherePermanentFloor = 0x1p-1000;

/// P~, the permanent of the rows (no weights) in the shape of insphere_determinant: at most 11
/// roundings along any monomial's path. It serves every stage of insphere after the filter: this
/// one, and the double-double stage and stage C of lifted_adaptive, whose bounds admit any P~
/// computed with at most 12 roundings along a path (lifted_adaptive.h).
inline double insphere_row_permanent(const LiftedRows& rows) {
    const double(&x)[4] = rows.x;
    const double(&y)[4] = rows.y;
    const double(&z)[4] = rows.z;
    double ax[4], ay[4], az[4], lift[4];
    for (int i = 0; i < 4; ++i) {
        ax[i] = std::abs(x[i]);
        ay[i] = std::abs(y[i]);
        az[i] = std::abs(z[i]);
        lift[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    }
    // The permanents of the 2x2 minors x_i y_j - x_j y_i.
    auto pm2 = [&](int i, int j) { return ax[i] * ay[j] + ax[j] * ay[i]; };
    const double ab = pm2(0, 1);
    const double bc = pm2(1, 2);
    const double cd = pm2(2, 3);
    const double da = pm2(3, 0);
    const double ac = pm2(0, 2);
    const double bd = pm2(1, 3);
    // The permanents of the 3x3 minors, in the shape of insphere_rows_determinant's.
    const double abc = az[0] * bc + az[1] * ac + az[2] * ab;
    const double bcd = az[1] * cd + az[2] * bd + az[3] * bc;
    const double cda = az[2] * da + az[3] * ac + az[0] * cd;
    const double dab = az[3] * ab + az[0] * bd + az[1] * da;
    return (lift[3] * abc + lift[2] * dab) + (lift[1] * cda + lift[0] * bcd);
}

/// The sign of the insphere determinant of the rows when their differences are exact and the
/// permanent bound certifies it; none otherwise. `permanent` is insphere_row_permanent(rows).
/// Requires inputs in kLiftedAdaptiveWindow and no weights (rows.w zero).
inline std::optional<Sign> insphere_permanent(const LiftedRows& rows, double permanent) {
    if (!rows.differences_exact) {
        return std::nullopt;
    }
    const double(&x)[4] = rows.x;
    const double(&y)[4] = rows.y;
    const double(&z)[4] = rows.z;
    const double det = insphere_rows_determinant(
        {x[0], y[0], z[0]}, {x[1], y[1], z[1]}, {x[2], y[2], z[2]}, {x[3], y[3], z[3]});
    const double bound = std::max(kInspherePermanentBound * permanent, kInspherePermanentFloor);
    if (!(std::abs(det) > bound)) {
        return std::nullopt;
    }
    return det > 0.0 ? Sign::kPos : Sign::kNeg;
}

}  // namespace cavity::predicates::detail
