// The parallel construction builds the sequential engine's tetrahedra, for every thread count and
// every interleaving, and stores them in the same canonical order whatever the thread count.
// Thresholds are set low here so that threads share even small batches and collide often: the
// hand-back path runs on every input of the degenerate corpus.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/base/error.h"
#include "cavity/core/delaunay/insertion_driver.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/delaunay_triangulation.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/core/parallel/parallel_build.h"
#include "cavity/predicates/generic_point.h"
#include "corpus.h"

namespace cavity::core {
namespace {

using Tets = std::vector<std::array<std::uint32_t, 4>>;
using test::canonical;

std::vector<std::uint32_t> brio(const PointSet& ps) {
    return make_insertion_order(ps.points, OrderOptions{}).sequence;
}

TriangulateOptions with_threads(unsigned threads) {
    TriangulateOptions options;
    options.threads = threads;
    return options;
}

/// build_in_parallel on its own, with thresholds that make the threads share every batch: the
/// stored tetrahedra as input indices, in storage order, and the redundant points.
struct Built {
    Tets stored;  ///< in the storage's order and rotation (ghosts included, as -1)
    Tets solid;   ///< solid ones as input indices
    std::vector<std::uint32_t> redundant;
};

Built build_forced(const PointSet& ps, unsigned threads) {
    Triangulation scratch;
    const detail::Prepared prep = detail::prepare(ps, brio(ps), BootstrapRule::kWidest, scratch);
    ParallelOptions options;
    options.threads = threads;
    options.min_points_per_thread = 1;
    options.lone_retry_below = 1;
    ArrayStorage storage;
    const ParallelBuild build = build_in_parallel(prep.geometry, options, storage);
    Built out;
    for (TetId t = 0; t < storage.capacity(); ++t) {
        EXPECT_TRUE(storage.alive(t));
        const TetVertices& v = storage.vertices(t);
        std::array<std::uint32_t, 4> keys{};
        for (std::size_t i = 0; i < 4; ++i) {
            keys[i] = v[i] == kGhostVertex ? 0xFFFF'FFFFu : prep.geometry.key(v[i]);
        }
        out.stored.push_back(keys);
        if (!is_ghost(v)) {
            out.solid.push_back(keys);
        }
    }
    for (VertexId v : build.redundant) {
        out.redundant.push_back(prep.geometry.key(v));
    }
    std::sort(out.redundant.begin(), out.redundant.end());
    return out;
}

/// list_in_parallel with the same thresholds: the solid tetrahedra as triangulate() hands them
/// out, and the number of hull triangles.
struct Listed {
    Tets tets;
    std::size_t hull_triangles = 0;
};

Listed list_forced(const PointSet& ps, unsigned threads) {
    Triangulation scratch;
    const detail::Prepared prep = detail::prepare(ps, brio(ps), BootstrapRule::kWidest, scratch);
    ParallelOptions options;
    options.threads = threads;
    options.min_points_per_thread = 1;
    options.lone_retry_below = 1;
    Listed out;
    out.hull_triangles = list_in_parallel(prep.geometry, options, out.tets).hull_triangles;
    return out;
}

/// The stored order's solid tetrahedra as the API lists them (the first two vertices swapped).
Tets mirrored_solid(const Built& built) {
    Tets out;
    for (const auto& t : built.solid) {
        out.push_back({t[1], t[0], t[2], t[3]});
    }
    return out;
}

TEST(ParallelBuild, SameTetrahedraAsTheSequentialEngineForEveryThreadCount) {
    const PointSet ps = generate_points("cube", 40000, 7);
    const Tets expected = canonical(triangulate(ps, brio(ps), TriangulateOptions{}).tets);
    Tets first_order;
    for (unsigned threads : {1u, 2u, 3u, 4u}) {
        SCOPED_TRACE(threads);
        const Triangulation tri = triangulate(ps, brio(ps), with_threads(threads));
        EXPECT_EQ(canonical(tri.tets), expected);
        // The canonical order: the same list, in the same order, whatever the thread count.
        if (threads == 1) {
            first_order = tri.tets;
        } else {
            EXPECT_EQ(tri.tets, first_order);
        }
    }
}

TEST(ParallelBuild, TheListIsTheLiveTriangulationsOrder) {
    // triangulate() lists the tetrahedra without building the storage; the live triangulation
    // stores them: the same canonical order either way.
    for (const char* distribution : {"cube", "grid"}) {
        const PointSet ps = generate_points(distribution, 30000, 8);
        const Triangulation listed = triangulate(ps, brio(ps), with_threads(2));
        const DelaunayTriangulation live(ps, brio(ps), with_threads(2));
        EXPECT_EQ(live.tets(), listed.tets) << distribution;
        EXPECT_EQ(live.hull_triangle_count(), listed.hull_triangles) << distribution;
    }
}

TEST(ParallelBuild, CollidingThreadsInAUniformCube) {
    const PointSet ps = generate_points("cube", 3000, 2);
    const Triangulation sequential = triangulate(ps, brio(ps), TriangulateOptions{});
    for (unsigned threads : {1u, 2u, 4u}) {
        SCOPED_TRACE(threads);
        const Built built = build_forced(ps, threads);
        EXPECT_EQ(canonical(built.solid), canonical(sequential.tets));
        EXPECT_TRUE(built.redundant.empty());
    }
}

TEST(ParallelBuild, CollidingThreadsOnTheDegenerateCorpus) {
    for (const test::CorpusCase& c : test::degenerate_corpus()) {
        SCOPED_TRACE(c.name);
        const Triangulation sequential =
            triangulate(c.points, brio(c.points), TriangulateOptions{});
        const Tets expected = canonical(sequential.tets);
        Built one = build_forced(c.points, 1);
        EXPECT_EQ(canonical(one.solid), expected);
        EXPECT_EQ(one.redundant, sequential.redundant);
        for (unsigned threads : {2u, 4u}) {
            SCOPED_TRACE(threads);
            const Built many = build_forced(c.points, threads);
            EXPECT_EQ(many.stored, one.stored);
            EXPECT_EQ(many.redundant, sequential.redundant);
        }
    }
}

TEST(ParallelBuild, TheListFollowsTheStoredOrderOnEveryInput) {
    // The list path sorts in buckets of highest ids spread by slot pieces: on inputs with many
    // buckets, degenerate ones and weighted ones it must give the stored order exactly, for
    // every thread count.
    std::vector<std::pair<std::string, PointSet>> inputs;
    for (const test::CorpusCase& c : test::degenerate_corpus()) {
        inputs.emplace_back(c.name, c.points);
    }
    inputs.emplace_back("cube", generate_points("cube", 20000, 4));
    inputs.emplace_back(
        "weighted grid",
        generate_points("grid", 6000, 3, WeightSpec{WeightSpec::Kind::kUniform, 0, 3.0}));
    for (const auto& [name, ps] : inputs) {
        SCOPED_TRACE(name);
        const Built stored = build_forced(ps, 1);
        const Tets expected = mirrored_solid(stored);
        const std::size_t hull = stored.stored.size() - stored.solid.size();
        for (unsigned threads : {1u, 2u, 3u, 4u}) {
            SCOPED_TRACE(threads);
            const Listed listed = list_forced(ps, threads);
            EXPECT_EQ(listed.tets, expected);
            EXPECT_EQ(listed.hull_triangles, hull);
        }
    }
}

TEST(ParallelBuild, WeightedPointsAndTheirRedundantOnes) {
    // Weights up to a few squared spacings of the points: many are submerged.
    const std::pair<const char*, double> cases[] = {{"cube", 0.05}, {"grid", 3.0}};
    for (const auto& [distribution, max_weight] : cases) {
        SCOPED_TRACE(distribution);
        const PointSet ps = generate_points(
            distribution, 6000, 3, WeightSpec{WeightSpec::Kind::kUniform, 0, max_weight});
        const Triangulation sequential = triangulate(ps, brio(ps), TriangulateOptions{});
        ASSERT_FALSE(sequential.redundant.empty());
        for (unsigned threads : {1u, 2u, 4u}) {
            SCOPED_TRACE(threads);
            const Built built = build_forced(ps, threads);
            EXPECT_EQ(canonical(built.solid), canonical(sequential.tets));
            EXPECT_EQ(built.redundant, sequential.redundant);
        }
    }
}

TEST(ParallelBuild, TheLiveTriangulationWorksOnTheResult) {
    const PointSet ps = generate_points("ball", 20000, 11);
    DelaunayTriangulation dt(ps, brio(ps), with_threads(2));
    EXPECT_TRUE(dt.check(CheckLevel::kDelaunay).empty());
    dt.insert(Point3{0.01, 0.02, 0.03});
    const std::vector<std::uint32_t> gone{5, 17, 400};
    dt.remove(gone);
    EXPECT_TRUE(dt.check(CheckLevel::kDelaunay).empty());
}

TEST(ParallelBuild, DuplicatesAreReportedAsSequentially) {
    PointSet ps = generate_points("cube", 9000, 5);
    for (std::size_t i = 0; i < 300; ++i) {
        ps.points.push_back(ps.points[i * 7]);
    }
    const Triangulation sequential = triangulate(ps, brio(ps), TriangulateOptions{});
    const Triangulation parallel = triangulate(ps, brio(ps), with_threads(2));
    EXPECT_EQ(parallel.duplicates, sequential.duplicates);
    EXPECT_EQ(canonical(parallel.tets), canonical(sequential.tets));
    EXPECT_EQ(parallel.hull_triangles, sequential.hull_triangles);
}

TEST(ParallelBuild, RefusesWhatItDoesNotDo) {
    const PointSet ps = generate_points("cube", 100, 1);
    TriangulateOptions counted = with_threads(2);
    counted.count = true;
    EXPECT_THROW(triangulate(ps, brio(ps), counted), Error);
    TriangulateOptions graph = with_threads(2);
    graph.locate = LocateKind::kConflictGraph;
    EXPECT_THROW(triangulate(ps, brio(ps), graph), Error);
    TriangulateOptions hashed = with_threads(2);
    hashed.storage = StorageKind::kHash;
    EXPECT_THROW(triangulate(ps, brio(ps), hashed), Error);
    TriangulateOptions prefix = with_threads(2);
    prefix.prefix = 50;
    EXPECT_THROW(triangulate(ps, brio(ps), prefix), Error);
    EXPECT_THROW(triangulate(ps, brio(ps), with_threads(128)), Error);
    // An implicit Steiner point (a CDT's): the workers would seek its cavity from its rounding.
    PointSet implicit = ps;
    implicit.exact.assign(ps.points.begin(), ps.points.end());
    const Point3 a = ps.points[1];
    const Point3 b = ps.points[2];
    implicit.exact[0] = predicates::SegmentParameterPoint{a, b, 1, 3};
    implicit.points[0] = {a.x + (b.x - a.x) / 3, a.y + (b.y - a.y) / 3, a.z + (b.z - a.z) / 3};
    EXPECT_THROW(triangulate(implicit, brio(implicit), with_threads(2)), Error);
    EXPECT_NO_THROW(triangulate(implicit, brio(implicit), TriangulateOptions{}));
}

}  // namespace
}  // namespace cavity::core
