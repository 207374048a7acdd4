#pragma once

#include <array>
#include <cstdint>

#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/orient4d.h"
#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"
#include "cavity/predicates/stage.h"

/// Symbolic perturbation of the vertex weights (Cheng, Dey & Shewchuk, §2.9; used by §5.2, §5.8).
///
/// Scheme. Point i of the input (i = its input index, the perturbation key) gets the weight
/// w_i + eps^(i+1) for an infinitesimal eps > 0, so its lifted height |p_i|^2 - w_i drops by
/// eps^(i+1): the lower the key, the larger its perturbation. The perturbed determinant is then a
/// polynomial in eps whose sign, when the exact (unperturbed) determinant is zero, is that of the
/// lowest-order nonzero coefficient. Expanding the 5x5 lifted determinant (rows x, y, z, h, 1)
/// along its height column, the coefficient of eps^(i+1) is minus the cofactor of row i, which is
/// +-orient3d of the other four points. So a zero is resolved by visiting the five points in key
/// order and taking the first nonzero cofactor; the cofactor of any row whose other four points
/// form a non-flat tetrahedron is nonzero, so the result is never zero when the reference
/// tetrahedron is non-flat.
///
/// Consistency. Every predicate that can see the same degeneracy (conflict tests on solid and ghost
/// tetrahedra, flips, deletion, polygon insertion) uses this one scheme, keyed on the input index,
/// which is intrinsic to the input: the perturbed (weighted) Delaunay triangulation is unique and
/// independent of the insertion order, the point-location method and the storage.
///
/// Steiner points. Implicit points (predicates/generic_point.h) are perturbed by the same scheme;
/// the caller gives each one a key after every input point's, in creation order: with n input
/// points, the k-th point created (k = 0, 1, ...) has key n + k, which is its index when new
/// points are appended to the input (as edge protection appends them to the PLC). Consequences:
/// the keys are distinct and deterministic (they depend only on the order of creation); a Steiner
/// point is perturbed less than every input point (eps^(n+k+1) is of higher order), so a tie among
/// input points alone is broken exactly as before any Steiner point existed, and a tie involving a
/// Steiner point is broken by the input points' cofactors first, then by older Steiner points'.
/// The cascade is unchanged: its cofactors are orient3d of four of the five points, exact on
/// implicit points too, and never all zero when the reference tetrahedron is not flat.
namespace cavity::perturbation {

using predicates::GenericPoint3;
using predicates::Point3;
using predicates::Sign;
using predicates::WeightedPoint3;

/// Perturbation keys (input indices) of the five arguments, in argument order.
using Keys5 = std::array<std::uint32_t, 5>;
using Keys4 = std::array<std::uint32_t, 4>;

/// A perturbed predicate's answer: the sign, the stage of the exact evaluation, and how many
/// orient3d cofactors the perturbation evaluated (0: the exact predicate decided on its own).
struct SosVerdict {
    Sign sign;
    predicates::Stage stage;
    std::uint8_t cofactors;
};

namespace detail {

/// The sign of the perturbed determinant when the exact one is zero: the first nonzero cofactor
/// in key order (out of line: rare, and kept off the callers' inlined fast path).
Sign sos_tie(const Point3& a,
             const Point3& b,
             const Point3& c,
             const Point3& d,
             const Point3& e,
             const Keys5& keys);

/// A tie's sign and the number of cofactors that decided it (what the engine's counters record).
struct SosTie {
    Sign sign;
    std::uint8_t cofactors;
};

/// sos_tie, with the cofactors it evaluated.
SosTie sos_tie_counted(const Point3& a,
                       const Point3& b,
                       const Point3& c,
                       const Point3& d,
                       const Point3& e,
                       const Keys5& keys);

/// sos_tie for integer points of an exact lattice box (predicates/lattice.h, an unchecked
/// precondition): each cofactor is then the plain orient3d determinant, exact as it stands.
Sign sos_tie_on_lattice(const Point3& a,
                        const Point3& b,
                        const Point3& c,
                        const Point3& d,
                        const Point3& e,
                        const Keys5& keys);

/// sos_tie_on_lattice, with the cofactors it evaluated: the counting engine takes the plain
/// engine's route on grids, where ties are most of the insphere tests.
SosTie sos_tie_on_lattice_counted(const Point3& a,
                                  const Point3& b,
                                  const Point3& c,
                                  const Point3& d,
                                  const Point3& e,
                                  const Keys5& keys);

}  // namespace detail

/// insphere under the perturbation: kPos when e is inside the perturbed circumball of a, b, c, d
/// (positively oriented). Never kZero if a, b, c, d is not flat and the five keys are distinct.
/// Inline, so that the exact predicate's filter inlines into the caller's loop.
inline Sign insphere_sos(const Point3& a,
                         const Point3& b,
                         const Point3& c,
                         const Point3& d,
                         const Point3& e,
                         const Keys5& keys) {
    const Sign exact = predicates::insphere(a, b, c, d, e);
    return exact != Sign::kZero ? exact : detail::sos_tie(a, b, c, d, e, keys);
}

SosVerdict insphere_sos_staged(const Point3& a,
                               const Point3& b,
                               const Point3& c,
                               const Point3& d,
                               const Point3& e,
                               const Keys5& keys);

/// insphere_sos on any mix of input and implicit points (keys as stated at the top).
Sign insphere_sos(const GenericPoint3& a,
                  const GenericPoint3& b,
                  const GenericPoint3& c,
                  const GenericPoint3& d,
                  const GenericPoint3& e,
                  const Keys5& keys);

SosVerdict insphere_sos_staged(const GenericPoint3& a,
                               const GenericPoint3& b,
                               const GenericPoint3& c,
                               const GenericPoint3& d,
                               const GenericPoint3& e,
                               const Keys5& keys);

/// orient4d (the power test) under the perturbation. Never kZero if a, b, c, d is not flat. The
/// cofactors see only the positions: the tie-break is the same as insphere_sos's.
inline Sign orient4d_sos(const WeightedPoint3& a,
                         const WeightedPoint3& b,
                         const WeightedPoint3& c,
                         const WeightedPoint3& d,
                         const WeightedPoint3& e,
                         const Keys5& keys) {
    const Sign exact = predicates::orient4d(a, b, c, d, e);
    if (exact != Sign::kZero) {
        return exact;
    }
    return detail::sos_tie(
        {a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}, {d.x, d.y, d.z}, {e.x, e.y, e.z}, keys);
}

SosVerdict orient4d_sos_staged(const WeightedPoint3& a,
                               const WeightedPoint3& b,
                               const WeightedPoint3& c,
                               const WeightedPoint3& d,
                               const WeightedPoint3& e,
                               const Keys5& keys);

}  // namespace cavity::perturbation
