#pragma once

#include <cstdint>
#include <utility>
#include <variant>
#include <vector>

#include "cavity/core/geometry/counters.h"
#include "cavity/core/mesh/tetrahedron.h"
#include "cavity/perturbation/outer_halfspace.h"
#include "cavity/perturbation/sos.h"
#include "cavity/predicates/generic_filter.h"
#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/insphere_static_filter.h"
#include "cavity/predicates/lattice.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient3d_static_filter.h"
#include "cavity/predicates/point.h"
#include "cavity/predicates/stage.h"

namespace cavity::core {

using predicates::GenericPoint3;
using predicates::Point3;
using predicates::Sign;
using predicates::WeightedPoint3;

/// The points the engine triangulates, in insertion order (vertex id = insertion rank, for memory
/// locality), each with its perturbation key (the input index), and the geometric tests of the
/// engine on top of the exact and perturbed predicates. Given Counters as its tally, every test
/// records its deciding stage.
///
/// Implicit points. A geometry may hold Steiner points defined exactly by input doubles
/// (generic_point.h; the CDT's edge protection makes them): `exact` is then one definition per
/// point (an input point is its own Point3) and `points` holds their coordinates rounded to
/// doubles. Every test by vertex id below is then decided on the definitions by the generic
/// predicates, so no exact decision sees a rounded coordinate; point(v) stays the rounded point,
/// for what needs no exactness (walks, boxes, output). Without implicit points `exact` is empty
/// and the tests are the plain ones, behind one well-predicted branch.
/// With implicit points each point also keeps a bound on its rounding (generic_filter.h's
/// rounding_error, computed once on arrival), so the tests by vertex id try the floating-point
/// stage on the rounded points first and call the generic predicates only when it cannot decide.
///
/// Lattices. When every point is an integer point and the points span at most
/// predicates::kLatticeMaxSpan along each axis (a grid: detected at construction and kept up to
/// date by the appends), the plain double determinants are exact (predicates/lattice.h). The
/// uncounted tests then take the sign of the plain determinant and, on a zero, go straight to the
/// tie-break, whose cofactors are plain determinants too: no filter bound, no adaptive stage. The
/// counted tests count the stages of the predicates' staged route, but take the plain route where
/// it gives the same counts: the tie-break counts its cofactors, not their stages, and orient3d's
/// stage after its filter is known on a lattice of small integers (orient3d_staged_on_lattice).
class Geometry {
public:
    Geometry(std::vector<Point3> points,
             std::vector<std::uint32_t> keys,
             std::vector<double> weights,
             std::vector<GenericPoint3> exact = {});

    /// The point's coordinates; rounded to doubles when it is implicit.
    const Point3& point(VertexId v) const { return points_[v]; }

    /// True when some point is implicit (its exact definition is not its coordinates).
    bool has_implicit() const { return !exact_.empty(); }

    /// True when point v is implicit.
    bool implicit(VertexId v) const {
        return has_implicit() && !std::holds_alternative<Point3>(exact_[v]);
    }

    /// The exact point v: its definition when implicit, else its coordinates.
    GenericPoint3 generic(VertexId v) const {
        return has_implicit() ? exact_[v] : GenericPoint3(points_[v]);
    }

    /// Point v's doubles and a bound on their distance to the exact point in every coordinate
    /// (0 when v is explicit), as the floating-point stages of the generic predicates take it.
    predicates::RoundedPoint rounded(VertexId v) const {
        return {points_[v], has_implicit() ? errors_[v] : 0.0};
    }

    std::uint32_t key(VertexId v) const { return keys_[v]; }

    /// Hands the coordinates' array over, in vertex order, and leaves the geometry without
    /// points (keys stay): how a batch run on lent points (triangulate_in_place) returns them.
    std::vector<Point3> take_points() && { return std::move(points_); }

    bool weighted() const { return !weights_.empty(); }

    /// True when the points form an exact lattice (see the top): the uncounted tests then use
    /// the plain determinants.
    bool lattice() const { return lattice_; }

    std::size_t size() const { return points_.size(); }

