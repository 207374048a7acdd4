#pragma once

// Exact rational geometry of PLC facets (Boost.Multiprecision over GMP): the plane of a facet,
// which side of it a vertex lies on, where an edge crosses it, and whether a point of the plane
// lies in the facet's region. Used by the reader (coplanarity), polygon insertion and the CDT
// validator; never on a hot path of Delaunay triangulation.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <boost/multiprecision/gmp.hpp>

#include "cavity/core/input/plc.h"
#include "cavity/predicates/generic_filter.h"
#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/sign.h"
#include "rounded_region.h"

namespace cavity::core {

using Rational = boost::multiprecision::mpq_rational;
using ExactPoint = std::array<Rational, 3>;

ExactPoint exact_point(const Point3& p);

/// The exact rational coordinates of an input or implicit point (generic_point.h).
ExactPoint exact_point(const predicates::GenericPoint3& g);

/// The point rounded to doubles coordinate by coordinate, to nearest: a monotone rounding, so
/// that boxes of rounded points meet (contain) whenever the exact points' boxes do, and serve as
/// a broad phase. Edge protection stores implicit points' coordinates this way.
Point3 rounded_point(const predicates::GenericPoint3& g);

/// Point i of a point set as exactly defined: its implicit definition when it has one.
inline predicates::GenericPoint3 generic_point(const PointSet& points, std::uint32_t i) {
    return points.exact.empty() ? predicates::GenericPoint3(points.points[i]) : points.exact[i];
}

/// The exact rational coordinates of point i of a point set.
inline ExactPoint exact_point(const PointSet& points, std::uint32_t i) {
    return points.exact.empty() ? exact_point(points.points[i]) : exact_point(points.exact[i]);
}

/// A point set's points in rationals, each converted on first use and kept: a point is a corner of
/// several triangles and an end of several edges near several facets, and converting an implicit
/// point costs some ten thousand instructions of GMP.
class RationalPoints {
public:
    explicit RationalPoints(const PointSet& points) : points_(points), made_(points.size()) {}

