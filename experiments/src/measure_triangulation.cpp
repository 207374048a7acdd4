#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>

#include "canonical.h"
#include "cavity/core/base/error.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/experiments/greedy_order.h"
#include "cavity/experiments/measure.h"
#include "format.h"

namespace cavity::experiments::measure {

namespace {

using detail::number;

/// Resets the kernel's peak-RSS mark (VmHWM) so the next reading is this run's peak; returns
/// false where /proc/self/clear_refs is not available.
bool reset_peak_rss() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    return static_cast<bool>(clear);
}

/// VmHWM in bytes, or 0 when /proc is missing.
std::uint64_t peak_rss_bytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) == 0) {
            return std::stoull(line.substr(6)) * 1024;
        }
    }
    return 0;
}

constexpr const char* kKindNames[] = {"orient3d", "insphere", "orient4d", "ghost"};

/// Counts like the counting engine and keeps each insertion's walk steps, by input index, for
/// the per-round trace of §5.5's reversal claim.
struct WalkTrace : core::CountingObserver {
    explicit WalkTrace(std::size_t n) : steps(n, 0) {}

    void on_insertion(const core::InsertionRecord& record) {
        steps[record.vertex] = record.walk_steps;
    }

    std::vector<std::uint32_t> steps;
};

/// §5.5: a BRIO round sorted along the curve starts where the previous one ended when alternate
/// rounds are reversed, so its first walk is short. Over the rounds after the first non-empty one:
/// the mean and the largest walk of each round's first insertion, and the mean walk of the rest.
struct RoundWalks {
    double first_mean = 0;
    double first_max = 0;
    double rest_mean = 0;
};

RoundWalks round_walks(const core::InsertionOrder& order, const std::vector<std::uint32_t>& steps) {
    RoundWalks out;
    const auto& begin = order.round_begin;
    const std::size_t n = order.sequence.size();
    double firsts = 0;
    double rest = 0;
    std::size_t rounds = 0;
    std::size_t others = 0;
    bool earlier = false;  // a non-empty round came before: the first walk crosses a boundary
    for (std::size_t r = 0; r < begin.size(); ++r) {
        const std::size_t end = r + 1 < begin.size() ? begin[r + 1] : n;
        if (begin[r] == end) {
            continue;
        }
        if (earlier) {
            const double first = steps[order.sequence[begin[r]]];
            firsts += first;
            out.first_max = std::max(out.first_max, first);
            ++rounds;
            for (std::size_t k = begin[r] + 1; k < end; ++k) {
                rest += steps[order.sequence[k]];
                ++others;
            }
        }
        earlier = true;
    }
    out.first_mean = rounds > 0 ? firsts / static_cast<double>(rounds) : 0;
    out.rest_mean = others > 0 ? rest / static_cast<double>(others) : 0;
    return out;
}

}  // namespace

std::vector<std::string> triangulation_columns() {
    std::vector<std::string> columns{"points",
                                     "vertices",
                                     "order_s",
                                     "time_s",
                                     "us_per_point",
                                     "tets",
                                     "hull_triangles",
                                     "created",
                                     "deleted",
                                     "ghosts_created",
                                     "ghosts_deleted",
                                     "created_per_point",
                                     "deleted_per_point",
                                     "max_cavity",
                                     "dig_tests",
                                     "walk_steps",
                                     "walk_steps_per_point",
                                     "walk_orient_calls",
                                     "walk_fallbacks",
                                     "redistributed",
                                     "redistribution_steps",
                                     "perturbations",
                                     "perturbation_cofactors",
                                     "hash_probes"};
    for (const char* kind : kKindNames) {
        for (int s = 0; s < predicates::kStageCount; ++s) {
            columns.push_back(
                std::string(kind) + "_" +
                std::string(predicates::stage_name(static_cast<predicates::Stage>(s))));
        }
    }
    // Theorem 5.4's conflicts (Σj over created solid tetrahedra, ghosts apart), "-" when the run
    // did not count them. Then, for BRIO only ("-" otherwise): the walk of each round's first
    // insertion, mean and largest, against the mean walk of the other insertions of those rounds.
    for (const char* c : {"conflicts",
                          "conflicts_per_point",
                          "ghost_conflicts",
                          "live_conflicts_max",
                          "round_first_walk_mean",
                          "round_first_walk_max",
                          "round_rest_walk_mean",
                          "storage_bytes",
                          "peak_rss_bytes",
                          "valid",
                          "hash"}) {
        columns.emplace_back(c);
    }
    return columns;
}