    /// Appends an unweighted point whose key is its new index (for geometries by index, like a
    /// live CDT receiving a vertex). Returns its vertex id.
    VertexId append_point(const Point3& p) {
        points_.push_back(p);
        widen_box(p);
        if (has_implicit()) {
            exact_.emplace_back(p);
            errors_.push_back(0.0);
        }
        keys_.push_back(static_cast<std::uint32_t>(keys_.size()));
        return static_cast<VertexId>(points_.size() - 1);
    }

    /// Appends a point with perturbation key `key` (an input index no other point has) and, when
    /// the geometry is weighted, weight `weight`. Returns its vertex id.
    VertexId append(const Point3& p, std::uint32_t key, double weight) {
        points_.push_back(p);
        widen_box(p);
        if (has_implicit()) {
            exact_.emplace_back(p);
            errors_.push_back(0.0);
        }
        keys_.push_back(key);
        if (weighted()) {
            weights_.push_back(weight);
        }
        return static_cast<VertexId>(points_.size() - 1);
    }

    /// Appends an unweighted point given exactly by `exact` (an implicit point: a Steiner point
    /// of the CDT's edge protection), `rounded` being its coordinates rounded to doubles, with
    /// perturbation key `key`. The first implicit point turns every test to the generic
    /// predicates (see the top): the points before it become their own definitions.
    /// Returns its vertex id.
    VertexId append_implicit(const GenericPoint3& exact, const Point3& rounded, std::uint32_t key);

    WeightedPoint3 weighted_point(VertexId v) const {
        const Point3& p = points_[v];
        return {p.x, p.y, p.z, weights_[v]};
    }

    /// Every test below comes in two forms: without a tally (the plain predicates) and with one
    /// (Tally, counters.h), which records the stage that decided it when the tally counts.
    Sign orient3d(VertexId a, VertexId b, VertexId c, VertexId d) const {
        if (has_implicit()) [[unlikely]] {
            return orient3d_generic(a, b, c, d).sign;
        }
        return predicates::orient3d(point(a), point(b), point(c), point(d));
    }

    template <Tally T>
    Sign orient3d(VertexId a, VertexId b, VertexId c, VertexId d, T& tally) const {
        if constexpr (!T::kCounting) {
            if (lattice_) {
                return predicates::orient3d_on_lattice(point(a), point(b), point(c), point(d));
            }
        } else {
            if (staged_lattice_) {
                const auto verdict =
                    predicates::orient3d_staged_on_lattice(point(a), point(b), point(c), point(d));
                tally.count_predicate(PredicateKind::kOrient3d, verdict.stage);
                return verdict.sign;
            }
        }
        if (has_implicit()) [[unlikely]] {
            const auto verdict = orient3d_generic(a, b, c, d);
            if constexpr (T::kCounting) {
                tally.count_predicate(PredicateKind::kOrient3d, verdict.stage);
            }
            return verdict.sign;
        }
        return orient3d(point(a), point(b), point(c), point(d), tally);
    }

    /// orient3d of three vertices and a point given by its definition (exact on implicit ones).
    Sign orient3d(VertexId a, VertexId b, VertexId c, const GenericPoint3& d) const;

    static Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
        return predicates::orient3d(a, b, c, d);
    }

    template <Tally T>
    static Sign orient3d(
        const Point3& a, const Point3& b, const Point3& c, const Point3& d, T& tally) {
        if constexpr (!T::kCounting) {
            return predicates::orient3d(a, b, c, d);
        } else {
            const auto verdict = predicates::orient3d_staged(a, b, c, d);
            tally.count_predicate(PredicateKind::kOrient3d, verdict.stage);
            return verdict.sign;
        }
    }

    /// True when p lies in the bounding box of the points (closed), where the static filters hold.
    bool in_box(const Point3& p) const {
        return !points_.empty() && box_lo_.x <= p.x && p.x <= box_hi_.x && box_lo_.y <= p.y &&
               p.y <= box_hi_.y && box_lo_.z <= p.z && p.z <= box_hi_.z;
    }

