#include <algorithm>
#include <list>
#include <random>

#include <gtest/gtest.h>

#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/experiments/memory_model.h"
#include "cavity/experiments/traced_storage.h"

namespace cavity::experiments {
namespace {

/// The textbook LRU: a list, most recent first, of at most `capacity` blocks.
std::uint64_t brute_force_misses(const std::vector<std::uint64_t>& stream, std::size_t capacity) {
    std::list<std::uint64_t> cache;
    std::uint64_t misses = 0;
    for (std::uint64_t b : stream) {
        const auto it = std::find(cache.begin(), cache.end(), b);
        if (it == cache.end()) {
            ++misses;
            if (cache.size() == capacity) {
                cache.pop_back();
            }
        } else {
            cache.erase(it);
        }
        cache.push_front(b);
    }
    return misses;
}

TEST(MemoryModel, StackDistancesEqualEveryLruSize) {
    // Streams with locality (a drifting window) and without, long enough to renumber the access
    // times several times (2^20 times per tree).
    std::mt19937_64 rng(7);
    for (const std::uint64_t spread : {40u, 3000u}) {
        std::vector<std::uint64_t> stream;
        std::uint64_t centre = 0;
        for (int i = 0; i < 2'500'000; ++i) {
            centre += rng() % 3 == 0 ? 1 : 0;
            stream.push_back((centre + rng() % spread) % 5000);
        }
        const std::vector<std::uint64_t> capacities{1, 16, 64, 1000};
        LruStack stack(capacities);
        for (std::uint64_t b : stream) {
            stack.access(b);
        }
        EXPECT_EQ(stack.accesses(), stream.size());
        // The list-based LRU is slow: compare on a prefix for the large cache.
        for (std::size_t i = 0; i < capacities.size(); ++i) {
            const std::size_t prefix = capacities[i] >= 1000 ? 300'000 : stream.size();
            LruStack partial(capacities);
            for (std::size_t k = 0; k < prefix; ++k) {
                partial.access(stream[k]);
            }
            const std::vector<std::uint64_t> head(
                stream.begin(), stream.begin() + static_cast<std::ptrdiff_t>(prefix));
            EXPECT_EQ(partial.misses(i), brute_force_misses(head, capacities[i]))
                << "capacity " << capacities[i] << ", spread " << spread;
        }
        for (std::size_t i = 1; i < capacities.size(); ++i) {
            EXPECT_LE(stack.misses(i), stack.misses(i - 1));  // LRU's inclusion property
        }
    }
}

TEST(MemoryModel, AnInsertionCountsEachBlockOnce) {
    MemoryTrace trace({64, 24}, {2}, {1});
    trace.touch_tet(0);
    trace.touch_tet(0);
    trace.touch_point(1);  // bytes 24..47: line 0 of the point array, not the tetrahedra's
    trace.touch_tet(1);    // bytes 64..127: line 1, page 0
    trace.end_insertion();
    EXPECT_EQ(trace.touches(), 4u);
    EXPECT_EQ(trace.distinct_lines(), 3u);
    EXPECT_EQ(trace.distinct_pages(), 2u);
    trace.touch_tet(1);
    trace.end_insertion();
    EXPECT_EQ(trace.insertions(), 2u);
    EXPECT_EQ(trace.lines().misses(0), 3u);  // tet line 1 was the latest: a hit in 2 lines
    EXPECT_EQ(trace.pages().misses(0), 3u);  // the point page came between: a miss in 1 page
}

struct EndInsertion : core::CountingObserver {
    MemoryTrace* trace = nullptr;

    void on_insertion(const core::InsertionRecord&) { trace->end_insertion(); }
};

TEST(MemoryModel, TracingLeavesTheTriangulationAlone) {
    const core::PointSet points = core::generate_points("cube", 3000, 4);
    core::OrderOptions brio;
    brio.kind = core::OrderKind::kBrio;
    brio.seed = 4;
    const core::InsertionOrder order = core::make_insertion_order(points.points, brio);
    core::TriangulateOptions options;
    options.count = true;
    const core::Triangulation plain = core::triangulate(points, order.sequence, options);
    core::Triangulation traced;
    const core::detail::Prepared prep =
        core::detail::prepare(points, order.sequence, options.bootstrap, traced);
    MemoryTrace trace({sizeof(core::ArrayRecord), sizeof(core::Point3)}, {512}, {64});
    TracedArrayStorage storage(trace);
    EndInsertion observer;
    observer.trace = &trace;
    core::detail::WalkLocator locator(options.seed);
    core::detail::run(prep.geometry, options, locator, storage, observer, traced);
    core::detail::drain_into(storage, prep.geometry, traced);
    EXPECT_EQ(traced.tets, plain.tets);
    EXPECT_EQ(traced.counters.walk_steps, plain.counters.walk_steps);
    EXPECT_EQ(trace.insertions(), points.size() - 4);
    // Every created tetrahedron's record is written, so touches outnumber creations.
    EXPECT_GT(trace.touches(), plain.counters.tets_created);
}

}  // namespace
}  // namespace cavity::experiments
