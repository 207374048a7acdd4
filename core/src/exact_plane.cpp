#include "exact_plane.h"

#include <cstdlib>

namespace cavity::core {

namespace {

ExactPoint minus(const ExactPoint& p, const ExactPoint& q) {
    return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}

ExactPoint cross(const ExactPoint& u, const ExactPoint& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

Rational dot(const ExactPoint& u, const ExactPoint& v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

bool is_zero(const ExactPoint& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

/// The two coordinates kept by the projection.
std::array<int, 2> kept_axes(int drop) {
    return {drop == 0 ? 1 : 0, drop == 2 ? 1 : 2};
}

/// Crossing number of x with respect to a loop, in the projection: odd when x is inside. The
/// half-open rule on the second coordinate counts a vertex on the ray once.
bool inside_loop(const Plc& plc, const std::vector<std::uint32_t>& loop, int drop,
                 const ExactPoint& x) {
    const auto [u, v] = kept_axes(drop);
    bool inside = false;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const ExactPoint p = exact_point(plc.points.points[loop[i]]);
        const ExactPoint q = exact_point(plc.points.points[loop[(i + 1) % loop.size()]]);
        if ((p[v] > x[v]) == (q[v] > x[v])) {
            continue;
        }
        // The side's abscissa at ordinate x[v], compared with x[u] without dividing.
        const Rational t_num = x[v] - p[v];
        const Rational t_den = q[v] - p[v];
        const Rational lhs = (p[u] - x[u]) * t_den + (q[u] - p[u]) * t_num;
        if ((t_den > 0) ? lhs > 0 : lhs < 0) {
            inside = !inside;
        }
    }
    return inside;
}

Rational loop_area2(const Plc& plc, const std::vector<std::uint32_t>& loop, int drop) {
    const auto [u, v] = kept_axes(drop);
    Rational sum = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const ExactPoint p = exact_point(plc.points.points[loop[i]]);
        const ExactPoint q = exact_point(plc.points.points[loop[(i + 1) % loop.size()]]);
        sum += p[u] * q[v] - q[u] * p[v];
    }
    return abs(sum);
}

/// How many other loops of the facet contain loop i (tested at its first corner).
int depth(const Plc& plc, const PlcFacet& facet, std::size_t i, int drop) {
    const ExactPoint x = exact_point(plc.points.points[facet.loops[i].front()]);
    int d = 0;
    for (std::size_t j = 0; j < facet.loops.size(); ++j) {
        d += (j != i && inside_loop(plc, facet.loops[j], drop, x)) ? 1 : 0;
    }
    return d;
}

}  // namespace

ExactPoint exact_point(const Point3& p) { return {Rational(p.x), Rational(p.y), Rational(p.z)}; }

std::optional<ExactPlane> ExactPlane::of_facet(const Plc& plc, const PlcFacet& facet) {
    std::vector<std::uint32_t> corners;
    for (const auto& loop : facet.loops) {
        corners.insert(corners.end(), loop.begin(), loop.end());
    }
    if (corners.empty()) {
        return std::nullopt;
    }
    const ExactPoint a = exact_point(plc.points.points[corners[0]]);
    for (std::size_t i = 1; i < corners.size(); ++i) {
        const ExactPoint b = exact_point(plc.points.points[corners[i]]);
        if (b == a) {
            continue;
        }
        for (std::size_t j = i + 1; j < corners.size(); ++j) {
            const ExactPoint n =
                cross(minus(b, a), minus(exact_point(plc.points.points[corners[j]]), a));
            if (!is_zero(n)) {
                ExactPlane plane;
                plane.a_ = a;
                plane.n_ = n;
                for (int k = 0; k < 3; ++k) {
                    if (abs(n[static_cast<std::size_t>(k)]) >
                        abs(n[static_cast<std::size_t>(plane.drop_)])) {
                        plane.drop_ = k;
                    }
                }
                return plane;
            }
        }
    }
    return std::nullopt;
}

Rational ExactPlane::offset(const Point3& p) const { return dot(n_, minus(exact_point(p), a_)); }

predicates::Sign ExactPlane::side(const Point3& p) const {
    const Rational d = offset(p);
    return d > 0 ? predicates::Sign::kPos : d < 0 ? predicates::Sign::kNeg : predicates::Sign::kZero;
}

ExactPoint ExactPlane::crossing(const Point3& p, const Point3& q) const {
    const Rational dp = offset(p);
    const Rational dq = offset(q);
    const Rational t = dp / (dp - dq);
    const ExactPoint ep = exact_point(p);
    const ExactPoint eq = exact_point(q);
    return {ep[0] + t * (eq[0] - ep[0]), ep[1] + t * (eq[1] - ep[1]), ep[2] + t * (eq[2] - ep[2])};
}

bool in_facet_region(const Plc& plc, const PlcFacet& facet, const ExactPlane& plane,
                     const ExactPoint& x) {
    bool inside = false;
    for (const auto& loop : facet.loops) {
        inside = inside != inside_loop(plc, loop, plane.dropped_axis(), x);
    }
    return inside;
}

Rational facet_region_area2(const Plc& plc, const PlcFacet& facet, const ExactPlane& plane) {
    Rational area = 0;
    for (std::size_t i = 0; i < facet.loops.size(); ++i) {
        const Rational a = loop_area2(plc, facet.loops[i], plane.dropped_axis());
        area += depth(plc, facet, i, plane.dropped_axis()) % 2 == 0 ? a : Rational(-a);
    }
    return area;
}

Rational triangle_area2(const ExactPlane& plane, const Point3& a, const Point3& b, const Point3& c) {
    Plc tri;
    tri.points.points = {a, b, c};
    return loop_area2(tri, {0, 1, 2}, plane.dropped_axis());
}

}  // namespace cavity::core