    /// orient3d of four points the caller knows to lie in the bounding box (in_box), as the
    /// walks' tests do: the static filter first (one comparison decides most tests), counted as
    /// the static stage, so the counting engine runs the plain engine's cascade.
    template <Tally T>
    [[gnu::always_inline]] Sign orient3d_in_box(
        const Point3& a, const Point3& b, const Point3& c, const Point3& d, T& tally) const {
        if (const int s = orient3d_static_.sign(a, b, c, d)) {
            if constexpr (T::kCounting) {
                tally.count_predicate(PredicateKind::kOrient3d, predicates::Stage::kStatic);
            }
            return s > 0 ? Sign::kPos : Sign::kNeg;
        }
        if constexpr (!T::kCounting) {
            if (lattice_) {
                return orient3d_on_lattice_or_exact(a, b, c, d);
            }
        } else {
            if (staged_lattice_) {
                const auto verdict = orient3d_staged_on_lattice_or_staged(a, b, c, d);
                tally.count_predicate(PredicateKind::kOrient3d, verdict.stage);
                return verdict.sign;
            }
        }
        return orient3d(a, b, c, d, tally);
    }

    /// True when u is in the perturbed open circumball (weighted: below the perturbed witness
    /// plane) of the solid tetrahedron t. The common case (unweighted, not a tie) is inline,
    /// counted or not; the perturbation keys are read only on an exact tie.
    [[gnu::always_inline]] bool conflicts_solid(const TetVertices& t, VertexId u) const {
        Uncounted none;
        return conflicts_solid(t, u, none);
    }

    template <Tally T>
    [[gnu::always_inline]] bool conflicts_solid(const TetVertices& t, VertexId u, T& tally) const {
        if constexpr (T::kCounting) {
            std::uint64_t decided_static = 0;
            const bool in = conflicts_solid(t, u, tally, decided_static);
            tally.count_predicate(
                PredicateKind::kInsphere, predicates::Stage::kStatic, decided_static);
            return in;
        } else {
            if (plain_) {
                // The static filter first: most tests of a well-spread point set are decided by
                // one comparison with the bounding box's bound. It is sound only for the points
                // in its box, which implicit points are not (plain_ is false then).
                if (const int s = insphere_static_.sign(
                        point(t[0]), point(t[1]), point(t[2]), point(t[3]), point(u))) {
                    return s > 0;
                }
                // On a lattice the static filter is exact (its bound is 0): this is a tie.
                const Sign exact =
                    lattice_ ? Sign::kZero
                             : predicates::insphere(
                                   point(t[0]), point(t[1]), point(t[2]), point(t[3]), point(u));
                // On an exact tie go straight to the tie-break: the exact determinant is already
                // known to be zero, and evaluating it again costs about 12% of a 50^3 grid's run.
                return exact != Sign::kZero ? exact == Sign::kPos : tie_breaks_into(t, u);
            }
        }
        return conflicts_solid_exactly(t, u, tally);
    }

    /// conflicts_solid counted, with the insphere tests its static stage decides (nearly every
    /// test of a well-spread point set, and every one on a lattice) added to `decided_static`
    /// rather than to the tally: the engine's cavity search keeps that count in its own frame and
    /// adds it to the tally once per insertion. An increment of the tally per test was a load of
    /// the tally's address and a read-modify-write of its field in the search's hottest block.
    /// The cascade is the plain engine's: the static filter, then the staged predicate inline
    /// (its filter shares the static filter's determinant), then the tie-break.
    [[gnu::always_inline]] bool conflicts_solid(const TetVertices& t,
                                                VertexId u,
                                                Counters& tally,
                                                std::uint64_t& decided_static) const {
        if (plain_) {
            if (const int s = insphere_static_.sign(
                    point(t[0]), point(t[1]), point(t[2]), point(t[3]), point(u))) {
                ++decided_static;
                return s > 0;
            }
            if (lattice_) {
                // The static filter is exact on a lattice (its bound is 0): a tie, decided.
                ++decided_static;
                return tie_breaks_into(t, u, tally);
            }
            const predicates::Verdict exact = predicates::insphere_staged(
                point(t[0]), point(t[1]), point(t[2]), point(t[3]), point(u));
            tally.count_predicate(PredicateKind::kInsphere, exact.stage);
            return exact.sign != Sign::kZero ? exact.sign == Sign::kPos
                                             : tie_breaks_into(t, u, tally);
        }
        return conflicts_solid_exactly(t, u, tally);
    }

