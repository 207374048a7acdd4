#include "triangle_intersection.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "cavity/predicates/orient2d.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {

namespace {

int orient(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    return static_cast<int>(predicates::orient3d(a, b, c, d));
}

}  // namespace

// The 2D orientation of the projected points, negated: the sign that orient3d of the points
// lifted to z = 0 with (0, 0, 1) gives, which callers and tests were written against.
int orient2d_projected(const Point3& a, const Point3& b, const Point3& c, int drop) {
    const auto flat = [drop](const Point3& p) -> std::array<double, 2> {
        switch (drop) {
            case 0:
                return {p.y, p.z};
            case 1:
                return {p.z, p.x};
            default:
                return {p.x, p.y};
        }
    };
    const auto [au, av] = flat(a);
    const auto [bu, bv] = flat(b);
    const auto [cu, cv] = flat(c);
    return -static_cast<int>(predicates::orient2d(au, av, bu, bv, cu, cv));
}

int projection_axis(const Point3& a, const Point3& b, const Point3& c) {
    // The axis of the normal's largest component by a floating-point estimate is tried first: its
    // projection is a triangle unless the estimate is far off, and the exact test then answers
    // from its filter. A degenerate projection (an axis-parallel plane seen edge-on, the commonest
    // flat face) makes orient3d prove a zero in exact arithmetic, the most expensive answer.
    const double u[3]{b.x - a.x, b.y - a.y, b.z - a.z};
    const double v[3]{c.x - a.x, c.y - a.y, c.z - a.z};
    const std::array<double, 3> size{std::abs(u[1] * v[2] - u[2] * v[1]),
                                     std::abs(u[2] * v[0] - u[0] * v[2]),
                                     std::abs(u[0] * v[1] - u[1] * v[0])};
    int first = 0;
    for (int k = 1; k < 3; ++k) {
        // NaN (an overflowed estimate) compares false and leaves the earlier axis.
        if (size[static_cast<std::size_t>(k)] > size[static_cast<std::size_t>(first)]) {
            first = k;
        }
    }
    if (orient2d_projected(a, b, c, first) != 0) {
        return first;
    }
    for (int drop = 0; drop < 2; ++drop) {
        if (drop != first && orient2d_projected(a, b, c, drop) != 0) {
            return drop;
        }
    }
    return 2;
}

