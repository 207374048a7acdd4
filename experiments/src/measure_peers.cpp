#include <atomic>
#include <filesystem>

#include <unistd.h>

#include "cavity/core/base/error.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/io/point_io.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/experiments/measure.h"
#include "child_process.h"
#include "format.h"
#include "peer_engines.h"

namespace cavity::experiments::measure {

namespace {

namespace fs = std::filesystem;
using detail::number;

/// One peer's cells of the row: status, seconds, tetrahedra, peak, and cavity's ratios to it.
struct PeerCells {
    std::string status = "unavailable";
    std::string seconds = "-", tets = "-", peak = "-", time_ratio = "-", memory_ratio = "-";

    void fill(double peer_seconds,
              std::uint64_t peer_tets,
              std::uint64_t peer_peak,
              const detail::ChildOutcome& cavity) {
        status = "ok";
        seconds = number(peer_seconds);
        tets = number(peer_tets);
        peak = number(peer_peak);
        time_ratio = peer_seconds > 0 ? number(cavity.report.seconds / peer_seconds) : "-";
        memory_ratio =
            peer_peak > 0
                ? number(static_cast<double>(cavity.peak_bytes) / static_cast<double>(peer_peak))
                : "-";
    }
};

/// A fresh scratch directory for TetGen's files, removed when the run is done.
class ScratchDirectory {
public:
    ScratchDirectory() {
        static std::atomic<unsigned> counter{0};
        path_ = fs::temp_directory_path() /
                ("cavity-peers-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }

    ~ScratchDirectory() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }

    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;

    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

}  // namespace

std::vector<std::string> peers_columns() {
    std::vector<std::string> columns{
        "points", "input_peak_bytes", "cavity_s", "cavity_tets", "cavity_peak_bytes"};
    for (const char* peer : {"cgal", "tetgen"}) {
        for (const char* c : {"status", "s", "tets", "peak_bytes", "time_ratio", "memory_ratio"}) {
            columns.push_back(std::string(peer) + "_" + c);
        }
    }
    columns.emplace_back("tetgen_delaunay_s");
    return columns;
}

RunOutput peers(const Suite& suite, const RunSpec& run) {
    // Every engine generates its own copy of the points in its own child, so the parent stays
    // small (a forked child starts with the parent's resident pages) and each peak is one
    // engine's. The same generator call gives the same points in every child.
    const auto generate = [&run] { return core::generate_points(run.dist, run.n, run.seed); };
    const fs::path tetgen = detail::find_on_path("tetgen");
    const ScratchDirectory scratch;
    const fs::path prefix = scratch.path() / "points";

    // The input alone (and TetGen's .node): the baseline under every engine's peak. Its report
    // carries the number of points in place of tetrahedra.
    const detail::ChildOutcome input = detail::run_in_child([&] {
        const core::PointSet set = generate();
        if (!tetgen.empty()) {
            core::write_points(prefix.string() + ".node", set);
        }
        return detail::EngineReport{0, set.size()};
    });
    const std::uint64_t points = input.report.tets;

    const detail::ChildOutcome cavity = detail::run_in_child([&] {
        const core::PointSet set = generate();
        core::TriangulateOptions options;
        options.locate = core::parse_locate_kind(run.locate);
        options.storage = core::parse_storage_kind(run.storage);
        const double start = detail::process_cpu_seconds();
        const core::InsertionOrder order = core::make_insertion_order(
            set.points, detail::order_options(run.order, suite.brio_ratio, run.seed));
        const core::Triangulation result = core::triangulate(set, order.sequence, options);
        return detail::EngineReport{detail::process_cpu_seconds() - start, result.tets.size()};
    });

    PeerCells cgal;
    if (detail::cgal_available()) {
        try {
            const detail::ChildOutcome c =
                detail::run_in_child([&] { return detail::cgal_delaunay(generate()); });
            cgal.fill(c.report.seconds, c.report.tets, c.peak_bytes, cavity);
        } catch (const core::Error&) {
            cgal.status = "failed";
        }
    }

    PeerCells tet;
    std::string tetgen_delaunay = "-";
    if (!tetgen.empty()) {
        const detail::TetgenRun t = detail::run_tetgen(tetgen, prefix);
        if (t.ok) {
            tet.fill(t.cpu_seconds, t.tets, t.peak_bytes, cavity);
        } else {
            tet.status = "failed";
        }
        if (t.delaunay_seconds) {
            tetgen_delaunay = number(*t.delaunay_seconds);
        }
    }

    RunOutput out;
    out.values = {number(points),
                  number(input.peak_bytes),
                  number(cavity.report.seconds),
                  number(cavity.report.tets),
                  number(cavity.peak_bytes)};
    for (const PeerCells* peer : {&cgal, &tet}) {
        for (const std::string* cell : {&peer->status,
                                        &peer->seconds,
                                        &peer->tets,
                                        &peer->peak,
                                        &peer->time_ratio,
                                        &peer->memory_ratio}) {
            out.values.push_back(*cell);
        }
    }
    out.values.push_back(tetgen_delaunay);
    return out;
}

}  // namespace cavity::experiments::measure