    /// True when u is in the perturbed outer halfspace of the hull triangle of ghost tetrahedron
    /// t. `interior` is any vertex strictly behind every hull facet's plane or on the hull
    /// (a bootstrap vertex); it is used only when u is coplanar with the hull triangle.
    bool conflicts_ghost(const TetVertices& t,
                         VertexId u,
                         const std::array<VertexId, 4>& interior) const {
        Uncounted none;
        return conflicts_ghost(t, u, interior, none);
    }

    template <Tally T>
    bool conflicts_ghost(const TetVertices& t,
                         VertexId u,
                         const std::array<VertexId, 4>& interior,
                         T& tally) const;

    /// The coplanar case of conflicts_ghost: u on the plane of the hull triangle of ghost t,
    /// `behind` a vertex strictly behind that plane (it orients the plane). True when u is inside
    /// the triangle's perturbed circumdisk (weighted: the perturbed power test in the plane), as
    /// the engine's ghost test decides; gift-wrapping asks the same question.
    bool conflicts_ghost_in_plane(const TetVertices& t, VertexId u, VertexId behind) const {
        Uncounted none;
        return conflicts_ghost_in_plane(t, u, behind, none);
    }

    template <Tally T>
    bool conflicts_ghost_in_plane(const TetVertices& t,
                                  VertexId u,
                                  VertexId behind,
                                  T& tally) const;

private:
    /// The perturbed in-sphere test of u against solid t when the exact one is zero (out of
    /// line: rare, and kept off the inlined fast path).
    bool tie_breaks_into(const TetVertices& t, VertexId u) const;
    /// The same, counting the tie-break and its cofactors.
    bool tie_breaks_into(const TetVertices& t, VertexId u, Counters& tally) const;
    /// orient3d on a lattice geometry of four points in its box (out of line, to keep the walks'
    /// inlined code as small as without lattices).
    Sign orient3d_on_lattice_or_exact(const Point3& a,
                                      const Point3& b,
                                      const Point3& c,
                                      const Point3& d) const;
    /// The counted tests' orient3d on a staged lattice of four points in the box, as
    /// orient3d_on_lattice_or_exact: orient3d_staged's verdict.
    predicates::Verdict orient3d_staged_on_lattice_or_staged(const Point3& a,
                                                             const Point3& b,
                                                             const Point3& c,
                                                             const Point3& d) const;

    /// orient3d on the exact points (out of line: only geometries with implicit points call it).
    predicates::Verdict orient3d_generic(VertexId a, VertexId b, VertexId c, VertexId d) const;
    template <Tally T>
    bool conflicts_solid_exactly(const TetVertices& t, VertexId u, T& tally) const;

    /// Grows the bounding box to hold p and remakes the static filters for it (the filters are
    /// sound only for points in their box), and keeps lattice_ true only while p keeps the points
    /// a lattice.
    void widen_box(const Point3& p);
    /// The static filters for the current box (exact insphere on a lattice), and staged_lattice_.
    void make_static_filters();

    std::vector<Point3> points_;
    std::vector<std::uint32_t> keys_;
    std::vector<double> weights_;
    std::vector<GenericPoint3> exact_;  // empty, or one definition per point (see the top)
    std::vector<double> errors_;        // with exact_: max |exact - point| per point, bounded
    bool plain_ = true;                 // unweighted and no implicit point: the inline fast path
    bool lattice_ = false;              // plain_, integer points, exact lattice box (see the top)
    bool staged_lattice_ = false;       // lattice_, coordinates below kLatticeStagedMagnitude
    Point3 box_lo_{};                   // bounding box of points_, when there are any
    Point3 box_hi_{};
    predicates::InsphereStaticFilter insphere_static_;  // for points in that box
    predicates::Orient3dStaticFilter orient3d_static_;  // likewise
};

}  // namespace cavity::core
