#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/experiments/harness.h"
#include "commands.h"
#include "integer_option.h"
#include "progress_bar.h"

namespace cavity::cli {

namespace {

struct ExperimentArgs {
    std::string suite;
    std::string tier = "quick";
    std::string out;
    std::string shard;
    std::uint64_t seed = 0;
    bool seed_given = false;
    bool resume = false;
    bool merge = false;
    bool partial = false;
    bool quiet = false;
    std::string command_line;
};

/// A suite is a file path, or a name looked up in the source tree's experiments/suites.
std::filesystem::path suite_path(const std::string& suite) {
    if (suite.find('/') != std::string::npos || suite.ends_with(".suite")) {
        return suite;
    }
    return std::filesystem::path(CAVITY_SUITES_DIR) / (suite + ".suite");
}

void parse_shard(const std::string& text, experiments::HarnessOptions& options) {
    const std::size_t slash = text.find('/');
    try {
        std::size_t used = 0;
        options.shard_index = std::stoull(text.substr(0, slash), &used);
        if (slash == std::string::npos || used != slash) {
            throw std::invalid_argument(text);
        }
        options.shard_count = std::stoull(text.substr(slash + 1), &used);
        if (used != text.size() - slash - 1) {
            throw std::invalid_argument(text);
        }
    } catch (const std::logic_error&) {
        throw core::Error("--shard '" + text + "': expected i/N, e.g. 2/8");
    }
}

void run_experiment_command(const ExperimentArgs& args) {
    experiments::HarnessOptions options;
    options.suite_file = suite_path(args.suite);
    options.tier = args.tier;
    options.out_dir = args.out.empty() ? std::filesystem::path("results/experiments") / args.tier
                                       : std::filesystem::path(args.out);
    options.resume = args.resume;
    options.merge_only = args.merge || args.partial;
    options.partial = args.partial;
    if (args.seed_given) {
        options.seed = args.seed;
    }
    if (!args.shard.empty()) {
        parse_shard(args.shard, options);
    }
    options.command_line = args.command_line;
    ProgressBar bar(args.suite, !args.quiet);
    options.progress = [&bar](double done, double total) {
        bar.update(static_cast<std::size_t>(done / total * 1e6), 1000000);
    };
    const experiments::HarnessResult result = experiments::run_experiment(options);
    if (!args.quiet) {
        std::fprintf(stderr,
                     "\r\033[K%s: %zu runs (%zu done now, %zu resumed) -> %s%s\n",
                     args.suite.c_str(),
                     result.runs_total,
                     result.runs_done,
                     result.runs_skipped,
                     result.csv.string().c_str(),
                     result.merged ? "" : " (part; not merged yet)");
    }
}

}  // namespace

void add_experiment_command(CLI::App& app) {
    auto args = std::make_shared<ExperimentArgs>();
    CLI::App* cmd = app.add_subcommand(
        "experiment",
        "Run an experiment suite (experiments/suites/NAME.suite or a path) and write "
        "NAME.csv, NAME.j.csv and NAME.meta.json");
    cmd->add_option("suite", args->suite, "suite name or file")->required();
    cmd->add_option("--tier", args->tier, "quick, full or paper (the suites that have one)")
        ->check(CLI::IsMember({"quick", "full", "paper"}));
    cmd->add_option("--out", args->out, "output directory (default results/experiments/TIER)");
    cmd->add_flag("--resume", args->resume, "skip runs already in the tables");
    cmd->add_option("--shard", args->shard, "run shard i of N (i/N); parts merge when all exist");
    cmd->add_option("--seed", args->seed, "replace the suite's seeds by this one")
        ->transform(integer_in("--seed", 0, UINT64_MAX))
        ->each([args](const std::string&) { args->seed_given = true; });
    cmd->add_flag("--merge", args->merge, "only merge finished shard parts");
    cmd->add_flag("--partial",
                  args->partial,
                  "merge the runs measured so far, even if some are missing (a long tier stopped "
                  "part-way); --resume continues from the merged table");
    cmd->add_flag("--quiet", args->quiet, "no progress bar or summary");
    cmd->callback([args] {
        args->command_line = "cavity experiment " + args->suite + " --tier " + args->tier;
        if (args->seed_given) {
            args->command_line += " --seed " + std::to_string(args->seed);
        }
        if (!args->shard.empty()) {
            args->command_line += " --shard " + args->shard;
        }
        run_experiment_command(*args);
    });
}

}  // namespace cavity::cli
