// Vertex deletion by gift-wrapping the star: after every deletion the complex equals the
// triangulation rebuilt by Bowyer-Watson without the deleted points, on random and degenerate
// sets, hull vertices included.
#include <algorithm>
#include <numeric>
#include <string>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/edit/vertex_deletion.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/mesh/star.h"

namespace cavity::core {
namespace {

using Tets = std::vector<std::array<std::uint32_t, 4>>;

using test::canonical;

Triangulation bowyer_watson(const PointSet& ps) {
    return test::triangulate_in_input_order(ps);
}

/// Deletes `count` vertices one by one from the live complex (every third one a hull vertex),
/// comparing with the rebuilt triangulation after each. Counts in `resurfaced` the submerged
/// (weighted redundant) points that became vertices.
void delete_and_compare(const PointSet& ps,
                        int count,
                        std::uint64_t seed,
                        std::size_t& resurfaced) {
    const Triangulation full = bowyer_watson(ps);
    const Geometry geometry = geometry_by_index(ps);
    ArrayStorage storage = complex_from_tets(full.tets);
    std::vector<VertexId> submerged(full.redundant.begin(), full.redundant.end());
    std::vector<bool> gone(ps.size(), false);
    Random random(seed);
    RetriangulationCounters counters;
    int hull_deletions = 0;
    for (int k = 0; k < count; ++k) {
        std::vector<VertexId> pool;
        const bool hull = k % 3 == 0;
        for (TetId t = 0; t < storage.capacity(); ++t) {
            if (storage.alive(t) && is_ghost(storage.vertices(t)) == hull) {
                for (VertexId v : storage.vertices(t)) {
                    if (v != kGhostVertex) {
                        pool.push_back(v);
                    }
                }
            }
        }
        std::sort(pool.begin(), pool.end());
        pool.erase(std::unique(pool.begin(), pool.end()), pool.end());
        const VertexId v = pool[random.below(pool.size())];
        SCOPED_TRACE("deletion " + std::to_string(k) + ": point " + std::to_string(v));
        std::vector<TetId> fresh;
        ASSERT_NO_THROW(fresh = delete_vertex(storage, geometry, v, submerged, counters))
            << (hull ? "hull vertex" : "interior vertex");
        hull_deletions += hull ? 1 : 0;
        gone[v] = true;
        resurfaced += std::erase_if(submerged, [&](VertexId s) {
            return std::any_of(fresh.begin(), fresh.end(), [&](TetId t) {
                return slot_of(storage.vertices(t), s) >= 0;
            });
        });
        const auto problems = check_complex(storage, geometry);
        ASSERT_TRUE(problems.empty()) << problems.front();
        const Triangulation expected = test::rebuilt_without(ps, gone);
        ASSERT_EQ(canonical(solid_tets(storage)), canonical(expected.tets));
        ASSERT_EQ(submerged, expected.redundant);
    }
    EXPECT_EQ(counters.vertices_deleted, static_cast<std::uint64_t>(count));
    EXPECT_GT(hull_deletions, 0);
    EXPECT_GT(counters.facets_wrapped, 0u);
}

class DeletionCorpus : public ::testing::TestWithParam<const char*> {};

TEST_P(DeletionCorpus, EqualsRebuildAfterEachDeletion) {
    std::size_t resurfaced = 0;
    delete_and_compare(generate_points(GetParam(), 150, 3), 70, 17, resurfaced);
}

INSTANTIATE_TEST_SUITE_P(
    RandomAndDegenerate,
    DeletionCorpus,
    ::testing::Values(
        "ball", "cube", "grid", "cospherical", "skew-lines", "moment", "paraboloid", "layers"));

TEST(VertexDeletion, WeightedDeletionUncoversSubmergedPoints) {
    const PointSet ps = generate_points("cube", 150, 9, parse_weight_spec("uniform:0:0.08"));
    std::size_t resurfaced = 0;
    delete_and_compare(ps, 70, 5, resurfaced);
    EXPECT_GT(resurfaced, 0u);
}

TEST(VertexDeletion, WeightedGridWithEqualWeights) {
    std::size_t resurfaced = 0;
    delete_and_compare(
        generate_points("grid", 125, 2, parse_weight_spec("equal:0.5")), 40, 8, resurfaced);
}

}  // namespace
}  // namespace cavity::core
