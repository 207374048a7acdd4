#pragma once

namespace cavity::predicates {

/// A point of R^3 given by its double coordinates. Every finite double is allowed.
struct Point3 {
    double x;
    double y;
    double z;
};

/// A weighted point: coordinates and weight w. Its lifted height is |p|^2 - w, which the weighted
/// predicates compute exactly inside (never rounded to a double first).
struct WeightedPoint3 {
    double x;
    double y;
    double z;
    double w;
};

}  // namespace cavity::predicates
