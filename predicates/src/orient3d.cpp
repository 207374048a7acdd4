#include "cavity/predicates/orient3d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "cavity/predicates/detail/expansion.h"
#include "exact_integer.h"
#include "small_integers.h"
#include "staged_pipeline.h"

namespace cavity::predicates::detail {
namespace {

// Inputs with exponents in [-280, 300]: differences are multiples of 2^-332 and below 2^302, so
// every product of three of them (and of their splits) is at least 2^-996, a normal number, and
// below 2^910: the expansion arithmetic neither underflows nor overflows.
constexpr ExponentWindow kAdaptiveWindow = {-280, 300};

// Error of the determinant of the rounded differences. With d = d~ + t, |t| <= u|d~|, each
// monomial of degree 3 moves by at most ((1 + u)^3 - 1) |m~| = (3u + 3u^2 + u^3) |m~|, so
// |det - det~| <= (3u + 3u^2 + u^3) * permanent, the permanent sum |m~| computed in doubles with
// 5 roundings along any path. The sign of the exact det~ is that of its largest component, and
// |det~| >= (1 - 2u) |largest| for a nonoverlapping expansion. Accepting when |largest| >
// fl(C * permanent) needs C >= (3u + 3u^2 + u^3) / ((1 - u)^6 (1 - 2u)) ~ 3u + 27u^2.
constexpr double kU = 0x1p-53;
constexpr double kRoundedDifferenceBound = (3.0 + 64.0 * kU) * kU;

/// The exact determinant of the rounded differences (Shewchuk's stage B), which is the exact
/// answer when every difference was exact and is otherwise accepted when it dominates the error
/// bound above. Requires inputs in kAdaptiveWindow.
std::optional<Sign> orient3d_adaptive(const std::array<Point3, 4>& p) {
    const Point3& a = p[0];
    const Point3& b = p[1];
    const Point3& c = p[2];
    const Point3& d = p[3];
    double adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz;
    double adx_t, ady_t, adz_t, bdx_t, bdy_t, bdz_t, cdx_t, cdy_t, cdz_t;
    two_diff(a.x, d.x, adx, adx_t);
    two_diff(a.y, d.y, ady, ady_t);
    two_diff(a.z, d.z, adz, adz_t);
    two_diff(b.x, d.x, bdx, bdx_t);
    two_diff(b.y, d.y, bdy, bdy_t);
    two_diff(b.z, d.z, bdz, bdz_t);
    two_diff(c.x, d.x, cdx, cdx_t);
    two_diff(c.y, d.y, cdy, cdy_t);
    two_diff(c.z, d.z, cdz, cdz_t);

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
    double det[24];
    const int det_len = expansion_sum(ab_sum_len, ab_sum, c_len, c_term, det);

    const bool differences_exact = adx_t == 0.0 && ady_t == 0.0 && adz_t == 0.0 && bdx_t == 0.0 &&
                                   bdy_t == 0.0 && bdz_t == 0.0 && cdx_t == 0.0 && cdy_t == 0.0 &&
                                   cdz_t == 0.0;
    if (differences_exact) {
        return static_cast<Sign>(expansion_sign(det_len, det));
    }
    const double permanent = (std::abs(bdx * cdy) + std::abs(bdy * cdx)) * std::abs(adz) +
                             (std::abs(cdx * ady) + std::abs(cdy * adx)) * std::abs(bdz) +
                             (std::abs(adx * bdy) + std::abs(ady * bdx)) * std::abs(cdz);
    if (det_len > 0 && std::abs(det[det_len - 1]) > kRoundedDifferenceBound * permanent) {
        return static_cast<Sign>(expansion_sign(det_len, det));
    }
    return std::nullopt;
}

/// The exact sign for integer inputs (below 2^50, so the differences are exact) whose differences
/// are at most 2^24: the 2x2 minors, below 2^49, are exact in doubles and the products with the
/// third column, below 2^74, exact in 128-bit integers. None for other inputs.
std::optional<Sign> orient3d_small_integers(const Point3& a,
                                            const Point3& b,
                                            const Point3& c,
                                            const Point3& d) {
    if (!(is_small_integer(a) & is_small_integer(b) & is_small_integer(c) & is_small_integer(d))) {
        return std::nullopt;
    }
    const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
    const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
    const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
    const double max = std::max({std::abs(adx),
                                 std::abs(ady),
                                 std::abs(adz),
                                 std::abs(bdx),
                                 std::abs(bdy),
                                 std::abs(bdz),
                                 std::abs(cdx),
                                 std::abs(cdy),
                                 std::abs(cdz)});
    if (max > 0x1p24) {
        return std::nullopt;
    }
    const auto bc = static_cast<std::int64_t>(bdx * cdy - bdy * cdx);
    const auto ca = static_cast<std::int64_t>(cdx * ady - cdy * adx);
    const auto ab = static_cast<std::int64_t>(adx * bdy - ady * bdx);
    const Int128 det = Int128{static_cast<std::int64_t>(adz)} * bc +
                       Int128{static_cast<std::int64_t>(bdz)} * ca +
                       Int128{static_cast<std::int64_t>(cdz)} * ab;
    return sign_of(det);
}

}  // namespace

Verdict orient3d_slow(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    if (const std::optional<Sign> s = orient3d_small_integers(a, b, c, d)) {
        return {*s, Stage::kAdaptive};
    }
    return run_after_filter(
        std::array<Point3, 4>{a, b, c, d},
        kAdaptiveWindow,
        [](const auto& p) { return orient3d_filter(p[0], p[1], p[2], p[3]); },
        orient3d_adaptive,
        [](const auto& p) { return orient3d_exact(p[0], p[1], p[2], p[3]); });
}

}  // namespace cavity::predicates::detail
