#include "cavity/experiments/greedy_order.h"

#include <numeric>
#include <queue>
#include <utility>

#include "cavity/core/base/error.h"
#include "cavity/core/live/triangulate.h"

namespace cavity::experiments {

std::vector<std::uint32_t> greedy_order(const core::PointSet& points) {
    if (points.weighted()) {
        throw core::Error("the greedy adversary takes unweighted points");
    }
    std::vector<std::uint32_t> input(points.size());
    std::iota(input.begin(), input.end(), 0u);
    core::Triangulation skipped;  // collects the exact repeats
    const core::detail::Prepared prep =
        core::detail::prepare(points, input, core::BootstrapRule::kFirst, skipped);
    const core::Geometry& geometry = prep.geometry;
    const std::size_t m = geometry.size();
    core::ArrayStorage storage;
    storage.reserve(7 * m + 64);
    core::NullObserver observer;
    core::BowyerWatson<core::ArrayStorage, core::NullObserver> engine(geometry, storage, observer);
    engine.bootstrap(0, 1, 2, 3);
    core::FullConflictGraph graph(0);
    graph.start(engine);

    // Max-heap of (conflicts, -vertex): the largest cavity first, then the lowest vertex id, which
    // after the bootstrap is input order. Entries go stale when a count falls; a popped entry is
    // checked against the current count and pushed again when it is out of date.
    using Entry = std::pair<std::uint32_t, std::int64_t>;
    std::priority_queue<Entry> heap;
    for (core::VertexId u = 4; u < m; ++u) {
        heap.push({graph.conflicts_of(u), -static_cast<std::int64_t>(u)});
    }
    std::vector<char> inserted(m, 0);
    std::vector<std::uint32_t> sequence;
    sequence.reserve(points.size());
    for (core::VertexId v = 0; v < 4; ++v) {
        inserted[v] = 1;
        sequence.push_back(geometry.key(v));
    }
    std::vector<core::TetId> scratch;
    std::uint64_t step = 0;
    while (!heap.empty()) {
        const auto [count, negated] = heap.top();
        heap.pop();
        const auto u = static_cast<core::VertexId>(-negated);
        if (inserted[u] != 0) {
            continue;
        }
        if (count != graph.conflicts_of(u)) {
            heap.push({graph.conflicts_of(u), negated});
            continue;
        }
        const core::ConflictSeed seed =
            core::seek_conflict(engine, u, graph.locate(engine, u), scratch);
        if (seed.tet == core::kNoTet) {
            throw core::Error("internal error: greedy adversary: point " +
                                  std::to_string(geometry.key(u)) + " has no cavity",
                              core::ErrorKind::kInternal);
        }
        engine.insert_vertex(u, seed.tet, ++step);
        graph.after_insertion(engine, u);
        inserted[u] = 1;
        sequence.push_back(geometry.key(u));
        for (core::TetId t : engine.created()) {
            for (core::VertexId q : graph.conflicts_of_tet(t)) {
                heap.push({graph.conflicts_of(q), -static_cast<std::int64_t>(q)});
            }
        }
    }
    for (const auto& d : skipped.duplicates) {
        sequence.push_back(d[0]);
    }
    return sequence;
}

}  // namespace cavity::experiments
