#include "point_ids.h"

#include "cavity/core/base/error.h"

namespace cavity::cli {

std::vector<std::uint32_t> zero_based_ids(const core::PointSet& points,
                                          const std::vector<std::uint64_t>& listed,
                                          const std::string& option) {
    const auto base = static_cast<std::uint64_t>(points.index_base);
    std::vector<std::uint32_t> ids;
    ids.reserve(listed.size());
    for (const std::uint64_t id : listed) {
        if (id < base || id - base >= points.size()) {
            throw core::Error(option + ": point " + std::to_string(id) + " is not in " +
                              points.source + " (its points are numbered " + std::to_string(base) +
                              " to " + std::to_string(points.size() - 1 + base) + ")");
        }
        ids.push_back(static_cast<std::uint32_t>(id - base));
    }
    return ids;
}

}  // namespace cavity::cli
