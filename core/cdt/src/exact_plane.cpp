#include "exact_plane.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

#include "cavity/predicates/detail/expansion.h"
#include "cavity/predicates/dyadic.h"
#include "cavity/predicates/generic_predicates.h"
#include "cavity/predicates/orient3d.h"
#include "segment_interior.h"

namespace cavity::core {

namespace {

/// x rounded toward zero (mpq_get_d: within one unit in the last place; Boost's convert_to
/// rounds to nearest through a generic path that cost as much as the rest of the region test).
double truncated(const Rational& x) {
    return mpq_get_d(x.backend().data());
}

/// The point (u, v) with its doubles.
Point2 point2(Rational u, Rational v) {
    const double du = truncated(u);
    const double dv = truncated(v);
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    return {std::move(u),
            std::move(v),
            du,
            dv,
            std::nextafter(dv, -kInfinity),
            std::nextafter(dv, kInfinity)};
}

Point2 project(const ExactPoint& p, int drop) {
    const std::size_t u = drop == 0 ? 1 : 0;
    const std::size_t v = drop == 2 ? 1 : 2;
    return point2(p[u], p[v]);
}

/// The same, taking p's coordinates rather than copying them (two GMP rationals each).
Point2 project(ExactPoint&& p, int drop) {
    const std::size_t u = drop == 0 ? 1 : 0;
    const std::size_t v = drop == 2 ? 1 : 2;
    return point2(std::move(p[u]), std::move(p[v]));
}

/// p.v > x.v, by the intervals when they are apart.
bool above(const Point2& p, const Point2& x) {
    if (p.v_lo > x.v_hi) {
        return true;
    }
    if (p.v_hi < x.v_lo) {
        return false;
    }
    return p.v > x.v;
}

/// p.v == x.v, by the intervals when they are apart.
bool level(const Point2& p, const Point2& x) {
    return p.v_lo <= x.v_hi && x.v_lo <= p.v_hi && p.v == x.v;
}

/// The loop's corners projected, converted to rationals or taken from `rational` (the PLC's
/// points) when given.
std::vector<Point2> project_loop(const Plc& plc,
                                 const std::vector<std::uint32_t>& loop,
                                 int drop,
                                 RationalPoints* rational = nullptr) {
    std::vector<Point2> out;
    out.reserve(loop.size());
    for (std::uint32_t c : loop) {
        out.push_back(rational != nullptr ? project((*rational)[c], drop)
                                          : project(exact_point(plc.points, c), drop));
    }
    return out;
}

/// The sign of twice the signed area of pqr: positive when r is left of pq. First in doubles:
/// with every rounded coordinate within 2^-52 of the exact one, relative, and M the largest
/// magnitude, the double evaluation errs by less than 64 * 2^-52 * M^2 (about 48 units of error
/// in any rounding mode: 4 * 2^-52 * M on each difference, 20 on each product, and the final
/// subtraction), so a result beyond 2^-45 * M^2 has the exact sign. Outside the range where the
/// relative bound holds (M tiny or huge), and near zero, the rationals decide.
int orient2_sign(const Point2& p, const Point2& q, const Point2& r) {
    const double m = std::max({std::abs(p.du),
                               std::abs(p.dv),
                               std::abs(q.du),
                               std::abs(q.dv),
                               std::abs(r.du),
                               std::abs(r.dv)});
    if (m > 0x1p-400 && m < 0x1p+400) {
        const double det = (q.du - p.du) * (r.dv - p.dv) - (q.dv - p.dv) * (r.du - p.du);
        const double bound = 0x1p-45 * m * m;
        if (det > bound) {
            return 1;
        }
        if (det < -bound) {
            return -1;
        }
    }
    const Rational exact = (q.u - p.u) * (r.v - p.v) - (q.v - p.v) * (r.u - p.u);
    return exact.sign();
}

/// True when x lies on the closed segment pq.
bool on_segment(const Point2& p, const Point2& q, const Point2& x) {
    return orient2_sign(p, q, x) == 0 && (x.u - p.u) * (x.u - q.u) <= 0 &&
           (x.v - p.v) * (x.v - q.v) <= 0;
}

LoopPosition position(const std::vector<Point2>& loop, const Point2& x) {
    bool inside = false;
    // Only the sides whose v-range holds x.v can hold x or cross the ray, so comparisons of v
    // (cheap) pick the few sides that need an orientation (a dozen GMP operations).
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point2& p = loop[i];
        const Point2& q = loop[(i + 1) % loop.size()];
        const bool p_above = above(p, x);
        const bool q_above = above(q, x);
        if (p_above != q_above) {
            const int o = orient2_sign(p, q, x);
            if (o == 0 && (x.u - p.u) * (x.u - q.u) <= 0) {
                return LoopPosition::kOnBoundary;
            }
            // Crossing number along the ray from x in direction +u; the half-open rule on v
            // counts a corner on the ray once (q_above is q.v > x.v >= p.v here, or the reverse).
            if (q_above == (o > 0)) {
                inside = !inside;
            }
        } else if (!p_above && (level(p, x) || level(q, x)) && on_segment(p, q, x)) {
            return LoopPosition::kOnBoundary;
        }
    }
    return inside ? LoopPosition::kInside : LoopPosition::kOutside;
}

/// Which loops of the facet contain x (strictly inside or on their boundary, as `position` says).
std::vector<bool> containing_loops(const std::vector<std::vector<Point2>>& loops, const Point2& x) {
    std::vector<bool> in(loops.size());
    for (std::size_t i = 0; i < loops.size(); ++i) {
        in[i] = position(loops[i], x) == LoopPosition::kInside;
    }
    return in;
}

SidePieces pieces(const std::vector<Point2>& a, const std::vector<Point2>& b) {
    SidePieces out;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Point2& p = a[i];
        const Point2& q = a[(i + 1) % a.size()];
        // Cut pq at the corners of b strictly inside it, ordered by their parameter along pq
        // (compared through the dominant coordinate of q - p, without dividing).
        const bool by_u = abs(q.u - p.u) >= abs(q.v - p.v);
        const auto key = [&](const Point2& x) {
            return by_u ? (x.u - p.u) / (q.u - p.u) : (x.v - p.v) / (q.v - p.v);
        };
        std::vector<Rational> cuts{0, 1};
        for (const Point2& c : b) {
            if (on_segment(p, q, c)) {
                const Rational t = key(c);
                if (t > 0 && t < 1) {
                    cuts.push_back(t);
                }
            }
        }
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            const Rational t = (cuts[k] + cuts[k + 1]) / 2;
            const Point2 mid = point2(p.u + t * (q.u - p.u), p.v + t * (q.v - p.v));
            switch (position(b, mid)) {
                case LoopPosition::kInside:
                    ++out.inside;
                    break;
                case LoopPosition::kOutside:
                    ++out.outside;
                    break;
                case LoopPosition::kOnBoundary:
                    ++out.on_boundary;
                    break;
            }
        }
    }
    return out;
}

