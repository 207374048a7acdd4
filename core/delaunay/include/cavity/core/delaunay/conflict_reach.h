#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "cavity/core/delaunay/point_kd_tree.h"
#include "cavity/predicates/point.h"

namespace cavity::core {

using predicates::Point3;

/// Floating-point certificates for "is q in conflict with this solid tetrahedron": a ball certain
/// to hold every point in conflict (`bounded` false when none can be certified in floating point)
/// and, for unweighted points, a concentric ball certain to hold only conflicts (`inner`,
/// negative when none is certified). A point strictly inside the circumsphere conflicts whatever
/// the perturbation, so only the shell between the two radii needs the exact test. Counting
/// conflicts with the certificates first costs a squared distance per point instead of an
/// insphere determinant.
struct ConflictReach {
    bool bounded = false;
    Point3 centre{};
    double radius = 0;
    double inner = -1;
    /// The two radii squared, rounded toward the safe side by far more than the few roundings
    /// of a squared distance (relative error below 6 units): points are tested without a root.
    double radius_squared = std::numeric_limits<double>::infinity();
    double inner_squared = -1;

    /// True when every point of a box with these corners has a squared distance the tests can
    /// trust (no coordinate beyond the bounds' range).
    static bool moderate(const Box3& b);

    bool includes_squared(double computed) const {
        return std::isfinite(computed) && computed < inner_squared;
    }

    bool excludes_squared(double computed) const {
        return std::isfinite(computed) && computed > radius_squared;
    }

    /// The computed squared distance from the centre, or NaN (which both tests above decline)
    /// where the coordinates are too large for the error bounds.
    double squared_distance(const Point3& q) const;

    /// Every point of the box is a conflict / none is.
    bool includes(const Box3& b) const;
    bool excludes(const Box3& b) const;
};

/// The certificates of the solid tetrahedron v (any orientation), for unweighted points.
ConflictReach conflict_reach(const std::array<Point3, 4>& v);

/// The same for weighted points (the orthoball; a point conflicts by the power test): `w` the
/// vertices' weights, `max_weight` the largest weight of any point that may be tested. No inner
/// ball is certified.
ConflictReach conflict_reach(const std::array<Point3, 4>& v,
                             const std::array<double, 4>& w,
                             double max_weight);

}  // namespace cavity::core
