#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "cavity/core/io/atomic_file.h"
#include "cavity/core/io/point_io.h"
#include "cavity/experiments/jtets.h"
#include "commands.h"
#include "progress_bar.h"

namespace cavity::cli {

namespace {

struct JTetsArgs {
    std::string input;
    std::string output;
    bool brute_force = false;
    bool quiet = false;
};

/// Warns once, on stderr, when the run so far predicts more than a minute: the sweep costs about
/// n^4 operations, so a user who meant a few hundred points learns it before waiting an hour.
class CostWarning {
public:
    CostWarning(std::size_t n, bool enabled) : n_(n), enabled_(enabled) {}

    void update(std::uint64_t done, std::uint64_t total) {
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (!enabled_ || warned_ || done == 0 || elapsed < 1.0) {
            return;
        }
        warned_ = true;
        const double estimate = elapsed * static_cast<double>(total) / static_cast<double>(done);
        if (estimate > 60) {
            std::fprintf(stderr,
                         "cavity jtets: %zu points will take about %.0f minutes (the cost grows "
                         "like n^4: %zu points would take about %.1f)\n",
                         n_,
                         estimate / 60,
                         n_ / 2,
                         estimate / 60 / 16);
        }
    }

private:
    std::size_t n_;
    bool enabled_;
    bool warned_ = false;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void run_jtets(const JTetsArgs& args) {
    const core::PointSet points = core::read_points(args.input, false);
    ProgressBar bar("counting j-tetrahedra", !args.quiet);
    CostWarning warning(points.size(), !args.quiet);
    const experiments::JTetCounts counts =
        args.brute_force
            ? experiments::count_jtets_brute_force(points.points)
            : experiments::count_jtets(points.points, [&](std::uint64_t done, std::uint64_t total) {
                  warning.update(done, total);
                  bar.update(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
              });
    bar.finish();
    const std::vector<std::uint64_t> cumulative = counts.cumulative();
    std::string csv = "j,f_j,F_j\n";
    for (std::size_t j = 0; j < counts.f.size(); ++j) {
        if (counts.f[j] != 0) {
            csv += std::to_string(j) + "," + std::to_string(counts.f[j]) + "," +
                   std::to_string(cumulative[j]) + "\n";
        }
    }
    if (args.output.empty()) {
        std::fwrite(csv.data(), 1, csv.size(), stdout);
        return;
    }
    core::AtomicFileGroup group;
    group.add(args.output).write(csv);
    group.commit();
}

}  // namespace

void add_jtets_command(CLI::App& app) {
    auto args = std::make_shared<JTetsArgs>();
    CLI::App* cmd = app.add_subcommand(
        "jtets",
        "Exact counts of j-tetrahedra (non-flat tetrahedra whose open circumball holds exactly j "
        "input points) as CSV j,f_j,F_j for every j with f_j > 0 (pencil sweep, exact predicates; "
        "a few hundred points)");
    cmd->add_option("points", args->input, "input points")->required();
    cmd->add_option("-o,--output", args->output, "write the CSV here instead of stdout");
    cmd->add_flag("--quiet", args->quiet, "no progress bar and no cost warning");
    cmd->add_flag("--brute-force",
                  args->brute_force,
                  "count over all 4-subsets instead (O(n^5), for cross-checks)");
    cmd->callback([args] { run_jtets(*args); });
}

}  // namespace cavity::cli