Rational loop_area2(const std::vector<Point2>& loop) {
    Rational sum = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point2& p = loop[i];
        const Point2& q = loop[(i + 1) % loop.size()];
        sum += p.u * q.v - q.u * p.v;
    }
    return abs(sum);
}

/// contains[i][j]: loop j encloses loop i (for non-crossing loops). Two loops with the same
/// boundary enclose each other; the later one is taken as the inner, so that "inside" stays a
/// strict order and every face has one innermost loop.
std::vector<std::vector<bool>> nesting(const std::vector<std::vector<Point2>>& loops) {
    std::vector<std::vector<bool>> contains(loops.size(), std::vector<bool>(loops.size(), false));
    for (std::size_t i = 0; i < loops.size(); ++i) {
        for (std::size_t j = 0; j < loops.size(); ++j) {
            if (i == j) {
                continue;
            }
            const SidePieces s = pieces(loops[i], loops[j]);
            contains[i][j] = s.inside > 0 || (s.outside == 0 && i > j);
        }
    }
    return contains;
}

}  // namespace

ExactPoint exact_point(const Point3& p) {
    return {Rational(p.x), Rational(p.y), Rational(p.z)};
}

Point3 rounded_point(const predicates::GenericPoint3& g) {
    if (const auto* p = std::get_if<Point3>(&g)) {
        return *p;
    }
    // Boost rounds a rational to the nearest double (mpq_get_d, see truncated(), would not).
    const ExactPoint e = exact_point(g);
    return {e[0].convert_to<double>(), e[1].convert_to<double>(), e[2].convert_to<double>()};
}

namespace {

using Integer = boost::multiprecision::mpz_int;

using predicates::spacing_exponent;

/// The least spacing exponent of the nonzero values (INT_MAX when all are zero): each of them is
/// an integer multiple of 2^result.
template <std::size_t N>
int common_spacing(const std::array<double, N>& values) {
    int k = std::numeric_limits<int>::max();
    for (const double v : values) {
        if (v != 0.0) {
            k = std::min(k, spacing_exponent(v));
        }
    }
    return k;
}

/// x * 2^-scale, an integer when scale <= spacing_exponent(x) (or x == 0).
Integer scaled(double x, int scale) {
    return predicates::scaled_to_integer<Integer>(x, scale);
}

/// out = numerator * 2^scale / denominator (denominator != 0), reduced once, written into out's
/// own integers (no copy of the operands).
void set_dyadic_quotient(Rational& out,
                         const Integer& numerator,
                         const Integer& denominator,
                         int scale) {
    const mpq_ptr q = out.backend().data();
    if (scale >= 0) {
        mpz_mul_2exp(mpq_numref(q), numerator.backend().data(), static_cast<mp_bitcnt_t>(scale));
        mpz_set(mpq_denref(q), denominator.backend().data());
    } else {
        mpz_set(mpq_numref(q), numerator.backend().data());
        mpz_mul_2exp(mpq_denref(q), denominator.backend().data(), static_cast<mp_bitcnt_t>(-scale));
    }
    mpq_canonicalize(q);
}

Rational dyadic_quotient(const Integer& numerator, const Integer& denominator, int scale) {
    Rational out;
    set_dyadic_quotient(out, numerator, denominator, scale);
    return out;
}

/// a + (tn / td)(b - a) for the integers a, b, tn, td (td != 0), scaled by 2^scale: one
/// reduction per coordinate, where rational arithmetic reduced after each of its four steps.
ExactPoint along(const std::array<Integer, 3>& a,
                 const std::array<Integer, 3>& b,
                 const Integer& tn,
                 const Integer& td,
                 int scale) {
    ExactPoint x;
    for (std::size_t k = 0; k < 3; ++k) {
        x[k] = dyadic_quotient(Integer(a[k] * td + tn * (b[k] - a[k])), td, scale);
    }
    return x;
}

std::array<Integer, 3> scaled(const Point3& p, int scale) {
    return {scaled(p.x, scale), scaled(p.y, scale), scaled(p.z, scale)};
}

}  // namespace