namespace {

double coordinate(const Point3& p, int axis) {
    return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}

/// r, collinear with p and q in the projection, lies on the closed segment pq: compared on the two
/// kept coordinates (exact comparisons of doubles).
bool on_segment(const Point3& p, const Point3& q, const Point3& r, int drop) {
    for (int axis = 0; axis < 3; ++axis) {
        if (axis == drop) {
            continue;
        }
        const double u = coordinate(p, axis);
        const double v = coordinate(q, axis);
        const double w = coordinate(r, axis);
        if (w < std::min(u, v) || std::max(u, v) < w) {
            return false;
        }
    }
    return true;
}

/// The closed segments pq and rs (coplanar) share a point, decided in the projection.
bool segments_meet(const Point3& p, const Point3& q, const Point3& r, const Point3& s, int drop) {
    const int o1 = orient2d_projected(p, q, r, drop);
    const int o2 = orient2d_projected(p, q, s, drop);
    const int o3 = orient2d_projected(r, s, p, drop);
    const int o4 = orient2d_projected(r, s, q, drop);
    if (o1 * o2 < 0 && o3 * o4 < 0) {
        return true;
    }
    return (o1 == 0 && on_segment(p, q, r, drop)) || (o2 == 0 && on_segment(p, q, s, drop)) ||
           (o3 == 0 && on_segment(r, s, p, drop)) || (o4 == 0 && on_segment(r, s, q, drop));
}

/// p (in the plane of abc) lies in the closed triangle: no two of its sides see p on opposite
/// sides.
bool in_triangle(const Point3& p, const Point3& a, const Point3& b, const Point3& c, int drop) {
    const int s1 = orient2d_projected(a, b, p, drop);
    const int s2 = orient2d_projected(b, c, p, drop);
    const int s3 = orient2d_projected(c, a, p, drop);
    const bool negative = s1 < 0 || s2 < 0 || s3 < 0;
    const bool positive = s1 > 0 || s2 > 0 || s3 > 0;
    return !(negative && positive);
}

/// segment_meets_triangle with sp = orient(a, b, c, p) and sq = orient(a, b, c, q) known.
bool segment_meets_triangle_sided(const Point3& p,
                                  const Point3& q,
                                  const Point3& a,
                                  const Point3& b,
                                  const Point3& c,
                                  int sp,
                                  int sq) {
    if (sp != 0 && sp == sq) {
        return false;
    }
    if (sp == 0 && sq == 0) {
        const int drop = projection_axis(a, b, c);
        return in_triangle(p, a, b, c, drop) || in_triangle(q, a, b, c, drop) ||
               segments_meet(p, q, a, b, drop) || segments_meet(p, q, b, c, drop) ||
               segments_meet(p, q, c, a, drop);
    }
    // The segment meets the plane in one point; it lies in the triangle exactly when the line pq
    // passes no side of the triangle on the outside: the three volumes spanned by pq and a side
    // never have opposite signs (zeros are the line through a side or a corner).
    const int s1 = orient(p, q, a, b);
    const int s2 = orient(p, q, b, c);
    const int s3 = orient(p, q, c, a);
    const bool negative = s1 < 0 || s2 < 0 || s3 < 0;
    const bool positive = s1 > 0 || s2 > 0 || s3 > 0;
    return !(negative && positive);
}

/// The closed triangles abc and def, coplanar and sharing no corner, meet: in the projection,
/// a corner of one lies in the other or two sides cross at a point inside both (an extreme point of
/// their convex intersection is one or the other). Eighteen orientations, each corner against
/// each side of the other triangle, decide every case.
bool coplanar_triangles_meet(const std::array<const Point3*, 3>& s,
                             const std::array<const Point3*, 3>& t,
                             int drop) {
    // of_s[i][k]: corner k of t against side i (corners i, i + 1) of s; of_t likewise.
    int of_s[3][3];
    int of_t[3][3];
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t k = 0; k < 3; ++k) {
            of_s[i][k] = orient2d_projected(*s[i], *s[(i + 1) % 3], *t[k], drop);
            of_t[i][k] = orient2d_projected(*t[i], *t[(i + 1) % 3], *s[k], drop);
        }
    }
    const auto inside = [](const int(&sides)[3][3], std::size_t k) {
        const int a = sides[0][k];
        const int b = sides[1][k];
        const int c = sides[2][k];
        return !((a < 0 || b < 0 || c < 0) && (a > 0 || b > 0 || c > 0));
    };
    for (std::size_t k = 0; k < 3; ++k) {
        if (inside(of_s, k) || inside(of_t, k)) {
            return true;
        }
    }
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) {
            // Side i of s against side j of t: each side's ends strictly apart by the other.
            if (of_s[i][j] * of_s[i][(j + 1) % 3] < 0 && of_t[j][i] * of_t[j][(i + 1) % 3] < 0) {
                return true;
            }
        }
    }
    return false;
}

/// The triangles v p q and v r w, coplanar and sharing the corner v alone, meet elsewhere than at
/// v exactly when their angles at v overlap: each triangle lies in its angle (below a half turn),
/// and near v fills it. Two such angles overlap exactly when a side of one lies in the other
/// (closed), since their overlap is an angle bounded by sides of the two.
bool coplanar_angles_overlap(
    const Point3& v, const Point3& p, const Point3& q, const Point3& r, const Point3& w, int drop) {
    const int s_turn = orient2d_projected(v, p, q, drop);
    const int t_turn = orient2d_projected(v, r, w, drop);
    const int pr = orient2d_projected(v, p, r, drop);
    const int pw = orient2d_projected(v, p, w, drop);
    const int qr = orient2d_projected(v, q, r, drop);
    const int qw = orient2d_projected(v, q, w, drop);
    // x lies in the closed angle from a to b (turning `turn`) when neither side sees it outside.
    const auto within = [](int turn, int from_a, int to_b) {
        return from_a * turn >= 0 && to_b * turn >= 0;
    };
    return within(s_turn, pr, -qr) || within(s_turn, pw, -qw) || within(t_turn, -pr, pw) ||
           within(t_turn, -qr, qw);
}

}  // namespace

bool is_degenerate_triangle(const Point3& a, const Point3& b, const Point3& c) {
    // Collinear in space exactly when collinear in each of the three projections.
    return orient2d_projected(a, b, c, 0) == 0 && orient2d_projected(a, b, c, 1) == 0 &&
           orient2d_projected(a, b, c, 2) == 0;
}

bool segment_meets_triangle(
    const Point3& p, const Point3& q, const Point3& a, const Point3& b, const Point3& c) {
    return segment_meets_triangle_sided(p, q, a, b, c, orient(a, b, c, p), orient(a, b, c, q));
}

