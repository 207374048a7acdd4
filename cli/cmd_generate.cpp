// `cavity generate`: writes a point set of a named distribution (uniform, degenerate, weighted).

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cavity/core/gen/generate.h"
#include "cavity/core/io/point_io.h"
#include "commands.h"
#include "integer_option.h"
#include "out_of_memory.h"

namespace cavity::cli {

namespace {

struct GenerateOptions {
    std::string distribution;
    std::size_t count = 0;
    std::uint64_t seed = 0;
    std::string weights = "none";
    std::string output;
};

void run_generate(const GenerateOptions& options) {
    const core::WeightSpec weights = core::parse_weight_spec(options.weights);
    const double bytes = static_cast<double>(options.count) *
                         (weights.kind == core::WeightSpec::Kind::kNone ? 24 : 32);
    const core::PointSet points =
        naming_memory("generating " + std::to_string(options.count) + " " + options.distribution +
                          " points (" + about_bytes(bytes) + ")",
                      [&] {
                          return core::generate_points(
                              options.distribution, options.count, options.seed, weights);
                      });
    core::write_points(options.output, points);
    std::printf("wrote %zu points to %s\n", points.size(), options.output.c_str());
}

}  // namespace

void add_generate_command(CLI::App& app) {
    auto options = std::make_shared<GenerateOptions>();
    CLI::App* generate = app.add_subcommand("generate", "Write a generated point set");
    std::vector<std::string> names;
    std::string list = "Distributions:\n";
    std::size_t width = 0;  // the longest name, and two spaces
    for (const core::Distribution& d : core::distributions()) {
        width = std::max(width, d.name.size() + 2);
    }
    for (const core::Distribution& d : core::distributions()) {
        names.emplace_back(d.name);
        list += "  " + std::string(d.name) + std::string(width - d.name.size(), ' ') +
                std::string(d.description) + "\n";
    }
    generate->add_option("distribution", options->distribution, "Distribution (listed below)")
        ->required()
        ->check(CLI::IsMember(names));
    generate->add_option("n", options->count, "Number of points (2000000, 2_000_000 or 2e6)")
        ->required()
        ->transform(integer_in("n", 4, 0xFFFF'FFFFu));
    generate->add_option("--seed", options->seed, "Seed of the random distributions (default 0)")
        ->transform(integer_in("--seed", 0, UINT64_MAX));
    generate->add_option("--weights",
                         options->weights,
                         "none (default), zero, equal:W or uniform:A:B (random in [A,B))");
    generate
        ->add_option("-o,--output",
                     options->output,
                     "Output file: .node (TetGen, 0-based), .xyz, .txt or .csv")
        ->required();
    generate->footer(list +
                     "The same arguments give the same points on every platform. Coordinates are "
                     "written in the\nshortest decimal form that reads back to the same double. "
                     "The file appears only once complete.\n");
    generate->callback([options] { run_generate(*options); });
}

}  // namespace cavity::cli
