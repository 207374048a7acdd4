#pragma once

#include <optional>
#include <variant>

#include "cavity/predicates/point.h"

/// Points defined exactly by input doubles, after Attene's indirect predicates ("Indirect
/// Predicates for Geometric Constructions", Computer-Aided Design 126, 2020) as used for Steiner
/// points by Diazzi, Panozzo, Vaxman and Attene ("Constrained Delaunay Tetrahedrization: A Robust
/// and Practical Approach", SIGGRAPH Asia 2023). A constructed point is never rounded: it is kept
/// as its definition, and every predicate on it is evaluated exactly from the defining doubles
/// (generic_predicates.h). Each kind has homogeneous coordinates (X, Y, Z, W), polynomials in the
/// defining doubles, with the point at (X/W, Y/W, Z/W).
namespace cavity::predicates {

/// The point a + t (b - a) of the line through a and b, at the exact rational parameter
/// t = numerator / denominator (both finite doubles, denominator nonzero): Attene's LNC.
/// Homogeneous coordinates: X = denominator a.x + numerator (b.x - a.x), W = denominator.
struct SegmentParameterPoint {
    Point3 a;
    Point3 b;
    double numerator;
    double denominator;
};

/// The intersection of the line through a and b with the plane through p, q, r: Attene's LPI.
/// With n = (q - p) x (r - p) the point is a + t (b - a), t = n.(p - a) / n.(b - a), so
/// W = n.(b - a) (degree 3 in the doubles) and X = W a.x + n.(p - a) (b.x - a.x) (degree 4).
/// Defined only when W != 0: p, q, r not collinear and the line not parallel to their plane; make
/// it with line_plane_point, which checks that exactly.
struct LinePlanePoint {
    Point3 a;
    Point3 b;
    Point3 p;
    Point3 q;
    Point3 r;
};

/// An input point (explicit, its doubles) or a constructed one (implicit, its definition).
using GenericPoint3 = std::variant<Point3, SegmentParameterPoint, LinePlanePoint>;

/// The point of line ab on plane pqr, or nullopt when it is not a single point (W == 0 exactly).
/// Every argument must be finite.
std::optional<LinePlanePoint> line_plane_point(
    const Point3& a, const Point3& b, const Point3& p, const Point3& q, const Point3& r);

/// The point a + (numerator / denominator)(b - a), or nullopt when the denominator is zero or an
/// argument is not finite.
std::optional<SegmentParameterPoint> segment_parameter_point(const Point3& a,
                                                             const Point3& b,
                                                             double numerator,
                                                             double denominator);

}  // namespace cavity::predicates
