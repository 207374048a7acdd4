// The static insphere filter (insphere_static_filter.h) against the exact oracle: whenever it
// answers, its sign is the exact one. Each query gets the tightest box around its own five points
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

std::array<Point3, 5> points_of(const Query& q) {
    std::array<Point3, 5> p{};
    for (std::size_t i = 0; i < 5; ++i) {
        p[i] = {q.v[3 * i], q.v[3 * i + 1], q.v[3 * i + 2]};
    }
    return p;
}

struct Box {
    Point3 lo;
    Point3 hi;
};

Box tightest_box(const std::array<Point3, 5>& p) {
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

// Checks the filter on a query in its tightest box and in that box widened by a random amount.
void check(const Query& q, Rng& rng, Tally& tally) {
    const auto p = points_of(q);
    Box box = tightest_box(p);
    const Sign exact = evaluate_oracle(q);
    for (int widened = 0; widened < 2; ++widened) {
        const int s = InsphereStaticFilter(box.lo, box.hi).sign(p[0], p[1], p[2], p[3], p[4]);
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

void check_family(std::uint64_t seed, const std::function<Query(Rng&)>& draw, Tally& tally) {
    Rng rng(seed);
    for (std::size_t i = 0; i < queries_per_family(); ++i) {
        check(draw(rng), rng, tally);
    }
}

TEST(InsphereStaticFilter, NeverDisagreesWithTheOracle) {
    Tally random;
    check_family(
        7001, [](Rng& rng) { return random_query(Kind::kInsphere, rng); }, random);
    Tally hard;
    check_family(
        7002, [](Rng& rng) { return degenerate_query(Kind::kInsphere, rng); }, hard);
    check_family(
        7003, [](Rng& rng) { return near_degenerate_query(Kind::kInsphere, rng); }, hard);
    check_family(
        7004, [](Rng& rng) { return extreme_query(Kind::kInsphere, rng); }, hard);
    EXPECT_EQ(random.wrong + hard.wrong, 0u);
    // Not vacuous: random queries in their own box are almost all decided by the filter.
    EXPECT_GT(random.answered, queries_per_family());
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

}  // namespace

}  // namespace cavity::predicates::testing
