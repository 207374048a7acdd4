// triangulate_in_place against triangulate: the same tetrahedra in the same order, the same lists
// and counters, for every locator, storage and thread count, on the degenerate corpus and on
// weighted points; and the lent points come back bit for bit (repeats, signed zeros), also when the
// run throws.

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "corpus.h"

namespace cavity::test {
namespace {

using core::PointSet;
using core::TriangulateOptions;

/// Bit for bit: -0.0 and +0.0 differ here, as they do in the caller's array.
bool same_bits(const std::vector<core::Point3>& a, const std::vector<core::Point3>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(core::Point3)) == 0);
}

/// triangulate_in_place on a copy of `points` agrees with triangulate on `points` in every output
/// field, and leaves the copy's points as they were.
void expect_same_as_const(const PointSet& points,
                          const std::vector<std::uint32_t>& sequence,
                          const TriangulateOptions& options,
                          const std::string& variant) {
    const core::Triangulation expected = core::triangulate(points, sequence, options);
    PointSet lent = points;
    std::vector<std::uint32_t> given = sequence;
    const core::Triangulation got = core::triangulate_in_place(lent, std::move(given), options);
    EXPECT_EQ(got.tets, expected.tets) << variant;
    EXPECT_EQ(got.duplicates, expected.duplicates) << variant;
    EXPECT_EQ(got.redundant, expected.redundant) << variant;
    EXPECT_EQ(got.hull_triangles, expected.hull_triangles) << variant;
    for (const core::CounterField& counter : core::kCounterFields) {
        EXPECT_EQ(got.counters.*counter.field, expected.counters.*counter.field)
            << variant << ": " << counter.name;
    }
    EXPECT_EQ(got.counters.stage_calls, expected.counters.stage_calls) << variant;
    EXPECT_TRUE(same_bits(lent.points, points.points)) << variant << ": points not given back";
    EXPECT_EQ(lent.weights, points.weights) << variant;
}

class InPlace : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(InPlace, SameTriangulationAndPointsBackForEveryLocatorStorageAndThreadCount) {
    const CorpusCase& c = GetParam();
    core::OrderOptions order;
    order.seed = 5;
    const auto sequence = core::make_insertion_order(c.points.points, order).sequence;
    for (const auto& [locate_name, locate, locate_help] : core::kLocateKinds) {
        for (const auto& [storage_name, storage, storage_help] : core::kStorageKinds) {
            TriangulateOptions options;
            options.locate = locate;
            options.storage = storage;
            options.count = true;
            expect_same_as_const(
                c.points,
                sequence,
                options,
                c.name + " " + std::string(locate_name) + " " + std::string(storage_name));
        }
    }
    for (unsigned threads : {1u, 2u, 3u}) {
        TriangulateOptions options;
        options.threads = threads;
        expect_same_as_const(
            c.points, sequence, options, c.name + " threads " + std::to_string(threads));
    }
}

INSTANTIATE_TEST_SUITE_P(DegenerateCorpus,
                         InPlace,
                         ::testing::ValuesIn(degenerate_corpus()),
                         [](const ::testing::TestParamInfo<CorpusCase>& p) {
                             return p.param.name;
                         });

TEST(InPlace, WeightedPointsWithRedundantOnes) {
    const PointSet points = core::generate_points(
        "cube", 2000, 7, core::WeightSpec{core::WeightSpec::Kind::kUniform, 0.0, 0.01});
    const auto sequence = core::make_insertion_order(points.points, core::OrderOptions{}).sequence;
    TriangulateOptions options;
    const core::Triangulation expected = core::triangulate(points, sequence, options);
    ASSERT_FALSE(expected.redundant.empty()) << "the case should submerge some points";
    expect_same_as_const(points, sequence, options, "weighted");
}

/// Repeats whose coordinates differ in the sign of a zero: the engine keeps the lowest index, and
/// the caller's array keeps every bit of every repeat.
TEST(InPlace, RepeatsAndSignedZerosComeBackBitForBit) {
    PointSet points = core::generate_points("cube", 500, 3, core::WeightSpec{});
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; i += 7) {
        points.points.push_back(points.points[i]);
    }
    points.points.push_back({0.0, 0.5, 0.5});
    points.points.push_back({-0.0, 0.5, 0.5});
    points.points.push_back({0.0, -0.0, 0.5});
    points.points.push_back({-0.0, 0.0, 0.5});
    const auto sequence = core::make_insertion_order(points.points, core::OrderOptions{}).sequence;
    const core::Triangulation expected = core::triangulate(points, sequence, TriangulateOptions{});
    ASSERT_GT(expected.duplicates.size(), n / 7);
    expect_same_as_const(points, sequence, TriangulateOptions{}, "repeats");
}

TEST(InPlace, PointsComeBackWhenTheRunThrows) {
    const PointSet points = core::generate_points("ball", 3000, 9, core::WeightSpec{});
    const auto sequence = core::make_insertion_order(points.points, core::OrderOptions{}).sequence;
    for (unsigned threads : {0u, 2u}) {
        PointSet lent = points;
        TriangulateOptions options;
        options.threads = threads;
        options.progress = [](std::size_t done, std::size_t) {
            if (done > 0) {
                throw std::runtime_error("stop");
            }
        };
        EXPECT_THROW(
            core::triangulate_in_place(lent, std::vector<std::uint32_t>(sequence), options),
            std::runtime_error);
        EXPECT_TRUE(same_bits(lent.points, points.points)) << "threads " << threads;
    }
}

TEST(InPlace, BadInputThrowsBeforeAnythingMoves) {
    const PointSet points = core::generate_points("cube", 100, 1, core::WeightSpec{});
    PointSet lent = points;
    std::vector<std::uint32_t> not_a_permutation(points.size(), 0);
    EXPECT_THROW(core::triangulate_in_place(lent, std::move(not_a_permutation), {}), core::Error);
    EXPECT_TRUE(same_bits(lent.points, points.points));
    PointSet flat;
    for (int i = 0; i < 10; ++i) {
        flat.points.push_back({static_cast<double>(i), static_cast<double>(i * i), 0.0});
    }
    const PointSet flat_copy = flat;
    std::vector<std::uint32_t> order{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    EXPECT_THROW(core::triangulate_in_place(flat, std::move(order), {}), core::Error);
    EXPECT_TRUE(same_bits(flat.points, flat_copy.points));
}

}  // namespace
}  // namespace cavity::test
