#pragma once

#include <cmath>
#include <cstdint>

#include "cavity/predicates/detail/insphere_filter.h"
#include "cavity/predicates/detail/orient3d_filter.h"
#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"
#include "cavity/predicates/stage.h"

namespace cavity::predicates {

// Small integer lattices, where the plain double determinants are exact (grids, the usual exactly
// degenerate input): the sign of the plain evaluation is then the exact sign, so no filter bound,
// no adaptive stage and no per-call integer test is needed.
//
// Why. Let every coordinate be an integer and the extent of the points along each axis be at most
// S. A difference of two coordinates is then an integer of magnitude at most S, computed exactly
// (the exact difference is representable, and rounding keeps representable values). From there
// the plain evaluations multiply, add and subtract integers, and each such operation is exact
// when its exact result has magnitude at most 2^53 (every integer up to 2^53 is a double). The
// largest magnitude of each intermediate, in the evaluation order of insphere_determinant
// (detail/insphere_filter.h), with every difference in [-S, S]:
//   2x2 minors ab = aex*bey - bex*aey, ...:      products S^2, minors 2 S^2;
//   3x3 minors abc = aez*bc - bez*ac + cez*ab:   products 2 S^3, partial sum 4 S^3, and the minor
//                                                is a 3x3 determinant with entries in [-S, S],
//                                                so at most 4 S^3 (the largest determinant of a
//                                                3x3 matrix with entries in [-1, 1] is 4);
//   lifts aex^2 + aey^2 + aez^2:                 squares S^2, partial sum 2 S^2, lift 3 S^2;
//   lift * 3x3 minor:                            12 S^5;
//   the two differences of such products:        24 S^5 each;
//   the determinant, their sum:                  48 S^5.
// So 48 S^5 <= 2^53, i.e. S <= 715 (48 * 715^5 < 2^53 < 48 * 716^5), makes insphere exact.
// orient3d_determinant (detail/orient3d_filter.h) needs less: 2x2 minors 2 S^2, their products
// with a z difference 2 S^3, the partial sum 4 S^3 and the 3x3 determinant 4 S^3 <= 2^53, i.e.
// S <= 2^17, which S <= 715 implies.

/// The largest extent along an axis of a set of integer points for which the plain insphere and
/// orient3d determinants are exact (above).
inline constexpr double kLatticeMaxSpan = 715.0;

/// True when v is an integer (every finite double of magnitude 2^52 or more is one).
[[gnu::always_inline]] inline bool is_integral(double v) {
    if (!(std::abs(v) < 0x1p52)) {
        return std::isfinite(v);
    }
    return static_cast<double>(static_cast<std::int64_t>(v)) == v;
}

/// Branch-free: the three tests taken into locals and combined with `&`.
[[gnu::always_inline]] inline bool is_integral(const Point3& p) {
    const bool x = is_integral(p.x);
    const bool y = is_integral(p.y);
    const bool z = is_integral(p.z);
    return x & y & z;
}

/// True when integer points in the box [lo, hi] are an exact lattice: their extent along each
/// axis is at most kLatticeMaxSpan. (The rounded extent exceeds the bound exactly when the true
/// one does: rounding is monotone and the bound is a double.)
inline bool is_lattice_box(const Point3& lo, const Point3& hi) {
    return hi.x - lo.x <= kLatticeMaxSpan && hi.y - lo.y <= kLatticeMaxSpan &&
           hi.z - lo.z <= kLatticeMaxSpan;
}

/// Sign of det[a-d; b-d; c-d] (as orient3d) for integer points of an exact lattice box (an
/// unchecked precondition): the plain determinant, which is then exact.
[[gnu::always_inline]] inline Sign orient3d_on_lattice(const Point3& a,
                                                       const Point3& b,
                                                       const Point3& c,
                                                       const Point3& d) {
    const double det = detail::orient3d_determinant(a, b, c, d);
    return static_cast<Sign>((det > 0.0) - (det < 0.0));
}

/// The magnitude below which a lattice's coordinates are small enough for
/// orient3d_staged_on_lattice: orient3d's stage after the filter decides integers below it exactly
/// (orient3d_slow, orient3d.cpp).
inline constexpr double kLatticeStagedMagnitude = 0x1p50;

/// True when every point of the box [lo, hi] has coordinates below kLatticeStagedMagnitude in
/// magnitude.
inline bool is_staged_lattice_box(const Point3& lo, const Point3& hi) {
    return -kLatticeStagedMagnitude < lo.x && -kLatticeStagedMagnitude < lo.y &&
           -kLatticeStagedMagnitude < lo.z && hi.x < kLatticeStagedMagnitude &&
           hi.y < kLatticeStagedMagnitude && hi.z < kLatticeStagedMagnitude;
}

/// orient3d_staged's verdict, sign and deciding stage, for integer points of an exact lattice box
/// with coordinates below kLatticeStagedMagnitude (an unchecked precondition), without its work:
/// the counting engine's route on grids. A zero goes past orient3d_staged's filter (its test is
/// |det| > bound, never met by 0) to orient3d_slow, which decides it at kAdaptive. Every other
/// determinant the filter certifies, so the route needs neither its bound nor its guards: the
/// differences are integers of magnitude at most kLatticeMaxSpan, so the filter's bound
/// kOrient3dErrorBound * maxx * maxy * maxz is below 50 * 2^-53 * 715^3 < 3e-6 (and so is its
/// rounded value), while a nonzero determinant of integers is at least 1 in magnitude and is
/// computed exactly (orient3d_filter evaluates the same determinant); a zero column maximum makes
/// the determinant 0, and the largest is at most 715, inside the filter's guards.
static_assert(detail::kOrient3dErrorBound * kLatticeMaxSpan * kLatticeMaxSpan * kLatticeMaxSpan <
                      0x1p-1 &&
                  detail::kOrient3dMinMax <= 1.0 && kLatticeMaxSpan <= detail::kOrient3dMaxMax,
              "orient3d's filter certifies every nonzero determinant of an exact lattice box");

[[gnu::always_inline]] inline Verdict orient3d_staged_on_lattice(const Point3& a,
                                                                 const Point3& b,
                                                                 const Point3& c,
                                                                 const Point3& d) {
    const double det = detail::orient3d_determinant(a, b, c, d);
    if (det == 0.0) {
        return {Sign::kZero, Stage::kAdaptive};
    }
    return {det > 0.0 ? Sign::kPos : Sign::kNeg, Stage::kFilter};
}

/// Sign of det[p-e, |p-e|^2] over p = a..d (as insphere) for integer points of an exact lattice
/// box (an unchecked precondition): the plain determinant, which is then exact.
[[gnu::always_inline]] inline Sign insphere_on_lattice(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    const double det = detail::insphere_determinant(a, b, c, d, e);
    return static_cast<Sign>((det > 0.0) - (det < 0.0));
}

}  // namespace cavity::predicates
