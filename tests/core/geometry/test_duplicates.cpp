// first_occurrences maps every point to the lowest index with the same coordinates (and weight),
// with the same result whatever the number of threads sharing the table.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/gen/generate.h"
#include "cavity/core/geometry/duplicates.h"

namespace cavity::core {
namespace {

/// The definition, quadratically: the first earlier point that is the same.
std::vector<std::uint32_t> by_definition(const std::vector<Point3>& points,
                                         const std::vector<double>& weights) {
    std::vector<std::uint32_t> first(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        first[i] = i;
        for (std::uint32_t j = 0; j < i; ++j) {
            const Point3& p = points[i];
            const Point3& q = points[j];
            if (p.x == q.x && p.y == q.y && p.z == q.z &&
                (weights.empty() || weights[i] == weights[j])) {
                first[i] = j;
                break;
            }
        }
    }
    return first;
}

TEST(FirstOccurrences, TheLowestIndexForEveryThreadCount) {
    // Repeats at every distance, a signed zero and a few thousand points, so that every part
    // of the table gets some.
    std::vector<Point3> points = generate_points("cube", 3000, 9).points;
    for (std::size_t i = 0; i < 900; ++i) {
        points.push_back(points[(i * 37) % points.size()]);
    }
    points.push_back({0.0, 0.5, 0.5});
    points.push_back({-0.0, 0.5, 0.5});
    std::vector<double> weights(points.size());
    for (std::size_t i = 0; i < weights.size(); ++i) {
        weights[i] = static_cast<double>(i % 3);
    }
    for (const bool weighted : {false, true}) {
        SCOPED_TRACE(weighted);
        const std::vector<double> w = weighted ? weights : std::vector<double>{};
        const std::vector<std::uint32_t> expected = by_definition(points, w);
        for (unsigned threads : {1u, 2u, 3u, 4u, 7u}) {
            SCOPED_TRACE(threads);
            EXPECT_EQ(first_occurrences(points, w, threads), expected);
        }
    }
}

TEST(FirstOccurrences, ThreadsShareLargeSetsWithTheSameResult) {
    // Large enough for every thread to get its own part of the table.
    std::vector<Point3> points = generate_points("cube", 300000, 4).points;
    for (std::size_t i = 0; i < 20000; ++i) {
        points.push_back(points[(i * 7919) % points.size()]);
    }
    const std::vector<std::uint32_t> one = first_occurrences(points, {}, 1);
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        ASSERT_LE(one[i], i);
        ASSERT_EQ(one[one[i]], one[i]);
    }
    EXPECT_EQ(one[300000], 0u);
    for (unsigned threads : {2u, 3u, 4u}) {
        SCOPED_TRACE(threads);
        EXPECT_EQ(first_occurrences(points, {}, threads), one);
    }
}

}  // namespace
}  // namespace cavity::core
