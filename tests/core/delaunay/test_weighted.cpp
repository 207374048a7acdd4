// Weighted Delaunay: equal weights give the unweighted triangulation; random weights give a valid
// regular triangulation, the same for every order and locator, with redundant points reported.

#include <algorithm>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "corpus.h"

namespace cavity::test {
namespace {

std::vector<std::array<std::uint32_t, 4>> build(const core::PointSet& points,
                                                core::OrderKind order,
                                                core::LocateKind locate,
                                                core::Triangulation* out = nullptr) {
    core::OrderOptions order_options;
    order_options.kind = order;
    order_options.seed = 5;
    const auto sequence = core::make_insertion_order(points.points, order_options).sequence;
    core::TriangulateOptions options;
    options.locate = locate;
    auto tri = core::triangulate(points, sequence, options);
    auto tets = tri.tets;
    if (out != nullptr) {
        *out = std::move(tri);
    }
    return canonical(tets);
}

TEST(Weighted, EqualWeightsGiveTheUnweightedTriangulation) {
    for (const CorpusCase& c : degenerate_corpus()) {
        if (c.name == "duplicates") {
            continue;  // weighted repeats are handled by weight, tested below
        }
        core::PointSet weighted = c.points;
        weighted.weights.assign(weighted.size(), 0.0);
        const auto plain = build(c.points, core::OrderKind::kBrio, core::LocateKind::kWalk);
        EXPECT_EQ(build(weighted, core::OrderKind::kRandom, core::LocateKind::kWalk), plain)
            << c.name;
        weighted.weights.assign(weighted.size(), 2.5);
        EXPECT_EQ(build(weighted, core::OrderKind::kHilbert, core::LocateKind::kConflictGraph),
                  plain)
            << c.name;
    }
}

TEST(Weighted, RandomWeightsValidAndOrderIndependent) {
    for (const char* dist : {"cube", "grid", "cospherical"}) {
        core::WeightSpec spec;
        spec.kind = core::WeightSpec::Kind::kUniform;
        spec.a = 0.0;
        spec.b = std::string(dist) == "cube" ? 0.01 : 3.0;
        const auto points = core::generate_points(dist, 400, 9, spec);
        core::Triangulation first;
        const auto reference =
            build(points, core::OrderKind::kBrio, core::LocateKind::kWalk, &first);
        const auto report = core::validate(points, first.tets);
        ASSERT_TRUE(report.ok()) << dist << ": "
                                 << (report.problems.empty() ? "" : report.problems[0]);
        EXPECT_EQ(report.redundant, first.redundant.size()) << dist;
        for (auto order : {core::OrderKind::kInput, core::OrderKind::kRandom}) {
            for (auto locate : {core::LocateKind::kWalk,
                                core::LocateKind::kConflictGraph,
                                core::LocateKind::kFullConflictGraph,
                                core::LocateKind::kStraightWalk}) {
                core::Triangulation other;
                EXPECT_EQ(build(points, order, locate, &other), reference) << dist;
                EXPECT_EQ(other.redundant, first.redundant) << dist;
            }
        }
    }
}

TEST(Weighted, HeavyPointSubmergesItsNeighboursAndTheyAreReported) {
    core::PointSet points = core::generate_points("cube", 200, 4, core::WeightSpec{});
    points.weights.assign(points.size(), 0.0);
    points.points.push_back({0.5, 0.5, 0.5});
    points.weights.push_back(0.05);  // a ball of radius ~0.22 around the centre
    core::Triangulation tri;
    build(points, core::OrderKind::kRandom, core::LocateKind::kWalk, &tri);
    ASSERT_FALSE(tri.redundant.empty());
    for (std::uint32_t r : tri.redundant) {
        const auto& p = points.points[r];
        const double d2 =
            (p.x - 0.5) * (p.x - 0.5) + (p.y - 0.5) * (p.y - 0.5) + (p.z - 0.5) * (p.z - 0.5);
        EXPECT_LT(d2, 0.05) << "point " << r
                            << " is reported redundant but is outside the heavy ball";
    }
    EXPECT_TRUE(core::validate(points, tri.tets).ok());
}

TEST(Weighted, SamePositionTheHeavierWins) {
    core::PointSet points = core::generate_points("grid", 27, 1, core::WeightSpec{});
    points.weights.assign(points.size(), 0.0);
    points.points.push_back(points.points[13]);  // the centre, again, heavier
    points.weights.push_back(0.5);
    core::Triangulation tri;
    build(points, core::OrderKind::kInput, core::LocateKind::kWalk, &tri);
    EXPECT_NE(std::find(tri.redundant.begin(), tri.redundant.end(), 13u), tri.redundant.end());
    EXPECT_TRUE(core::validate(points, tri.tets).ok());
}

}  // namespace
}  // namespace cavity::test
