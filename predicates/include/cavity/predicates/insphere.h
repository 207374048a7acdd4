#pragma once

#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"
#include "cavity/predicates/stage.h"

namespace cavity::predicates {

/// Sign of det[p-e, |p-e|^2] over the rows p = a, b, c, d: kPos when e lies inside the circumball
/// of a, b, c, d if they are positively oriented (the sign flips when they are negatively
/// oriented). Exact for every finite double input.
Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e);

/// insphere, also reporting the stage that decided.
Verdict insphere_staged(const Point3& a,
                        const Point3& b,
                        const Point3& c,
                        const Point3& d,
                        const Point3& e);

}  // namespace cavity::predicates
