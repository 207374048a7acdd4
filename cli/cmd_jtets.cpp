#include <cstdio>
#include <memory>
#include <string>

#include "cavity/core/atomic_file.h"
#include "cavity/core/point_io.h"
#include "cavity/experiments/jtets.h"
#include "commands.h"

namespace cavity::cli {

namespace {

struct JTetsArgs {
    std::string input;
    std::string output;
    bool brute_force = false;
};

void run_jtets(const JTetsArgs& args) {
    const core::PointSet points = core::read_points(args.input, false);
    const experiments::JTetCounts counts = args.brute_force
                                               ? experiments::count_jtets_brute_force(points.points)
                                               : experiments::count_jtets(points.points);
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
    cmd->add_flag("--brute-force", args->brute_force,
                  "count over all 4-subsets instead (O(n^5), for cross-checks)");
    cmd->callback([args] { run_jtets(*args); });
}

}  // namespace cavity::cli
