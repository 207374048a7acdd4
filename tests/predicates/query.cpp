#include "query.h"

#include <cstdio>

#include "cavity/predicates/insphere.h"
#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient4d.h"

namespace cavity::predicates::testing {

namespace {

Point3 point(const Query& q, std::size_t i) {
    const double* p = q.v.data() + stride(q.kind) * i;
    return {p[0], p[1], p[2]};
}

WeightedPoint3 weighted_point(const Query& q, std::size_t i) {
    const double* p = q.v.data() + 4 * i;
    return {p[0], p[1], p[2], p[3]};
}

}  // namespace

const char* kind_name(Kind k) {
    switch (k) {
        case Kind::kOrient3d:
            return "orient3d";
        case Kind::kInsphere:
            return "insphere";
        case Kind::kOrient4d:
            return "orient4d";
    }
    return "?";
}

std::string to_line(const Query& q) {
    std::string line = kind_name(q.kind);
    for (std::size_t i = 0; i < value_count(q.kind); ++i) {
        char number[40];
        std::snprintf(number, sizeof number, " %a", q.v[i]);
        line += number;
    }
    return line;
}

Signs evaluate(const Query& q) {
    switch (q.kind) {
        case Kind::kOrient3d: {
            const Point3 a = point(q, 0), b = point(q, 1), c = point(q, 2), d = point(q, 3);
            return {orient3d(a, b, c, d), orient3d_staged(a, b, c, d).sign};
        }
        case Kind::kInsphere: {
            const Point3 a = point(q, 0), b = point(q, 1), c = point(q, 2), d = point(q, 3),
                         e = point(q, 4);
            return {insphere(a, b, c, d, e), insphere_staged(a, b, c, d, e).sign};
        }
        case Kind::kOrient4d: {
            const WeightedPoint3 a = weighted_point(q, 0), b = weighted_point(q, 1),
                                 c = weighted_point(q, 2), d = weighted_point(q, 3),
                                 e = weighted_point(q, 4);
            return {orient4d(a, b, c, d, e), orient4d_staged(a, b, c, d, e).sign};
        }
    }
    return {Sign::kZero, Sign::kZero};
}

Sign evaluate_oracle(const Query& q) {
    switch (q.kind) {
        case Kind::kOrient3d:
            return oracle::orient3d(point(q, 0), point(q, 1), point(q, 2), point(q, 3));
        case Kind::kInsphere:
            return oracle::insphere(
                point(q, 0), point(q, 1), point(q, 2), point(q, 3), point(q, 4));
        case Kind::kOrient4d:
            return oracle::orient4d(weighted_point(q, 0),
                                    weighted_point(q, 1),
                                    weighted_point(q, 2),
                                    weighted_point(q, 3),
                                    weighted_point(q, 4));
    }
    return Sign::kZero;
}

}  // namespace cavity::predicates::testing
