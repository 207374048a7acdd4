#include <chrono>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/experiments/measure.h"
#include "cavity/experiments/memory_model.h"
#include "cavity/experiments/traced_storage.h"
#include "format.h"

namespace cavity::experiments::measure {

namespace {

using detail::number;

// LRU capacities, in blocks: 32 KiB and 1 MiB of 64-byte lines (a first- and a second-level
// cache), and 256 KiB, 4 MiB and 64 MiB of 4 KiB pages (from a TLB's reach to a small main
// memory). The mesh of 10^6 points takes about 420 MB, so only the order's locality keeps the
// larger ones effective.
const std::vector<std::uint64_t> kLineCapacities{512, 16384};
const std::vector<std::uint64_t> kPageCapacities{64, 1024, 16384};

/// Closes the memory trace's insertion after each point, and counts as the engine does.
struct LocalityObserver : core::CountingObserver {
    explicit LocalityObserver(MemoryTrace& t) : trace(&t) {}

    void on_insertion(const core::InsertionRecord&) { trace->end_insertion(); }

    MemoryTrace* trace;
};

template <class Locator>
void run_traced(const core::detail::Prepared& prep,
                const core::TriangulateOptions& options,
                Locator locator,
                MemoryTrace& trace,
                core::Triangulation& out) {
    TracedArrayStorage storage(trace);
    LocalityObserver observer(trace);
    core::detail::run(prep.geometry, options, locator, storage, observer, out);
}

}  // namespace

std::vector<std::string> locality_columns() {
    std::vector<std::string> columns{"points",
                                     "time_s",
                                     "insertions",
                                     "walk_steps_per_point",
                                     "created_per_point",
                                     "touches_per_insertion",
                                     "lines_per_insertion",
                                     "pages_per_insertion"};
    for (std::uint64_t c : kLineCapacities) {
        columns.push_back("line_misses_" + std::to_string(c));
    }
    for (std::uint64_t c : kPageCapacities) {
        columns.push_back("page_misses_" + std::to_string(c));
    }
    return columns;
}

RunOutput locality(const Suite& suite, const RunSpec& run) {
    const core::PointSet points = core::generate_points(run.dist, run.n, run.seed);
    const core::InsertionOrder order = core::make_insertion_order(
        points.points, detail::order_options(run.order, suite.brio_ratio, run.seed));
    core::TriangulateOptions options;
    options.count = true;
    options.seed = run.seed;
    options.bootstrap =
        suite.bootstrap_first ? core::BootstrapRule::kFirst : core::BootstrapRule::kWidest;
    core::Triangulation out;
    const auto start = std::chrono::steady_clock::now();
    // The points are laid out in insertion order, as the engine lays them out.
    const core::detail::Prepared prep =
        core::detail::prepare(points, order.sequence, options.bootstrap, out);
    MemoryTrace trace(
        {sizeof(core::ArrayRecord), sizeof(core::Point3)}, kLineCapacities, kPageCapacities);
    if (run.locate == "walk") {
        run_traced(prep, options, core::detail::WalkLocator(run.seed), trace, out);
    } else if (run.locate == "straight-walk") {
        run_traced(prep, options, core::detail::StraightWalkLocator(run.seed), trace, out);
    } else {
        // A conflict graph's own lists are not in the trace: its misses would be undercounted.
        throw core::Error("the locality suite traces the walks only, not '" + run.locate + "'");
    }
    const double time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto count = static_cast<double>(points.size());
    const auto per = [&](std::uint64_t v) {
        return number(static_cast<double>(v) / static_cast<double>(trace.insertions()));
    };
    RunOutput output;
    output.values = {number(std::uint64_t{points.size()}),
                     number(time_s),
                     number(trace.insertions()),
                     number(static_cast<double>(out.counters.walk_steps) / count),
                     number(static_cast<double>(out.counters.tets_created) / count),
                     per(trace.touches()),
                     per(trace.distinct_lines()),
                     per(trace.distinct_pages())};
    for (std::size_t i = 0; i < kLineCapacities.size(); ++i) {
        output.values.push_back(per(trace.lines().misses(i)));
    }
    for (std::size_t i = 0; i < kPageCapacities.size(); ++i) {
        output.values.push_back(per(trace.pages().misses(i)));
    }
    return output;
}

}  // namespace cavity::experiments::measure
