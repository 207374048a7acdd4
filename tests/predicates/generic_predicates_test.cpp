// The predicates on generic points (explicit and implicit, generic_predicates.h) against an
// independent oracle: each implicit point is turned into its Cartesian coordinates over exact
// rationals (GMP via Boost.Multiprecision) by a different formula from the predicates' homogeneous
// one (the line-plane parameter from two orient3d determinants, t = f(a) / (f(a) - f(b))), and each
// determinant is taken from its definition in differences. Families: random mixes over every
// exponent range, exactly degenerate configurations (implicit points exactly on a plane or a sphere
// through explicit ones), and the same moved by a few ulps. Zero disagreements allowed.
//
// CAVITY_GENERIC_QUERIES sets the number of queries per family and predicate (default 2000).

#include "cavity/predicates/generic_predicates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <boost/multiprecision/gmp.hpp>
#include <gtest/gtest.h>

#include "cavity/predicates/generic_filter.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/orient3d.h"
#include "coplanarity_certificate.h"
#include "random_source.h"
#include "scaled_integers.h"

namespace cavity::predicates {
namespace {

using Rational = boost::multiprecision::mpq_rational;
using Exact = std::array<Rational, 3>;

std::size_t queries() {
    const char* text = std::getenv("CAVITY_GENERIC_QUERIES");
    return text != nullptr && *text != '\0' ? std::strtoull(text, nullptr, 0) : 2000;
}

Exact exact(const Point3& p) {
    return {Rational(p.x), Rational(p.y), Rational(p.z)};
}

Exact minus(const Exact& u, const Exact& v) {
    return {u[0] - v[0], u[1] - v[1], u[2] - v[2]};
}

Rational det3(const Exact& r, const Exact& s, const Exact& t) {
    return r[0] * (s[1] * t[2] - s[2] * t[1]) - r[1] * (s[0] * t[2] - s[2] * t[0]) +
           r[2] * (s[0] * t[1] - s[1] * t[0]);
}

Rational orient3d_of(const Exact& a, const Exact& b, const Exact& c, const Exact& d) {
    return det3(minus(a, d), minus(b, d), minus(c, d));
}

/// a + t (b - a).
Exact along(const Exact& a, const Exact& b, const Rational& t) {
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

Exact cartesian(const GenericPoint3& g) {
    if (const auto* p = std::get_if<Point3>(&g)) {
        return exact(*p);
    }
    if (const auto* s = std::get_if<SegmentParameterPoint>(&g)) {
        return along(exact(s->a), exact(s->b), Rational(s->numerator) / Rational(s->denominator));
    }
    // orient3d(p, q, r, x) is affine in x, so along the line it is f(a) + t (f(b) - f(a)).
    const auto& l = std::get<LinePlanePoint>(g);
    const Exact p = exact(l.p), q = exact(l.q), r = exact(l.r), a = exact(l.a), b = exact(l.b);
    const Rational fa = orient3d_of(p, q, r, a);
    const Rational fb = orient3d_of(p, q, r, b);
    return along(a, b, fa / (fa - fb));
}

Sign sign_of(const Rational& x) {
    return x > 0 ? Sign::kPos : (x < 0 ? Sign::kNeg : Sign::kZero);
}

Sign oracle_orient3d(const std::array<GenericPoint3, 5>& g) {
    return sign_of(orient3d_of(cartesian(g[0]), cartesian(g[1]), cartesian(g[2]), cartesian(g[3])));
}

Sign oracle_insphere(const std::array<GenericPoint3, 5>& g) {
    const Exact e = cartesian(g[4]);
    std::array<std::array<Rational, 4>, 4> m;
    for (std::size_t i = 0; i < 4; ++i) {
        const Exact d = minus(cartesian(g[i]), e);
        m[i] = {d[0], d[1], d[2], d[0] * d[0] + d[1] * d[1] + d[2] * d[2]};
    }
    // Expansion along the last column.
    Rational det = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        std::array<Exact, 3> rest;
        for (std::size_t k = 0, n = 0; k < 4; ++k) {
            if (k != i) {
                rest[n++] = {m[k][0], m[k][1], m[k][2]};
            }
        }
        const Rational term = m[i][3] * det3(rest[0], rest[1], rest[2]);
        det += (i % 2 == 0) ? -term : term;  // cofactor sign (-1)^(i + 3) for column 3
    }
    return sign_of(det);
}

std::string hex(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%a", v);
    return buffer;
}

std::string describe(const Point3& p) {
    return "(" + hex(p.x) + ", " + hex(p.y) + ", " + hex(p.z) + ")";
}

std::string describe(const GenericPoint3& g) {
    if (const auto* p = std::get_if<Point3>(&g)) {
        return describe(*p);
    }
    if (const auto* s = std::get_if<SegmentParameterPoint>(&g)) {
        return "LNC[" + describe(s->a) + " " + describe(s->b) + " " + hex(s->numerator) + "/" +
               hex(s->denominator) + "]";
    }
    const auto& l = std::get<LinePlanePoint>(g);
    return "LPI[" + describe(l.a) + " " + describe(l.b) + " " + describe(l.p) + " " +
           describe(l.q) + " " + describe(l.r) + "]";
}

/// Counts disagreements with the oracle and the stages, printing the first few queries.
struct Tally {
    std::size_t mismatches = 0;
    std::size_t zeros = 0;
    std::size_t exact_stage = 0;