bool triangles_meet_improperly(const std::vector<Point3>& points,
                               const Triangle& s,
                               const Triangle& t) {
    // Corners of s shared with t, and each triangle's others (fixed arrays: this runs for every
    // candidate pair).
    std::array<std::uint32_t, 3> shared{};
    std::array<std::uint32_t, 3> s_own{};
    std::array<std::uint32_t, 3> t_own{};
    std::size_t n_shared = 0;
    std::size_t n_s_own = 0;
    std::size_t n_t_own = 0;
    for (const std::uint32_t v : s) {
        if (std::find(t.begin(), t.end(), v) != t.end()) {
            shared[n_shared++] = v;
        } else {
            s_own[n_s_own++] = v;
        }
    }
    for (const std::uint32_t v : t) {
        if (std::find(s.begin(), s.end(), v) == s.end()) {
            t_own[n_t_own++] = v;
        }
    }
    const auto& P = points;
    switch (n_shared) {
        case 3:
            return true;  // the same triangle twice
        case 2: {
            // Two planes through the shared side meet only along it; one plane holds both
            // triangles, which overlap when their third corners lie on one side of the side.
            const Point3& p = P[shared[0]];
            const Point3& q = P[shared[1]];
            const Point3& a = P[s_own[0]];
            const Point3& b = P[t_own[0]];
            if (orient(p, q, a, b) != 0) {
                return false;
            }
            const int drop = projection_axis(p, q, a);
            return orient2d_projected(p, q, a, drop) == orient2d_projected(p, q, b, drop);
        }
        case 1: {
            const Point3& v = P[shared[0]];
            const Point3& p = P[s_own[0]];
            const Point3& q = P[s_own[1]];
            const Point3& r = P[t_own[0]];
            const Point3& w = P[t_own[1]];
            const int sp = orient(v, r, w, p);
            const int sq = orient(v, r, w, q);
            if (sp == 0 && sq == 0) {
                return coplanar_angles_overlap(v, p, q, r, w, projection_axis(v, p, q));
            }
            // Their intersection is convex and holds the shared corner v; if it holds more, a ray
            // from v through it leaves each triangle through the side opposite v, and the nearer
            // exit lies in both triangles: so one opposite side meets the other triangle.
            return segment_meets_triangle_sided(p, q, v, r, w, sp, sq) ||
                   segment_meets_triangle_sided(
                       r, w, v, p, q, orient(v, p, q, r), orient(v, p, q, w));
        }
        default:
            break;
    }
    const Point3& a = P[s[0]];
    const Point3& b = P[s[1]];
    const Point3& c = P[s[2]];
    const Point3& d = P[t[0]];
    const Point3& e = P[t[1]];
    const Point3& f = P[t[2]];
    // Each corner's side of the other triangle's plane, taken once: the side tests below ask for
    // the same signs. Coplanar triangles (every sign a zero, proved in exact arithmetic) are
    // decided in a projection without the other three.
    const std::array<int, 3> st{orient(a, b, c, d), orient(a, b, c, e), orient(a, b, c, f)};
    if (st[0] != 0 && st[0] == st[1] && st[0] == st[2]) {
        return false;  // t strictly on one side of s's plane
    }
    if (st[0] == 0 && st[1] == 0 && st[2] == 0) {
        return coplanar_triangles_meet({&a, &b, &c}, {&d, &e, &f}, projection_axis(a, b, c));
    }
    const std::array<int, 3> ss{orient(d, e, f, a), orient(d, e, f, b), orient(d, e, f, c)};
    if (ss[0] != 0 && ss[0] == ss[1] && ss[0] == ss[2]) {
        return false;
    }
    // Two closed triangles meet exactly when a side of one meets the other: an extreme point of
    // their (convex) intersection lies on the boundary of one of them.
    return segment_meets_triangle_sided(a, b, d, e, f, ss[0], ss[1]) ||
           segment_meets_triangle_sided(b, c, d, e, f, ss[1], ss[2]) ||
           segment_meets_triangle_sided(c, a, d, e, f, ss[2], ss[0]) ||
           segment_meets_triangle_sided(d, e, a, b, c, st[0], st[1]) ||
           segment_meets_triangle_sided(e, f, a, b, c, st[1], st[2]) ||
           segment_meets_triangle_sided(f, d, a, b, c, st[2], st[0]);
}

}  // namespace cavity::core
