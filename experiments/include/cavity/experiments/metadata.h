#pragma once

#include <string>

#include "cavity/experiments/suite.h"

namespace cavity::experiments {

/// What a reader needs to reproduce or trust a table: the suite, tier and seeds, the git commit
/// of the source (and whether the tree had local changes), compiler and flags, CPU model and
/// count, and the UTC date, as a JSON object. `runs_measured` is less than `runs` for a table
/// merged with `partial` (a long tier stopped part-way).
std::string metadata_json(const Suite& suite,
                          const std::string& tier,
                          const TierSettings& settings,
                          std::size_t runs,
                          std::size_t runs_measured,
                          std::uint64_t shard_count,
                          const std::string& command_line);

}  // namespace cavity::experiments
