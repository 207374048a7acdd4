// The static orient3d and insphere filters (orient3d_static_filter.h, insphere_static_filter.h)
// against the exact oracle: whenever one answers, its sign is the exact one. Each query gets the
// tightest box around its own points
// (the smallest bound the filter can have for it, so the hardest case), or that box widened on one
// side; the families are those of the agreement tests (random, degenerate, near-degenerate,
// extreme magnitudes, subnormal spacing included). CAVITY_ORACLE_QUERIES sets the number of
// queries per family (default 10^5 shared by the families, as in agreement_test.cpp).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>

#include <gtest/gtest.h>

#include "cavity/predicates/insphere.h"
#include "cavity/predicates/insphere_static_filter.h"
#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient3d_static_filter.h"
#include "query.h"
#include "query_generators.h"

namespace cavity::predicates::testing {

namespace {

std::size_t queries_per_family() {
    const char* text = std::getenv("CAVITY_ORACLE_QUERIES");
    const std::uint64_t total =
        text != nullptr && *text != '\0' ? std::strtoull(text, nullptr, 0) : 100'000;
    return static_cast<std::size_t>((total + 3) / 4);
}

template <std::size_t N>
std::array<Point3, N> points_of(const Query& q) {
    std::array<Point3, N> p{};
    for (std::size_t i = 0; i < N; ++i) {
        p[i] = {q.v[3 * i], q.v[3 * i + 1], q.v[3 * i + 2]};
    }
    return p;
}

struct Box {
    Point3 lo;
    Point3 hi;
};

template <std::size_t N>
Box tightest_box(const std::array<Point3, N>& p) {
    Box box{p[0], p[0]};
    for (const Point3& q : p) {
        box.lo = {std::min(box.lo.x, q.x), std::min(box.lo.y, q.y), std::min(box.lo.z, q.z)};
        box.hi = {std::max(box.hi.x, q.x), std::max(box.hi.y, q.y), std::max(box.hi.z, q.z)};
    }
    return box;
}

struct Tally {
    std::size_t answered = 0;
    std::size_t wrong = 0;
};

int static_sign(const Box& box, const std::array<Point3, 4>& p) {
    return Orient3dStaticFilter(box.lo, box.hi).sign(p[0], p[1], p[2], p[3]);
}

int static_sign(const Box& box, const std::array<Point3, 5>& p) {
    return InsphereStaticFilter(box.lo, box.hi).sign(p[0], p[1], p[2], p[3], p[4]);
}

// Checks the filter on a query of N points in its tightest box and in that box widened by a
// random amount.
template <std::size_t N>
void check(const Query& q, Rng& rng, Tally& tally) {
    const auto p = points_of<N>(q);
    Box box = tightest_box(p);
    const Sign exact = evaluate_oracle(q);
    for (int widened = 0; widened < 2; ++widened) {
        const int s = static_sign(box, p);
        if (s != 0) {
            ++tally.answered;
            if (s != static_cast<int>(exact) && ++tally.wrong <= 10) {
                ADD_FAILURE() << "the static filter says " << s << ", the exact sign is "
                              << static_cast<int>(exact) << "\n  query: " << to_line(q);
            }
        }
        const double grow = std::ldexp(1.0, static_cast<int>(rng.integer(-20, 20)));
        box.hi.x += grow * (box.hi.x - box.lo.x);
        box.lo.y -= grow * (box.hi.y - box.lo.y);
    }
}

template <std::size_t N>
void check_family(std::uint64_t seed, const std::function<Query(Rng&)>& draw, Tally& tally) {
    Rng rng(seed);
    for (std::size_t i = 0; i < queries_per_family(); ++i) {
        check<N>(draw(rng), rng, tally);
    }
}

// The four families of the agreement tests for a predicate of N points.
template <std::size_t N>
void check_all_families(Kind kind, std::uint64_t seed) {
    Tally random;
    check_family<N>(
        seed + 1, [kind](Rng& rng) { return random_query(kind, rng); }, random);
    Tally hard;
    check_family<N>(
        seed + 2, [kind](Rng& rng) { return degenerate_query(kind, rng); }, hard);
    check_family<N>(
        seed + 3, [kind](Rng& rng) { return near_degenerate_query(kind, rng); }, hard);
    check_family<N>(
        seed + 4, [kind](Rng& rng) { return extreme_query(kind, rng); }, hard);
    EXPECT_EQ(random.wrong + hard.wrong, 0u);
    // Not vacuous: random queries in their own box are almost all decided by the filter.
    EXPECT_GT(random.answered, queries_per_family());
}

TEST(InsphereStaticFilter, NeverDisagreesWithTheOracle) {
    check_all_families<5>(Kind::kInsphere, 7000);
}

TEST(Orient3dStaticFilter, NeverDisagreesWithTheOracle) {
    check_all_families<4>(Kind::kOrient3d, 7100);
}

TEST(InsphereStaticFilter, NeverAnswersOutsideItsRange) {
    const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1}, e{0.1, 0.1, 0.1};
    EXPECT_EQ(InsphereStaticFilter().sign(a, b, c, d, e), 0);
    // A flat box (no extent in z), a box too small and one too large for the guards.
    EXPECT_EQ(InsphereStaticFilter({0, 0, 0}, {1, 1, 0}).sign(a, b, c, d, e), 0);
    const double tiny = 0x1p-200;
    EXPECT_EQ(InsphereStaticFilter({0, 0, 0}, {tiny, tiny, tiny})
                  .sign({0, 0, 0}, {tiny, 0, 0}, {0, tiny, 0}, {0, 0, tiny}, {0, 0, 0}),
              0);
    const double huge = 0x1p200;
    EXPECT_EQ(InsphereStaticFilter({0, 0, 0}, {huge, huge, huge})
                  .sign({0, 0, 0}, {huge, 0, 0}, {0, huge, 0}, {0, 0, huge}, {1, 1, 1}),
              0);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(InsphereStaticFilter({0, 0, 0}, {inf, 1, 1}).sign(a, b, c, d, e), 0);
    // In range it decides the plain case.
    const int s = InsphereStaticFilter({0, 0, 0}, {1, 1, 1}).sign(a, b, c, d, e);
    EXPECT_NE(s, 0);
    EXPECT_EQ(s, static_cast<int>(insphere(a, b, c, d, e)));
}

TEST(Orient3dStaticFilter, NeverAnswersOutsideItsRange) {
    const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0.1, 0.1, 0.1};
    EXPECT_EQ(Orient3dStaticFilter().sign(a, b, c, d), 0);
    // A flat box (no extent in z), a box too small and one too large for the guards.
    EXPECT_EQ(Orient3dStaticFilter({0, 0, 0}, {1, 1, 0}).sign(a, b, c, d), 0);
    const double tiny = 0x1p-301;
    EXPECT_EQ(Orient3dStaticFilter({0, 0, 0}, {tiny, tiny, tiny})
                  .sign({0, 0, 0}, {tiny, 0, 0}, {0, tiny, 0}, {0, 0, tiny}),
              0);
    const double huge = 0x1p331;
    EXPECT_EQ(Orient3dStaticFilter({0, 0, 0}, {huge, huge, huge})
                  .sign({0, 0, 0}, {huge, 0, 0}, {0, huge, 0}, {0, 0, huge}),
              0);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(Orient3dStaticFilter({0, 0, 0}, {inf, 1, 1}).sign(a, b, c, d), 0);
    // In range it decides the plain case.
    const int s = Orient3dStaticFilter({0, 0, 0}, {1, 1, 1}).sign(a, b, c, d);
    EXPECT_NE(s, 0);
    EXPECT_EQ(s, static_cast<int>(orient3d(a, b, c, d)));
}

