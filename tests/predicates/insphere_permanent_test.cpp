// The permanent stage of insphere (predicates/src/insphere_permanent.h) against the exact oracle:
// whenever it answers, its sign is the exact one. The inputs are those it exists for and those
// that probe its bound: five nearby points on the unit sphere (rounded, so near-cospherical), the
// same scaled to the edges of kLiftedAdaptiveWindow (tiny and huge exponents, differences down to
// a few multiples of 2^-192, products near the underflow floor), exactly cospherical integer
// points (the sign is 0, which the stage must never claim) and the same moved a few ulps.

#include "insphere_permanent.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include "cavity/predicates/detail/expansion.h"
#include "cavity/predicates/oracle.h"
#include "cospherical_queries.h"
#include "lifted_adaptive.h"

namespace cavity::predicates::detail {
namespace {

using Query = std::array<Point3, 5>;

/// The rows insphere's adaptive stage builds (insphere.cpp).
LiftedRows rows_of(const Query& q) {
    return insphere_rows(q);
}

struct Tally {
    std::size_t answered = 0;
    std::size_t wrong = 0;
};

// Only queries in the stage's exponent window (its precondition; insphere rescales the others).
void check(const Query& q, Tally& tally) {
    if (!within(q, kLiftedAdaptiveWindow)) {
        return;
    }
    const LiftedRows rows = rows_of(q);
    const std::optional<Sign> s = insphere_permanent(rows, insphere_row_permanent(rows));
    if (!s) {
        return;
    }
    ++tally.answered;
    const Sign exact = oracle::insphere(q[0], q[1], q[2], q[3], q[4]);
    if (*s != exact && ++tally.wrong <= 10) {
        ADD_FAILURE() << "the permanent stage says " << static_cast<int>(*s)
                      << ", the exact sign is " << static_cast<int>(exact);
    }
}

/// Five points of the unit sphere near a random one (spread `cap`), rounded, scaled by 2^scale.
Query nearby_on_sphere(std::mt19937_64& rng, double cap, int scale) {
    std::normal_distribution<double> normal;
    const double cx = normal(rng), cy = normal(rng), cz = normal(rng);
    const double cn = std::sqrt(cx * cx + cy * cy + cz * cz);
    Query q{};
    for (Point3& p : q) {
        const double x = cx / cn + cap * normal(rng);
        const double y = cy / cn + cap * normal(rng);
        const double z = cz / cn + cap * normal(rng);
        const double r = std::sqrt(x * x + y * y + z * z);
        p = {std::ldexp(x / r, scale), std::ldexp(y / r, scale), std::ldexp(z / r, scale)};
    }
    return q;
}

TEST(InspherePermanent, NearbyPointsOnASphereAgreeWithTheOracle) {
    std::mt19937_64 rng(7301);
    Tally tally;
    for (const double cap : {2e-2, 2e-3, 2e-4, 2e-6}) {
        // Scales at the edges of the window: inputs near 2^-139 and 2^179, and 1.
        for (const int scale : {-139, -100, 0, 100, 179}) {
            for (int i = 0; i < 3000; ++i) {
                check(nearby_on_sphere(rng, cap, scale), tally);
            }
        }
    }
    EXPECT_EQ(tally.wrong, 0u);
    // Not vacuous: it decides most of these (the semi-static filter decides few).
    EXPECT_GT(tally.answered, 30000u);
}

// Exactly cospherical integer points (x^2 + y^2 + z^2 = 9^2 + ... about an integer centre), and
// the same with a few coordinates moved 1-4 ulps, at scales 2^k that keep them in the window.
TEST(InspherePermanent, CosphericalIntegerPointsAgreeWithTheOracle) {
    std::mt19937_64 rng(7302);
    std::uniform_int_distribution<int> centre(-1000, 1000);
    Tally exact_zero;
    Tally moved;
    for (const int scale : {-130, 0, 150}) {
        for (int i = 0; i < 20000; ++i) {
            const double ox = centre(rng), oy = centre(rng), oz = centre(rng);
            Query q = testing::cospherical_query(rng, ox, oy, oz, scale);
            check(q, exact_zero);
            testing::move_a_few_ulps(q, rng);
            check(q, moved);
        }
    }
    EXPECT_EQ(exact_zero.wrong + moved.wrong, 0u);
}

}  // namespace
}  // namespace cavity::predicates::detail
