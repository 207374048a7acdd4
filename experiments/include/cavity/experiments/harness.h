#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

/// `cavity experiment`: runs a suite's grid at a tier and writes its tables.
///
/// Files in the output directory, for a suite NAME:
///   NAME.csv        one row per run: the key columns, then the kind's measurements
///   NAME.j.csv      per-j rows (jtets and creation suites): the key columns, then j, ...
///   NAME.meta.json  git commit, compiler, flags, CPU, date, tier, seeds, shard count
/// Work in progress goes to NAME.part-I-of-N.csv (and .j.csv), one complete line appended per
/// run, so an interrupted run loses at most the run under way and `resume` picks up after the last
/// complete row. A shard runs the runs whose canonical index k has k mod N = I - 1. When every
/// part holds all its runs, the parts are merged (rows in canonical order, whatever the shard
/// count) into NAME.csv, NAME.j.csv and NAME.meta.json, written atomically, and the parts are
/// removed; the merged tables of a sharded and an unsharded run differ only in measured times.
namespace cavity::experiments {

struct HarnessOptions {
    std::filesystem::path suite_file;
    std::string tier = "quick";
    std::filesystem::path out_dir;
    bool resume = false;
    std::uint64_t shard_index = 1;  ///< 1-based
    std::uint64_t shard_count = 1;
    std::optional<std::uint64_t> seed;  ///< replaces the suite's seed list
    bool merge_only = false;            ///< only merge finished parts
    /// With merge_only: merge the rows measured so far even when runs are missing (a long tier
    /// stopped part-way); the metadata says how many. A later `resume` continues from the table.
    bool partial = false;
    std::string command_line;  ///< recorded in the metadata
    /// (work done, total work), in arbitrary cost units; may be empty.
    std::function<void(double, double)> progress;
};

struct HarnessResult {
    std::size_t runs_total = 0;    ///< runs of the suite at this tier
    std::size_t runs_done = 0;     ///< executed by this call
    std::size_t runs_skipped = 0;  ///< found complete in the part file (resume)
    bool merged = false;
    std::filesystem::path csv;  ///< the merged table, or the part file when not merged yet
};

/// Runs (a shard of) a suite. \throws Error for a malformed suite, bad options, a run that fails
/// (naming it), a part file whose header differs from the suite's columns, or, with merge_only
/// and not partial, missing parts or rows.
HarnessResult run_experiment(const HarnessOptions& options);

}  // namespace cavity::experiments
