#include "cavity/predicates/orient3d.h"

#include <array>
#include <cstdint>
#include <optional>

#include "cavity/predicates/detail/translated_rows.h"
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
    if (!(is_small_integer(a) && all_small_integers(b, c, d))) {
        return std::nullopt;
    }
    const Point3 ad = translated(a, d);
    const Point3 bd = translated(b, d);
    const Point3 cd = translated(c, d);
    if (max_magnitude(ad, bd, cd) > 0x1p24) {
        return std::nullopt;
    }
    const auto bc = static_cast<std::int64_t>(bd.x * cd.y - bd.y * cd.x);
    const auto ca = static_cast<std::int64_t>(cd.x * ad.y - cd.y * ad.x);
    const auto ab = static_cast<std::int64_t>(ad.x * bd.y - ad.y * bd.x);
    const Int128 det = Int128{static_cast<std::int64_t>(ad.z)} * bc +
                       Int128{static_cast<std::int64_t>(bd.z)} * ca +
                       Int128{static_cast<std::int64_t>(cd.z)} * ab;
    return sign_of(det);
}

/// True when the four points lie in one plane perpendicular to a coordinate axis: a column of
/// differences is zero, so the determinant is, whatever the other columns. The walls and floors of
/// CAD models and height fields give these exact zeros by the thousand; with fractional
/// coordinates the stages below prove each in full, in exact arithmetic when the other
/// differences are inexact.
bool on_axis_plane(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    const bool x = (a.x == d.x) & (b.x == d.x) & (c.x == d.x);
    const bool y = (a.y == d.y) & (b.y == d.y) & (c.y == d.y);
    const bool z = (a.z == d.z) & (b.z == d.z) & (c.z == d.z);
    return x | y | z;
}

}  // namespace

// orient3d_staged_on_lattice (lattice.h) gives this function's verdict on lattices without
// calling it: every small-integer query decided here at kAdaptive (lattice_test checks it).
Verdict orient3d_slow(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    if (on_axis_plane(a, b, c, d)) {
        return {Sign::kZero, Stage::kAdaptive};
    }
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
