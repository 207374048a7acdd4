#include "cavity/core/geometry/bootstrap.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>

#include "cavity/core/base/error.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {

using predicates::Point3;
using predicates::Sign;

namespace {

bool same_point(const Point3& a, const Point3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

// The 2D orientation of the projections onto one coordinate plane, through orient3d: with the
// fourth point one unit above a plane holding the other three, orient3d is minus their 2D
// orientation. Exact like orient3d, for every finite double.
Sign orient2d_projected(const Point3& a, const Point3& b, const Point3& c, int drop) {
    const auto project = [drop](const Point3& p) {
        return drop == 0   ? Point3{p.y, p.z, 0.0}
               : drop == 1 ? Point3{p.z, p.x, 0.0}
                           : Point3{p.x, p.y, 0.0};
    };
    return predicates::orient3d(project(a), project(b), project(c), Point3{0.0, 0.0, 1.0});
}

// Three distinct points are collinear exactly when all three coordinate projections are.
bool collinear(const Point3& a, const Point3& b, const Point3& c) {
    for (int drop = 0; drop < 3; ++drop) {
        if (orient2d_projected(a, b, c, drop) != Sign::kZero) {
            return false;
        }
    }
    return true;
}

std::size_t count_distinct(std::span<const Point3> points) {
    std::set<std::tuple<double, double, double>> seen;
    for (const Point3& p : points) {
        // +0.0 and -0.0 are the same point; adding 0.0 maps -0.0 to +0.0.
        seen.emplace(p.x + 0.0, p.y + 0.0, p.z + 0.0);
        if (seen.size() >= 4) {
            break;
        }
    }
    return seen.size();
}

// Halved differences cannot overflow; scaling each edge vector by its largest component makes the
// shape measures below independent of the input's scale. Only used to prefer well-shaped
// bootstrap tetrahedra: exactness comes from the predicates.
Point3 direction(const Point3& from, const Point3& to) {
    const Point3 d{to.x / 2 - from.x / 2, to.y / 2 - from.y / 2, to.z / 2 - from.z / 2};
    const double m = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    return m > 0 ? Point3{d.x / m, d.y / m, d.z / m} : d;
}

Point3 cross(const Point3& a, const Point3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

double dot(const Point3& a, const Point3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// How many candidates past the first valid one are weighed for shape.
constexpr std::size_t kShapeCandidates = 64;

[[noreturn]] void degenerate(std::span<const Point3> points, int dimension) {
    const std::size_t distinct = count_distinct(points);
    if (distinct < 4) {
        throw Error("fewer than 4 distinct points (" + std::to_string(distinct) +
                    "): no tetrahedron can be formed");
    }
    const char* what = dimension == 1 ? "collinear" : "coplanar";
    throw Error("all points are " + std::string(what) + " (affine dimension " +
                std::to_string(dimension) + "): no 3D triangulation exists");
}

}  // namespace

BootstrapRule parse_bootstrap_rule(std::string_view name) {
    return parse_kind(kBootstrapRules, name, "bootstrap rule");
}

std::array<std::size_t, 4> find_bootstrap(std::span<const Point3> points,
                                          std::span<const std::uint32_t> sequence,
                                          BootstrapRule rule) {
    const auto at = [&](std::size_t i) -> const Point3& { return points[sequence[i]]; };
    const std::size_t n = sequence.size();
    if (n == 0) {
        throw Error("no points: no tetrahedron can be formed");
    }
    std::size_t i1 = 1;
    while (i1 < n && same_point(at(i1), at(0))) {
        ++i1;
    }
    if (i1 == n) {
        degenerate(points, 0);
    }
    // The first point not collinear with the first two exists exactly when the input is not
    // collinear; among it and the next few valid ones, take the widest triangle, and likewise for
    // the fourth point, so that the bootstrap tetrahedron is not needlessly thin (the conflict
    // graph needs a representable point strictly inside it).
    // kFirst weighs one candidate only: the first valid one.
    const std::size_t candidates = rule == BootstrapRule::kFirst ? 1 : kShapeCandidates;
    const Point3 e1 = direction(at(0), at(i1));
    std::size_t i2 = n;
    double best = -1;
    for (std::size_t i = i1 + 1, seen = 0; i < n && seen < candidates; ++i) {
        if (collinear(at(0), at(i1), at(i))) {
            continue;
        }
        const Point3 c = cross(e1, direction(at(0), at(i)));
        const double width = dot(c, c);
        if (width > best) {
            best = width;
            i2 = i;
        }
        ++seen;
    }
    if (i2 >= n) {
        degenerate(points, 1);
    }
    const Point3 normal = cross(e1, direction(at(0), at(i2)));
    std::size_t i3 = n;
    best = -1;
    for (std::size_t i = 1, seen = 0; i < n && seen < candidates; ++i) {
        if (i == i1 || i == i2 ||
            predicates::orient3d(at(0), at(i1), at(i2), at(i)) == Sign::kZero) {
            continue;
        }
        const double height = std::fabs(dot(normal, direction(at(0), at(i))));
        if (height > best) {
            best = height;
            i3 = i;
        }
        ++seen;
    }
    if (i3 >= n) {
        degenerate(points, 2);
    }
    return {0, i1, i2, i3};
}

}  // namespace cavity::core
