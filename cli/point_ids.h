#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace cavity::cli {

/// Point numbers given on the command line in the input's own numbering (0- or 1-based, as the
/// file), turned into 0-based input indices. \throws core::Error naming `option` and the first
/// number that is not a point of `points`.
std::vector<std::uint32_t> zero_based_ids(const core::PointSet& points,
                                          const std::vector<std::uint64_t>& listed,
                                          const std::string& option);

}  // namespace cavity::cli