    void check(Verdict v, Sign expected, const std::array<GenericPoint3, 5>& g, std::size_t n) {
        zeros += expected == Sign::kZero ? 1 : 0;
        exact_stage += v.stage == Stage::kExact ? 1 : 0;
        if (v.sign != expected && ++mismatches <= 3) {
            std::string text;
            for (std::size_t i = 0; i < n; ++i) {
                text += describe(g[i]) + "\n";
            }
            ADD_FAILURE() << "got " << to_int(v.sign) << ", oracle " << to_int(expected) << "\n"
                          << text;
        }
    }
};

using Source = testing::RandomSource;

/// A random generic point of the given kind (0 explicit, 1 on a segment, 2 line-plane).
GenericPoint3 random_generic(Source& s, int kind, int lo, int hi) {
    if (kind == 1) {
        double den = s.unit();
        den = den == 0.0 ? 1.0 : den;
        return SegmentParameterPoint{s.point(lo, hi), s.point(lo, hi), s.unit(), den};
    }
    if (kind == 2) {
        for (;;) {
            if (auto l = line_plane_point(s.point(lo, hi),
                                          s.point(lo, hi),
                                          s.point(lo, hi),
                                          s.point(lo, hi),
                                          s.point(lo, hi))) {
                return *l;
            }
        }
    }
    return s.point(lo, hi);
}

struct Range {
    int lo;
    int hi;
};

/// Runs `check` on random mixes of five points, each made by `draw(s, band)`, for each exponent
/// band in turn: tiny, unit, huge, the whole double range and a moderate one; `rounded_edges` adds
/// the bands around 2^-150 and 2^150 that bracket the rounded stage's range (generic_filter.h).
template <class Draw, class Check>
void for_random_mixes(Source& s, bool rounded_edges, Draw draw, Check check) {
    std::vector<Range> bands{Range{-1074, -1000}};
    if (rounded_edges) {
        bands.push_back(Range{-160, -140});
    }
    bands.push_back(Range{-2, 2});
    if (rounded_edges) {
        bands.push_back(Range{140, 160});
    }
    bands.insert(bands.end(), {Range{900, 1023}, Range{-1074, 1023}, Range{-40, 40}});
    for (const Range r : bands) {
        // The whole range makes the oracle's rationals thousands of bits long: fewer queries.
        const std::size_t count = r.hi - r.lo > 1000 ? queries() / 8 : queries();
        for (std::size_t n = 0; n < count; ++n) {
            std::array<GenericPoint3, 5> g;
            for (auto& p : g) {
                p = draw(s, r);
            }
            check(g);
        }
    }
}

/// Random mixes: every point explicit or implicit at random, coordinates 2^k [-1, 1) with k in
/// one narrow band (tiny, unit, huge) or spread over the whole double range.
TEST(GenericPredicates, AgreeWithTheOracleOnRandomMixes) {
    Source s(15);
    Tally orient, sphere;
    for_random_mixes(
        s,
        /*rounded_edges=*/false,
        [](Source& t, Range r) { return random_generic(t, t.integer(0, 2), r.lo, r.hi); },
        [&](const std::array<GenericPoint3, 5>& g) {
            orient.check(orient3d_staged(g[0], g[1], g[2], g[3]), oracle_orient3d(g), g, 4);
            sphere.check(insphere_staged(g[0], g[1], g[2], g[3], g[4]), oracle_insphere(g), g, 5);
        });
    EXPECT_EQ(orient.mismatches, 0u);
    EXPECT_EQ(sphere.mismatches, 0u);
}

/// The filter decides random general-position queries on its own (it is not merely sound), also
/// far from the origin: unit-range points 2^-10 apart offset by about 10^6, where determinants of
/// the raw coordinates would cancel 16 orders of magnitude.
TEST(GenericPredicates, FilterDecidesGeneralPositionQueries) {
    Source s(16);
    for (const double offset : {0.0, 1048576.0 + 0.375}) {
        Tally orient, sphere;
        const auto moved = [&](Point3 p) {
            return Point3{offset + std::ldexp(p.x, -10),
                          offset + std::ldexp(p.y, -10),
                          offset + std::ldexp(p.z, -10)};
        };
        for (std::size_t n = 0; n < queries(); ++n) {
            std::array<GenericPoint3, 5> g;
            for (auto& p : g) {
                const int kind = s.integer(0, 2);
                if (kind == 0) {
                    p = moved(s.point(-2, 2));
                } else if (kind == 1) {
                    p = SegmentParameterPoint{
                        moved(s.point(-2, 2)), moved(s.point(-2, 2)), s.unit(), 1.0};
                } else {
                    std::optional<LinePlanePoint> l;
                    while (!l) {
                        l = line_plane_point(moved(s.point(-2, 2)),
                                             moved(s.point(-2, 2)),
                                             moved(s.point(-2, 2)),
                                             moved(s.point(-2, 2)),
                                             moved(s.point(-2, 2)));
                    }
                    p = *l;
                }
            }
            orient.check(orient3d_staged(g[0], g[1], g[2], g[3]), oracle_orient3d(g), g, 4);
            sphere.check(insphere_staged(g[0], g[1], g[2], g[3], g[4]), oracle_insphere(g), g, 5);
        }
        std::printf("offset %g: exact stage orient3d %zu, insphere %zu of %zu\n",
                    offset,
                    orient.exact_stage,
                    sphere.exact_stage,
                    queries());
        EXPECT_EQ(orient.mismatches, 0u);
        EXPECT_EQ(sphere.mismatches, 0u);
        EXPECT_LT(orient.exact_stage * 20, queries());
        EXPECT_LT(sphere.exact_stage * 20, queries());
    }
}

/// A configuration with an exact degeneracy: implicit points exactly on the plane of three
/// explicit points (orient3d = 0) or on the sphere through four (insphere = 0), built from small
/// integers times 2^scale plus an exactly representable offset.
struct Degenerate {
    std::array<GenericPoint3, 5> coplanar;
    std::array<GenericPoint3, 5> cospherical;
};

Degenerate degenerate(Source& s, int scale) {
    const auto at = [&](int x, int y, int z) {
        return Point3{std::ldexp(x, scale), std::ldexp(y, scale), std::ldexp(z, scale)};
    };
    const auto random_at = [&] {
        return at(s.integer(-50, 50), s.integer(-50, 50), s.integer(-50, 50));
    };
    Degenerate d;
    // Plane pqr; two line-plane points on it and a segment point on a segment inside it.
    const Point3 p = random_at(), q = random_at(), r = random_at();
    const auto on_plane = [&]() -> GenericPoint3 {
        for (;;) {
            if (auto l = line_plane_point(random_at(), random_at(), p, q, r)) {
                return *l;
            }
        }
    };
    const GenericPoint3 l1 = on_plane();
    const GenericPoint3 l2 = on_plane();
    // A segment between two points of the plane, at an odd parameter.
    const Point3 u{p.x + (q.x - p.x) * 2 + (r.x - p.x) * 3,
                   p.y + (q.y - p.y) * 2 + (r.y - p.y) * 3,
                   p.z + (q.z - p.z) * 2 + (r.z - p.z) * 3};
    const GenericPoint3 m =
        SegmentParameterPoint{p, u, double(s.integer(-7, 7)), 3.0 + s.integer(0, 1) * -6.0};
    d.coplanar = {p, l1, m, l2, random_at()};
    if (s.integer(0, 1) == 0) {
        std::swap(d.coplanar[0], d.coplanar[3]);
    }
    // Sphere through corners of the cube [0, 2]^3 (centre (1, 1, 1)); an implicit point at another
    // corner: on a segment through it, or where a line through it meets a face plane of the cube.
    const int cx = 2 * s.integer(0, 1), cy = 2 * s.integer(0, 1), cz = 2 * s.integer(0, 1);
    const int dx = s.integer(1, 5) * (s.integer(0, 1) == 0 ? 1 : -1);
    const int dy = s.integer(-5, 5), dz = s.integer(-5, 5);
    GenericPoint3 implicit;
    if (s.integer(0, 1) == 0) {
        // corner = a + (1/4)(b - a) with a = corner - d, b = corner + 3d.
        implicit = SegmentParameterPoint{
            at(cx - dx, cy - dy, cz - dz), at(cx + 3 * dx, cy + 3 * dy, cz + 3 * dz), -1.0, -4.0};
    } else {
        // The plane x = cx through three points of it; the line through the corner crosses it
        // there (dx != 0).
        implicit = *line_plane_point(at(cx - dx, cy - dy, cz - dz),
                                     at(cx + 2 * dx, cy + 2 * dy, cz + 2 * dz),
                                     at(cx, 0, 0),
                                     at(cx, 2, 0),
                                     at(cx, 0, 2));
    }
    d.cospherical = {at(2 - cx, cy, cz),
                     at(cx, 2 - cy, cz),
                     at(cx, cy, 2 - cz),
                     at(2 - cx, 2 - cy, 2 - cz),
                     implicit};
    if (s.integer(0, 1) == 0) {
        std::swap(d.cospherical[1], d.cospherical[4]);
    }
    return d;
}

TEST(GenericPredicates, ExactZerosOnDegenerateConfigurations) {
    Source s(1515);
    Tally orient, sphere;
    for (const int scale : {-1070, -500, -30, 0, 30, 500, 960}) {
        for (std::size_t n = 0; n < queries() / 4; ++n) {
            const Degenerate d = degenerate(s, scale);
            const auto& c = d.coplanar;
            orient.check(orient3d_staged(c[0], c[1], c[2], c[3]), oracle_orient3d(c), c, 4);
            const auto& e = d.cospherical;
            sphere.check(insphere_staged(e[0], e[1], e[2], e[3], e[4]), oracle_insphere(e), e, 5);
        }
    }
    EXPECT_EQ(orient.mismatches, 0u);
    EXPECT_EQ(sphere.mismatches, 0u);
    // Every coplanar query is a zero; cospherical ones too, unless the swap put a flat tetrahedron
    // first, which the oracle counts as well.
    EXPECT_EQ(orient.zeros, 7 * (queries() / 4));
    EXPECT_EQ(orient.exact_stage, orient.zeros);
    EXPECT_GT(sphere.zeros, 0u);
}

/// Moves one defining double of `target` (a random coordinate of a random defining point) by
/// 1-4 ulps.
void nudge_defining_double(Source& s, GenericPoint3& target) {
    Point3* p = std::get_if<Point3>(&target);
    if (auto* seg = std::get_if<SegmentParameterPoint>(&target)) {
        p = s.integer(0, 1) == 0 ? &seg->a : &seg->b;
    } else if (auto* l = std::get_if<LinePlanePoint>(&target)) {
        p = std::array<Point3*, 5>{&l->a, &l->b, &l->p, &l->q, &l->r}[s.integer(0, 4)];
    }
    double& v = std::array<double*, 3>{&p->x, &p->y, &p->z}[s.integer(0, 2)][0];
    v = s.nudged(v);
}

/// The degenerate configurations with one defining double moved by 1-4 ulps: nonzero, tiny
/// determinants that the filter must leave to the exact stage.
TEST(GenericPredicates, AgreeWithTheOracleNearDegeneracies) {
    Source s(151515);
    Tally orient, sphere;
    const auto nudge = [&](std::array<GenericPoint3, 5>& g) {
        nudge_defining_double(s, g[static_cast<std::size_t>(s.integer(0, 4))]);
    };
    for (const int scale : {-1070, -30, 0, 30, 960}) {
        for (std::size_t n = 0; n < queries() / 4; ++n) {
            Degenerate d = degenerate(s, scale);
            nudge(d.coplanar);
            nudge(d.cospherical);
            auto& c = d.coplanar;
            // A nudged line-plane point may have lost its intersection; skip those.
            const auto defined = [](const std::array<GenericPoint3, 5>& g) {
                for (const auto& x : g) {
                    if (const auto* l = std::get_if<LinePlanePoint>(&x)) {
                        if (!line_plane_point(l->a, l->b, l->p, l->q, l->r)) {
                            return false;
                        }
                    }
                }
                return true;
            };
            if (defined(c)) {
                orient.check(orient3d_staged(c[0], c[1], c[2], c[3]), oracle_orient3d(c), c, 4);
            }
            auto& e = d.cospherical;
            if (defined(e)) {
                sphere.check(
                    insphere_staged(e[0], e[1], e[2], e[3], e[4]), oracle_insphere(e), e, 5);
            }
        }
    }
    EXPECT_EQ(orient.mismatches, 0u);
    EXPECT_EQ(sphere.mismatches, 0u);
}

/// The scaled integers (scaled_integers.h) on generic queries: the cospherical configurations
/// through a segment point at parameter 1/4, as given and nudged, and random mixes of explicit
/// points and segment points at dyadic parameters (k / 2^j, |k| <= 2^20, j < 48) in a moderate
/// exponent band. Wherever they answer they agree with the oracle, and they answer most of these;
/// line-plane points and non-dyadic parameters they leave to the GMP stage.
TEST(GenericPredicates, ScaledIntegersAgreeWithTheOracle) {
    Source s(424242);
    std::size_t asked = 0, answered = 0, zeros = 0, mismatches = 0;
    const auto check = [&](const std::array<GenericPoint3, 5>& g) {
        const std::array<const GenericPoint3*, 5> p{&g[0], &g[1], &g[2], &g[3], &g[4]};
        const std::optional<Sign> v = detail::insphere_scaled_integers(p);
        ++asked;
        const bool eligible = std::none_of(g.begin(), g.end(), [](const GenericPoint3& x) {
            return std::holds_alternative<LinePlanePoint>(x);
        });
        if (!eligible) {
            EXPECT_FALSE(v.has_value());
            return;
        }
        if (!v) {
            return;
        }
        ++answered;
        const Sign expected = oracle_insphere(g);
        zeros += expected == Sign::kZero ? 1 : 0;
        if (*v != expected && ++mismatches <= 3) {
            std::string text;
            for (const GenericPoint3& x : g) {
                text += describe(x) + "\n";
            }
            ADD_FAILURE() << "scaled integers " << to_int(*v) << ", oracle " << to_int(expected)
                          << "\n"
                          << text;
        }
    };
    for (const int scale : {-1070, -30, 0, 30, 960}) {
        for (std::size_t n = 0; n < queries() / 4; ++n) {
            Degenerate d = degenerate(s, scale);
            check(d.cospherical);
            nudge_defining_double(s, d.cospherical[static_cast<std::size_t>(s.integer(0, 4))]);
            check(d.cospherical);
        }
    }
    const std::size_t degenerate_asked = asked;
    const std::size_t degenerate_zeros = zeros;
    for (std::size_t n = 0; n < queries(); ++n) {
        std::array<GenericPoint3, 5> g;
        for (auto& x : g) {
            if (s.integer(0, 1) == 0) {
                x = s.point(-3, 3);
            } else {
                x = SegmentParameterPoint{
                    s.point(-3, 3),
                    s.point(-3, 3),
                    double(s.integer(-(1 << 20), 1 << 20)),
                    std::ldexp(s.integer(0, 1) == 0 ? 1.0 : -1.0, s.integer(0, 47))};
            }
        }
        check(g);
    }
    EXPECT_EQ(mismatches, 0u);
    // Not vacuous: the exact zeros are answered (a half of the configurations has a segment
    // point, the other a line-plane point), and most random mixes too.
    EXPECT_GT(degenerate_zeros, degenerate_asked / 8);
    EXPECT_GT(answered, degenerate_asked / 4 + queries() / 2);
}

/// The scaled integers at the edge of their range: defining doubles from {+-(2^53 - 1) 2^8, 2^60,
/// +-1, 0} (bits 0 to 60, the widest span accepted) and segment points between them at parameters
/// k / 2^62 with k odd, so that the explicit coordinates are shifted by 62 bits to below 2^123 and
/// the differences reach 2^124: the determinant's terms run as close to their widths as any
/// accepted query's.
TEST(GenericPredicates, ScaledIntegersAtTheEdgeOfTheirRange) {
    Source s(434343);
    const double top = std::ldexp(0x1.fffffffffffffp52, 8);
    const std::array<double, 7> values = {top, -top, 0x1p60, 1, -1, 0, top / 2};
    const auto any_point = [&] {
        return Point3{values[static_cast<std::size_t>(s.integer(0, 6))],
                      values[static_cast<std::size_t>(s.integer(0, 6))],
                      values[static_cast<std::size_t>(s.integer(0, 6))]};
    };
    std::size_t answered = 0, mismatches = 0;
    std::array<std::size_t, 3> signs{};
    for (int n = 0; n < 4000; ++n) {
        std::array<GenericPoint3, 5> g;
        for (auto& x : g) {
            if (s.integer(0, 2) == 0) {
                x = any_point();
            } else {
                x = SegmentParameterPoint{any_point(),
                                          any_point(),
                                          double(2 * s.integer(-(1 << 19), 1 << 19) + 1),
                                          0x1p62};
            }
        }
        const std::array<const GenericPoint3*, 5> p{&g[0], &g[1], &g[2], &g[3], &g[4]};
        const std::optional<Sign> v = detail::insphere_scaled_integers(p);
        if (!v) {
            continue;
        }
        ++answered;
        const Sign expected = oracle_insphere(g);
        ++signs[static_cast<std::size_t>(to_int(expected) + 1)];
        if (*v != expected && ++mismatches <= 3) {
            ADD_FAILURE() << "scaled integers " << to_int(*v) << ", oracle " << to_int(expected);
        }
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(answered, 4000u);
    EXPECT_GT(signs[0], 500u);
    EXPECT_GT(signs[2], 500u);
}

/// Queries that the structural certificate (coplanarity_certificate.h) must prove zero, or must
/// leave alone once moved: points on the plane of three random points, or on one line. Explicit
/// points of the plane, segment points between them, line-plane points on it through a line
/// crossing it (their plane another triple of it, so the certificate matches it through orient3d)
/// or through a line inside it (their plane a random one); on a line the same kinds. Every
/// result against the oracle, as given and with one defining double moved by 1-4 ulps.
TEST(GenericPredicates, CoplanarAndCollinearMixesAgreeWithTheOracle) {
    Source s(2323);
    Tally orient, sphere, moved;
    std::size_t uncertified = 0;
    std::size_t unsound = 0;
    for (const int scale : {-1070, -30, 0, 30, 960}) {
        const auto at = [&](int x, int y, int z) {
            return Point3{std::ldexp(x, scale), std::ldexp(y, scale), std::ldexp(z, scale)};
        };
        const auto random_at = [&] {
            return at(s.integer(-50, 50), s.integer(-50, 50), s.integer(-50, 50));
        };
        for (std::size_t n = 0; n < queries() / 4; ++n) {
            const bool on_line = s.integer(0, 3) == 0;
            const Point3 p = random_at(), q = random_at(), r = random_at();
            // p + i (q - p) + j (r - p): exact for these small integers; j = 0 on a line.
            const auto inside = [&] {
                const int i = s.integer(-3, 3), j = on_line ? 0 : s.integer(-3, 3);
                return Point3{p.x + (q.x - p.x) * i + (r.x - p.x) * j,
                              p.y + (q.y - p.y) * i + (r.y - p.y) * j,
                              p.z + (q.z - p.z) * i + (r.z - p.z) * j};
            };
            const auto point = [&]() -> GenericPoint3 {
                for (;;) {
                    switch (s.integer(0, 3)) {
                        case 0:
                            return inside();
                        case 1:
                            return SegmentParameterPoint{
                                inside(), inside(), double(s.integer(-9, 9)), 8.0};
                        case 2:
                            if (on_line) {
                                continue;  // a line crossing a line meets it nowhere in general
                            }
                            if (auto l = line_plane_point(
                                    random_at(), random_at(), inside(), inside(), inside())) {
                                return *l;
                            }
                            break;
                        default:
                            if (auto l = line_plane_point(
                                    inside(), inside(), random_at(), random_at(), random_at())) {
                                return *l;
                            }
                            break;
                    }
                }
            };
            std::array<GenericPoint3, 5> g;
            for (auto& x : g) {
                x = point();
            }
            // The certificate proves these zeros itself, without the integers.
            const std::array<const GenericPoint3*, 5> all{&g[0], &g[1], &g[2], &g[3], &g[4]};
            uncertified += detail::certified_coplanar(all) ? 0 : 1;
            orient.check(orient3d_staged(g[0], g[1], g[2], g[3]), oracle_orient3d(g), g, 4);
            sphere.check(insphere_staged(g[0], g[1], g[2], g[3], g[4]), oracle_insphere(g), g, 5);
            // One defining double moved: mostly off the plane, a tiny nonzero determinant.
            GenericPoint3& target = g[static_cast<std::size_t>(s.integer(0, 3))];
            nudge_defining_double(s, target);
            if (const auto* l = std::get_if<LinePlanePoint>(&target);
                l != nullptr && !line_plane_point(l->a, l->b, l->p, l->q, l->r)) {
                continue;  // the move lost the intersection: no point for the oracle
            }
            const Sign expected = oracle_orient3d(g);
            moved.check(orient3d_staged(g[0], g[1], g[2], g[3]), expected, g, 4);
            const std::array<const GenericPoint3*, 4> four{&g[0], &g[1], &g[2], &g[3]};
            unsound += detail::certified_coplanar(four) && expected != Sign::kZero ? 1 : 0;
        }
    }
    EXPECT_EQ(uncertified, 0u);
    EXPECT_EQ(unsound, 0u);
    EXPECT_EQ(orient.mismatches, 0u);
    EXPECT_EQ(sphere.mismatches, 0u);
    EXPECT_EQ(moved.mismatches, 0u);
    // Every unmoved query is flat: orient3d of four and insphere of five coplanar points are 0.
    EXPECT_EQ(orient.zeros, 5 * (queries() / 4));
    EXPECT_EQ(sphere.zeros, 5 * (queries() / 4));
}

/// The sign of W never matters: the same point with W negated (the parameter's numerator and
/// denominator negated, or the line-plane segment reversed) gives the same signs.
TEST(GenericPredicates, NegativeHomogeneousWeightIsNormalised) {
    Source s(7);
    for (std::size_t n = 0; n < queries(); ++n) {
        const Point3 a = s.point(-3, 3), b = s.point(-3, 3);
        const double num = s.unit();
        const double den = std::ldexp(1.0 + s.unit(), s.integer(-3, 3));  // nonzero
        const GenericPoint3 lnc = SegmentParameterPoint{a, b, num, den};
        const GenericPoint3 lnc_negated = SegmentParameterPoint{a, b, -num, -den};
        const Point3 p = s.point(-3, 3), q = s.point(-3, 3), r = s.point(-3, 3);
        const auto lpi = line_plane_point(a, b, p, q, r);
        const auto lpi_reversed = line_plane_point(b, a, p, q, r);
        ASSERT_TRUE(lpi && lpi_reversed);
        const Point3 c = s.point(-3, 3), d = s.point(-3, 3), e = s.point(-3, 3);
        EXPECT_EQ(orient3d(c, d, e, lnc), orient3d(c, d, e, lnc_negated));
        EXPECT_EQ(orient3d(c, lnc, e, GenericPoint3(*lpi)),
                  orient3d(c, lnc_negated, e, GenericPoint3(*lpi_reversed)));
        EXPECT_EQ(insphere(c, d, lnc, e, GenericPoint3(*lpi)),
                  insphere(c, d, lnc_negated, e, GenericPoint3(*lpi_reversed)));
    }
}

/// An implicit point whose coordinates happen to be doubles agrees with the explicit predicates
/// on those doubles.
TEST(GenericPredicates, AgreeWithTheExplicitPredicatesOnDoublePoints) {
    Source s(77);
    for (std::size_t n = 0; n < queries(); ++n) {
        const auto small = [&] {
            return Point3{double(s.integer(-1000, 1000)),
                          double(s.integer(-1000, 1000)),
                          double(s.integer(-1000, 1000))};
        };
        const Point3 a = small(), b = small();
        // The midpoint of integers is a multiple of 1/2: a double.
        const GenericPoint3 mid = SegmentParameterPoint{a, b, 1.0, 2.0};
        const Point3 mid_doubles{(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2};
        const Point3 c = small(), d = small(), e = small(), f = small();
        EXPECT_EQ(orient3d(c, d, e, mid), orient3d(c, d, e, mid_doubles));
        EXPECT_EQ(insphere(c, d, mid, e, GenericPoint3(f)), insphere(c, d, mid_doubles, e, f));
    }
}

/// A line-plane point whose line is nearly parallel to its plane (the direction leaves the plane
/// by about 2^-tilt of its length): W is tiny against its terms, so the rounded point is the
/// least accurate the construction makes.
GenericPoint3 grazing_line_plane_point(Source& s, int lo, int hi, int tilt) {
    for (;;) {
        const Point3 p = s.point(lo, hi), q = s.point(lo, hi), r = s.point(lo, hi);
        const Point3 a = s.point(lo, hi);
        const double k = s.unit(), j = s.unit(), eps = std::ldexp(s.unit(), -tilt);
        // a + k (q - p) + j (r - p) stays in the plane's direction; eps (a - p) leaves it.
        const Point3 b{a.x + k * (q.x - p.x) + j * (r.x - p.x) + eps * (a.x - p.x),
                       a.y + k * (q.y - p.y) + j * (r.y - p.y) + eps * (a.y - p.y),
                       a.z + k * (q.z - p.z) + j * (r.z - p.z) + eps * (a.z - p.z)};
        if (auto l = line_plane_point(a, b, p, q, r)) {
            return *l;
        }
    }
}

/// The doubles nearest to g's coordinates (as Boost converts), moved by up to three ulps each
/// half of the time: the rounded point a caller may hold.
Point3 rounded_near(Source& s, const GenericPoint3& g) {
    const Exact x = cartesian(g);
    Point3 r{x[0].convert_to<double>(), x[1].convert_to<double>(), x[2].convert_to<double>()};
    if (s.integer(0, 1) == 0) {
        for (double* v : {&r.x, &r.y, &r.z}) {
            for (int k = s.integer(0, 3); k > 0; --k) {
                *v = s.nudged(*v);
            }
        }
    }
    return r;
}

/// The floating-point stage (generic_filter.h) against the oracle: when it answers, the oracle
/// agrees, and rounding_error bounds the distance from each point to its doubles.
struct RoundedTally {
    std::size_t mismatches = 0;
    std::size_t decided = 0;
    std::size_t queries = 0;
    std::size_t loose_bounds = 0;  // rounding_error below the true distance: must stay 0

    RoundedPoint rounded(Source& s, const GenericPoint3& g) {
        const Point3 r = rounded_near(s, g);
        const double error = rounding_error(g, r);
        if (std::isfinite(error)) {
            const Exact x = cartesian(g);
            const Rational bound(error);
            for (std::size_t i = 0; i < 3; ++i) {
                const Rational distance = abs(x[i] - Rational(std::array{r.x, r.y, r.z}[i]));
                if (distance > bound && ++loose_bounds <= 3) {
                    ADD_FAILURE() << "rounding_error " << hex(error) << " below the distance of "
                                  << describe(g) << " to " << describe(r);
                }
            }
        }
        return {r, error};
    }

    void check(int sign, Sign expected, const std::array<GenericPoint3, 5>& g, std::size_t n) {
        ++queries;
        if (sign == 0) {
            return;
        }
        ++decided;
        if (sign != to_int(expected) && ++mismatches <= 3) {
            std::string text;
            for (std::size_t i = 0; i < n; ++i) {
                text += describe(g[i]) + "\n";
            }
            ADD_FAILURE() << "rounded stage " << sign << ", oracle " << to_int(expected) << "\n"
                          << text;
        }
    }

    void run(Source& s, const std::array<GenericPoint3, 5>& g) {
        std::array<RoundedPoint, 5> r;
        for (std::size_t i = 0; i < 5; ++i) {
            r[i] = rounded(s, g[i]);
        }
        check(orient3d_rounded(r[0], r[1], r[2], r[3]), oracle_orient3d(g), g, 4);
        check(insphere_rounded(r[0], r[1], r[2], r[3], r[4]), oracle_insphere(g), g, 5);
    }
};

TEST(GenericPredicates, RoundedStageAgreesWithTheOracleOnRandomMixes) {
    Source s(25);
    RoundedTally tally;
    for_random_mixes(
        s,
        /*rounded_edges=*/true,
        [](Source& t, Range r) {
            const int kind = t.integer(0, 3);
            return kind == 3 ? grazing_line_plane_point(t, r.lo, r.hi, t.integer(10, 60))
                             : random_generic(t, kind, r.lo, r.hi);
        },
        [&](const std::array<GenericPoint3, 5>& g) { tally.run(s, g); });
    EXPECT_EQ(tally.mismatches, 0u);
    EXPECT_EQ(tally.loose_bounds, 0u);
}

/// General position, near the origin and offset by about 10^6, with line-plane points on lines
/// from steep to grazing: the stage must decide most of these queries on its own, and never
/// wrongly.
TEST(GenericPredicates, RoundedStageDecidesGeneralPositionQueries) {
    Source s(26);
    for (const double offset : {0.0, 1048576.0 + 0.375}) {
        RoundedTally tally;
        RoundedTally grazing;
        const auto moved = [&](const GenericPoint3& g) {
            GenericPoint3 m = g;
            const auto shift = [&](Point3& p) {
                p = {offset + std::ldexp(p.x, -10),
                     offset + std::ldexp(p.y, -10),
                     offset + std::ldexp(p.z, -10)};
            };
            if (auto* p = std::get_if<Point3>(&m)) {
                shift(*p);
            } else if (auto* q = std::get_if<SegmentParameterPoint>(&m)) {
                shift(q->a);
                shift(q->b);
            } else {
                auto& l = std::get<LinePlanePoint>(m);
                for (Point3* x : {&l.a, &l.b, &l.p, &l.q, &l.r}) {
                    shift(*x);
                }
            }
            return m;
        };
        for (std::size_t n = 0; n < queries(); ++n) {
            std::array<GenericPoint3, 5> g;
            for (auto& p : g) {
                p = moved(random_generic(s, s.integer(0, 2), -2, 2));
            }
            tally.run(s, g);
            // A grazing point, exactly a line-plane point of the moved definition when it is one.
            const GenericPoint3 graze = moved(grazing_line_plane_point(s, -2, 2, s.integer(4, 40)));
            if (const auto* l = std::get_if<LinePlanePoint>(&graze);
                l != nullptr && line_plane_point(l->a, l->b, l->p, l->q, l->r)) {
                g[static_cast<std::size_t>(s.integer(0, 4))] = graze;
                grazing.run(s, g);
            }
        }
        std::printf(
            "offset %g: rounded stage decided %zu of %zu, with a grazing point %zu of %zu\n",
            offset,
            tally.decided,
            tally.queries,
            grazing.decided,
            grazing.queries);
        EXPECT_EQ(tally.mismatches + grazing.mismatches, 0u);
        EXPECT_EQ(tally.loose_bounds + grazing.loose_bounds, 0u);
        EXPECT_GT(tally.decided * 10, tally.queries * 9);
    }
}

/// The exact and nudged degeneracies: the stage may answer only nonzero signs, and only right.
TEST(GenericPredicates, RoundedStageAgreesWithTheOracleNearDegeneracies) {
    Source s(27);
    RoundedTally tally;
    for (const int scale : {-1070, -150, -30, 0, 30, 150, 960}) {
        for (std::size_t n = 0; n < queries() / 4; ++n) {
            Degenerate d = degenerate(s, scale);
            tally.run(s, d.coplanar);
            tally.run(s, d.cospherical);
            for (auto* g : {&d.coplanar, &d.cospherical}) {
                Point3* p = std::get_if<Point3>(&(*g)[static_cast<std::size_t>(s.integer(0, 4))]);
                if (p != nullptr) {
                    p->x = s.nudged(p->x);
                    tally.run(s, *g);
                }
            }
        }
    }
    EXPECT_EQ(tally.mismatches, 0u);
    EXPECT_EQ(tally.loose_bounds, 0u);
}

/// The point translated_rounded made against the exact translated point: true when the bound
/// covers the distance in every coordinate.
bool translated_bound_holds(const GenericPoint3& g, const Point3& o, const RoundedPoint& r) {
    const Exact x = minus(cartesian(g), exact(o));
    const Rational bound(r.error);
    const std::array<double, 3> doubles{r.p.x, r.p.y, r.p.z};
    for (std::size_t i = 0; i < 3; ++i) {
        if (abs(x[i] - Rational(doubles[i])) > bound) {
            ADD_FAILURE() << "translated_rounded's bound " << hex(r.error) << " is below the "
                          << "distance of " << describe(g) << " translated by " << describe(o);
            return false;
        }
    }
    return true;
}

/// translated_rounded (the predicates' first stage) bounds its distance on random explicit points
/// and segment points of every exponent band, translated to one of their defining points or to an
/// unrelated point, with the parameters the CDT makes (dyadic) and random ones.
TEST(GenericPredicates, TranslatedRoundingBoundsTheDistance) {
    Source s(31);
    std::size_t checked = 0;
    for_random_mixes(
        s,
        /*rounded_edges=*/true,
        [](Source& t, Range r) -> GenericPoint3 {
            if (t.integer(0, 2) == 0) {
                const int j = t.integer(1, 53);  // the CDT's n / 2^j, n odd below 2^j
                const double n =
                    std::ldexp(std::floor(std::ldexp(std::abs(t.unit()), j - 1)), 1) + 1;
                return SegmentParameterPoint{
                    t.point(r.lo, r.hi), t.point(r.lo, r.hi), n, std::ldexp(1.0, j)};
            }
            return random_generic(t, t.integer(0, 1), r.lo, r.hi);
        },
        [&](const std::array<GenericPoint3, 5>& g) {
            // As the predicates translate: to a point that defines one of the query's points.
            const auto* spp = std::get_if<SegmentParameterPoint>(&g[1]);
            const Point3 o = spp != nullptr ? spp->b : std::get<Point3>(g[1]);
            for (const GenericPoint3& p : g) {
                for (const Point3& origin : {o, Point3{}}) {
                    if (const auto r = translated_rounded(p, origin)) {
                        if (std::isfinite(r->error)) {
                            ++checked;
                            EXPECT_TRUE(translated_bound_holds(p, origin, *r));
                        }
                    }
                }
            }
        });
    EXPECT_GT(checked, queries());
}

/// Parameters at the edges of the doubles: zero (exact), underflowing (no direct rounding),
/// overflowing and differences that overflow (an infinite bound, never a wrong one), and the bound
/// is tight where nothing is extreme.
TEST(GenericPredicates, TranslatedRoundingAtExtremeParameters) {
    const Point3 a{0.3, -0.7, 0.1}, b{0.9, 0.2, -0.4}, o{0.1, 0.1, 0.1};
    const auto zero = translated_rounded(SegmentParameterPoint{a, b, 0.0, 3.0}, o);
    ASSERT_TRUE(zero);
    EXPECT_TRUE(translated_bound_holds(SegmentParameterPoint{a, b, 0.0, 3.0}, o, *zero));
    EXPECT_FALSE(translated_rounded(SegmentParameterPoint{a, b, 0x1p-1074, 0x1p100}, o));
    EXPECT_FALSE(translated_rounded(SegmentParameterPoint{a, b, 0x1p-600, 0x1p500}, o));
    EXPECT_FALSE(translated_rounded(LinePlanePoint{a, b, o, Point3{1, 0, 0}, Point3{0, 1, 0}}, o));
    const double huge = std::numeric_limits<double>::max();
    for (const GenericPoint3& g :
         {GenericPoint3(SegmentParameterPoint{a, b, huge, 0x1p-10}),
          GenericPoint3(SegmentParameterPoint{Point3{-huge, 0, 0}, Point3{huge, 1, 1}, 1.0, 3.0}),
          GenericPoint3(Point3{-huge, 0, 0})}) {
        const auto r = translated_rounded(g, Point3{huge, 0, 0});
        ASSERT_TRUE(r);
        EXPECT_FALSE(std::isfinite(r->error) && std::isfinite(r->p.x) && std::isfinite(r->p.y) &&
                     std::isfinite(r->p.z));
    }
    // A third of the way along a unit segment: within a few ulps of the exact point.
    const GenericPoint3 third = SegmentParameterPoint{a, b, 1.0, 3.0};
    const auto r = translated_rounded(third, o);
    ASSERT_TRUE(r);
    EXPECT_TRUE(translated_bound_holds(third, o, *r));
    EXPECT_LT(r->error, 0x1p-48);
}

TEST(GenericPredicates, RoundingErrorIsZeroOnlyForTheExactDoubles) {
    const Point3 a{1, 2, 3}, b{2, 2, 3};
    EXPECT_EQ(rounding_error(GenericPoint3(a), a), 0.0);
    EXPECT_GT(rounding_error(GenericPoint3(a), b), 0.0);
    // The third of the way from a to b is not a double: a positive bound, and a small one.
    const GenericPoint3 third = SegmentParameterPoint{a, b, 1.0, 3.0};
    const double error = rounding_error(third, Point3{1.0 + 1.0 / 3.0, 2, 3});
    EXPECT_GT(error, 0.0);
    EXPECT_LT(error, 0x1p-48);
    EXPECT_EQ(rounding_error(third, Point3{std::numeric_limits<double>::infinity(), 2, 3}),
              std::numeric_limits<double>::infinity());
}

TEST(GenericPredicates, UndefinedPointsAreRefused) {
    const Point3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    // The line along x is parallel to the plane z = 0 shifted up; the plane through o, x, 2x is
    // no plane.
    EXPECT_FALSE(line_plane_point(z, Point3{1, 0, 1}, o, x, y));
    EXPECT_FALSE(line_plane_point(o, z, o, x, Point3{2, 0, 0}));
    EXPECT_TRUE(line_plane_point(o, z, o, x, y));
    EXPECT_FALSE(segment_parameter_point(o, x, 1.0, 0.0));
    EXPECT_FALSE(segment_parameter_point(o, x, std::numeric_limits<double>::infinity(), 1.0));
    EXPECT_TRUE(segment_parameter_point(o, x, 1.0, 3.0));
}

}  // namespace
}  // namespace cavity::predicates