    const ExactPoint& operator[](std::uint32_t i) {
        std::optional<ExactPoint>& p = made_[i];
        if (!p) {
            p.emplace(exact_point(points_, i));
        }
        return *p;
    }

private:
    const PointSet& points_;
    std::vector<std::optional<ExactPoint>> made_;
};

/// Vector arithmetic on exact points.
inline ExactPoint minus(const ExactPoint& p, const ExactPoint& q) {
    return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}

inline ExactPoint cross(const ExactPoint& u, const ExactPoint& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

inline Rational dot(const ExactPoint& u, const ExactPoint& v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

inline bool is_zero(const ExactPoint& v) {
    return v[0] == 0 && v[1] == 0 && v[2] == 0;
}

/// The sign of component k of (b - a) x (c - a), exactly: in doubles when the differences of the
/// coordinates involved are exact (points on a common grid), else by orient3d of the points
/// projected along axis k.
predicates::Sign cross_component_sign(const Point3& a, const Point3& b, const Point3& c, int k);

/// The plane through three non-collinear points a, b, c, with normal n = (b - a) x (c - a).
class ExactPlane {
public:
    /// The plane of a facet: through its first three non-collinear loop corners; nullopt when every
    /// corner is collinear.
    static std::optional<ExactPlane> of_facet(const Plc& plc, const PlcFacet& facet);

    /// n . (p - a): positive on the side n points to. Proportional to the signed distance, without
    /// radicals (the chapter's advice for d(v, h) in §5.8).
    Rational offset(const ExactPoint& p) const;
    /// The sign of offset(p), by the exact orient3d predicate (no rational arithmetic). Asked of
    /// three input corners when the facet has them (see explicit_), and for a point inside a
    /// segment between input points, decided by the sides of its ends when they agree: most
    /// answers are zero, and a zero orient3d with an implicit point is always decided in GMP.
    predicates::Sign side(const predicates::GenericPoint3& p) const;
    /// The point where segment pq meets the plane (p and q strictly on opposite sides).
    ExactPoint crossing(const ExactPoint& p, const ExactPoint& q) const;
    /// crossing() of input points or points on segments, its coordinate along dropped_axis()
    /// left zero (the region never reads it), computed in integers from three input corners of
    /// the facet: nullopt when the facet has no three such corners or p or q is a line-plane
    /// point. Each rational point and offset cost more than the region test itself.
    std::optional<ExactPoint> projected_crossing(const predicates::GenericPoint3& p,
                                                 const predicates::GenericPoint3& q) const;
    /// The same crossing in doubles, projected, within a proven distance of the exact one
    /// (rounded_region.h), from p's and q's rounded points: nullopt when the facet has no three
    /// input corners or the floating-point stage cannot bound it tightly.
    std::optional<RoundedPoint2> rounded_crossing(const predicates::RoundedPoint& p,
                                                  const predicates::RoundedPoint& q) const;

    /// The coordinate dropped to project the plane one-to-one onto a coordinate plane: an axis
    /// whose normal component is not zero (exactly), the largest by a floating-point estimate.
    int dropped_axis() const { return drop_; }

private:
    /// The first corner and the normal in rationals, made on the first question that needs them:
    /// most facets are only asked for sides (orient3d) and their projection axis, and the rational
    /// conversions cost more than the rest of the PLC check.
    const std::pair<ExactPoint, ExactPoint>& rational() const;

    /// Finds explicit_ among the facet's corners (those that are input points).
    void use_explicit_corners(const Plc& plc, const std::vector<std::uint32_t>& corners);

    /// The sign of offset(p) for an input point p.
    predicates::Sign explicit_side(const Point3& p) const;

    /// explicit_ in integers, for projected_crossing: every coordinate scaled by 2^-scale (the
    /// least spacing exponent among them), the normal m = (e1 - e0) x (e2 - e0) and m . e0 of the
    /// scaled corners. Made on the first crossing and kept: a facet asks for many crossings, and
    /// scaling the corners and forming m was a third of each.
    struct ExplicitIntegers {
        int scale = 0;
        std::array<boost::multiprecision::mpz_int, 3> normal;
        boost::multiprecision::mpz_int normal_dot_corner;
    };

    const ExplicitIntegers& explicit_integers() const;

    /// The integers projected_crossing works in, kept from call to call: made afresh, they were
    /// some forty GMP allocations and frees per crossing, and a facet asks for thousands of
    /// crossings (cheese.off: malloc and free were a tenth of the whole run). Their values mean
    /// nothing between calls, so a copy of the plane starts with its own empty ones (copying them
    /// cost 30 M instructions on cheese.off, planes being copied out of of_facet). One plane is
    /// therefore not for crossings on several threads at once (the CDT runs on one).
    struct CrossingWork {
        using Integer = boost::multiprecision::mpz_int;
        CrossingWork() = default;

        CrossingWork(const CrossingWork& /*unused*/) {}

        CrossingWork& operator=(const CrossingWork& /*unused*/) { return *this; }

        ~CrossingWork() = default;
        std::array<Integer, 3> pv;
        std::array<Integer, 3> qv;
        std::array<Integer, 3> segment_a;
        std::array<Integer, 3> segment_b;
        Integer pw;
        Integer qw;
        Integer parameter;
        Integer term;
        Integer h_p;
        Integer h_q;
        Integer w;
        Integer numerator;
    };

    std::array<predicates::GenericPoint3, 3> corners_;  ///< the corners that define the plane
    /// Three non-collinear input corners of the facet, and the sign relating their orientation to
    /// that of corners_ (0: the facet has no such three; side() then asks corners_). The plane is
    /// the same, so orient3d with them differs from orient3d with corners_ by a constant factor.
    std::array<Point3, 3> explicit_{};
    int explicit_sign_ = 0;
    mutable std::optional<std::pair<ExactPoint, ExactPoint>> rational_;  ///< a and n, or not yet
    mutable std::optional<ExplicitIntegers> explicit_integers_;          ///< or not yet
    mutable CrossingWork work_;
    int drop_ = 2;
};

/// The centroid of input points and points on segments, its coordinate along `drop` left zero
/// (as ExactPlane::projected_crossing's, for FacetRegion::contains), computed in integers with
/// one reduction per coordinate; nullopt when the span is empty or holds a line-plane point or a
/// segment point with parameter 0 / 0. Summing rational points reduced after every addition,
/// and converting each point to rationals cost several times more.
std::optional<ExactPoint> projected_centroid(std::span<const predicates::GenericPoint3> points,
                                             int drop);

/// A point of a facet's plane, projected one-to-one by dropping one coordinate, with its
/// coordinates rounded to doubles (each within one unit in the last place) and doubles
/// v_lo <= v <= v_hi: the point-in-loop test compares v against every side's ends and takes
/// orientations, and the doubles decide nearly all of those without GMP.
struct Point2 {
    Rational u;
    Rational v;
    double du;
    double dv;
    double v_lo;
    double v_hi;
};

/// A facet's region made ready for many point queries: its loops projected to rationals and the
/// faces of the loops' arrangement that hold its hole points, made on the first query (a
/// triangle's questions are mostly answered by orientations alone) and kept. Converting a loop's
/// implicit corners costs dozens of GMP operations each, so projecting the loops per query made
/// polygon insertion and the validator quadratic in the length of a loop split by edge
/// protection. Holds references to plc and facet.
class FacetRegion {
public:
    /// With `rational` (the PLC's points, kept by the caller), the loops' corners are taken from
    /// it: a corner is shared by the facets around it, and so is its conversion.
    FacetRegion(const Plc& plc,
                const PlcFacet& facet,
                const ExactPlane& plane,
                RationalPoints* rational = nullptr);

    /// True when x (a point of the facet's plane, not on any loop side) lies in the region, by
    /// TetGen's rule (see PlcFacet): x is inside at least one loop, and no hole point of the facet
    /// lies in the same face of the loops' arrangement, i.e. no hole point is inside exactly the
    /// same loops as x. Exact, in the projection that drops the plane's dropped_axis(): x's
    /// coordinate along that axis is never read, so a caller may leave it unmade.
    /// Takes x by value: a caller done with its point moves it in, and its coordinates become the
    /// projection's without a copy.
    bool contains(ExactPoint x) const;
    /// contains() of the exact point near x (rounded_region.h), when the doubles decide every
    /// step of the test; nullopt otherwise. The loops are taken in doubles, made on the first
    /// call without a rational; a facet with hole points makes the exact ones too, for them.
    std::optional<bool> contains_rounded(const RoundedPoint2& x) const;

private:
    struct Projected {
        std::vector<std::vector<Point2>> loops;
        std::vector<std::vector<bool>> hole_faces;  ///< per hole point, the loops it is inside
    };

    const Projected& projected() const;

    /// The loops in doubles for contains_rounded (empty when a corner's rounding is unbounded).
    const std::vector<std::vector<RoundedPoint2>>& rounded_loops() const;

    const Plc& plc_;
    const PlcFacet& facet_;
    int drop_;
    RationalPoints* rational_;
    mutable std::optional<Projected> projected_;                                    ///< or not yet
    mutable std::optional<std::vector<std::vector<RoundedPoint2>>> rounded_loops_;  ///< or not yet
};

/// True when segment pq, whose ends lie strictly on opposite sides of the facet's plane, crosses
/// it inside the facet's region. For a triangle without hole points by three exact orientations
/// (the crossing is inside the open triangle exactly when pq turns the same way, strictly,
/// around its three sides), without rationals; otherwise at the rational crossing point, asked of
/// `region` (the facet's).
bool crosses_facet_region(const Plc& plc,
                          const PlcFacet& facet,
                          const ExactPlane& plane,
                          const FacetRegion& region,
                          const predicates::GenericPoint3& p,
                          const predicates::GenericPoint3& q);

/// Twice the area of the facet's region (the same rule), measured in the projection (exact). With
/// non-crossing loops every face of the arrangement is "inside loop L, outside L's children": its
/// area is L's minus its children's, and it counts unless a hole point lies in it. The corners
/// are taken from `rational` when given (as FacetRegion's).
Rational facet_region_area2(const Plc& plc,
                            const PlcFacet& facet,
                            const ExactPlane& plane,
                            RationalPoints* rational = nullptr);

/// Where a point of the plane lies with respect to one loop, in the projection.
enum class LoopPosition { kOutside, kOnBoundary, kInside };
LoopPosition loop_position(const Plc& plc,
                           const std::vector<std::uint32_t>& loop,
                           int drop,
                           const ExactPoint& x);

/// How the sides of loop `a` lie with respect to loop `b` (coplanar): each side is cut at the
/// corners of b that lie on it and each piece is classified by its midpoint. For loops whose sides
/// do not cross, a piece is wholly inside, outside or on b: `a` is nested in b when it has pieces
/// inside and none outside, and the two loops overlap without nesting (they cross) when either has
/// pieces both inside and outside the other.
struct SidePieces {
    std::size_t inside = 0;
    std::size_t outside = 0;
    std::size_t on_boundary = 0;
};

SidePieces side_pieces(const Plc& plc,
                       const std::vector<std::uint32_t>& a,
                       const std::vector<std::uint32_t>& b,
                       int drop);

/// Twice the absolute area of triangle abc in the same projection.
Rational triangle_area2(const ExactPlane& plane,
                        const ExactPoint& a,
                        const ExactPoint& b,
                        const ExactPoint& c);

}  // namespace cavity::core