ExactPoint exact_point(const predicates::GenericPoint3& g) {
    if (const auto* p = std::get_if<Point3>(&g)) {
        return exact_point(*p);
    }
    // Both kinds are a + t (b - a) for a rational t. Every double is an integer times a power of
    // two, so the defining points scaled by a common power 2^s are integers, and so are the
    // numerator and denominator of t (scaled by their own power, or, for a line and a plane, as
    // two dot products of the scaled points: the same power of 2^s in both).
    if (const auto* sp = std::get_if<predicates::SegmentParameterPoint>(&g)) {
        int s = common_spacing(
            std::array<double, 6>{sp->a.x, sp->a.y, sp->a.z, sp->b.x, sp->b.y, sp->b.z});
        if (s == std::numeric_limits<int>::max()) {
            s = 0;  // a = b = 0
        }
        const int r = common_spacing(std::array<double, 2>{sp->numerator, sp->denominator});
        return along(scaled(sp->a, s),
                     scaled(sp->b, s),
                     scaled(sp->numerator, r),
                     scaled(sp->denominator, r),
                     s);
    }
    const auto& l = std::get<predicates::LinePlanePoint>(g);
    int s = std::numeric_limits<int>::max();
    for (const Point3* q : {&l.a, &l.b, &l.p, &l.q, &l.r}) {
        s = std::min(s, common_spacing(std::array<double, 3>{q->x, q->y, q->z}));
    }
    if (s == std::numeric_limits<int>::max()) {
        s = 0;
    }
    const auto a = scaled(l.a, s);
    const auto b = scaled(l.b, s);
    const auto p = scaled(l.p, s);
    const auto q = scaled(l.q, s);
    const auto r = scaled(l.r, s);
    const std::array<Integer, 3> u{q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const std::array<Integer, 3> v{r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const std::array<Integer, 3> n{
        u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const auto dot = [&](const std::array<Integer, 3>& x, const std::array<Integer, 3>& y) {
        return Integer(n[0] * (x[0] - y[0]) + n[1] * (x[1] - y[1]) + n[2] * (x[2] - y[2]));
    };
    return along(a, b, dot(p, a), dot(b, a), s);
}

namespace {

/// -s: orient3d(a, b, c, p) is positive on the side opposite (b - a) x (c - a).
predicates::Sign opposite(predicates::Sign s) {
    return s == predicates::Sign::kPos   ? predicates::Sign::kNeg
           : s == predicates::Sign::kNeg ? predicates::Sign::kPos
                                         : predicates::Sign::kZero;
}

/// The sign of u_i v_j - u_j v_i for the differences u = b - a, v = c - a, i = (k + 1) % 3 and
/// j = (k + 2) % 3 (component k of u x v), from doubles alone when the four differences are
/// exact (two_diff leaves no error) and each is zero or within [2^-400, 2^400]; nullopt
/// otherwise. Then both products are p + e exactly (Dekker's product, no underflow or overflow
/// in that range), with p = fl(product): rounding is monotone, so unequal p order the products,
/// and equal p leave the sign of e1 - e2, a difference of doubles whose sign rounding keeps.
/// The facets' corners are mostly on a grid where these differences are exact, and collinear
/// triples (a zero sign) were an exact-stage orient3d each, most of a facet's plane.
std::optional<int> cross_sign_in_doubles(const Point3& a, const Point3& b, const Point3& c, int k) {
    const std::array<double, 3> pa{a.x, a.y, a.z};
    const std::array<double, 3> pb{b.x, b.y, b.z};
    const std::array<double, 3> pc{c.x, c.y, c.z};
    const auto i = static_cast<std::size_t>((k + 1) % 3);
    const auto j = static_cast<std::size_t>((k + 2) % 3);
    std::array<double, 4> d{};  // u_i, u_j, v_i, v_j
    const std::array<std::pair<const std::array<double, 3>*, std::size_t>, 4> terms{
        {{&pb, i}, {&pb, j}, {&pc, i}, {&pc, j}}};
    for (std::size_t t = 0; t < 4; ++t) {
        const auto& [p, axis] = terms[t];
        double error = 0;
        predicates::detail::two_diff((*p)[axis], pa[axis], d[t], error);
        const double size = std::abs(d[t]);
        if (error != 0 || !(size == 0 || (size >= 0x1p-400 && size <= 0x1p+400))) {
            return std::nullopt;  // also NaN
        }
    }
    double p1 = 0;
    double e1 = 0;
    double p2 = 0;
    double e2 = 0;
    predicates::detail::two_product(d[0], d[3], p1, e1);
    predicates::detail::two_product(d[1], d[2], p2, e2);
    if (p1 != p2) {
        return p1 > p2 ? 1 : -1;
    }
    return e1 > e2 ? 1 : e1 < e2 ? -1 : 0;
}

}  // namespace

predicates::Sign cross_component_sign(const Point3& a, const Point3& b, const Point3& c, int k) {
    if (const std::optional<int> s = cross_sign_in_doubles(a, b, c, k)) {
        return *s > 0   ? predicates::Sign::kPos
               : *s < 0 ? predicates::Sign::kNeg
                        : predicates::Sign::kZero;
    }
    // The orientation of a, b, c projected onto the coordinate plane normal to axis k, as
    // orient3d of the projections (in the plane z = 0) and a point above them, which is exact
    // for every finite double.
    const auto flat = [k](const Point3& p) {
        const std::array<double, 3> x{p.x, p.y, p.z};
        return Point3{x[static_cast<std::size_t>((k + 1) % 3)],
                      x[static_cast<std::size_t>((k + 2) % 3)],
                      0.0};
    };
    // det[a-d; b-d; c-d] with d = (0, 0, 1) is minus the 2D orientation of the projections.
    return opposite(predicates::orient3d(flat(a), flat(b), flat(c), {0.0, 0.0, 1.0}));
}

namespace {

/// p == q coordinate by coordinate.
bool same(const Point3& p, const Point3& q) {
    return p.x == q.x && p.y == q.y && p.z == q.z;
}

/// For three input points: the axis to drop (see dropped_axis), or nullopt when they are
/// collinear. Decided by exact signs, without rationals; the floating-point normal only orders the
/// candidate axes (any axis with a non-zero component projects the plane one-to-one).
std::optional<int> drop_axis(const Point3& a, const Point3& b, const Point3& c) {
    const double u[3]{b.x - a.x, b.y - a.y, b.z - a.z};
    const double v[3]{c.x - a.x, c.y - a.y, c.z - a.z};
    std::array<double, 3> size{std::abs(u[1] * v[2] - u[2] * v[1]),
                               std::abs(u[2] * v[0] - u[0] * v[2]),
                               std::abs(u[0] * v[1] - u[1] * v[0])};
    for (double& x : size) {
        x = std::isnan(x) ? -1.0 : x;  // an estimate that overflowed into inf - inf goes last
    }
    std::array<int, 3> axes{0, 1, 2};
    // Largest estimate first; ties keep the lower axis (std::stable_sort took a heap buffer).
    std::sort(axes.begin(), axes.end(), [&](int i, int j) {
        const double si = size[static_cast<std::size_t>(i)];
        const double sj = size[static_cast<std::size_t>(j)];
        return si > sj || (si == sj && i < j);
    });
    for (int k : axes) {
        if (cross_component_sign(a, b, c, k) != predicates::Sign::kZero) {
            return k;
        }
    }
    return std::nullopt;
}

/// A point off the plane through `corner` whose normal has a non-zero component along `axis`:
/// `corner` moved along that axis; nullopt when the move overflows.
std::optional<Point3> off_plane(const Point3& corner, int axis) {
    std::array<double, 3> x{corner.x, corner.y, corner.z};
    auto& c = x[static_cast<std::size_t>(axis)];
    c += 2 * (std::abs(c) + 1);
    if (!std::isfinite(c)) {
        return std::nullopt;
    }
    return Point3{x[0], x[1], x[2]};
}

}  // namespace

void ExactPlane::use_explicit_corners(const Plc& plc, const std::vector<std::uint32_t>& corners) {
    std::vector<Point3> inputs;
    for (std::uint32_t c : corners) {
        if (const auto* p = std::get_if<Point3>(&plc.points.exact[c])) {
            inputs.push_back(*p);
        }
    }
    for (std::size_t i = 1; i < inputs.size(); ++i) {
        const Point3& a = inputs[0];
        const Point3& b = inputs[i];
        if (b.x == a.x && b.y == a.y && b.z == a.z) {
            continue;
        }
        for (std::size_t j = i + 1; j < inputs.size(); ++j) {
            if (!drop_axis(a, b, inputs[j])) {
                continue;
            }
            const auto x = off_plane(a, drop_);
            if (!x) {
                return;
            }
            const predicates::Sign mine = predicates::orient3d(a, b, inputs[j], *x);
            const predicates::Sign theirs =
                predicates::orient3d(corners_[0], corners_[1], corners_[2], *x);
            if (mine == predicates::Sign::kZero || theirs == predicates::Sign::kZero) {
                return;  // not off the plane after all: keep asking corners_
            }
            explicit_ = {a, b, inputs[j]};
            explicit_sign_ = mine == theirs ? 1 : -1;
            return;
        }
    }
}

std::optional<ExactPlane> ExactPlane::of_facet(const Plc& plc, const PlcFacet& facet) {
    std::vector<std::uint32_t> corners;
    for (const auto& loop : facet.loops) {
        corners.insert(corners.end(), loop.begin(), loop.end());
    }
    if (corners.empty()) {
        return std::nullopt;
    }
    const auto make = [&](std::size_t i, std::size_t j, int drop) {
        ExactPlane plane;
        plane.corners_ = {generic_point(plc.points, corners[0]),
                          generic_point(plc.points, corners[i]),
                          generic_point(plc.points, corners[j])};
        plane.drop_ = drop;
        if (plc.points.exact.empty()) {
            const auto& pts = plc.points.points;
            plane.explicit_ = {pts[corners[0]], pts[corners[i]], pts[corners[j]]};
            plane.explicit_sign_ = 1;
        } else {
            plane.use_explicit_corners(plc, corners);
        }
        return plane;
    };
    if (plc.points.exact.empty()) {
        // Input points only: exact signs decide collinearity and the axis.
        const auto& pts = plc.points.points;
        const Point3& a = pts[corners[0]];
        for (std::size_t i = 1; i < corners.size(); ++i) {
            const Point3& b = pts[corners[i]];
            if (b.x == a.x && b.y == a.y && b.z == a.z) {
                continue;
            }
            for (std::size_t j = i + 1; j < corners.size(); ++j) {
                if (const auto drop = drop_axis(a, b, pts[corners[j]])) {
                    return make(i, j, *drop);
                }
            }
        }
        return std::nullopt;
    }
    // Some points are implicit: most are split points of loop sides, strictly inside a segment
    // between input points, and a triple is decided from input points with the same exact signs
    // whenever the segments allow (below); rationals are made only for the other triples, and a
    // corner's once. Building every facet's plane in rationals cost 0.90 G instructions on
    // homer, 4.0 G on cheese.
    const auto input = [&](std::size_t k) {
        return std::get_if<Point3>(&plc.points.exact[corners[k]]);
    };
    std::vector<std::optional<ExactPoint>> rational(corners.size());
    const auto exact = [&](std::size_t k) -> const ExactPoint& {
        if (!rational[k]) {
            rational[k].emplace(exact_point(plc.points, corners[k]));
        }
        return *rational[k];
    };
    const Point3* a = input(0);
    // Corner k as a point strictly inside a segment uv of input points, u != v.
    const auto inside = [&](std::size_t k) -> const predicates::SegmentParameterPoint* {
        const auto* s =
            std::get_if<predicates::SegmentParameterPoint>(&plc.points.exact[corners[k]]);
        if (s == nullptr || same(s->a, s->b)) {
            return nullptr;
        }
        return strictly_inside(*s) ? s : nullptr;
    };
    // An input point p with corner i - a = lambda (p - a), lambda > 0 (so p != a): corner i
    // itself, or the far end of a segment from a that it is inside. Null when there is none.
    const auto ray = [&](std::size_t i) -> const Point3* {
        if (const Point3* b = input(i)) {
            return same(*a, *b) ? nullptr : b;
        }
        if (const auto* s = inside(i)) {
            return same(*a, s->a) ? &s->b : same(*a, s->b) ? &s->a : nullptr;
        }
        return nullptr;
    };
    for (std::size_t i = 1; i < corners.size(); ++i) {
        const Point3* b = a != nullptr ? ray(i) : nullptr;
        if (b == nullptr && exact(i) == exact(0)) {
            continue;  // a repeat of the first corner (a ray's point differs from a)
        }
        for (std::size_t j = i + 1; j < corners.size(); ++j) {
            if (b != nullptr) {
                // (corner i - a) x (corner j - a) = lambda (b - a) x (corner j - a): for a corner
                // j inside segment uv, (1 - t)(b - a) x (u - a) + t (b - a) x (v - a), which is a
                // positive multiple of one term when the other end is on line ab.
                const Point3* c = input(j);
                const auto* s = c == nullptr ? inside(j) : nullptr;
                if (s != nullptr) {
                    const bool u_on = !drop_axis(*a, *b, s->a);
                    const bool v_on = !drop_axis(*a, *b, s->b);
                    c = u_on && v_on ? nullptr : u_on ? &s->b : v_on ? &s->a : nullptr;
                    if (u_on && v_on) {
                        continue;  // corner j is on line ab
                    }
                }
                if (c != nullptr) {
                    if (const auto drop = drop_axis(*a, *b, *c)) {
                        return make(i, j, *drop);
                    }
                    continue;
                }
            }
            const ExactPoint n = cross(minus(exact(i), exact(0)), minus(exact(j), exact(0)));
            if (!is_zero(n)) {
                int drop = 2;
                for (int k = 0; k < 3; ++k) {
                    if (abs(n[static_cast<std::size_t>(k)]) >
                        abs(n[static_cast<std::size_t>(drop)])) {
                        drop = k;
                    }
                }
                ExactPlane plane = make(i, j, drop);
                plane.rational_.emplace(exact(0), n);
                return plane;
            }
        }
    }
    return std::nullopt;
}

const std::pair<ExactPoint, ExactPoint>& ExactPlane::rational() const {
    if (!rational_) {
        const ExactPoint a = exact_point(corners_[0]);
        rational_.emplace(
            a, cross(minus(exact_point(corners_[1]), a), minus(exact_point(corners_[2]), a)));
    }
    return *rational_;
}

Rational ExactPlane::offset(const ExactPoint& p) const {
    const auto& [a, n] = rational();
    return dot(n, minus(p, a));
}

predicates::Sign ExactPlane::explicit_side(const Point3& p) const {
    // Most points asked about are the facet's own corners, or the ends of split points on its
    // sides, and the three corners asked most are these: a zero orient3d is its dearest answer
    // (the exact stage), which repeating a point makes plain.
    if (same(p, explicit_[0]) || same(p, explicit_[1]) || same(p, explicit_[2])) {
        return predicates::Sign::kZero;
    }
    const predicates::Sign s =
        opposite(predicates::orient3d(explicit_[0], explicit_[1], explicit_[2], p));
    return explicit_sign_ > 0 ? s : opposite(s);
}

predicates::Sign ExactPlane::side(const predicates::GenericPoint3& p) const {
    if (explicit_sign_ != 0) {
        if (const auto* x = std::get_if<Point3>(&p)) {
            return explicit_side(*x);
        }
        if (const auto* s = std::get_if<predicates::SegmentParameterPoint>(&p)) {
            // orient3d is affine in its last point, so strictly inside segment ab (0 < t < 1)
            // its sign is that of the ends when they agree or one of them is zero.
            if (strictly_inside(*s)) {
                const predicates::Sign sa = explicit_side(s->a);
                const predicates::Sign sb = explicit_side(s->b);
                if (sa == sb || sb == predicates::Sign::kZero) {
                    return sa;
                }
                if (sa == predicates::Sign::kZero) {
                    return sb;
                }
            }
        }
    }
    return opposite(predicates::orient3d(corners_[0], corners_[1], corners_[2], p));
}

ExactPoint ExactPlane::crossing(const ExactPoint& ep, const ExactPoint& eq) const {
    const Rational dp = offset(ep);
    const Rational dq = offset(eq);
    const Rational t = dp / (dp - dq);
    return {ep[0] + t * (eq[0] - ep[0]), ep[1] + t * (eq[1] - ep[1]), ep[2] + t * (eq[2] - ep[2])};
}

namespace {

/// GMP's own view of an integer: the sums of products below run in place (mpz_addmul), where
/// Boost's expressions made and freed a temporary integer per operation.
mpz_ptr raw(Integer& x) {
    return x.backend().data();
}

mpz_srcptr raw(const Integer& x) {
    return x.backend().data();
}

/// out = p * 2^-scale (scaled() in place), for scale <= the spacing exponent of every
/// nonzero coordinate: integers that already have the room allocate nothing.
void set_scaled(std::array<Integer, 3>& out, const Point3& p, int scale) {
    predicates::set_scaled(raw(out[0]), p.x, scale);
    predicates::set_scaled(raw(out[1]), p.y, scale);
    predicates::set_scaled(raw(out[2]), p.z, scale);
}

/// The integers `homogeneous` works in: a segment's ends and its parameter's numerator.
struct SegmentWork {
    std::array<Integer, 3>& a;
    std::array<Integer, 3>& b;
    Integer& n;
};

/// A point as integers v / w scaled by 2^-s (v a vector, w != 0): an input point with w = 1, or
/// a point a + (n / d)(b - a) on a segment, with n and d scaled by their own power; false (v and
/// w unset) for a line-plane point, or a parameter 0 / 0. Written into integers the caller keeps,
/// with `work` for the intermediate ones.
bool homogeneous(const predicates::GenericPoint3& g,
                 int s,
                 std::array<Integer, 3>& v,
                 Integer& w,
                 const SegmentWork& work) {
    if (const auto* p = std::get_if<Point3>(&g)) {
        set_scaled(v, *p, s);
        mpz_set_ui(raw(w), 1);
        return true;
    }
    const auto* sp = std::get_if<predicates::SegmentParameterPoint>(&g);
    if (sp == nullptr) {
        return false;
    }
    const int r = common_spacing(std::array<double, 2>{sp->numerator, sp->denominator});
    if (r == std::numeric_limits<int>::max()) {
        return false;
    }
    std::array<Integer, 3>& a = work.a;
    std::array<Integer, 3>& b = work.b;
    set_scaled(a, sp->a, s);
    set_scaled(b, sp->b, s);
    predicates::set_scaled(raw(work.n), sp->numerator, r);
    predicates::set_scaled(raw(w), sp->denominator, r);
    for (std::size_t k = 0; k < 3; ++k) {
        // v = a d + n (b - a), with b - a formed in b's place.
        mpz_sub(raw(b[k]), raw(b[k]), raw(a[k]));
        mpz_mul(raw(v[k]), raw(a[k]), raw(w));
        mpz_addmul(raw(v[k]), raw(work.n), raw(b[k]));
    }
    return true;
}

/// The least spacing exponent of the doubles that define g (see common_spacing).
int spacing_of(const predicates::GenericPoint3& g) {
    if (const auto* p = std::get_if<Point3>(&g)) {
        return common_spacing(std::array<double, 3>{p->x, p->y, p->z});
    }
    if (const auto* sp = std::get_if<predicates::SegmentParameterPoint>(&g)) {
        return common_spacing(
            std::array<double, 6>{sp->a.x, sp->a.y, sp->a.z, sp->b.x, sp->b.y, sp->b.z});
    }
    return std::numeric_limits<int>::max();
}

}  // namespace

const ExactPlane::ExplicitIntegers& ExactPlane::explicit_integers() const {
    if (!explicit_integers_) {
        const auto& e = explicit_;
        ExplicitIntegers made;
        // Three non-collinear corners are not all the origin, so the scale is finite.
        made.scale = std::min({spacing_of(e[0]), spacing_of(e[1]), spacing_of(e[2])});
        const std::array<Integer, 3> a = scaled(e[0], made.scale);
        const std::array<Integer, 3> b = scaled(e[1], made.scale);
        const std::array<Integer, 3> c = scaled(e[2], made.scale);
        const std::array<Integer, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const std::array<Integer, 3> v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        made.normal = {Integer(u[1] * v[2] - u[2] * v[1]),
                       Integer(u[2] * v[0] - u[0] * v[2]),
                       Integer(u[0] * v[1] - u[1] * v[0])};
        made.normal_dot_corner =
            made.normal[0] * a[0] + made.normal[1] * a[1] + made.normal[2] * a[2];
        explicit_integers_.emplace(std::move(made));
    }
    return *explicit_integers_;
}

std::optional<ExactPoint> ExactPlane::projected_crossing(const predicates::GenericPoint3& p,
                                                         const predicates::GenericPoint3& q) const {
    if (explicit_sign_ == 0 || std::holds_alternative<predicates::LinePlanePoint>(p) ||
        std::holds_alternative<predicates::LinePlanePoint>(q)) {
        return std::nullopt;
    }
    const ExplicitIntegers& e = explicit_integers();
    const int s = std::min({e.scale, spacing_of(p), spacing_of(q)});
    CrossingWork& work = work_;
    const std::array<Integer, 3>& pv = work.pv;
    const std::array<Integer, 3>& qv = work.qv;
    const Integer& pw = work.pw;
    const Integer& qw = work.qw;
    const SegmentWork segment{work.segment_a, work.segment_b, work.parameter};
    if (!homogeneous(p, s, work.pv, work.pw, segment) ||
        !homogeneous(q, s, work.qv, work.qw, segment)) {
        return std::nullopt;
    }
    // Scaled by 2^-s every coordinate is an integer, and D(x) = (e1 - e0) x (e2 - e0) . (x - e0)
    // is a constant multiple of offset(x) (the same plane). For x = v / w, D(x) = h / w with h =
    // m . (v - e0 w), and the crossing (D(p) q - D(q) p) / (D(p) - D(q)) is
    // (h_p q_v - h_q p_v) / (h_p q_w - h_q p_w): the same point as crossing()'s, without a
    // rational normal, offset or reduction per operation. The corners scaled by 2^-s are those
    // scaled by 2^-e.scale times 2^k, k = e.scale - s >= 0, so m and m . e0 at scale s are the
    // kept ones times 2^2k and 2^3k: h is 2^2k (m . v - (m . e0) w 2^k) with the kept m, and
    // the common factor 2^2k of both h cancels from the crossing.
    const auto shift = static_cast<mp_bitcnt_t>(e.scale - s);
    Integer& term = work.term;
    const auto height = [&](const std::array<Integer, 3>& x, const Integer& w, Integer& h) {
        mpz_mul(raw(h), raw(e.normal[0]), raw(x[0]));
        mpz_addmul(raw(h), raw(e.normal[1]), raw(x[1]));
        mpz_addmul(raw(h), raw(e.normal[2]), raw(x[2]));
        mpz_mul(raw(term), raw(e.normal_dot_corner), raw(w));
        mpz_mul_2exp(raw(term), raw(term), shift);
        mpz_sub(raw(h), raw(h), raw(term));
    };
    Integer& h_p = work.h_p;
    Integer& h_q = work.h_q;
    height(pv, pw, h_p);
    height(qv, qw, h_q);
    Integer& w = work.w;
    mpz_mul(raw(w), raw(h_p), raw(qw));
    mpz_submul(raw(w), raw(h_q), raw(pw));
    ExactPoint x;
    Integer& numerator = work.numerator;
    for (std::size_t k = 0; k < 3; ++k) {
        if (static_cast<int>(k) != drop_) {
            mpz_mul(raw(numerator), raw(h_p), raw(qv[k]));
            mpz_submul(raw(numerator), raw(h_q), raw(pv[k]));
            set_dyadic_quotient(x[k], numerator, w, s);
        }
    }
    return x;
}

std::optional<RoundedPoint2> ExactPlane::rounded_crossing(const predicates::RoundedPoint& p,
                                                          const predicates::RoundedPoint& q) const {
    if (explicit_sign_ == 0) {
        return std::nullopt;
    }
    return core::rounded_crossing(explicit_, drop_, p, q);
}

std::optional<ExactPoint> projected_centroid(std::span<const predicates::GenericPoint3> points,
                                             int drop) {
    int s = std::numeric_limits<int>::max();
    for (const auto& g : points) {
        s = std::min(s, spacing_of(g));
    }
    if (s == std::numeric_limits<int>::max()) {
        s = 0;  // every coordinate zero, or a line-plane point (refused below)
    }
    // The sum of the v_i / w_i over a common denominator, scaled by 2^-s: X / W with X = X w_i +
    // v_i W and W = W w_i at each step, then W times the count.
    std::array<Integer, 3> sum;
    Integer denominator;
    std::array<Integer, 3> v;
    Integer w;
    std::array<Integer, 3> a;
    std::array<Integer, 3> b;
    Integer n;
    const SegmentWork work{a, b, n};
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!homogeneous(points[i], s, v, w, work)) {
            return std::nullopt;
        }
        if (i == 0) {
            sum = std::move(v);
            v = {};
            denominator = std::move(w);
            continue;
        }
        for (std::size_t k = 0; k < 3; ++k) {
            if (static_cast<int>(k) != drop) {
                mpz_mul(raw(sum[k]), raw(sum[k]), raw(w));
                mpz_addmul(raw(sum[k]), raw(v[k]), raw(denominator));
            }
        }
        mpz_mul(raw(denominator), raw(denominator), raw(w));
    }
    if (points.empty()) {
        return std::nullopt;
    }
    mpz_mul_ui(raw(denominator), raw(denominator), static_cast<unsigned long>(points.size()));
    ExactPoint x;
    for (std::size_t k = 0; k < 3; ++k) {
        if (static_cast<int>(k) != drop) {
            set_dyadic_quotient(x[k], sum[k], denominator, s);
        }
    }
    return x;
}

FacetRegion::FacetRegion(const Plc& plc,
                         const PlcFacet& facet,
                         const ExactPlane& plane,
                         RationalPoints* rational)
    : plc_(plc), facet_(facet), drop_(plane.dropped_axis()), rational_(rational) {}

const FacetRegion::Projected& FacetRegion::projected() const {
    if (!projected_) {
        Projected made;
        for (const auto& loop : facet_.loops) {
            made.loops.push_back(project_loop(plc_, loop, drop_, rational_));
        }
        for (const Point3& h : facet_.holes) {
            made.hole_faces.push_back(containing_loops(made.loops, project(exact_point(h), drop_)));
        }
        projected_.emplace(std::move(made));
    }
    return *projected_;
}

bool FacetRegion::contains(ExactPoint x) const {
    const Projected& p = projected();
    const std::vector<bool> face = containing_loops(p.loops, project(std::move(x), drop_));
    return std::find(face.begin(), face.end(), true) != face.end() &&
           std::find(p.hole_faces.begin(), p.hole_faces.end(), face) == p.hole_faces.end();
}

const std::vector<std::vector<RoundedPoint2>>& FacetRegion::rounded_loops() const {
    if (!rounded_loops_) {
        std::vector<std::vector<RoundedPoint2>> made;
        for (const auto& loop : facet_.loops) {
            auto rounded = rounded_loop(plc_, loop, drop_);
            if (!rounded) {
                made.clear();
                break;
            }
            made.push_back(std::move(*rounded));
        }
        rounded_loops_.emplace(std::move(made));
    }
    return *rounded_loops_;
}

std::optional<bool> FacetRegion::contains_rounded(const RoundedPoint2& x) const {
    const auto& loops = rounded_loops();
    if (loops.empty()) {
        return std::nullopt;
    }
    std::vector<bool> face(loops.size());
    for (std::size_t i = 0; i < loops.size(); ++i) {
        const std::optional<bool> inside = inside_loop_rounded(loops[i], x);
        if (!inside) {
            return std::nullopt;
        }
        face[i] = *inside;
    }
    if (std::find(face.begin(), face.end(), true) == face.end()) {
        return false;
    }
    if (facet_.holes.empty()) {
        return true;
    }
    const auto& holes = projected().hole_faces;
    return std::find(holes.begin(), holes.end(), face) == holes.end();
}

bool crosses_facet_region(const Plc& plc,
                          const PlcFacet& facet,
                          const ExactPlane& plane,
                          const FacetRegion& region,
                          const predicates::GenericPoint3& p,
                          const predicates::GenericPoint3& q) {
    if (facet.loops.size() == 1 && facet.loops[0].size() == 3 && facet.holes.empty()) {
        const auto& loop = facet.loops[0];
        const auto corner = [&](std::size_t i) { return generic_point(plc.points, loop[i]); };
        const predicates::Sign first = predicates::orient3d(p, q, corner(0), corner(1));
        return first != predicates::Sign::kZero &&
               predicates::orient3d(p, q, corner(1), corner(2)) == first &&
               predicates::orient3d(p, q, corner(2), corner(0)) == first;
    }
    if (auto x = plane.projected_crossing(p, q)) {
        return region.contains(std::move(*x));
    }
    return region.contains(plane.crossing(exact_point(p), exact_point(q)));
}

Rational facet_region_area2(const Plc& plc,
                            const PlcFacet& facet,
                            const ExactPlane& plane,
                            RationalPoints* rational) {
    const int drop = plane.dropped_axis();
    std::vector<std::vector<Point2>> loops;
    for (const auto& loop : facet.loops) {
        loops.push_back(project_loop(plc, loop, drop, rational));
    }
    const auto contains = nesting(loops);
    const std::size_t n = loops.size();
    // The face just inside loop i is inside exactly i and the loops that enclose i.
    std::vector<std::vector<bool>> face(n);
    std::vector<std::size_t> depth(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        face[i] = contains[i];
        face[i][i] = true;
        depth[i] =
            static_cast<std::size_t>(std::count(contains[i].begin(), contains[i].end(), true));
    }
    std::vector<std::vector<bool>> holes;
    for (const Point3& h : facet.holes) {
        holes.push_back(containing_loops(loops, project(exact_point(h), drop)));
    }
    Rational area = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (std::find(holes.begin(), holes.end(), face[i]) != holes.end()) {
            continue;
        }
        area += loop_area2(loops[i]);
        // Minus the children: the loops whose innermost enclosing loop is i.
        for (std::size_t c = 0; c < n; ++c) {
            if (contains[c][i] && depth[c] == depth[i] + 1) {
                area -= loop_area2(loops[c]);
            }
        }
    }
    return area;
}

LoopPosition loop_position(const Plc& plc,
                           const std::vector<std::uint32_t>& loop,
                           int drop,
                           const ExactPoint& x) {
    return position(project_loop(plc, loop, drop), project(x, drop));
}

SidePieces side_pieces(const Plc& plc,
                       const std::vector<std::uint32_t>& a,
                       const std::vector<std::uint32_t>& b,
                       int drop) {
    return pieces(project_loop(plc, a, drop), project_loop(plc, b, drop));
}

Rational triangle_area2(const ExactPlane& plane,
                        const ExactPoint& a,
                        const ExactPoint& b,
                        const ExactPoint& c) {
    // The cross product of two sides in the projection, read in place: projecting the corners
    // copied six rationals and rounded each to doubles, most of the validator's area sums.
    const int drop = plane.dropped_axis();
    const std::size_t u = drop == 0 ? 1 : 0;
    const std::size_t v = drop == 2 ? 1 : 2;
    return abs(Rational((b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u])));
}

}  // namespace cavity::core
