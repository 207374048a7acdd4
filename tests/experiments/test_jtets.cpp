#include <gtest/gtest.h>

#include "cavity/core/gen/generate.h"
#include "cavity/experiments/jtets.h"

namespace cavity::experiments {
namespace {

TEST(JTets, SkewLinesMatchTheClosedForm) {
    for (std::size_t n : {8, 20, 31}) {
        const core::PointSet points = core::generate_points("skew-lines", n, 0);
        const JTetCounts counted = count_jtets(points.points);
        const JTetCounts closed = skew_lines_jtets((n + 1) / 2, n / 2);
        EXPECT_EQ(counted.f, closed.f) << "n = " << n;
    }
}

TEST(JTets, SkewLinesClosedFormSumsToAllNonFlatSubsets) {
    // Only two points from each line make a non-flat tetrahedron: C(m1,2) C(m2,2) in all.
    const JTetCounts closed = skew_lines_jtets(7, 5);
    EXPECT_EQ(closed.cumulative().back(), 21u * 10u);
    EXPECT_EQ(closed.f[0], 6u * 4u);
}

TEST(JTets, PencilSweepAgreesWithBruteForceOnRandomSets) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const core::PointSet points = core::generate_points("cube", 22, seed);
        EXPECT_EQ(count_jtets(points.points).f, count_jtets_brute_force(points.points).f)
            << "seed " << seed;
    }
}

TEST(JTets, PencilSweepAgreesWithBruteForceOnDegenerateSets) {
    // Cospherical and coplanar subsets: ties must be decided exactly.
    for (const char* dist : {"grid", "moment", "layers", "cospherical"}) {
        const core::PointSet points = core::generate_points(dist, 27, 5);
        EXPECT_EQ(count_jtets(points.points).f, count_jtets_brute_force(points.points).f) << dist;
    }
}

TEST(JTets, ZeroTetrahedraAreTheDelaunayTetrahedraOfGenericInput) {
    const core::PointSet points = core::generate_points("ball", 30, 9);
    const JTetCounts counts = count_jtets(points.points);
    // Every non-flat 4-subset is counted exactly once.
    EXPECT_EQ(counts.cumulative().back(), 27405u);  // C(30, 4), no flat subsets in generic input
}

}  // namespace
}  // namespace cavity::experiments
