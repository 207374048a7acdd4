// Exercise 1's greedy adversary: a permutation that, at every step, inserts a point whose cavity is
// the largest of all uninserted points', checked by brute force on the triangulation of each
// prefix.

#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/experiments/greedy_order.h"

namespace cavity::experiments {
namespace {

/// The tetrahedra (ghosts included) of the triangulation of `prefix` that point q conflicts with.
/// The prefix is triangulated in increasing input index, so that the subset's own indices order the
/// points as the full set's do and the perturbation (which compares keys only) decides alike.
std::size_t cavity_size(const core::PointSet& points,
                        std::vector<std::uint32_t> prefix,
                        std::uint32_t q) {
    const std::vector<std::uint32_t> first_four(prefix.begin(), prefix.begin() + 4);
    std::sort(prefix.begin(), prefix.end());
    core::PointSet subset;
    for (std::uint32_t i : prefix) {
        subset.points.push_back(points.points[i]);
    }
    std::vector<std::uint32_t> sequence(prefix.size());
    std::iota(sequence.begin(), sequence.end(), 0u);
    core::TriangulateOptions options;
    options.bootstrap = core::BootstrapRule::kFirst;
    const core::Triangulation tri = core::triangulate(subset, sequence, options);
    const core::ArrayStorage storage = core::complex_from_tets(tri.tets);
    // The engine's ghost test needs four affinely independent vertices inside the hull: the
    // greedy run's own bootstrap.
    std::array<core::VertexId, 4> inside{};
    for (std::size_t k = 0; k < 4; ++k) {
        inside[k] = static_cast<core::VertexId>(
            std::lower_bound(prefix.begin(), prefix.end(), first_four[k]) - prefix.begin());
    }
    std::vector<std::uint32_t> keys = prefix;
    keys.push_back(q);
    subset.points.push_back(points.points[q]);
    const core::Geometry geometry(subset.points, keys, {});
    const auto last = static_cast<core::VertexId>(prefix.size());
    std::size_t count = 0;
    for (core::TetId t = 0; t < storage.capacity(); ++t) {
        if (!storage.alive(t)) {
            continue;
        }
        const core::TetVertices& v = storage.vertices(t);
        count += core::is_ghost(v) ? geometry.conflicts_ghost(v, last, inside)
                                   : geometry.conflicts_solid(v, last);
    }
    return count;
}

TEST(GreedyOrder, EachStepDigsTheLargestCavity) {
    for (const char* dist : {"cube", "grid"}) {
        SCOPED_TRACE(dist);
        const core::PointSet points = core::generate_points(dist, 27, 3);
        const std::vector<std::uint32_t> order = greedy_order(points);
        std::vector<std::uint32_t> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        std::vector<std::uint32_t> all(points.size());
        std::iota(all.begin(), all.end(), 0u);
        ASSERT_EQ(sorted, all);
        EXPECT_EQ(greedy_order(points), order);
        for (std::size_t k = 4; k + 1 < order.size(); ++k) {
            const std::vector<std::uint32_t> prefix(order.begin(),
                                                    order.begin() + static_cast<long>(k));
            const std::size_t chosen = cavity_size(points, prefix, order[k]);
            for (std::size_t other = k + 1; other < order.size(); ++other) {
                EXPECT_GE(chosen, cavity_size(points, prefix, order[other]))
                    << "step " << k << ": point " << order[other] << " has a larger cavity than "
                    << order[k];
            }
        }
    }
}

TEST(GreedyOrder, WeightedPointsAreRefused) {
    core::WeightSpec weights;
    weights.kind = core::WeightSpec::Kind::kEqual;
    EXPECT_THROW(greedy_order(core::generate_points("cube", 20, 1, weights)), core::Error);
}

}  // namespace
}  // namespace cavity::experiments
