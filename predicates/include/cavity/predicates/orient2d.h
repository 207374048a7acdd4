#pragma once

#include "cavity/predicates/sign.h"

namespace cavity::predicates {

/// Sign of det[a-c; b-c] for points of the plane: kPos when a, b, c turn counter-clockwise
/// (Shewchuk's orient2d). Exact for every finite double input. A filter decides most queries;
/// collinear points, common where coordinates are on a grid or share their exponents, get the
/// exact product difference when the coordinate differences are exact doubles; the rest go to
/// orient3d of the points lifted to z = 0 with (0, 0, 1).
Sign orient2d(double ax, double ay, double bx, double by, double cx, double cy);

}  // namespace cavity::predicates
