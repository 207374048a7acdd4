// Gift-wrapping (§5.6) against Bowyer-Watson: the same tetrahedra, one by one, on the degenerate
// corpus, where only the shared symbolic perturbation makes the triangulation unique.
#include <algorithm>
#include <numeric>
#include <string>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/base/error.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/edit/gift_wrap.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"

namespace cavity::core {
namespace {

using Tets = std::vector<std::array<std::uint32_t, 4>>;

using test::canonical;

Triangulation bowyer_watson(const PointSet& ps) {
    return test::triangulate_in_input_order(ps);
}

void expect_same_as_bowyer_watson(const PointSet& ps) {
    const GiftWrapResult wrapped = gift_wrap_delaunay(ps);
    const Triangulation reference = bowyer_watson(ps);
    EXPECT_EQ(canonical(wrapped.tets), canonical(reference.tets));
    EXPECT_EQ(wrapped.hull_triangles, reference.hull_triangles);
    EXPECT_EQ(wrapped.redundant, reference.redundant);
    const ValidationReport report = validate(ps, wrapped.tets);
    EXPECT_TRUE(report.ok()) << (report.problems.empty() ? "" : report.problems.front());
    // Every facet is wrapped once from each side except the hull's, wrapped once.
    const RetriangulationCounters& c = wrapped.counters;
    EXPECT_EQ(c.tets_created, wrapped.tets.size());
    EXPECT_EQ(c.facets_wrapped, wrapped.tets.size() - 1 + wrapped.hull_triangles);
    EXPECT_GT(c.insphere_calls, 0u);
}

class GiftWrapCorpus : public ::testing::TestWithParam<const char*> {};

TEST_P(GiftWrapCorpus, SameTetrahedraAsBowyerWatson) {
    for (std::uint64_t seed : {1u, 2u}) {
        SCOPED_TRACE(std::string(GetParam()) + " seed " + std::to_string(seed));
        expect_same_as_bowyer_watson(generate_points(GetParam(), 180, seed));
    }
}

INSTANTIATE_TEST_SUITE_P(
    Degenerate,
    GiftWrapCorpus,
    ::testing::Values(
        "grid", "cospherical", "skew-lines", "moment", "paraboloid", "layers", "ball", "cube"));

TEST(GiftWrap, WeightedSetWithRedundantPoints) {
    const PointSet ps = generate_points("cube", 200, 5, parse_weight_spec("uniform:0:0.05"));
    const Triangulation reference = bowyer_watson(ps);
    ASSERT_FALSE(reference.redundant.empty());
    expect_same_as_bowyer_watson(ps);
}

TEST(GiftWrap, WeightedGridWithEqualWeights) {
    expect_same_as_bowyer_watson(generate_points("grid", 125, 3, parse_weight_spec("equal:0.25")));
}

TEST(GiftWrap, DuplicatesAreReported) {
    PointSet ps = generate_points("grid", 27, 1);
    ps.points.push_back(ps.points[5]);
    const GiftWrapResult wrapped = gift_wrap_delaunay(ps);
    ASSERT_EQ(wrapped.duplicates.size(), 1u);
    EXPECT_EQ(wrapped.duplicates[0], (std::array<std::uint32_t, 2>{27, 5}));
    expect_same_as_bowyer_watson(ps);
}

TEST(GiftWrap, CoplanarInputIsAnError) {
    PointSet ps;
    ps.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}};
    EXPECT_THROW(gift_wrap_delaunay(ps), Error);
}

}  // namespace
}  // namespace cavity::core
