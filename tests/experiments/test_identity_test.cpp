#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/experiments/identity_test.h"

namespace cavity::experiments {
namespace {

// Orders simulated as dependent counts: per order, bin 1 and bin 2 share a common random part
// (a creation that makes others likely), bin 0 is fixed, and the rest is rare.
std::map<std::uint64_t, std::uint64_t> draw(std::mt19937_64& rng, double shift, double rarity) {
    std::poisson_distribution<int> common(20.0);
    std::poisson_distribution<int> own(10.0 + shift);
    std::poisson_distribution<int> rare(rarity);
    const auto c = static_cast<std::uint64_t>(common(rng));
    std::map<std::uint64_t, std::uint64_t> h{{0, 7}};
    h[1] = c + static_cast<std::uint64_t>(own(rng));
    h[2] = c + static_cast<std::uint64_t>(own(rng));
    h[3] = static_cast<std::uint64_t>(rare(rng));
    h[4] = static_cast<std::uint64_t>(rare(rng));
    return h;
}

IdentityTest::Result run(double shift,
                         std::uint64_t orders,
                         std::uint64_t seed,
                         double rarity = 0.001) {
    const std::vector<double> expected{7, 30, 30, rarity, rarity};
    IdentityTest test(expected, orders);
    std::mt19937_64 rng(seed);
    for (std::uint64_t r = 0; r < orders; ++r) {
        test.add(draw(rng, shift, rarity));
    }
    return test.result();
}

TEST(IdentityTest, BinsTheRareTailAndLeavesTheFixedBinOut) {
    // j = 3 expects 10 events in 10^4 orders: it and j = 4 are pooled; j = 0 never varies.
    const IdentityTest::Result r = run(0, 10000, 1);
    EXPECT_EQ(r.fixed, 1u);
    EXPECT_EQ(r.bins, 3u);
}

TEST(IdentityTest, FollowsChiSquareWhenTheIdentityHolds) {
    // Over many repetitions the mean of T² is its degrees of freedom (3), despite the
    // dependence between bins 1 and 2 that per-bin binomial tests would ignore. The pooled tail
    // expects 80 events per repetition, so it varies in every one.
    double sum = 0;
    const int repetitions = 200;
    for (int k = 0; k < repetitions; ++k) {
        const IdentityTest::Result r = run(0, 2000, 100 + static_cast<std::uint64_t>(k), 0.02);
        ASSERT_EQ(r.bins, 3u);
        sum += r.t2;
    }
    // The mean of 200 χ²_3 values has a standard deviation of √(6/200) ≈ 0.17.
    EXPECT_NEAR(sum / repetitions, 3.0, 0.7);
}

TEST(IdentityTest, UsesTheCovarianceBetweenBins) {
    // Four orders of (h0, h1, h2) with h0 fixed at its exact value: mean (2.5, 3) against
    // (2, 2.5), S = [[5/3, 1], [1, 2]] over the orders, so T² = 4 dᵀS⁻¹d = 5/7. Ignoring the
    // covariance would give 4 (0.25 / (5/3) + 0.25 / 2) = 1.1.
    IdentityTest test(std::vector<double>{7, 2, 2.5}, 4, 0.0);
    for (const auto& [h1, h2] :
         std::vector<std::pair<std::uint64_t, std::uint64_t>>{{1, 2}, {2, 2}, {3, 5}, {4, 3}}) {
        test.add({{0, 7}, {1, h1}, {2, h2}});
    }
    const IdentityTest::Result r = test.result();
    EXPECT_EQ(r.bins, 2u);
    EXPECT_EQ(r.fixed, 1u);
    EXPECT_NEAR(r.t2, 5.0 / 7.0, 1e-12);
}

TEST(IdentityTest, DetectsAShiftedMean) {
    // A shift of 0.3 per order in both bins (1 % of their mean) is 6 standard errors of their
    // sum at 10^4 orders; T² > 25 has a chance below 2·10^-5 under χ²_3.
    EXPECT_GT(run(0.3, 10000, 5).t2, 25.0);
}

TEST(IdentityTest, AFixedBinOffItsValueFailsOutright) {
    IdentityTest test(std::vector<double>{8, 30}, 100);
    std::mt19937_64 rng(3);
    for (int r = 0; r < 100; ++r) {
        test.add(draw(rng, 0, 0.001));  // bin 0 is always 7, not 8
    }
    EXPECT_TRUE(std::isinf(test.result().t2));
}

}  // namespace
}  // namespace cavity::experiments
