#include "cavity/predicates/orient3d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "exact_integer.h"
#include "orient3d_adaptive.h"
#include "small_integers.h"
#include "staged_pipeline.h"

namespace cavity::predicates::detail {
namespace {

/// The exact sign for integer inputs (below 2^50, so the differences are exact) whose differences
/// are at most 2^24: the 2x2 minors, below 2^49, are exact in doubles and the products with the
/// third column, below 2^74, exact in 128-bit integers. None for other inputs.
std::optional<Sign> orient3d_small_integers(const Point3& a,
                                            const Point3& b,
                                            const Point3& c,
                                            const Point3& d) {
    // The first point alone before the others: most queries here have fractional coordinates.
    if (!(is_small_integer(a) &&
          (is_small_integer(b) & is_small_integer(c) & is_small_integer(d)))) {
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
        kOrient3dAdaptiveWindow,
        [](const auto& p) { return orient3d_filter(p[0], p[1], p[2], p[3]); },
        orient3d_adaptive,
        [](const auto& p) { return orient3d_exact(p[0], p[1], p[2], p[3]); });
}

}  // namespace cavity::predicates::detail
