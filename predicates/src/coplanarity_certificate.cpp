#include "coplanarity_certificate.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <variant>

#include "cavity/predicates/orient3d.h"

// Why a certificate means a zero, for the exact stage of generic_predicates.cpp (which computes
// det[X Y Z W] for orient3d and det[XW YW ZW X^2+Y^2+Z^2 W^2] for insphere over the homogeneous
// coordinates of the query scaled by a positive power of two):
//
// Take a plane P = {y : n.y = c}, n != 0, spanned by three non-collinear doubles u, v, w. A point
// "passes" P when
//  - explicit x: orient3d(u, v, w, x) == 0 exactly, i.e. x is on P;
//  - SegmentParameterPoint: a and b on P. With W = denominator != 0 the point a + t (b - a) is an
//    affine combination of a and b, so on P;
//  - LinePlanePoint: a and b on P (with W != 0 the point is on line ab, inside P); or p, q, r on
//    P (with W = n_pqr.(b - a) != 0 the normal n_pqr = (q - p) x (r - p) is nonzero, so p, q, r
//    are not collinear, their plane is P, and the point is on their plane by construction).
// So every point with W != 0 that passes lies on P; scaling by 2^-s maps P to the plane
// n.y = 2^-s c, on which the scaled point (X/W, Y/W, Z/W) lies: n.(X, Y, Z) - 2^-s c W = 0.
//  - orient3d: if any W is 0 the exact stage returns 0 (the product of the W signs); else the
//    column combination n_x X + n_y Y + n_z Z - 2^-s c W vanishes on every row: det = 0.
//  - insphere: n.(XW, YW, ZW) - 2^-s c W^2 = W (n.(X, Y, Z) - 2^-s c W) vanishes on every row,
//    rows with W = 0 included, so columns 1, 2, 3 and 5 are dependent: det = 0.
// If instead every defining double of the query lies on one line L (or is one point), every
// explicit point is on L, every SegmentParameterPoint with W != 0 too (affine in a, b), and every
// LinePlanePoint with W != 0 is on line ab = L (a != b, else W = n.0 = 0); L lies in some plane,
// and the same two arguments apply to it.
//
// Both answers come from the exact orient3d of input doubles, never from rounding; the tests
// check them against an independent rational oracle on exactly coplanar and nearly coplanar
// mixes (tests/predicates/generic_predicates_test.cpp).
namespace cavity::predicates::detail {

namespace {

bool same(const Point3& u, const Point3& v) {
    return u.x == v.x && u.y == v.y && u.z == v.z;
}

/// u with one coordinate moved to the adjacent double (toward zero, or off zero): u + delta e_axis
/// for some delta != 0, still finite.
Point3 nudged(Point3 u, int axis) {
    double& c = axis == 0 ? u.x : (axis == 1 ? u.y : u.z);
    c = c == 0.0 ? std::numeric_limits<double>::denorm_min() : std::nextafter(c, 0.0);
    return u;
}

/// Whether u, v, w are collinear, exactly. With s = u + delta e_k, subtracting row u - s from the
/// others gives orient3d(u, v, w, s) = det[u - s; v - u; w - u] = -delta ((v - u) x (w - u))_k:
/// zero for k = x, y, z exactly when the cross product is zero. The component that is largest in
/// doubles goes first: on the axis-aligned facets of CAD models the other two are exact zeros,
/// which orient3d proves only in its slow stages, and the filter settles a clear nonzero.
bool collinear(const Point3& u, const Point3& v, const Point3& w) {
    const double ax = v.x - u.x, ay = v.y - u.y, az = v.z - u.z;
    const double bx = w.x - u.x, by = w.y - u.y, bz = w.z - u.z;
    const std::array<double, 3> cross{
        std::abs(ay * bz - az * by), std::abs(az * bx - ax * bz), std::abs(ax * by - ay * bx)};
    const int first =
        cross[2] >= cross[1] ? (cross[2] >= cross[0] ? 2 : 0) : (cross[1] >= cross[0] ? 1 : 0);
    for (const int axis : {first, (first + 1) % 3, (first + 2) % 3}) {
        if (orient3d(u, v, w, nudged(u, axis)) != Sign::kZero) {
            return false;
        }
    }
    return true;
}

/// The plane through three non-collinear doubles.
struct Plane {
    Point3 u;
    Point3 v;
    Point3 w;
};

bool on(const Plane& plane, const Point3& x) {
    return same(x, plane.u) || same(x, plane.v) || same(x, plane.w) ||
           orient3d(plane.u, plane.v, plane.w, x) == Sign::kZero;
}

bool passes(const Plane& plane, const GenericPoint3& g) {
    if (const auto* x = std::get_if<Point3>(&g)) {
        return on(plane, *x);
    }
    if (const auto* s = std::get_if<SegmentParameterPoint>(&g)) {
        return on(plane, s->a) && on(plane, s->b);
    }
    const auto& l = std::get<LinePlanePoint>(g);
    return (on(plane, l.a) && on(plane, l.b)) ||
           (on(plane, l.p) && on(plane, l.q) && on(plane, l.r));
}

bool all_pass(const Plane& plane, std::span<const GenericPoint3* const> g) {
    for (const GenericPoint3* p : g) {
        if (!passes(plane, *p)) {
            return false;
        }
    }
    return true;
}

/// The distinct defining doubles that a plane through the query must hold, at most two a point.
class Pool {
public:
    void add(const Point3& x) {
        for (std::size_t i = 0; i < size_; ++i) {
            if (same(points_[i], x)) {
                return;
            }
        }
        points_[size_++] = x;
    }

    /// The plane of the first two distinct points and the first point off their line; none when
    /// every point lies on one line.
    std::optional<Plane> spanned_plane() const {
        for (std::size_t i = 2; i < size_; ++i) {
            if (!collinear(points_[0], points_[1], points_[i])) {
                return Plane{points_[0], points_[1], points_[i]};
            }
        }
        return std::nullopt;
    }

private:
    std::array<Point3, 10> points_{};
    std::size_t size_ = 0;
};

}  // namespace

bool certified_coplanar(std::span<const GenericPoint3* const> g) {
    // Explicit points and segment ends first: a LinePlanePoint needs its line in the plane only
    // when its own plane is another one, so its ends are the last choice for spanning it.
    Pool pool;
    for (const GenericPoint3* p : g) {
        if (const auto* x = std::get_if<Point3>(p)) {
            pool.add(*x);
        } else if (const auto* s = std::get_if<SegmentParameterPoint>(p)) {
            pool.add(s->a);
            pool.add(s->b);
        }
    }
    for (const GenericPoint3* p : g) {
        if (const auto* l = std::get_if<LinePlanePoint>(p)) {
            pool.add(l->a);
            pool.add(l->b);
        }
    }
    const std::optional<Plane> spanned = pool.spanned_plane();
    if (!spanned || all_pass(*spanned, g)) {
        return true;
    }
    for (const GenericPoint3* p : g) {
        if (const auto* l = std::get_if<LinePlanePoint>(p);
            l != nullptr && !collinear(l->p, l->q, l->r) && all_pass(Plane{l->p, l->q, l->r}, g)) {
            return true;
        }
    }
    return false;
}

}  // namespace cavity::predicates::detail
