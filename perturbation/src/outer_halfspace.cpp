#include "cavity/perturbation/outer_halfspace.h"

#include <type_traits>

#include "cascade.h"
#include "cavity/predicates/generic_predicates.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient4d.h"

namespace cavity::perturbation {

namespace {

using predicates::Verdict;

/// Breaks a tie of u on the (power) circle of v, w, x, all four in the plane of vwx.
///
/// In affine coordinates (s, t) of the plane, the in-plane test is D = det of the rows
/// (s, t, h, 1) over v, w, x, u, with h = |p|^2 - w_p: u is inside iff D * orient2d(v, w, x) > 0
/// (an affine change of (s, t) scales both factors by the same determinant, and |p|^2 differs from
/// s^2 + t^2 in orthonormal coordinates by an affine function, a combination of columns). Lowering
/// h_r by eps_r = eps^(key_r + 1) gives, as for the 3D determinant,
///   D(eps) = D(0) - sum_r eps_r * C_r,   C_r = (-1)^(r+3) * M_r   (rows r = 1..4),
/// where M_r = orient2d of the other three points in row order. So at D(0) = 0 the sign of D is
/// (-1)^r * M_r for the first row in key order with M_r != 0.
///
/// orient2d is taken as o(p, q, r) = orient3d(p, q, r, y): for p, q, r in the plane this is a fixed
/// nonzero multiple of orient2d, and the factor cancels in the product of two of them. Since
/// x w v y is positive, o(v, w, x) = orient3d(v, w, x, y) < 0 (one transposition), so u conflicts
/// iff (-1)^r * M_r < 0, i.e. with the 0-based row index i = r - 1, the sign is +M for even i and
/// -M for odd i. For u (i = 3) it is -o(v, w, x) > 0: lowering u's height puts u inside.
///
/// Unweighted, the four points lie on one circle, and a line meets a circle in at most two points,
/// so no three of them are collinear: every minor is nonzero and the first one decides. Weighted,
/// u may lie on the line of an edge of vwx, zeroing one minor, but never on two such lines unless
/// it is a vertex; M_4 = o(v, w, x) != 0, so at most two minors are evaluated.
///
/// Consistency: for u in the plane this is exactly insphere_sos / orient4d_sos(x, w, v, y, u)
/// whatever y's key. After a rigid motion putting the plane at z = 0, the 5x5 lifted determinant
/// expands along its z column to a multiple of the in-plane D(eps) fixed by y, so the ghost and the
/// solid tetrahedron behind vwx never disagree on a coplanar u.
///
/// P is Point3 or GenericPoint3 (implicit points: the same argument, exact orient3d).
template <class P>
Resolution resolve_tie(const std::array<P, 4>& p, const P& y, const Keys4& keys) {
    std::uint8_t cofactors = 0;
    for (const std::uint8_t i : key_order(keys)) {
        const std::array<P, 3> others = other_rows(p, i);
        ++cofactors;
        const Sign minor = predicates::orient3d(others[0], others[1], others[2], y);
        if (minor != Sign::kZero) {
            return {i % 2 == 0 ? minor : negate(minor), cofactors};
        }
    }
    return {Sign::kZero, cofactors};
}

/// For u in the plane of vwx: u is inside the circumdisk of vwx iff it is inside the circumball
/// of x w v y, whose intersection with the plane is that disk (for weighted points, the witness
/// plane of x w v y restricted to the plane's lift is the witness plane of v w x).
Verdict in_circumball(
    const Point3& x, const Point3& w, const Point3& v, const Point3& y, const Point3& u) {
    return predicates::insphere_staged(x, w, v, y, u);
}

Verdict in_circumball(const GenericPoint3& x,
                      const GenericPoint3& w,
                      const GenericPoint3& v,
                      const GenericPoint3& y,
                      const GenericPoint3& u) {
    return predicates::insphere_staged(x, w, v, y, u);
}

Verdict in_circumball(const WeightedPoint3& x,
                      const WeightedPoint3& w,
                      const WeightedPoint3& v,
                      const WeightedPoint3& y,
                      const WeightedPoint3& u) {
    return predicates::orient4d_staged(x, w, v, y, u);
}

/// The stage reported is that of the last exact predicate evaluated (orient3d, then the disk
/// test if u is coplanar).
template <class P>
SosVerdict outer_halfspace(
    const P& v, const P& w, const P& x, const P& y, const P& u, const Keys4& keys) {
    // Points in front of vwx have orient3d(v, w, x, .) > 0, since y behind it has
    // orient3d(v, w, x, y) = -orient3d(x, w, v, y) < 0.
    const Verdict side =
        predicates::orient3d_staged(position(v), position(w), position(x), position(u));
    if (side.sign != Sign::kZero) {
        return {side.sign, side.stage, 0};
    }
    const Verdict disk = in_circumball(x, w, v, y, u);
    if (disk.sign != Sign::kZero) {
        return {disk.sign, disk.stage, 0};
    }
    using Position = std::decay_t<decltype(position(v))>;
    const Resolution r =
        resolve_tie(std::array<Position, 4>{position(v), position(w), position(x), position(u)},
                    Position(position(y)),
                    keys);
    return {r.sign, disk.stage, r.cofactors};
}

}  // namespace

SosVerdict outer_halfspace_sos_staged(const Point3& v,
                                      const Point3& w,
                                      const Point3& x,
                                      const Point3& y,
                                      const Point3& u,
                                      const Keys4& keys) {
    return outer_halfspace(v, w, x, y, u, keys);
}

Sign outer_halfspace_sos(const Point3& v,
                         const Point3& w,
                         const Point3& x,
                         const Point3& y,
                         const Point3& u,
                         const Keys4& keys) {
    return outer_halfspace(v, w, x, y, u, keys).sign;
}

SosVerdict outer_halfspace_sos_staged(const GenericPoint3& v,
                                      const GenericPoint3& w,
                                      const GenericPoint3& x,
                                      const GenericPoint3& y,
                                      const GenericPoint3& u,
                                      const Keys4& keys) {
    return outer_halfspace(v, w, x, y, u, keys);
}

Sign outer_halfspace_sos(const GenericPoint3& v,
                         const GenericPoint3& w,
                         const GenericPoint3& x,
                         const GenericPoint3& y,
                         const GenericPoint3& u,
                         const Keys4& keys) {
    return outer_halfspace(v, w, x, y, u, keys).sign;
}

SosVerdict outer_halfspace_weighted_sos_staged(const WeightedPoint3& v,
                                               const WeightedPoint3& w,
                                               const WeightedPoint3& x,
                                               const WeightedPoint3& y,
                                               const WeightedPoint3& u,
                                               const Keys4& keys) {
    return outer_halfspace(v, w, x, y, u, keys);
}

Sign outer_halfspace_weighted_sos(const WeightedPoint3& v,
                                  const WeightedPoint3& w,
                                  const WeightedPoint3& x,
                                  const WeightedPoint3& y,
                                  const WeightedPoint3& u,
                                  const Keys4& keys) {
    return outer_halfspace(v, w, x, y, u, keys).sign;
}

}  // namespace cavity::perturbation
