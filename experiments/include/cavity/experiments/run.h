#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cavity/experiments/suite.h"

/// One run of a suite: a cell of its grid, how to execute it, and the CSV columns it fills.
namespace cavity::experiments {

struct RunSpec {
    std::string dist;
    std::uint64_t n = 0;
    std::string order;    ///< "-" when the kind has no insertion order
    std::string locate;   ///< "-" when the kind does not triangulate with a choice of locator
    std::string storage;  ///< "-" likewise
    std::uint64_t seed = 0;
};

/// The columns that identify a run, in CSV order.
std::vector<std::string> key_columns();

/// The values of key_columns() for a run.
std::vector<std::string> key_values(const RunSpec& run);

/// The runs of a suite at a tier, in canonical order (the order of the merged CSV).
std::vector<RunSpec> enumerate_runs(const Suite& suite, const TierSettings& tier);

/// A rough relative cost, for the progress bar's ETA.
double run_cost(const Suite& suite, const TierSettings& tier, const RunSpec& run);

/// What one run measured: one row of the main table and the rows of the per-j table (each
/// without the key columns).
struct RunOutput {
    std::vector<std::string> values;
    std::vector<std::vector<std::string>> j_rows;
};

/// Column names of the main table (after the key columns) and of the per-j table (after the key
/// columns; empty when the kind has no per-j table).
std::vector<std::string> metric_columns(SuiteKind kind);
std::vector<std::string> j_columns(SuiteKind kind);

/// Executes one run. \throws Error when the run cannot be made (a generator refusing a size,
/// input with no triangulation, an invalid output under `validate`).
RunOutput execute_run(const Suite& suite, const TierSettings& tier, const RunSpec& run);

}  // namespace cavity::experiments