// Adversarial for the underflow term of the bound: boxes at the edges of the guards (extents
// 2^-300 and 2^330 mixed), so that the 2x2 minors of thin directions are subnormal or underflow to
// zero, with points that are exactly or nearly coplanar (a plane through the box, its points
// rounded, some moved a few ulps) or random in the box.
TEST(Orient3dStaticFilter, AgreesAtTheEdgesOfItsRange) {
    Rng rng(7201);
    const double small = 0x1p-300;
    const double large = 0x1p330;
    Tally tally;
    for (int i = 0; i < 20000; ++i) {
        const Point3 extent{
            rng.coin() ? small : large, rng.coin() ? small : large, rng.coin() ? small : large};
        const Box box{{0, 0, 0}, extent};
        std::array<Point3, 4> p{};
        const bool planar = rng.coin();
        const double gx = rng.unit(), gy = rng.unit();
        for (Point3& q : p) {
            const double u = 0.5 * (rng.unit() + 1.0), v = 0.5 * (rng.unit() + 1.0);
            q.x = u * extent.x;
            q.y = v * extent.y;
            // A plane z = (0.5 + gx u / 4 + gy v / 4) Z through the box, or a random height.
            const double w = planar ? 0.5 + 0.25 * (gx * u + gy * v) : 0.5 * (rng.unit() + 1.0);
            q.z = w * extent.z;
            if (planar && rng.coin()) {
                for (int k = static_cast<int>(rng.integer(1, 4)); k > 0; --k) {
                    q.z = std::nextafter(q.z, rng.coin() ? 0.0 : extent.z);
                }
            }
        }
        const int s = static_sign(box, p);
        if (s != 0) {
            ++tally.answered;
            const Sign exact = oracle::orient3d(p[0], p[1], p[2], p[3]);
            if (s != static_cast<int>(exact) && ++tally.wrong <= 10) {
                ADD_FAILURE() << "the static filter says " << s << ", the exact sign is "
                              << static_cast<int>(exact);
            }
        }
    }
    EXPECT_EQ(tally.wrong, 0u);
    EXPECT_GT(tally.answered, 0u);
}

}  // namespace

}  // namespace cavity::predicates::testing
