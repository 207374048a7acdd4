#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cavity/experiments/run.h"
#include "cavity/experiments/suite.h"

namespace cavity::experiments {

/// Everything the harness knows about a suite kind, in one row: a new kind is its SuiteKind value,
/// its measurement (measure_<kind>.cpp) and a row of kinds() in suite_kinds.cpp.
struct SuiteKindInfo {
    SuiteKind kind;
    std::string_view name;  ///< the suite file's `kind` value
    RunOutput (*measure)(const Suite&, const TierSettings&, const RunSpec&);
    std::vector<std::string> (*columns)();    ///< the metric columns of its table
    std::vector<std::string> (*j_columns)();  ///< its .j.csv's columns; null: no .j.csv
    /// The relative cost of one run, for progress and the tier's cost line.
    double (*cost)(const Suite&, const TierSettings&, const RunSpec&);
    bool ordered;    ///< its runs vary the insertion order
    bool locates;    ///< they vary the point locator
    bool stores;     ///< they vary the storage
    bool own_first;  ///< it always starts from the order's own first four points
    bool timed;      ///< time_s times a whole triangulation (metadata says which engine)
};

/// Every kind, one row each (tests run every row).
std::span<const SuiteKindInfo> suite_kinds();

const SuiteKindInfo& suite_kind_info(SuiteKind kind);

}  // namespace cavity::experiments
