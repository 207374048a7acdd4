#pragma once

#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/sign.h"
#include "cavity/predicates/stage.h"

/// orient3d and insphere on any mix of explicit and implicit points (generic_point.h), exact for
/// every finite double defining them, with the sign conventions of orient3d.h and insphere.h. An
/// interval filter decides first (Stage::kFilter); exact integers decide the rest (Stage::kExact).
/// When every point is explicit they hand the query to the Point3 predicates (and their stages).
namespace cavity::predicates {

Verdict orient3d_staged(const GenericPoint3& a,
                        const GenericPoint3& b,
                        const GenericPoint3& c,
                        const GenericPoint3& d);

/// Sign of det[a-d; b-d; c-d]: kPos when a, b, c, d are positively oriented.
inline Sign orient3d(const GenericPoint3& a,
                     const GenericPoint3& b,
                     const GenericPoint3& c,
                     const GenericPoint3& d) {
    return orient3d_staged(a, b, c, d).sign;
}

Verdict insphere_staged(const GenericPoint3& a,
                        const GenericPoint3& b,
                        const GenericPoint3& c,
                        const GenericPoint3& d,
                        const GenericPoint3& e);

/// Sign of det[p-e, |p-e|^2] over the rows p = a, b, c, d: kPos when e lies inside the circumball
/// of a, b, c, d if they are positively oriented.
inline Sign insphere(const GenericPoint3& a,
                     const GenericPoint3& b,
                     const GenericPoint3& c,
                     const GenericPoint3& d,
                     const GenericPoint3& e) {
    return insphere_staged(a, b, c, d, e).sign;
}

}  // namespace cavity::predicates
