#include "cavity/perturbation/sos.h"

#include "cascade.h"
#include "cavity/predicates/generic_predicates.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/lattice.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient4d.h"

namespace cavity::perturbation {

namespace {

/// Resolves a zero of the lifted determinant D with rows (x, y, z, h, 1) over p[0..4].
///
/// Lowering h_r by eps_r = eps^(key_r + 1) changes only column 4, and D is linear in it:
///   D(eps) = D(0) - sum_r eps_r * C_r,   C_r = (-1)^(r+4) * M_r   (rows r = 1..5),
/// where the minor M_r deletes row r and column 4: the 4x4 determinant with rows (x, y, z, 1) of
/// the other four points in row order, which is orient3d of them in that order (subtract the last
/// row and expand along the column of ones). With D(0) = 0 the sign is that of the lowest-order
/// nonzero term, i.e. of -C_r = (-1)^(r+1) * M_r for the first row in key order with M_r != 0.
/// With the 0-based row index i this is +M for even i and -M for odd i; for e (i = 4) it is
/// orient3d(a, b, c, d): lowering e's height puts e inside, as a larger weight should.
///
/// If a, b, c, d is not flat, M_5 != 0, so the loop returns a nonzero sign at e at the latest.
/// Another minor vanishes only if e lies on a face plane of abcd; two vanish only if e lies on an
/// edge line, three only if e is a vertex. So distinct points need at most three cofactors, and at
/// most two when all five are cospherical (a line meets a sphere in at most two points).
///
/// P is Point3 or GenericPoint3: the argument is the same for implicit points, whose orient3d is
/// as exact as that of doubles. `orient3d` is an exact orient3d of four P.
template <class P, class Orient3d>
Resolution resolve_zero(const std::array<P, 5>& p, const Keys5& keys, Orient3d orient3d) {
    std::uint8_t cofactors = 0;
    for (const std::uint8_t i : key_order(keys)) {
        const std::array<P, 4> others = other_rows(p, i);
        ++cofactors;
        const Sign minor = orient3d(others[0], others[1], others[2], others[3]);
        if (minor != Sign::kZero) {
            return {i % 2 == 0 ? minor : negate(minor), cofactors};
        }
    }
    return {Sign::kZero, cofactors};
}

/// The exact orient3d of the predicates layer, for any point kind.
template <class P>
Resolution resolve_zero(const std::array<P, 5>& p, const Keys5& keys) {
    return resolve_zero(p, keys, [](const P& a, const P& b, const P& c, const P& d) {
        return predicates::orient3d(a, b, c, d);
    });
}

}  // namespace

// insphere is the sign of the same 5x5 determinant with h = |p|^2: subtracting e's row from the
// others and expanding along the column of ones leaves det[p - e, |p|^2 - |e|^2], and
// |p|^2 - |e|^2 = |p - e|^2 + 2 e.(p - e) differs from |p - e|^2 by a combination of columns.
SosVerdict insphere_sos_staged(const Point3& a,
                               const Point3& b,
                               const Point3& c,
                               const Point3& d,
                               const Point3& e,
                               const Keys5& keys) {
    const predicates::Verdict exact = predicates::insphere_staged(a, b, c, d, e);
    if (exact.sign != Sign::kZero) {
        return {exact.sign, exact.stage, 0};
    }
    const Resolution r = resolve_zero(std::array<Point3, 5>{a, b, c, d, e}, keys);
    return {r.sign, exact.stage, r.cofactors};
}

SosVerdict insphere_sos_staged(const GenericPoint3& a,
                               const GenericPoint3& b,
                               const GenericPoint3& c,
                               const GenericPoint3& d,
                               const GenericPoint3& e,
                               const Keys5& keys) {
    const predicates::Verdict exact = predicates::insphere_staged(a, b, c, d, e);
    if (exact.sign != Sign::kZero) {
        return {exact.sign, exact.stage, 0};
    }
    const Resolution r = resolve_zero(std::array<GenericPoint3, 5>{a, b, c, d, e}, keys);
    return {r.sign, exact.stage, r.cofactors};
}

Sign insphere_sos(const GenericPoint3& a,
                  const GenericPoint3& b,
                  const GenericPoint3& c,
                  const GenericPoint3& d,
                  const GenericPoint3& e,
                  const Keys5& keys) {
    return insphere_sos_staged(a, b, c, d, e, keys).sign;
}

namespace detail {

Sign sos_tie(const Point3& a,
             const Point3& b,
             const Point3& c,
             const Point3& d,
             const Point3& e,
             const Keys5& keys) {
    return resolve_zero(std::array<Point3, 5>{a, b, c, d, e}, keys).sign;
}

SosTie sos_tie_counted(const Point3& a,
                       const Point3& b,
                       const Point3& c,
                       const Point3& d,
                       const Point3& e,
                       const Keys5& keys) {
    const Resolution r = resolve_zero(std::array<Point3, 5>{a, b, c, d, e}, keys);
    return {r.sign, r.cofactors};
}

Sign sos_tie_on_lattice(const Point3& a,
                        const Point3& b,
                        const Point3& c,
                        const Point3& d,
                        const Point3& e,
                        const Keys5& keys) {
    return resolve_zero(std::array<Point3, 5>{a, b, c, d, e},
                        keys,
                        [](const Point3& p, const Point3& q, const Point3& r, const Point3& s) {
                            return predicates::orient3d_on_lattice(p, q, r, s);
                        })
        .sign;
}

SosTie sos_tie_on_lattice_counted(const Point3& a,
                                  const Point3& b,
                                  const Point3& c,
                                  const Point3& d,
                                  const Point3& e,
                                  const Keys5& keys) {
    // A lambda of its own, as in sos_tie_on_lattice: each cascade then has one caller and is
    // inlined into it (one shared instantiation was not, and cost the plain engine 0.5% on a
    // grid).
    const Resolution r =
        resolve_zero(std::array<Point3, 5>{a, b, c, d, e},
                     keys,
                     [](const Point3& p, const Point3& q, const Point3& u, const Point3& v) {
                         return predicates::orient3d_on_lattice(p, q, u, v);
                     });
    return {r.sign, r.cofactors};
}

}  // namespace detail

SosVerdict orient4d_sos_staged(const WeightedPoint3& a,
                               const WeightedPoint3& b,
                               const WeightedPoint3& c,
                               const WeightedPoint3& d,
                               const WeightedPoint3& e,
                               const Keys5& keys) {
    const predicates::Verdict exact = predicates::orient4d_staged(a, b, c, d, e);
    if (exact.sign != Sign::kZero) {
        return {exact.sign, exact.stage, 0};
    }
    const Resolution r = resolve_zero(
        std::array<Point3, 5>{position(a), position(b), position(c), position(d), position(e)},
        keys);
    return {r.sign, exact.stage, r.cofactors};
}

}  // namespace cavity::perturbation