RunOutput triangulation(const Suite& suite, const RunSpec& run) {
    const core::PointSet points = core::generate_points(run.dist, run.n, run.seed);
    using Clock = std::chrono::steady_clock;
    const auto order_start = Clock::now();
    // "greedy": Exercise 1's adversary, which needs the triangulation to choose each next point.
    const core::InsertionOrder order =
        run.order == "greedy"
            ? core::InsertionOrder{greedy_order(points), {}}
            : core::make_insertion_order(
                  points.points, detail::order_options(run.order, suite.brio_ratio, run.seed));
    const double order_s = std::chrono::duration<double>(Clock::now() - order_start).count();
    core::TriangulateOptions options;
    options.locate = core::parse_locate_kind(run.locate);
    options.storage = core::parse_storage_kind(run.storage);
    options.count = true;
    options.count_conflicts = suite.count_conflicts;
    options.prefix = suite.prefix;
    options.seed = run.seed;
    options.bootstrap =
        suite.bootstrap_first ? core::BootstrapRule::kFirst : core::BootstrapRule::kWidest;
    const bool conflicts_counted =
        suite.count_conflicts || options.locate == core::LocateKind::kFullConflictGraph;
    // Time and memory are those of the engine users run: without counters, on the same order.
    // The counting run that follows gives the counters. A suite that counts conflicts measures
    // the counting run instead (its time is the counting's; the metadata says which).
    bool peak_known = reset_peak_rss();
    auto start = Clock::now();
    if (!suite.count_conflicts) {
        core::TriangulateOptions plain = options;
        plain.count = false;
        core::triangulate(points, order.sequence, plain);
    }
    double time_s = std::chrono::duration<double>(Clock::now() - start).count();
    std::uint64_t peak = peak_known ? peak_rss_bytes() : 0;
    if (suite.count_conflicts) {
        peak_known = reset_peak_rss();
        start = Clock::now();
    }
    // The trace costs one store per insertion; runs that count conflicts use their own observer.
    WalkTrace trace(points.size());
    const core::Triangulation result =
        suite.count_conflicts ? core::triangulate(points, order.sequence, options)
                              : core::triangulate_observed(points, order.sequence, options, trace);
    if (suite.count_conflicts) {
        time_s = std::chrono::duration<double>(Clock::now() - start).count();
        peak = peak_known ? peak_rss_bytes() : 0;
    }
    std::string valid = "-";
    if (suite.validates(run.n) && suite.prefix == 0) {
        const core::ValidationReport report = core::validate(points, result.tets);
        if (!report.ok()) {
            throw core::Error(run.dist + " n=" + std::to_string(run.n) + " order " + run.order +
                              ": invalid triangulation: " + report.problems.front());
        }
        valid = "1";
    }
    const core::Counters& c = result.counters;
    const auto count = static_cast<double>(points.size());
    // A prefix run's vertices are its first points; per-point columns stay per input point, so
    // its conflicts_per_point is the prefix's share of a whole run's Σj/n.
    const std::uint64_t inserted =
        suite.prefix == 0 ? points.size() : std::min<std::uint64_t>(suite.prefix, points.size());
    const std::uint64_t vertices = inserted - result.duplicates.size() - result.redundant.size();
    RunOutput out;
    out.values = {number(std::uint64_t{points.size()}),
                  number(vertices),
                  number(order_s),
                  number(time_s),
                  number(time_s * 1e6 / count),
                  number(std::uint64_t{result.tets.size()}),
                  number(std::uint64_t{result.hull_triangles}),
                  number(c.tets_created),
                  number(c.tets_deleted),
                  number(c.ghosts_created),
                  number(c.ghosts_deleted),
                  number(static_cast<double>(c.tets_created) / count),
                  number(static_cast<double>(c.tets_deleted) / count),
                  number(c.max_cavity),
                  number(c.dig_tests),
                  number(c.walk_steps),
                  number(static_cast<double>(c.walk_steps) / count),
                  number(c.walk_orient_calls),
                  number(c.walk_fallbacks),
                  number(c.points_redistributed),
                  number(c.redistribution_steps),
                  number(c.perturbations),
                  number(c.perturbation_cofactors),
                  number(c.hash_probes)};
    for (const auto& kind : c.stage_calls) {
        for (std::uint64_t calls : kind) {
            out.values.push_back(number(calls));
        }
    }
    char hash[20];
    std::snprintf(hash,
                  sizeof hash,
                  "%016llx",
                  static_cast<unsigned long long>(detail::canonical_hash(result.tets)));
    const auto counted = [&](std::uint64_t value) {
        return conflicts_counted ? number(value) : std::string("-");
    };
    out.values.push_back(counted(c.conflicts_created));
    out.values.push_back(conflicts_counted
                             ? number(static_cast<double>(c.conflicts_created) / count)
                             : std::string("-"));
    out.values.push_back(counted(c.ghost_conflicts_created));
    out.values.push_back(counted(c.live_conflicts_max));
    const bool traced = !order.round_begin.empty() && !suite.count_conflicts;
    const RoundWalks walks = traced ? round_walks(order, trace.steps) : RoundWalks{};
    for (const double v : {walks.first_mean, walks.first_max, walks.rest_mean}) {
        out.values.push_back(traced ? number(v) : std::string("-"));
    }
    out.values.push_back(number(std::uint64_t{result.storage_bytes}));
    out.values.push_back(number(peak));
    out.values.push_back(valid);
    out.values.push_back(hash);
    return out;
}

}  // namespace cavity::experiments::measure
